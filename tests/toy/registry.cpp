// The registry of granrepro_toy: granrepro's list and one line for the toy, as a new experiment
// adds its line to experiments/registry.hpp. This object defines experiment_registry(), so the
// linker takes granrepro_lib's registry object out of the archive no more.
#include "experiments/registry.hpp"

#define TOY_EXPERIMENTS(X) GRANREPRO_EXPERIMENTS(X) X(toy)
GRANREPRO_DEFINE_REGISTRY(TOY_EXPERIMENTS)
