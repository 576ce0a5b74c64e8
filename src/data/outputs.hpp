// Outputs named once, where they are made (issue 44). A report declares a handle per output
// family at namespace scope, next to the code that writes it, and writes only through it:
//
//   const ScalarOut v_crit = outputs.scalar("v_crit_kN<n>", "m/s", "v_y^i at the first maximum");
//   ...
//   r.put(v_crit, pk.x, {k_N});          // writes v_crit_kN2000
//
// `outputs` is the experiment's catalog (`inline constexpr Outputs outputs{"brake-failure"}` in
// its spec.hpp). Each handle registers its pattern with the catalog when the program starts, so
// the harness knows every name a run can write without running it: `--dry-run` and the claim
// loader refuse a claim naming a quantity no handle makes (exit 2, file and line), a plot
// script's literal table names are checked against them (a unit test), and a run that writes a
// name no handle declares cannot exist, because there is no other way to write one.
// A pattern is a name in which <n> stands for a number (matches_output_pattern) and, at most
// once, <w> for one of the handle's words (a family over readings or cases that are not numbers:
// "eq2_<w>_v_crit" over {"magnitude", "elastic", ...}); the catalog holds one pattern per word.
#pragma once
#include <concepts>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "data/parameter_set.hpp"

namespace granrepro {

// What fills one <n> or <w>: a number as number_text writes it, a number already written (e.g.
// with "%.2f"), or one of the handle's words; anything else is refused when the name is made.
struct NamePart {
    std::string text;
    template <class T>
        requires std::is_arithmetic_v<T>
    NamePart(T x) : text(number_text(double(x))) {}
    NamePart(std::string s) : text(std::move(s)) {}
    NamePart(const char* s) : text(s) {}
};

using Words = std::vector<std::string>;
struct ScalarOut {
    std::string pattern, unit, description;
    Words words; // what <w> stands for
};
struct TableOut {
    std::string pattern, description;
    Words words;
};

// The pattern with its <n> and <w>, in order, filled by parts; std::logic_error if the counts
// differ, a part for <n> holds a character a number cannot, or one for <w> is not among words (a
// bug in the report, caught by every quick run).
std::string fill_pattern(std::string_view pattern, const Words& words, std::initializer_list<NamePart> parts);

// True if name is one the handle's pattern (and words) can make: for a name made where the
// handle's parts are not at hand, e.g. carried in a sweep point (Result::table_named).
bool makes_name(std::string_view pattern, const Words& words, std::string_view name);

// One experiment's catalog. Constant-initialized, so handles in any translation unit may register
// with it during static initialization.
class Outputs {
public:
    constexpr explicit Outputs(const char* experiment) : experiment_(experiment) {}
    ScalarOut scalar(std::string pattern, std::string unit, std::string description, Words words = {}) const;
    TableOut table(std::string pattern, std::string description, Words words = {}) const;
    constexpr const char* experiment() const { return experiment_; }

private:
    const char* experiment_;
};

// Every pattern declared for an experiment, in registration order, and what is wrong with any
// (a malformed pattern, one declared twice): tests/unit/declared_outputs_test.cpp requires none.
struct DeclaredOutputs {
    std::vector<std::string> scalars, tables, errors;
    bool declared() const { return !scalars.empty() || !tables.empty(); }
    bool declares_scalar(std::string_view name) const;
    bool declares_table(std::string_view name) const;
};
const DeclaredOutputs& declared_outputs(std::string_view experiment);

// True if name is pattern with every <n> replaced by one or more of [0-9.eE+-].
bool matches_output_pattern(std::string_view pattern, std::string_view name);
// Empty if the pattern is well formed, else what is wrong with it (a placeholder other than <n>,
// an unclosed <, characters a name cannot hold).
std::string output_pattern_error(std::string_view pattern);

} // namespace granrepro
