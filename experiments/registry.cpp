// The explicit table of experiments. To add one: write experiments/<name>.toml (parameters),
// experiments/<name>.cpp (defining a function returning its Experiment), expected/<name>.toml
// (claims), plots/<figure-id>.gp, and add one line below.
#include "harness/experiment.hpp"

namespace granrepro {

namespace experiments {
Experiment brake_failure();
Experiment emergency_brake();
Experiment bistable_pipe();
Experiment impact_parameter();
Experiment cooling();
Experiment pipe_arching();
Experiment parameter_study();
Experiment cluster_growth();
} // namespace experiments

namespace {
// Its sweep goes through distributed_sweep(): MPI ranks and --points shards share its points.
Experiment distributed(Experiment e) {
    e.distributed = true;
    return e;
}
} // namespace

const std::vector<Experiment>& experiment_registry() {
    static const std::vector<Experiment> table = {
        experiments::brake_failure(),
        experiments::emergency_brake(),
        experiments::bistable_pipe(),
        experiments::impact_parameter(),
        experiments::cooling(),
        distributed(experiments::pipe_arching()),
        experiments::parameter_study(),
        distributed(experiments::cluster_growth()),
    };
    return table;
}

} // namespace granrepro
