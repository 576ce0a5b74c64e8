// Upper bounds on the work a run may ask for, checked up front by the experiments' validate()
// (ParameterSet::limit_work): a parameter set beyond them is refused with exit 2, naming the
// parameters and the estimate, instead of running for weeks or overflowing a counter. The bounds
// sit far above the paper-scale runs (~1e10 collisions, ~1e11 grain-steps) and below what one
// machine could finish: event-driven codes manage ~1e6 collisions/s, soft-sphere ones ~1e7
// grain-steps/s per core, so either bound is weeks of one core.
#pragma once

namespace granrepro::experiments {

constexpr double kMaxCollisions = 1e12; // event-driven and DSMC collisions of one run
constexpr double kMaxGrainSteps = 1e13; // soft-sphere grains x time steps of one run

} // namespace granrepro::experiments
