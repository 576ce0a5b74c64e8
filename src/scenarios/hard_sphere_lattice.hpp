// The start of the 3D elastic check of Luding 1998 Sec. 3.2 ("P(b/d) = 2b/d in 3D"), shared by
// the impact-parameter experiment and the unit tests of src/engines/ed3d.
#pragma once
#include <cmath>
#include <vector>

#include "core/rng_stream.hpp"
#include "engines/ed3d/hard_sphere_gas.hpp"

namespace granrepro {

// n_side^3 spheres of diameter d [m] on a simple cubic lattice in a periodic cube sized for the
// packing fraction eta, Gaussian velocity components of standard deviation vbar [m/s] with the
// mean removed (zero total momentum).
inline HardSphereGas3D simple_cubic_gas(long n_side, double eta, double d, double vbar, RngStream& rng) {
    const auto n = static_cast<double>(n_side * n_side * n_side);
    const double box = std::cbrt(n * M_PI / 6 / eta) * d;
    std::vector<Vec3> r, v;
    Vec3 mean;
    for (long a = 0; a < n_side; ++a)
        for (long b = 0; b < n_side; ++b)
            for (long c = 0; c < n_side; ++c) {
                r.push_back({(a + 0.5) * box / n_side, (b + 0.5) * box / n_side, (c + 0.5) * box / n_side});
                v.push_back({vbar * rng.normal(), vbar * rng.normal(), vbar * rng.normal()});
                mean += v.back();
            }
    for (Vec3& x : v) x -= mean * (1.0 / n);
    return HardSphereGas3D(r, v, d, box);
}

} // namespace granrepro
