// Coulomb shear force, Schäfer & Wolf (1995) Eq. (2):
//     F_S = -|mu F_N| sgn(v_S)
// mu is the coefficient of dynamic friction and v_S the tangential relative velocity of the
// contact (no rotation in that paper). sgn(0) = 0, so a contact without shear feels no friction.
//
// Which F_N enters Eq. (2) is not settled by the paper. Eq. (2) prints |F_N| of Eq. (1), dashpot
// included; the derivation of Fig. 3 (Eqs. 6-7) integrates the signed F_N = m xi'' instead, and
// Fig. 3's "bend back to the abscissa in a 1/v fashion" follows only if the dashpot part does not
// add a speed-independent friction impulse mu gamma_N m 2 xi_max (brake-failure's analysis).
// The readings, studied side by side by the brake-failure experiment:
//   magnitude: N = |F_N|                 Eq. (2) as printed, attractive end included;
//   clipped:   N = max(F_N, 0), and the normal force itself is clipped at 0 (no attraction,
//              friction only while pressed: the contact ends when F_N would turn attractive);
//   elastic:   N = k_N xi                Coulomb on the elastic part only;
//   signed:    N = F_N                   the signed normal force of the Eq. (7) argument
//                                        (friction reverses while F_N is attractive).
// Stateless; laws with history (Luding's tangential spring, Eq. 13) will carry per-contact state.
#pragma once
#include <cmath>
#include <optional>
#include <string>

#include "models/normal_force.hpp"

namespace granrepro {

enum class FrictionNormal { Magnitude, Clipped, Elastic, Signed };

inline const char* to_string(FrictionNormal r) {
    switch (r) {
    case FrictionNormal::Magnitude: return "magnitude";
    case FrictionNormal::Clipped: return "clipped";
    case FrictionNormal::Elastic: return "elastic";
    default: return "signed";
    }
}
inline std::optional<FrictionNormal> parse_friction_normal(const std::string& s) {
    for (auto r : {FrictionNormal::Magnitude, FrictionNormal::Clipped, FrictionNormal::Elastic, FrictionNormal::Signed})
        if (s == to_string(r)) return r;
    return std::nullopt;
}
// For typed specs (data/spec.hpp): the TOML's choices have been checked, so value() cannot throw.
inline void parse_choice(const std::string& s, FrictionNormal& r) { r = parse_friction_normal(s).value(); }

struct CoulombShear {
    double mu = 0.0; // dynamic friction coefficient [1]
    FrictionNormal reading = FrictionNormal::Magnitude;

    // The normal force the contact applies [N]: the law's total, or max(total, 0) when clipped.
    double applied_normal(const NormalForce& f) const {
        return reading == FrictionNormal::Clipped ? std::fmax(f.total, 0.0) : f.total;
    }

    // Shear force on grain 1 along the tangent s [N], for the normal force f and v_S [m/s].
    double shear_force(const NormalForce& f, double v_S) const {
        const double sgn = (v_S > 0.0) - (v_S < 0.0);
        double n;
        switch (reading) {
        case FrictionNormal::Magnitude: n = std::abs(f.total); break;
        case FrictionNormal::Clipped: n = std::fmax(f.total, 0.0); break;
        case FrictionNormal::Elastic: n = f.elastic; break;
        default: n = f.total; break;
        }
        return -mu * n * sgn;
    }
};

} // namespace granrepro
