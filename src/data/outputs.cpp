#include "data/outputs.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace granrepro {

namespace {
constexpr std::string_view kNumber = "<n>", kWord = "<w>";

bool number_char(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

bool any_matches(const std::vector<std::string>& patterns, std::string_view name) {
    return std::any_of(patterns.begin(), patterns.end(),
                       [&](const std::string& p) { return matches_output_pattern(p, name); });
}

// The catalogs, filled during static initialization (a function-local static, so it exists
// before the first handle registers, whatever the order of the translation units).
std::map<std::string, DeclaredOutputs, std::less<>>& registry() {
    static std::map<std::string, DeclaredOutputs, std::less<>> r;
    return r;
}

// The pattern, or one per word where it holds <w>, into the experiment's catalog.
void enroll(const char* experiment, std::vector<std::string> DeclaredOutputs::*list, const std::string& pattern,
            const Words& words, const char* kind) {
    DeclaredOutputs& d = registry()[experiment];
    const std::size_t w = pattern.find(kWord);
    if ((w == std::string::npos) != words.empty() || (w != std::string::npos && pattern.find(kWord, w + 1) != std::string::npos))
        d.errors.push_back(std::string(kind) + " '" + pattern + "' must hold <w> once exactly when it has words");
    Words expanded;
    if (w == std::string::npos) expanded.push_back(pattern);
    for (const std::string& word : w == std::string::npos ? Words{} : words)
        expanded.push_back(std::string(pattern).replace(w, kWord.size(), word));
    for (const std::string& p : expanded) {
        if (const std::string why = output_pattern_error(p); !why.empty())
            d.errors.push_back(std::string(kind) + " '" + p + "' holds " + why);
        if (std::find((d.*list).begin(), (d.*list).end(), p) != (d.*list).end())
            d.errors.push_back(std::string(kind) + " '" + p + "' is declared twice");
        (d.*list).push_back(p);
    }
}
} // namespace

std::string fill_pattern(std::string_view pattern, const Words& words, std::initializer_list<NamePart> parts) {
    const std::string whole(pattern);
    std::string name;
    auto part = parts.begin();
    for (;;) {
        const std::size_t n = pattern.find(kNumber), w = pattern.find(kWord), at = std::min(n, w);
        if (at == std::string_view::npos) break;
        if (part == parts.end()) throw std::logic_error("output '" + whole + "' has more placeholders than parts given");
        const std::string& text = (part++)->text;
        const bool fits = at == w ? std::find(words.begin(), words.end(), text) != words.end()
                                  : !text.empty() && std::all_of(text.begin(), text.end(), number_char);
        if (!fits) throw std::logic_error("output '" + whole + "': '" + text + "' cannot stand for " + std::string(pattern.substr(at, 3)));
        name.append(pattern.substr(0, at)).append(text);
        pattern.remove_prefix(at + 3);
    }
    if (part != parts.end()) throw std::logic_error("output '" + whole + "' has fewer placeholders than parts given");
    return name.append(pattern);
}

ScalarOut Outputs::scalar(std::string pattern, std::string unit, std::string description, Words words) const {
    enroll(experiment_, &DeclaredOutputs::scalars, pattern, words, "scalar");
    return {std::move(pattern), std::move(unit), std::move(description), std::move(words)};
}

TableOut Outputs::table(std::string pattern, std::string description, Words words) const {
    enroll(experiment_, &DeclaredOutputs::tables, pattern, words, "table");
    return {std::move(pattern), std::move(description), std::move(words)};
}

bool makes_name(std::string_view pattern, const Words& words, std::string_view name) {
    const std::size_t w = pattern.find(kWord);
    if (w == std::string_view::npos) return matches_output_pattern(pattern, name);
    return std::any_of(words.begin(), words.end(), [&](const std::string& word) {
        return matches_output_pattern(std::string(pattern).replace(w, kWord.size(), word), name);
    });
}

const DeclaredOutputs& declared_outputs(std::string_view experiment) {
    static const DeclaredOutputs none;
    const auto it = registry().find(experiment);
    return it == registry().end() ? none : it->second;
}

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
