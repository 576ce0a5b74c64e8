#include "data/interval.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/input_error.hpp"

namespace granrepro {

std::string trim(const std::string& s, const char* blanks) {
    const auto a = s.find_first_not_of(blanks);
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(blanks) - a + 1);
}

namespace {
// The whole trimmed text as one number that `strto` reads in range (not NaN); `out` is kept otherwise.
template <class T, class Strto>
bool parse_whole(const std::string& in, T& out, Strto strto) {
    const std::string s = trim(in);
    if (s.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const T v = strto(s.c_str(), &end);
    if (end != s.c_str() + s.size() || errno == ERANGE || std::isnan(double(v))) return false;
    out = v;
    return true;
}
} // namespace

bool parse_double(const std::string& in, double& out) {
    return parse_whole(in, out, [](const char* s, char** end) { return std::strtod(s, end); });
}

bool parse_long(const std::string& in, long& out) {
    return parse_whole(in, out, [](const char* s, char** end) { return std::strtol(s, end, 10); });
}

Interval Interval::parse(const std::string& text) {
    const std::string t = trim(text);
    const auto comma = t.find(',');
    if (t.size() < 5 || comma == std::string::npos || (t.front() != '(' && t.front() != '[') ||
        (t.back() != ')' && t.back() != ']'))
        throw InputError("range '" + text + "' is not of the form (a, b], [a, b) ...");
    Interval iv;
    iv.text = t;
    iv.lo_open = t.front() == '(';
    iv.hi_open = t.back() == ')';
    const std::string a = trim(t.substr(1, comma - 1));
    const std::string b = trim(t.substr(comma + 1, t.size() - comma - 2));
    const double inf = std::numeric_limits<double>::infinity();
    if (a == "-inf") iv.lo = -inf;
    else if (!parse_double(a, iv.lo)) throw InputError("range '" + text + "': bad lower bound");
    if (b == "inf") iv.hi = inf;
    else if (!parse_double(b, iv.hi)) throw InputError("range '" + text + "': bad upper bound");
    // "(1, 0)" holds no number: every value, the default included, would be refused with a
    // message that blames the value.
    if (iv.lo > iv.hi || (iv.lo == iv.hi && (iv.lo_open || iv.hi_open)))
        throw InputError("range '" + text + "' is empty (written backwards? the lower bound comes first)");
    return iv;
}

bool Interval::contains(double x) const {
    if (std::isnan(x)) return false;
    const bool above = lo_open ? x > lo : x >= lo;
    const bool below = hi_open ? x < hi : x <= hi;
    return above && below;
}

} // namespace granrepro
