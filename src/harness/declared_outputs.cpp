#include "harness/declared_outputs.hpp"

#include <algorithm>

namespace granrepro {

namespace {
constexpr std::string_view kNumber = "<n>";

bool number_char(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

bool any_matches(const std::vector<std::string>& patterns, std::string_view name) {
    return std::any_of(patterns.begin(), patterns.end(),
                       [&](const std::string& p) { return matches_output_pattern(p, name); });
}
} // namespace

bool matches_output_pattern(std::string_view pattern, std::string_view name) {
    const std::size_t at = pattern.find(kNumber);
    if (at == std::string_view::npos) return pattern == name;
    if (name.substr(0, at) != pattern.substr(0, at)) return false;
    const std::string_view rest = pattern.substr(at + kNumber.size());
    // <n> takes one or more number characters; try every length (names are short).
    for (std::size_t k = at; k < name.size() && number_char(name[k]); ++k)
        if (matches_output_pattern(rest, name.substr(k + 1))) return true;
    return false;
}

bool DeclaredOutputs::declares_scalar(std::string_view name) const { return any_matches(scalars, name); }
bool DeclaredOutputs::declares_table(std::string_view name) const { return any_matches(tables, name); }

std::string output_pattern_error(std::string_view pattern) {
    if (pattern.empty()) return "an empty name";
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '<') {
            if (pattern.substr(i, kNumber.size()) != kNumber) return "a placeholder other than <n>";
            i += kNumber.size() - 1;
        } else if (c == '>' || c == ' ' || c == '\t' || c == '\n' || c == '/' || c == '"' || c == '\'') {
            return std::string("the character '") + c + "'";
        }
    }
    return "";
}

} // namespace granrepro
