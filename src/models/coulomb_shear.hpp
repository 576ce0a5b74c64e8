// Coulomb shear force, Schäfer & Wolf (1995) Eq. (2):
//     F_S = -|mu F_N| sgn(v_S)
// mu is the coefficient of dynamic friction and v_S the tangential relative velocity of the
// contact (no rotation in that paper). sgn(0) = 0, so a contact without shear feels no friction.
// Stateless; laws with history (Luding's tangential spring, Eq. 13) will carry per-contact state.
#pragma once
#include <cmath>

namespace granrepro {

struct CoulombShear {
    double mu = 0.0; // dynamic friction coefficient [1]

    // Shear force on grain 1 along the tangent s [N], for normal force F_N [N] and v_S [m/s].
    double shear_force(double F_N, double v_S) const {
        const double sgn = (v_S > 0.0) - (v_S < 0.0);
        return -std::abs(mu * F_N) * sgn;
    }
};

// Luding (1998) Eq. (14): viscous shear capped by Coulomb, F = -min(gamma_t |v_S|, mu F_N) sgn(v_S).
// Reduces to Eq. (12) for mu -> infinity.
struct CappedViscousShear {
    double gamma_t = 0.0; // tangential viscous coefficient [kg/s]
    double mu = 0.0;      // Coulomb cap [1]

    double shear_force(double F_N, double v_S) const {
        const double sgn = (v_S > 0.0) - (v_S < 0.0);
        return -std::fmin(gamma_t * std::abs(v_S), std::abs(mu * F_N)) * sgn;
    }
};

} // namespace granrepro
