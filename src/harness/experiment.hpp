// An experiment: the C++ half of experiments/<name>.toml and experiments/<name>/ (made by
// protocol_experiment, harness/protocol.hpp). It knows its physics set-up and
// which observables to compute; it knows nothing of files, plots or the command line.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "data/parameter_set.hpp"
#include "data/result.hpp"
#include "data/sweep_points.hpp"
#include "data/outputs.hpp"

namespace granrepro {

// How this process takes part in the experiment's sweep (harness/distributed_sweep.hpp).
struct SweepPlan {
    enum class Mode {
        All,    // compute every point not in the checkpoint (with MPI: spread over the ranks)
        Shard,  // --points I/N: compute shard I of N into the checkpoint, then stop
        Gather, // `gather`: compute nothing; every point must be in the checkpoint
        Verify, // `verify`: compute one point (rerun), no checkpoint (data/sweep_points.hpp)
    };
    Mode mode = Mode::All;
    PointRerun* rerun = nullptr; // Verify
    int shard = 1, shards = 1; // 1 <= shard <= shards
    int ranks = 1;             // MPI ranks serving this sweep (1: this process alone)
};

struct RunContext {
    const ParameterSet& params;
    Scale scale;
    std::uint64_t seed;
    int threads;                    // independent sweep points may run concurrently
    bool quiet;                     // no progress output
    std::filesystem::path work_dir; // for checkpoints of long runs (survives an interrupted run)
    double checkpoint_interval = 60.0; // [s] wall time between mid-run checkpoints (RunCheckpoint)
    SweepPlan sweep = {};
    // Where distributed_sweep records every point (computed or resumed) for the results' /points;
    // null: not recorded.
    SweepPoints* points = nullptr;
};

struct Experiment {
    std::string name; // subcommand and experiments/<name>.toml
    // Checks that relate parameters (e.g. time step against contact duration); throws InputError.
    void (*validate)(const ParameterSet&);
    Result (*run)(const RunContext&);
    // True if run() computes its sweep points through distributed_sweep(): then MPI ranks and
    // --points shards share its points; other experiments run on rank 0 alone.
    bool distributed = false;
};

// The explicit table of experiments, in experiments/registry.cpp.
const std::vector<Experiment>& experiment_registry();

// Metadata of an experiment file: what `list` shows and which figures it makes.
struct FigureInfo {
    std::string id;      // e.g. "schaefer95-fig3"; the script is plots/<id>.gp
    std::string caption; // one line
};

struct ExperimentInfo {
    std::string name, description;
    // The paper: `paper` the reference ("Luding, TASK Quarterly 2, 417 (1998)"), `paper_key` the
    // prefix of its figure ids ("luding98"), `paper_short` its name in figure labels ("Luding
    // (1998)"), `paper_citation` authors, title and reference. Experiments of one paper give the
    // same four (tests/unit/experiment_files_test.cpp); the report groups its papers by them.
    std::string paper, paper_key, paper_short, paper_citation;
    std::vector<FigureInfo> figures;
    // [smoke] set: --set overrides that make a quick run take about a second, for tests that run
    // every experiment many times (tests/integration/input_fuzz_test.cpp); empty if none.
    std::vector<std::string> smoke;
    DeclaredOutputs outputs; // every scalar and table a run can write: its reports' handles (data/outputs.hpp)
    std::filesystem::path file;
    static ExperimentInfo load(const std::filesystem::path& file); // throws InputError
};

// Where experiments/, expected/ and plots/ live, first found of: ../share/granrepro relative to
// the binary (/proc/self/exe; an installed copy), $GRANREPRO_HOME, the source tree it was built
// from. `granrepro --version` prints which.
struct DataRoot {
    std::filesystem::path path;
    std::string how; // which of the three
};
DataRoot find_data_root();
std::filesystem::path project_root(); // find_data_root().path, looked up once

} // namespace granrepro
