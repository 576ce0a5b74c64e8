// What the subcommands do: run an experiment into OUT/<name>/, check its claims, render figures.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "harness/experiment.hpp"

namespace granrepro {

struct RunOptions {
    Scale scale = Scale::Quick;
    std::filesystem::path out = "out";
    std::uint64_t seed = 1;
    int threads = 1;
    bool quiet = false;
    double checkpoint_interval = 60.0;      // [s] wall time between mid-run checkpoints
    std::vector<std::string> sets;          // --set name=value
    std::vector<std::string> figures;       // empty: render all of the experiment's figures
};

const Experiment& find_experiment(const std::string& name);          // throws InputError
ExperimentInfo experiment_info(const std::string& name);
// The experiment that makes figure `id`; throws InputError listing the known figures.
std::string experiment_of_figure(const std::string& id);
// Resolves parameters (scale, --set) and runs the experiment's validate(): used by the run and
// by --help.
ParameterSet resolve_parameters(const std::string& name, const RunOptions& opt);

// Runs, writes, renders and prints the check table. Returns the process exit code (0; claims that
// fail are reported by `check`, which exits 1).
int run_experiment(const std::string& name, const RunOptions& opt);
// Compares OUT/<name>/summary.json with expected/<name>.toml; prints the table; 0 if no claim fails.
int check_experiment(const std::string& name, const std::filesystem::path& out, bool quiet = false);
// Re-renders figures from an existing OUT/<name>/ (the `plot` subcommand).
int plot_experiment(const std::string& name, const std::filesystem::path& out,
                    const std::vector<std::string>& figures);

} // namespace granrepro
