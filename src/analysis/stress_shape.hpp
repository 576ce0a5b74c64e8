#pragma once
// Shape measures of a grid of Eq. (9) stresses (Luding 1998, Fig. 5 and Sec. 3.2): "the stress
// tensor typically has strongly different eigenvalues" outside the eddies, "rather random
// stresses" for r >= 0.9.
#include <cmath>
#include <vector>

#include "observables/collisional_stress.hpp"

namespace granrepro {

// (|s1| - |s2|) / (|s1| + |s2|) of a cell's principal stresses: 0 for an isotropic stress (a
// homogeneous gas), 1 for a uniaxial one; NaN for a cell without stress.
inline double stress_anisotropy(const CollisionalStress::Cell& c) {
    const double a = std::fabs(c.sigma_min), b = std::fabs(c.sigma_max);
    return a + b > 0 ? std::fabs(a - b) / (a + b) : NAN;
}

// Alignment S = |mean over cells of exp(2 i theta)| of the axes of sigma_min (the major
// compression of a tension-positive Eq. (9)); axes are headless, hence 2 theta. S = 1 when
// every cell shares one axis. For n independent uniformly random axes n S^2 is exponential with
// mean 1 (Rayleigh), so P(S > s) = exp(-n s^2): S < sqrt(ln(1/p) / n) at level p.
inline double stress_axes_alignment(const std::vector<CollisionalStress::Cell>& cells) {
    double c2 = 0, s2 = 0;
    for (const auto& c : cells) {
        const double th = std::atan2(c.axis_min.y(), c.axis_min.x());
        c2 += std::cos(2 * th);
        s2 += std::sin(2 * th);
    }
    return cells.empty() ? NAN : std::hypot(c2, s2) / static_cast<double>(cells.size());
}

// The Rayleigh level of stress_axes_alignment: below it, n random axes fall with probability 1 - p.
inline double random_axes_level(std::size_t n, double p) { return std::sqrt(std::log(1.0 / p) / static_cast<double>(n)); }

} // namespace granrepro
