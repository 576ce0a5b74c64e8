// Static friction by a virtual tangential spring, Luding (1998) Eq. (13):
//     f_t = -min(k_t |xi_t|, mu f_n) sgn(xi_t),   xi_t = integral over the contact of v_S dt.
// When two grains start to touch, a spring of length 0 is put between the contact points; the
// tangential relative velocity v_S stretches it and it pulls back with -k_t xi_t, but Coulomb's
// criterion caps the force at mu f_n, and the spring "has to be kept at a maximum length
// xi_max = mu f_n / k_t" (the text after Eq. 13). It is removed when the contact ends.
//
// The law has history: xi_t is per-contact state (ContactState), carried by the engine from the
// contact's start to its end. The engine integrates d(xi_t)/dt = v_S with the grains' equations
// of motion and calls hold() after each step, which keeps the spring at most xi_max long.
// In 2D without rotation (the soft engines' setting) xi_t is a scalar along perp(n); swapping the
// grains leaves v_S, and so xi_t, unchanged (coulomb_shear.hpp's sign convention).
//
// f_n is the applied normal force max(F_N, 0): a contact the dashpot pulls together at its end
// presses nothing, so Coulomb's criterion allows no tangential force there (Eq. 13 speaks of the
// normal force "at this contact" without a sign; a pulling cap would reverse friction).
#pragma once
#include <algorithm>
#include <cmath>

#include "models/normal_force.hpp"

namespace granrepro {

struct TangentialSpring {
    double k_t = 0.0; // tangential spring constant [N/m]
    double mu = 0.0;  // Coulomb coefficient [1]

    using ContactState = double; // xi_t, the spring's signed length along perp(n) [m]

    double applied_normal(const NormalForce& f) const { return f.total; }
    // Shear force on grain 1 along perp(n) [N] for the spring length xi_t [m].
    double shear_force(const NormalForce& f, double /*v_S*/, ContactState xi_t) const {
        const double cap = mu * std::fmax(f.total, 0.0);
        const double sgn = (xi_t > 0.0) - (xi_t < 0.0);
        return -std::fmin(k_t * std::abs(xi_t), cap) * sgn;
    }
    // The spring length after a step: at most xi_max = mu f_n / k_t.
    ContactState hold(const NormalForce& f, ContactState xi_t) const {
        const double xi_max = mu * std::fmax(f.total, 0.0) / k_t;
        return std::clamp(xi_t, -xi_max, xi_max);
    }
};

} // namespace granrepro
