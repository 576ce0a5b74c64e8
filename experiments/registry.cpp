// The table of experiments, made from the one list in experiments/registry.hpp.
#include "experiments/registry.hpp"

GRANREPRO_DEFINE_REGISTRY(GRANREPRO_EXPERIMENTS)
