// The start of the 3D elastic check of Luding 1998 Sec. 3.2 ("P(b/d) = 2b/d in 3D"), shared by
// the impact-parameter experiment and the unit tests of src/engines/ed3d.
#pragma once
#include "core/rng_stream.hpp"
#include "engines/ed3d/hard_sphere_gas.hpp"

namespace granrepro {

// n_side^3 spheres of diameter d [m] on a simple cubic lattice in a periodic cube sized for the
// packing fraction eta, Gaussian velocity components of standard deviation vbar [m/s] with the
// mean removed (zero total momentum).
HardSphereGas3D simple_cubic_gas(long n_side, double eta, double d, double vbar, RngStream& rng);

} // namespace granrepro
