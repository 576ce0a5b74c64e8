// An allowed range written the way physicists write it: "(0, inf)", "(0, 1]", "[3, 1000]".
#pragma once
#include <string>

namespace granrepro {

struct Interval {
    double lo = 0, hi = 0;
    bool lo_open = false, hi_open = false;
    std::string text; // as written in the experiment file

    static Interval parse(const std::string& text); // throws InputError
    bool contains(double x) const;
};

// Strict number parsing: the whole string must be a finite double ("inf" only where allowed).
bool parse_double(const std::string& s, double& out);
bool parse_long(const std::string& s, long& out);
// s without the leading and trailing characters of `blanks`.
std::string trim(const std::string& s, const char* blanks = " \t");

} // namespace granrepro
