// The parameters of one experiment, read from experiments/<name>.toml. Each parameter carries
// its value at both scales, its unit, the paper's source for it (or the reason for our choice
// where the paper is silent) and its allowed range. `--set name=value` overrides any of them;
// the resolved set is written into every output file.
#pragma once
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "data/interval.hpp"

namespace granrepro {

enum class Scale { Quick, Paper };
const char* to_string(Scale s);
// A number in messages: %g-like with `precision` significant digits, never 300 digits ("1e+308", "0.00083").
std::string number_text(double x, int precision = 6);
Scale parse_scale(const std::string& s); // throws InputError
// "a, b, c": name(x) of every x, as messages list what is known or missing.
template <class Range, class Name = std::identity>
std::string joined(const Range& xs, Name name = {}) {
    std::string out;
    for (const auto& x : xs) out += (out.empty() ? "" : ", ") + std::string(name(x));
    return out;
}

struct Parameter {
    enum class Kind { Real, Integer, Text, Flag, RealList };
    std::string name;
    Kind kind = Kind::Real;
    std::string unit;   // SI unit, "1" for dimensionless
    std::string source; // paper section/figure/equation, or why we chose it
    std::string help;   // one line
    bool has_range = false;
    Interval range;
    std::vector<std::string> choices; // for Text
    // Resolved value (one of these, by kind).
    double real = 0;
    long integer = 0;
    std::string text;
    bool flag = false;
    std::vector<double> reals;
    std::string quick_text, paper_text; // defaults at both scales, for --help
    bool overridden = false;
    long line = 0;       // of its table in the experiment file, for messages
    long value_line = 0; // of its default at the chosen scale
    // A list's entries name the tables and scalars of the run: with number_text's 6 significant
    // digits (-1), or with this many decimals (`name_decimals` in the experiment file). Entries
    // must differ in their names.
    int name_decimals = -1;

    std::string value_text() const;
    std::string allowed_text() const; // "a number in (0, 1] [1]" etc.
};

class ParameterSet {
public:
    // Reads the [parameters] of an experiment file and resolves them for one scale.
    static ParameterSet load(const std::filesystem::path& file, Scale scale);

    // Applies one `--set name=value`; throws InputError naming the parameter and what is allowed.
    void set(const std::string& assignment);

    double real(const std::string& name) const;
    long integer(const std::string& name) const;
    const std::string& text(const std::string& name) const;
    bool flag(const std::string& name) const;
    const std::vector<double>& reals(const std::string& name) const;
    const Parameter& get(const std::string& name) const;

    // Throws InputError("name = value: must be ...") — for checks that relate parameters.
    [[noreturn]] void reject(const std::string& name, const std::string& requirement) const;
    // The same for a requirement that relates several parameters: all are named with their values
    // ("gamma_N = 10000, k_N = 2000, m_free = 1e+308: ...").
    [[noreturn]] void reject(const std::vector<std::string>& names, const std::string& requirement) const;
    // Refuses up front a run whose cost, derived from the parameters `names`, exceeds `limit` (or
    // is not finite): "t_end = 1e+308 s needs ~1e+312 events (at most 1e+11 allowed)". `what`
    // names the unit of work: "collisions", "time steps", "particles".
    void limit_work(const std::vector<std::string>& names, double estimate, double limit, const std::string& what) const;

    // Refuses a parameter of the experiment file that is not in `read` (the names the experiment's
    // spec lists): a [parameters.x] no code reads is a typo or a leftover, and changing it with
    // --set would change nothing.
    void refuse_unread(const std::vector<std::string>& read) const;

    const std::vector<Parameter>& all() const { return params_; }
    nlohmann::json to_json() const;

private:
    const Parameter& find(const std::string& name, Parameter::Kind kind) const;
    std::vector<Parameter> params_;
    std::string file_; // the experiment file, named in errors about it
};

} // namespace granrepro
