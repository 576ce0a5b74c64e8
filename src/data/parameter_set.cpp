#include "data/parameter_set.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <toml.hpp>

#include "core/input_error.hpp"
#include "data/toml_file.hpp"

namespace granrepro {

const char* to_string(Scale s) { return s == Scale::Quick ? "quick" : "paper"; }

Scale parse_scale(const std::string& s) {
    if (s == "quick") return Scale::Quick;
    if (s == "paper") return Scale::Paper;
    throw InputError("--scale " + s + ": must be 'quick' or 'paper'");
}

std::string number_text(double x, int precision) {
    std::ostringstream os;
    os.precision(precision);
    os << x;
    return os.str();
}

namespace {

std::string fmt(double x) { return number_text(x, 10); }

std::string kind_text(Parameter::Kind k) {
    switch (k) {
    case Parameter::Kind::Real: return "a number";
    case Parameter::Kind::Integer: return "an integer";
    case Parameter::Kind::Text: return "one of";
    case Parameter::Kind::Flag: return "true or false";
    default: return "a comma-separated list of numbers";
    }
}

std::string toml_text(const toml::value& v) {
    if (v.is_string()) return v.as_string().str;
    if (v.is_floating()) return fmt(v.as_floating());
    if (v.is_integer()) return std::to_string(v.as_integer());
    if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
    if (v.is_array()) {
        std::string out;
        for (const auto& e : v.as_array()) out += (out.empty() ? "" : ",") + toml_text(e);
        return out;
    }
    return "?";
}

// Why `text` is no usable number although it reads as one, or "": strtod refuses a magnitude
// beyond the doubles (1e400) and one below the smallest normal double (1e-308, subnormal: its
// precision is gone and a product with it underflows to 0), where the plain refusal "must be a
// number in [0, inf)" would leave the user guessing.
std::string number_problem(const std::string& text) {
    const std::string t = trim(text);
    if (t.empty()) return {};
    errno = 0;
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || errno != ERANGE) return {};
    if (std::abs(x) > 1) return t + " is beyond the largest double (~1.8e308)";
    return t + " is subnormal (its magnitude is below 2.2e-308, the smallest normal double; use 0 or a normal number)";
}

// The entries of a list as the run names them: tables and scalars carry each entry's value in
// their name ("collapse_beta100", "impacts_vx0.3"), written by number_text (6 significant
// digits) or, where the experiment file says so (name_decimals), with that many decimals
// ("r0.80"). Two entries with one name would make one table twice and fail the run at its end.
std::string entry_name(const Parameter& p, double x) {
    if (p.name_decimals < 0) return number_text(x);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", p.name_decimals, x);
    return buf;
}

// "" or why the list repeats an entry (as the run names them).
std::string repeated_entry(const Parameter& p) {
    for (std::size_t i = 0; i < p.reals.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (entry_name(p, p.reals[i]) == entry_name(p, p.reals[j]))
                return "entries " + fmt(p.reals[j]) + " and " + fmt(p.reals[i]) + " are both named '" +
                       entry_name(p, p.reals[i]) + "' in the results (" +
                       (p.name_decimals < 0 ? std::string("6 significant digits")
                                            : std::to_string(p.name_decimals) + " decimals") +
                       "); each entry must differ there";
    return {};
}

// A finite number in p's range.
bool allowed_number(const Parameter& p, const std::string& text, double& x) {
    return parse_double(text, x) && std::isfinite(x) && (!p.has_range || p.range.contains(x));
}

// Parses `text` into p according to its kind and checks range/choices; false when not allowed.
bool assign(Parameter& p, const std::string& text) {
    switch (p.kind) {
    case Parameter::Kind::Real: {
        double x;
        if (!allowed_number(p, text, x)) return false;
        p.real = x;
        return true;
    }
    case Parameter::Kind::Integer: {
        long x;
        if (!parse_long(text, x)) return false;
        if (p.has_range && !p.range.contains(double(x))) return false;
        p.integer = x;
        return true;
    }
    case Parameter::Kind::Text:
        if (!p.choices.empty() && std::find(p.choices.begin(), p.choices.end(), text) == p.choices.end())
            return false;
        p.text = text;
        return true;
    case Parameter::Kind::Flag:
        if (text == "true" || text == "1") p.flag = true;
        else if (text == "false" || text == "0") p.flag = false;
        else return false;
        return true;
    case Parameter::Kind::RealList: {
        std::vector<double> xs;
        std::stringstream ss(text);
        std::string item;
        while (std::getline(ss, item, ',')) {
            double x;
            if (!allowed_number(p, item, x)) return false;
            xs.push_back(x);
        }
        if (xs.empty()) return false;
        p.reals = xs;
        return true;
    }
    }
    return false;
}

Parameter::Kind kind_of(const toml::value& v) {
    if (v.is_floating()) return Parameter::Kind::Real;
    if (v.is_integer()) return Parameter::Kind::Integer;
    if (v.is_string()) return Parameter::Kind::Text;
    if (v.is_boolean()) return Parameter::Kind::Flag;
    if (v.is_array()) return Parameter::Kind::RealList;
    throw InputError("unsupported parameter type");
}

// The parameters behind a refusal: those the user changed with --set (they are the likely cause),
// or all of them when none was changed.
std::string named_values(const ParameterSet& set, const std::vector<std::string>& names) {
    std::vector<std::string> shown;
    for (const auto& n : names)
        if (set.get(n).overridden) shown.push_back(n);
    if (shown.empty()) shown = names;
    std::string out;
    for (const auto& n : shown) {
        const Parameter& p = set.get(n);
        out += (out.empty() ? "" : ", ") + n + " = " + p.value_text();
        if (p.kind != Parameter::Kind::Text && p.kind != Parameter::Kind::Flag && !p.unit.empty() && p.unit != "1")
            out += " " + p.unit;
    }
    return out;
}

} // namespace

std::string Parameter::value_text() const {
    switch (kind) {
    case Kind::Real: return fmt(real);
    case Kind::Integer: return std::to_string(integer);
    case Kind::Text: return text;
    case Kind::Flag: return flag ? "true" : "false";
    default: {
        std::string out;
        for (double x : reals) out += (out.empty() ? "" : ",") + fmt(x);
        return out;
    }
    }
}

std::string Parameter::allowed_text() const {
    std::string out = kind_text(kind);
    if (kind == Kind::Text) {
        for (std::size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : " ") + choices[i];
    } else if (has_range) {
        out += (kind == Kind::RealList ? ", each in " : " in ") + range.text;
    }
    if (!unit.empty() && unit != "1" && kind != Kind::Text && kind != Kind::Flag) out += " [" + unit + "]";
    return out;
}

namespace {

// The numbers of a default as written: 1e400 (read by toml11 as 1.8e308) or 1e-400 (as 0) is
// refused at its line, as is NaN, which no range holds and no run can use.
void check_default_numbers(const toml::value& v, const std::string& file, const std::string& what) {
    if (v.is_array()) {
        for (const auto& e : v.as_array()) check_default_numbers(e, file, what);
        return;
    }
    if (!v.is_floating()) return;
    if (std::isnan(toml_number(v, file, what)))
        throw InputError(toml_place(file, v) + ": " + what + " is NaN; a default must be a number");
}

// One [parameters.<name>] table: its texts, range, choices and the default at `scale`. Every
// refusal starts with "<file>:<line>" of the offending value.
Parameter read_parameter(const std::string& where, const std::string& name, const toml::value& spec, Scale scale) {
    Parameter p;
    p.name = name;
    const std::string ctx = toml_place(where, spec) + ": parameter " + name;
    if (!spec.is_table()) throw InputError(ctx + ": must be a table");
    const auto& t = spec.as_table();
    // file:line of one key's value, and the parameter named.
    auto at = [&](const toml::value& v) { return toml_place(where, v) + ": parameter " + name; };
    for (const auto& [key, v] : t)
        if (key != "unit" && key != "source" && key != "help" && key != "range" && key != "choices" &&
            key != "value" && key != "quick" && key != "paper" && key != "name_decimals" && key != "calibrated_on")
            throw InputError(at(v) + ": unknown key '" + key +
                             "'; allowed: unit, source, help, range, choices, value, quick, paper, name_decimals, calibrated_on");
    auto str = [&](const char* key) -> std::string {
        const auto it = t.find(key);
        if (it == t.end()) return {};
        if (!it->second.is_string()) throw InputError(at(it->second) + ": '" + key + "' must be a string");
        return it->second.as_string().str;
    };
    p.unit = str("unit");
    p.source = str("source");
    p.help = str("help");
    if (p.unit.empty() || p.source.empty()) throw InputError(ctx + ": every parameter needs a unit and a source");
    const std::string range = str("range");
    if (!range.empty()) {
        p.has_range = true;
        try {
            p.range = Interval::parse(range);
        } catch (const InputError& e) {
            throw InputError(at(t.at("range")) + ": " + e.what());
        }
    }
    if (t.count("choices")) {
        try {
            p.choices = toml::find<std::vector<std::string>>(spec, "choices");
        } catch (const std::exception& e) {
            throw InputError(toml_error_line(where, e.what()) + " (parameter " + name + ": choices must be a list of strings)");
        }
    }
    if (t.count("name_decimals")) {
        const toml::value& d = t.at("name_decimals");
        if (!d.is_integer() || d.as_integer() < 0 || d.as_integer() > 17)
            throw InputError(at(d) + ": name_decimals must be an integer in [0, 17] (the decimals of each entry in the run's names)");
        p.name_decimals = int(d.as_integer());
    }
    const toml::value* quick = nullptr;
    const toml::value* paper = nullptr;
    if (t.count("value")) quick = paper = &t.at("value");
    if (t.count("quick")) quick = &t.at("quick");
    if (t.count("paper")) paper = &t.at("paper");
    if (!quick || !paper) throw InputError(ctx + ": needs 'value' or both 'quick' and 'paper'");
    const toml::value& chosen = scale == Scale::Quick ? *quick : *paper;
    for (const toml::value* v : {quick, paper}) {
        try {
            kind_of(*v);
        } catch (const InputError&) {
            throw InputError(at(*v) + ": value has an unsupported type (a number, an integer, a string, true/false "
                                      "or an array of numbers)");
        }
        check_default_numbers(*v, where, "parameter " + name);
        if (v->is_array() && v->as_array().empty()) throw InputError(at(*v) + ": value is an empty array");
    }
    p.kind = kind_of(chosen);
    if (p.kind == Parameter::Kind::Integer && kind_of(scale == Scale::Quick ? *paper : *quick) == Parameter::Kind::Real)
        p.kind = Parameter::Kind::Real; // 1 and 1.5 at the two scales: a real parameter
    for (const toml::value* v : {quick, paper}) {
        // A range makes it a number (or a list of numbers): "abc" or true there is a typo,
        // not a text parameter that the experiment would then read as a number.
        const bool numeric = v->is_floating() || v->is_integer() ||
                             (v->is_array() && std::all_of(v->as_array().begin(), v->as_array().end(), [](const auto& e) {
                                  return e.is_floating() || e.is_integer();
                              }));
        if (p.has_range && !numeric)
            throw InputError(at(*v) + ": value " + toml_text(*v) + " must be a number or a list of numbers (it has range " +
                             p.range.text + ")");
    }
    p.quick_text = toml_text(*quick);
    p.paper_text = toml_text(*paper);
    if (!assign(p, toml_text(chosen)))
        throw InputError(at(chosen) + ": default " + toml_text(chosen) + " is not " + p.allowed_text());
    if (const std::string why = repeated_entry(p); !why.empty()) throw InputError(at(chosen) + ": default: " + why);
    p.line = long(spec.location().line());
    p.value_line = long(chosen.location().line());
    return p;
}

} // namespace

ParameterSet ParameterSet::load(const std::filesystem::path& file, Scale scale) {
    const std::string where = file.string();
    const toml::value root = parse_toml_file(file, "experiment file");
    ParameterSet set;
    set.file_ = where;
    if (!root.is_table()) throw InputError(where + ": not a table of keys");
    for (const auto& [key, v] : root.as_table())
        if (key != "name" && key != "paper" && key != "paper_key" && key != "paper_short" && key != "paper_citation" &&
            key != "description" && key != "figure" && key != "parameters" && key != "readings" &&
            key != "smoke")
            throw InputError(toml_place(where, v) + ": unknown key '" + key +
                             "'; allowed: name, paper, paper_key, paper_short, paper_citation, description, [[figure]], "
                             "[parameters.<name>], [readings.<name>], [smoke]");
    if (!root.contains("parameters") || !root.at("parameters").is_table())
        throw InputError(where + ": missing [parameters] table");
    std::vector<std::pair<std::uint_least32_t, Parameter>> ordered;
    for (const auto& [name, spec] : root.at("parameters").as_table())
        ordered.emplace_back(spec.location().line(), read_parameter(where, name, spec, scale));
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [line, p] : ordered) set.params_.push_back(std::move(p));
    return set;
}

