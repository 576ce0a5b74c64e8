// The explicit table of experiments. To add one: write experiments/<name>.toml (parameters and
// [outputs]), experiments/<name>/ (a protocol, harness/protocol.hpp, and a function returning
// protocol_experiment<...>()), expected/<name>.toml (claims), plots/<figure-id>.gp, and add one
// line below. ARCHITECTURE.md's worked example lists every step, CI's included.
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

const std::vector<Experiment>& experiment_registry() {
    static const std::vector<Experiment> table = {
        experiments::brake_failure(),    experiments::emergency_brake(), experiments::bistable_pipe(),
        experiments::impact_parameter(), experiments::cooling(),         experiments::pipe_arching(),
        experiments::parameter_study(),  experiments::cluster_growth(),
    };
    return table;
}

} // namespace granrepro
