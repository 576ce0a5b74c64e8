// The gases of equal hard disks (diameter kD, mass kM) that the ED and DSMC tests start from.
#pragma once
#include "engines/dsmc/dsmc_engine.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace granrepro::test {

constexpr double kD = 1e-3; // diameter [m]
constexpr double kM = 1e-6; // mass [kg]

// Side of the square box in which n disks have area fraction rho [m].
inline double box_for(std::size_t n, double rho) {
    return kD * std::sqrt(static_cast<double>(n) * std::numbers::pi / (4.0 * rho));
}

struct Disks {
    std::vector<Vec2> pos, vel;
    std::vector<double> rad, mass;
};

// n disks placed at random without overlap in an l x l box, then Maxwellian velocities with
// Luding's vbar, both drawn from RngStream(seed, 0).
inline Disks random_disks(std::size_t n, double l, bool periodic_x, bool periodic_y, std::uint64_t seed, double vbar = 1.0) {
    RngStream rng(seed, 0);
    Disks d{{}, {}, std::vector<double>(n, 0.5 * kD), std::vector<double>(n, kM)};
    d.pos = random_positions(d.rad, l, l, periodic_x, periodic_y, rng);
    d.vel = maxwellian_velocities(d.mass, vbar, rng);
    return d;
}

// An ED gas of random_disks at area fraction rho; cfg gives everything but the box.
template <class Engine = EdEngine>
Engine random_ed_gas(std::size_t n, double rho, std::uint64_t seed, EdConfig cfg = {}, double vbar = 1.0) {
    cfg.lx = cfg.ly = box_for(n, rho);
    const Disks d = random_disks(n, cfg.lx, cfg.periodic_x, cfg.periodic_y, seed, vbar);
    return Engine(cfg, d.pos, d.vel, d.rad, d.mass);
}

// A DSMC gas at area fraction rho: uniform positions (DSMC disks may overlap), then standard
// normal velocity components, drawn from RngStream(seed, stream); cfg gives everything but the box.
inline DsmcEngine uniform_dsmc_gas(std::size_t n, double rho, DsmcConfig cfg, std::uint64_t seed, std::uint64_t stream) {
    const double l = box_for(n, rho);
    cfg.lx = cfg.ly = l;
    RngStream rng(seed, stream);
    std::vector<Vec2> pos(n), vel(n);
    for (auto& p : pos) p = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
    for (auto& v : vel) v = {rng.normal(), rng.normal()};
    return DsmcEngine(cfg, pos, vel, std::vector<double>(n, 0.5 * kD), std::vector<double>(n, kM));
}

} // namespace granrepro::test
