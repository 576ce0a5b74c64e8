// A small event-driven gas of elastic, smooth, equal hard spheres in a periodic cube: the 3D
// check of Luding 1998 Sec. 3.2, "From ED simulations with elastic particles the normalized
// probability distributions P(b/d) = 1 in 2D, and P(b/d) = 2b/d in 3D, are found".
//
// Deliberately simple (a few hundred spheres): positions are kept at a common time and every
// event moves all spheres; each sphere stores its earliest predicted collision, found by scanning
// all others at their minimum image. A minimum-image prediction stays right while no pair can
// close a distance of L/2 - d, so predictions are valid only up to the horizon
// (L/2 - d) / (2 v_max) and a sphere whose horizon passes is re-predicted (all spheres are
// re-predicted when a collision raises v_max).
// Collision (elastic, smooth, equal masses): the normal components of the velocities swap,
//     v_i' = v_i - (v_ij . n) n,  v_j' = v_j + (v_ij . n) n,  n = r_ij / |r_ij|.
// Each collision reports the impact parameter b/d = |r_ij x v_ij| / (|v_ij| d) at contact
// (Eq. (17) in 3D).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/interrupt.hpp"
#include "core/vec3.hpp"

namespace granrepro {

class HardSphereGas3D {
public:
    // pos [m] inside [0, box)^3, vel [m/s], diameter d [m]; throws std::invalid_argument on
    // overlaps, on a box smaller than 3 d, or on size mismatch.
    HardSphereGas3D(std::vector<Vec3> pos, std::vector<Vec3> vel, double diameter, double box);

    // Runs until n more collisions happened; obs(b_over_d) is called for each. Throws
    // std::runtime_error after 1000 N events in a row without a collision (a gas so dilute that
    // horizon events crowd out collisions would otherwise run for ever).
    template <class Obs>
    void run_collisions(std::uint64_t n, Obs&& obs) {
        const std::uint64_t idle_limit = 1000 * std::uint64_t(r_.size());
        std::uint64_t idle = 0;
        for (std::uint64_t k = 0; k < n;) {
            if ((++events_ & 1023) == 0) engine_pause_point();
            if (step()) {
                obs(last_b_);
                ++k;
                idle = 0;
            } else if (++idle > idle_limit) {
                throw std::runtime_error("HardSphereGas3D: " + std::to_string(idle_limit) +
                                         " events without a collision; the gas is too dilute for its box");
            }
        }
    }
    void run_collisions(std::uint64_t n) {
        run_collisions(n, [](double) {});
    }

    double time() const { return t_; }
    std::uint64_t collisions() const { return collisions_; }
    const std::vector<Vec3>& positions() const { return r_; }
    const std::vector<Vec3>& velocities() const { return v_; }
    double kinetic_energy_per_mass() const; // sum v^2 / 2 [m^2/s^2]
    Vec3 momentum_per_mass() const;         // sum v [m/s]
    double min_distance() const;            // smallest centre distance over all pairs [m]

private:
    bool step(); // one event; true if it was a collision
    void predict(std::size_t i);
    Vec3 min_image(Vec3 d) const;
    double max_speed() const;

    std::vector<Vec3> r_, v_;
    std::vector<double> t_ev_;
    std::vector<int> partner_; // -1: horizon
    double d_, box_, t_ = 0, last_b_ = 0;
    double vmax_ = 0; // the speed bound the horizons were computed with [m/s]
    std::uint64_t collisions_ = 0, events_ = 0;
};

} // namespace granrepro
