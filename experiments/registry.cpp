// The explicit table of experiments. To add one: write experiments/<name>.toml (parameters,
// [outputs], the paper and the [smoke] settings), experiments/<name>/ (a protocol,
// harness/protocol.hpp, and a function returning protocol_experiment<...>()),
// expected/<name>.toml (claims), plots/<figure-id>.gp, and add one X(...) line below.
// ARCHITECTURE.md's worked example lists every step, CI's included.
//
// One list makes both the declarations and the table (registry order is the order of `list`,
// `all`, `check --all` and the report). A plain table, not objects that register themselves at
// static initialization: a static library's object file that nothing references would be dropped
// by the linker, and its experiment with it.
#include "harness/experiment.hpp"

#define GRANREPRO_EXPERIMENTS(X) \
    X(brake_failure)             \
    X(emergency_brake)           \
    X(bistable_pipe)             \
    X(impact_parameter)          \
    X(cooling)                   \
    X(pipe_arching)              \
    X(parameter_study)           \
    X(cluster_growth)

namespace granrepro {

namespace experiments {
#define GRANREPRO_DECLARE(name) Experiment name();
GRANREPRO_EXPERIMENTS(GRANREPRO_DECLARE)
#undef GRANREPRO_DECLARE
} // namespace experiments

const std::vector<Experiment>& experiment_registry() {
#define GRANREPRO_ENTRY(name) experiments::name(),
    static const std::vector<Experiment> table = {GRANREPRO_EXPERIMENTS(GRANREPRO_ENTRY)};
#undef GRANREPRO_ENTRY
    return table;
}

} // namespace granrepro
