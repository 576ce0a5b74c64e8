// Kinetic energies of Luding 1998 Figs 2, 8-10: K(t) (Eq. 18 compares K/K_0 with homogeneous
// cooling) and the anisotropy (K_x - K_z)/K of Fig. 8(b) that flags the shearing mode.
// In 2D the paper's vertical axis "z" is our y.
#pragma once
#include "core/vec2.hpp"

#include <span>

namespace granrepro {

struct KineticEnergy {
    double x = 0.0;   // K_x = 1/2 sum m v_x^2 [J]
    double y = 0.0;   // K_y = 1/2 sum m v_y^2 [J]
    double rot = 0.0; // K_rot = 1/2 sum I omega^2 [J]

    // Translational energy K_x + K_y [J]. The paper's K(t) in Figs 2, 8-10 is this: its
    // freely-cooling runs are frictionless, so spins never change and K_rot is a constant.
    double translational() const { return x + y; }
    double total() const { return x + y + rot; }
    // (K_x - K_y) / (K_x + K_y), Fig. 8(b): ~0 when homogeneous, ~+-1 in the shearing mode.
    // Zero when there is no translational energy.
    double anisotropy() const;

    // velocities [m/s], masses [kg]; all spans of the particle count.
    static KineticEnergy compute(std::span<const Vec2> velocities, std::span<const double> masses);
    // As above, plus spins omega_z [rad/s] and moments of inertia [kg m^2]. Throws
    // std::invalid_argument if the spans differ in length.
    static KineticEnergy compute(std::span<const Vec2> velocities, std::span<const double> masses,
                                 std::span<const double> spins, std::span<const double> inertia);
    // Monodisperse shortcut: one mass [kg] for every particle.
    static KineticEnergy compute(std::span<const Vec2> velocities, double mass);
};

} // namespace granrepro
