// Hertz-Kuwabara-Kono normal force, Schäfer & Wolf (1995) Eq. (3) with alpha = 3/2, beta = 1/2,
// gamma = 1 (Kuwabara & Kono 1987):
//     F_N = -k_HKK xi^(3/2) - gamma_HKK m_red xi^(1/2) dxi/dt
// written with the same m_red scaling of the damping as Eq. (1) so that the two laws can be
// matched at a reference overlap (see brake-failure.toml). Restitution now depends on impact speed.
#pragma once
#include <cmath>

#include "models/normal_force.hpp"

namespace granrepro {

struct HertzKuwabaraKono {
    double k = 0.0;     // [N / m^(3/2)]
    double gamma = 0.0; // [1 / (s m^(1/2))]

    NormalForce normal_force(double xi, double xi_dot, double m_red) const {
        // xi can be a round-off negative right at the contact boundary; the force is then zero.
        const double s = xi > 0.0 ? std::sqrt(xi) : 0.0;
        const double elastic = k * xi * s;
        return {elastic + gamma * m_red * s * xi_dot, elastic};
    }

    // The HKK law whose stiffness and damping equal those of a linear law (k_N, gamma_N) at the
    // overlap xi_ref [m]: k = k_N / sqrt(xi_ref), gamma = gamma_N / sqrt(xi_ref).
    static HertzKuwabaraKono matched_at(double k_N, double gamma_N, double xi_ref) {
        const double s = std::sqrt(xi_ref);
        return {k_N / s, gamma_N / s};
    }
};

} // namespace granrepro