void ParameterSet::set(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set " + assignment + ": expected name=value");
    const std::string name = assignment.substr(0, eq);
    const std::string value = assignment.substr(eq + 1);
    auto it = std::find_if(params_.begin(), params_.end(), [&](const Parameter& p) { return p.name == name; });
    if (it == params_.end())
        throw InputError("--set " + name + ": unknown parameter; this experiment has: " +
                         joined(params_, [](const Parameter& p) { return p.name; }));
    Parameter changed = *it;
    if (!assign(changed, value)) {
        // A number out of the doubles' reach is named as such, not as one outside the range.
        std::string why;
        std::stringstream items(value);
        for (std::string item; why.empty() && std::getline(items, item, ',');) why = number_problem(item);
        throw InputError("--set " + name + "=" + value + ": " + name + (why.empty() ? "" : ": " + why + "; " + name) +
                         " must be " + it->allowed_text());
    }
    if (const std::string why = repeated_entry(changed); !why.empty())
        throw InputError("--set " + name + "=" + value + ": " + name + ": " + why);
    *it = std::move(changed);
    it->overridden = true;
}

const Parameter& ParameterSet::get(const std::string& name) const {
    for (const auto& p : params_)
        if (p.name == name) return p;
    // The experiment's code needs it: a table renamed or removed in the experiment file.
    throw InputError(file_ + ": missing [parameters." + name + "] (the experiment needs it)");
}

