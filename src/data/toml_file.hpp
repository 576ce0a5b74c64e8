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

} // namespace granrepro
