// Upper bounds on the work a run may ask for, checked up front by the experiments' validate()
// (ParameterSet::limit_work): a parameter set beyond them is refused with exit 2, naming the
// parameters and the estimate, instead of running for weeks or overflowing a counter. The bounds
// sit far above the paper-scale runs (~1e10 collisions, ~1e11 grain-steps) and below what one
// machine could finish: event-driven codes manage ~1e6 collisions/s, soft-sphere ones ~1e7
// grain-steps/s per core, so either bound is weeks of one core.
#pragma once
#include <string>
#include <vector>

#include "data/parameter_set.hpp"

namespace granrepro::experiments {

constexpr double kMaxCollisions = 1e12; // event-driven and DSMC collisions of one run
constexpr double kMaxGrainSteps = 1e13; // soft-sphere grains x time steps of one run

// The ED box of box_over_d diameters with n_side^2 disks on a square lattice at the start.
inline void validate_lattice_box(const ParameterSet& p, double box_over_d, long n_side) {
    if (box_over_d / double(n_side) < 1.0000001)
        p.reject(std::vector<std::string>{"box_over_d", "n_side"},
                 "box_over_d too small for a square-lattice start of n_side^2 disks (lattice spacing below d)");
    // The linked-cell grid of the ED engine has ~(box_over_d)^2 cells of one diameter.
    p.limit_work({"box_over_d"}, box_over_d * box_over_d, 1e8, "cells of the linked-cell grid");
    if (box_over_d < 3.0) p.reject("box_over_d", "must be at least 3 (three cells for the minimum image)");
}

} // namespace granrepro::experiments