const Parameter& ParameterSet::find(const std::string& name, Parameter::Kind kind) const {
    const Parameter& p = get(name);
    if (p.kind != kind)
        throw InputError(file_ + ":" + std::to_string(p.value_line) + ": parameter " + name + " = " + p.value_text() + " must be " +
                         (kind == Parameter::Kind::Text ? std::string("text") : kind_text(kind)));
    return p;
}

double ParameterSet::real(const std::string& n) const {
    const Parameter& p = get(n);
    if (p.kind == Parameter::Kind::Integer) return double(p.integer);
    return find(n, Parameter::Kind::Real).real;
}
long ParameterSet::integer(const std::string& n) const { return find(n, Parameter::Kind::Integer).integer; }
const std::string& ParameterSet::text(const std::string& n) const { return find(n, Parameter::Kind::Text).text; }
bool ParameterSet::flag(const std::string& n) const { return find(n, Parameter::Kind::Flag).flag; }
const std::vector<double>& ParameterSet::reals(const std::string& n) const {
    return find(n, Parameter::Kind::RealList).reals;
}

void ParameterSet::reject(const std::string& name, const std::string& requirement) const {
    throw InputError(name + " = " + get(name).value_text() + ": " + requirement);
}

void ParameterSet::reject(const std::vector<std::string>& names, const std::string& requirement) const {
    throw InputError(named_values(*this, names) + ": " + requirement);
}

