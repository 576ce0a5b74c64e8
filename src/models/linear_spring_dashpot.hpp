// Linear spring-dashpot normal force, Schäfer & Wolf (1995) Eq. (1):
//     F_N = -k_N xi - gamma_N m_red dxi/dt
// xi is the overlap r1 + r2 - |x2 - x1| > 0 and m_red = m1 m2 / (m1 + m2) (a wall grain has
// infinite mass, so m_red = m of the free grain). The damping is proportional to m_red, which
// makes free-wall collisions more dissipative than free-free ones, as the paper stresses.
// The analytic solution with xi(0) = 0 gives (Eq. 4)
//     t_col = pi (k_N/m_red - gamma_N^2/4)^(-1/2),   e_N = exp(-gamma_N t_col / 2).
// The force is not clipped at zero: Eq. (4) assumes the (weakly attractive) end of the contact
// is kept and the contact ends when xi returns to 0. (Luding's Eqs. (10)-(11) with nu = 1, phi = 0
// are the same law with gamma_n = gamma_N m_red.)
#pragma once
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/normal_force.hpp"

namespace granrepro {

struct LinearSpringDashpot {
    double k_N = 0.0;     // normal spring constant [N/m]
    double gamma_N = 0.0; // damping rate per unit reduced mass [1/s]

    // The repulsive force on either grain along the normal [N]; > 0 pushes apart.
    NormalForce normal_force(double xi, double xi_dot, double m_red) const {
        const double elastic = k_N * xi;
        return {elastic + gamma_N * m_red * xi_dot, elastic};
    }

    // Eq. (4): contact duration [s] for a pair of reduced mass m_red [kg].
    double collision_time(double m_red) const {
        const double w2 = k_N / m_red - 0.25 * gamma_N * gamma_N;
        if (w2 <= 0.0) throw std::domain_error("over-damped contact: no rebound");
        return std::numbers::pi / std::sqrt(w2);
    }
    // e_N = exp(-gamma_N t_col / 2).
    double restitution(double m_red) const {
        return std::exp(-0.5 * gamma_N * collision_time(m_red));
    }
    // Inverts Eq. (4): the gamma_N that gives restitution e_N for a pair of reduced mass m_red.
    static LinearSpringDashpot from_restitution(double k_N, double e_N, double m_red) {
        const double l = std::log(e_N);
        const double gamma =
            2.0 * std::abs(l) * std::sqrt(k_N / m_red) / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
        return {k_N, gamma};
    }
};

} // namespace granrepro
