// What the subcommands do: run an experiment into OUT/<name>/, check its claims, render figures.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "harness/claims.hpp"
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
    std::string command_line;               // as typed (provenance, run.log)
    SweepPlan sweep;                        // --points I/N or `gather` (ranks: set by the runner)
    bool shard_from_slurm = false;          // no --points: a job-array task is shard ID of COUNT
};

// Parses --points "I/N" (1 <= I <= N); throws InputError.
SweepPlan parse_points(const std::string& text);
// The shard of a Slurm job-array task ($SLURM_ARRAY_TASK_ID of $SLURM_ARRAY_TASK_COUNT, counted
// from $SLURM_ARRAY_TASK_MIN in steps of $SLURM_ARRAY_TASK_STEP), or nothing outside an array job.
// Throws InputError naming the variable if one is not a whole number in range or the ID is not
// one of the array's.
std::optional<SweepPlan> slurm_array_shard();
// How a run of experiment `name` takes part in its sweep: opt.sweep, or the Slurm array task's
// shard (a distributed experiment without --points). The run and --dry-run both ask here.
SweepPlan sweep_plan(const std::string& name, const RunOptions& opt);

const Experiment& find_experiment(const std::string& name);          // throws InputError
ExperimentInfo experiment_info(const std::string& name);
// expected/<name>.toml, each claim's measured scalar checked against the declared outputs.
std::vector<Claim> experiment_claims(const std::string& name);
// The experiment that makes figure `id`; throws InputError listing the known figures.
std::string experiment_of_figure(const std::string& id);
// Resolves parameters (scale, --set) and runs the experiment's validate(): used by the run and
// by --help.
ParameterSet resolve_parameters(const std::string& name, const RunOptions& opt);

// The exit code of a command that ran but did not draw a figure it was asked for (gnuplot
// failed or is missing, a table or parameter the script needs is missing); 1 stays "a claim failed".
inline constexpr int kFigureNotDrawn = 4;

// Runs, writes, renders and prints the check table. Under mpirun, rank 0 does all of this; the
// other ranks compute sweep points of distributed experiments and skip the rest. A --points shard
// only computes its points into OUT/.<name>.checkpoint/ (exit 0); `gather` (sweep.mode Gather)
// writes the results from there, or fails with exit 2 naming the missing points. Returns the process exit code: 0 if no claim
// fails, 1 if one does, else kFigureNotDrawn if a requested figure (any, without opt.figures) was not drawn. `figure` (opt.figures) renders the requested figures plus those the
// previous run had rendered, so a figure run never deletes the experiment's other figures.
// totals, if given, accumulates the verdicts.
int run_experiment(const std::string& name, const RunOptions& opt, VerdictCounts* totals = nullptr);
// True if OUT/<name>/ already holds what a run with `opt` would write: summary.json and data.h5
// pass check's validation with their hashes verified, and are of this scale, seed, physics hash
// and resolved parameters (no --set), with every figure of the experiment drawn whole. `all`
// skips such an experiment (a rerun after an interruption resumes where it stopped).
bool complete_result(const std::string& name, const RunOptions& opt);

struct CheckOptions {
    bool explain = false;     // print the known-deviation texts and band reasons under the table
    bool missing_ok = false;  // check --all: list experiments without results but do not fail
};
// True if OUT/<name>/summary.json exists.
bool has_results(const std::string& name, const std::filesystem::path& out);
// Compares OUT/<name>/summary.json with expected/<name>.toml; prints the table; 0 if no claim fails.
int check_experiment(const std::string& name, const std::filesystem::path& out, const CheckOptions& opt = {},
                     VerdictCounts* totals = nullptr);
// OUT/<name>/'s claims judged against expected/<name>.toml exactly as check_experiment judges
// them (after the same checks of summary.json against data.h5; InputError if damaged), without
// printing: {"scale", "notes" (check's lines under the title), "claims" (summary.json's format)}.
// For `report`.
nlohmann::json judged_claims(const std::string& name, const std::filesystem::path& out);
// OUT/<name>/summary.json, validated against the data.h5 beside it as `check` does it (damaged or
// one-sided edits: InputError naming the file).
// missing: the InputError's text when there are no results (default: "no results of <name> in ...").
nlohmann::json read_checked_summary(const std::string& name, const std::filesystem::path& out,
                                    const std::string& missing = "");
// Checks every experiment with results in OUT, prints one table each and the totals; lists the
// experiments without results on stderr. 1 if a claim fails or (unless missing_ok) results are missing.
int check_all(const std::filesystem::path& out, const CheckOptions& opt = {});
// Copies OUT/<name>/summary.json and a compact data.h5 (tables of at most max_values values;
// snapshots left out) to TO/<name>/, for committing paper-scale results (paper_figures/).
int export_experiment(const std::string& name, const std::filesystem::path& out, const std::filesystem::path& to,
                      std::size_t max_values);
// Re-renders figures from an existing OUT/<name>/ (the `plot` subcommand). A figure the
// experiment does not make is an input error. kFigureNotDrawn if a figure is not drawn, or
// (strict) if gnuplot warns. edited: render the scripts the user edited (see render_figure).
int plot_experiment(const std::string& name, const std::filesystem::path& out,
                    const std::vector<std::string>& figures, bool strict = false, bool edited = false);

} // namespace granrepro