void ParameterSet::limit_work(const std::vector<std::string>& names, double estimate, double limit,
                              const std::string& what) const {
    if (estimate <= limit) return; // false for NaN
    throw InputError(named_values(*this, names) + ": the run needs ~" + number_text(estimate) + " " + what +
                     " (at most " + number_text(limit) + " allowed)");
}

void ParameterSet::refuse_unread(const std::vector<std::string>& read) const {
    for (const auto& p : params_)
        if (std::find(read.begin(), read.end(), p.name) == read.end())
            throw InputError(file_ + ":" + std::to_string(p.line) + ": [parameters." + p.name +
                             "] is read by no code of this experiment (a typo or a leftover); remove it");
}

nlohmann::json ParameterSet::to_json() const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& p : params_) {
        nlohmann::json e = {{"unit", p.unit}, {"source", p.source}};
        switch (p.kind) {
        case Parameter::Kind::Real: e["value"] = p.real; break;
        case Parameter::Kind::Integer: e["value"] = p.integer; break;
        case Parameter::Kind::Text: e["value"] = p.text; break;
        case Parameter::Kind::Flag: e["value"] = p.flag; break;
        case Parameter::Kind::RealList: e["value"] = p.reals; break;
        }
        if (p.overridden) e["overridden"] = true;
        j[p.name] = e;
    }
    return j;
}

} // namespace granrepro
