// Reading the project's TOML files (experiments/, expected/) with errors of one line that keep
// toml11's location: toml11 reports a syntax or type error on several lines (the message, the
// file, the offending line with a caret and a hint), and a bad input must be one line.
#pragma once
#include <filesystem>
#include <string>
#include <toml.hpp>

namespace granrepro {

// "<file>:<line>: <message> (<hint>)" from toml11's text; "<file>: <first line>" for any other.
std::string toml_error_line(const std::string& file, const std::string& what);

// Parses `file`; throws InputError (one line) if it is missing, is not a regular file (a
// directory made toml11 throw std::bad_alloc) or is not valid TOML. `role` names the file in
// messages ("experiment file", "expected-claims file").
toml::value parse_toml_file(const std::filesystem::path& file, const std::string& role);

// "<file>:<line>" of a value, the head of a message about it (toml11 keeps each value's place).
std::string toml_place(const std::string& file, const toml::value& v);

// A number as written (an integer, or a float that toml11 read faithfully): toml11 reads a float
// with a stream, so 1e400 becomes 1.8e308 and 1e-400 becomes 0 without a word. Throws InputError
// "<file>:<line>: <what> = 1e400 is beyond ..." for a float whose text is out of the doubles'
// range (or subnormal); NaN and inf pass (the caller refuses them where it must).
double toml_number(const toml::value& v, const std::string& file, const std::string& what);

} // namespace granrepro
