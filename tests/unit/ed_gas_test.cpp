// The elastic equilibration of the Luding experiments (scenarios/ed_gas): measuring the collision
// rate over the second half must not change the equilibrated state, and that rate is the Enskog
// rate the enskog_rate claims compare with (issue 27 §4).
#include "core/rng_stream.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "scenarios/ed_gas.hpp"
#include "theory/kinetic_theory.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

using namespace granrepro;

namespace {

struct Gas {
    double L, d = 1e-3, vbar = 0.2;
    std::vector<double> rad, mass;
    std::vector<Vec2> vel;
};

// n_side^2 disks at area fraction rho, Maxwellian velocities.
Gas make_gas(int n_side, double rho, std::uint64_t seed) {
    Gas g;
    const std::size_t n = std::size_t(n_side) * std::size_t(n_side);
    g.L = std::sqrt(double(n) * std::numbers::pi * g.d * g.d / (4 * rho));
    g.rad.assign(n, g.d / 2);
    g.mass.assign(n, 1e-6);
    RngStream rng(seed, 0);
    g.vel = maxwellian_velocities(g.mass, g.vbar, rng);
    return g;
}

} // namespace

// cluster-growth's initial state must stay what it was when its rate moved to the second half:
// the two halves run exactly the collisions of the whole (N x 10 / 4 is an integer).
TEST(EquilibratedGas, RateOverSecondHalfLeavesTheStateBitIdentical) {
    const Gas g = make_gas(12, 0.25, 7);
    const auto whole = equilibrated_lattice_gas(g.L, g.vel, g.rad, g.mass, g.vbar, 10.0, false);
    const auto halves = equilibrated_lattice_gas(g.L, g.vel, g.rad, g.mass, g.vbar, 10.0, true);
    ASSERT_EQ(whole.pos.size(), halves.pos.size());
    for (std::size_t i = 0; i < whole.pos.size(); ++i) {
        EXPECT_EQ(whole.pos[i].x, halves.pos[i].x) << i;
        EXPECT_EQ(whole.pos[i].y, halves.pos[i].y) << i;
        EXPECT_EQ(whole.vel[i].x, halves.vel[i].x) << i;
        EXPECT_EQ(whole.vel[i].y, halves.vel[i].y) << i;
    }
}

// The lattice start's first collisions are rarer than in equilibrium, so the whole-run rate lies
// below Enskog's (omega = 8 rho vbar g(d) / (sqrt(2 pi) d), Henderson's g) and the second half's
// rate agrees with it: 1e4 disks, 2.5e4 pair collisions in the second half (1.9 % at 3 sigma)
// plus Henderson's 1 %.
TEST(EquilibratedGas, SecondHalfRateIsEnskogsWholeRunRateIsLower) {
    const double rho = 0.25;
    const Gas g = make_gas(100, rho, 3);
    const double enskog = theory::enskog_collision_rate_vbar(rho, g.d, g.vbar, theory::henderson_contact_value(rho));
    const auto whole = equilibrated_lattice_gas(g.L, g.vel, g.rad, g.mass, g.vbar, 10.0, false);
    const auto halves = equilibrated_lattice_gas(g.L, g.vel, g.rad, g.mass, g.vbar, 10.0, true);
    EXPECT_NEAR(halves.collision_rate / enskog, 1.0, 0.03);
    EXPECT_LT(whole.collision_rate, halves.collision_rate);
}
