// The names an experiment's run writes, declared before it runs in experiments/<name>.toml
// [outputs] (issue 28): every scalar and table, a family written as a pattern in which <n> stands
// for a number as number_text writes it (v_crit_kN<n> for v_crit_kN200, v_crit_kN20000). Claims
// (expected/<name>.toml, `measured`) and plot scripts (plots/*.gp, literal table names) may name
// only declared outputs: a claim naming anything else is refused when the claims load (exit 2,
// also under --dry-run), a plot script by a unit test; a run that writes an undeclared name fails
// before it writes anything, so the declaration cannot fall behind the code.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace granrepro {

// True if name is pattern with every <n> replaced by one or more of [0-9.eE+-].
bool matches_output_pattern(std::string_view pattern, std::string_view name);

struct DeclaredOutputs {
    std::vector<std::string> scalars, tables; // patterns
    bool declared() const { return !scalars.empty() || !tables.empty(); }
    bool declares_scalar(std::string_view name) const;
    bool declares_table(std::string_view name) const;
};

// Empty if the pattern is well formed, else what is wrong with it (a placeholder other than <n>,
// an unclosed <, characters a scalar name cannot hold).
std::string output_pattern_error(std::string_view pattern);

} // namespace granrepro
