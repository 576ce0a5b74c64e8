// The list of experiments: to add one, write experiments/<name>.toml (parameters, [outputs], the
// paper and the [smoke] settings), experiments/<name>/ (a protocol, harness/protocol.hpp, and a
// function returning protocol_experiment<...>()), expected/<name>.toml (claims),
// plots/<figure-id>.gp and its caption in python/granrepro/report/figures.toml, and add one X(...)
// line below. ARCHITECTURE.md's worked example lists every step; tests/toy/ does it for a toy.
//
// One list makes both the declarations and the table (registry order is the order of `list`,
// `all`, `check --all` and the report). A plain table, not objects that register themselves at
// static initialization: a static library's object file that nothing references would be dropped
// by the linker, and its experiment with it.
#pragma once
#include <vector>

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

// Defines experiment_registry() (harness/experiment.hpp) as the experiments of LIST, in order.
#define GRANREPRO_DECLARE_EXPERIMENT(name) Experiment name();
#define GRANREPRO_EXPERIMENT_ENTRY(name) experiments::name(),
#define GRANREPRO_DEFINE_REGISTRY(LIST)                                                             \
    namespace granrepro {                                                                           \
    namespace experiments {                                                                         \
    LIST(GRANREPRO_DECLARE_EXPERIMENT)                                                              \
    }                                                                                               \
    const std::vector<Experiment>& experiment_registry() {                                          \
        static const std::vector<Experiment> table = {LIST(GRANREPRO_EXPERIMENT_ENTRY)};            \
        return table;                                                                               \
    }                                                                                               \
    }
