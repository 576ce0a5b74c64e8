#include "data/toml_file.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "core/input_error.hpp"
#include "core/untrusted_file.hpp"
#include "data/interval.hpp"

namespace granrepro {

std::string toml_error_line(const std::string& file, const std::string& what) {
    std::istringstream in(what);
    std::string message, l;
    std::getline(in, message);
    if (message.rfind("[error] ", 0) == 0) message.erase(0, 8);
    // "toml::parse_key_value_pair: missing ..." names the parser's function, not the problem.
    if (message.rfind("toml::", 0) == 0)
        if (const auto colon = message.find(": "); colon != std::string::npos) message.erase(0, colon + 2);
    if (message.rfind("bad_cast to ", 0) == 0) message = "expected a " + message.substr(12) + " value"; // a type error
    long first = 0, current = 0;
    std::vector<std::pair<long, std::string>> hints;
    while (std::getline(in, l)) {
        const std::string t = trim(l, " ");
        const auto bar = t.find(" |");
        if (!t.empty() && std::isdigit(static_cast<unsigned char>(t[0])) && bar != std::string::npos &&
            t.find_first_not_of("0123456789") == bar) {
            current = std::stol(t.substr(0, bar));
            if (!first) first = current;
        } else if (t.rfind("|", 0) == 0) {
            // "|     ^--- expected value": the hint after the caret or tildes.
            const std::string mark = trim(t.substr(1), " ");
            const auto text = mark.find_first_not_of("^~-");
            if (!mark.empty() && (mark[0] == '^' || mark[0] == '~') && text != std::string::npos)
                hints.emplace_back(current, trim(mark.substr(text), " "));
        }
    }
    std::string out = file + (first ? ":" + std::to_string(first) : "") + ": " + message;
    std::string hint;
    for (const auto& [line, text] : hints)
        hint += (hint.empty() ? "" : "; ") + (hints.size() > 1 ? "line " + std::to_string(line) + ": " : "") + text;
    return hint.empty() ? out : out + " (" + hint + ")";
}

toml::value parse_toml_file(const std::filesystem::path& file, const std::string& role) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec)))
        throw InputError(file.string() + ": " + role + " not found");
    // Bounded before toml11 sees it: a regular file under the cap, nested no deeper than the cap
    // (toml11 parses arrays and dotted keys recursively).
    const std::string text = read_untrusted_file(file, kMaxTextFileBytes, role);
    check_toml_depth(text, file.string());
    try {
        std::istringstream in(text);
        return toml::parse(in, file.string());
    } catch (const std::exception& e) {
        throw InputError(toml_error_line(file.string(), e.what()));
    }
}

std::string toml_place(const std::string& file, const toml::value& v) {
    return file + ":" + std::to_string(v.location().line());
}

double toml_number(const toml::value& v, const std::string& file, const std::string& what) {
    if (v.is_integer()) return double(v.as_integer());
    const double x = toml::get<double>(v); // throws toml::type_error for a non-number
    // The token as written in the file: toml11 keeps its line, column (from 1) and length.
    const toml::source_location loc = v.location();
    std::string token;
    if (loc.column() >= 1 && loc.column() - 1 < loc.line_str().size())
        token = loc.line_str().substr(loc.column() - 1, loc.region());
    std::erase(token, '_'); // TOML allows 1_000.5
    errno = 0;
    char* end = nullptr;
    const double read = std::strtod(token.c_str(), &end);
    if (!token.empty() && end == token.c_str() + token.size() && errno == ERANGE)
        throw InputError(toml_place(file, v) + ": " + what + " = " + token +
                         (std::abs(read) > 1 ? " is beyond the largest double (~1.8e308): an infinite or out-of-range number"
                                             : " is subnormal (below 2.2e-308, the smallest normal double); write 0 or a normal number"));
    return x;
}

} // namespace granrepro
