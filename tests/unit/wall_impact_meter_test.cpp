// The pipe's wall-impact meter (src/engines/soft/wall_impact_meter.hpp) on its own, fed steps by
// hand: the Δv_y of Eq. (9) of Schäfer & Wolf as the wall impulse over the mass, when an impact
// begins and ends, and the sums independent of which slot holds which grain.
#include "engines/soft/wall_impact_meter.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

using namespace granrepro;

namespace {

// Stands in for the engine: grains in slots (slot = id unless moved), velocities at touch, and one
// step as the engine reports it (near list and marks).
struct Grains {
    std::vector<int> id;
    std::vector<double> inv_mass, vx, vy;
    explicit Grains(std::size_t n, double mass) : inv_mass(n, 1.0 / mass), vx(n, 0.0), vy(n, 0.0) {
        for (std::size_t i = 0; i < n; ++i) id.push_back(int(i));
    }
    // A step in which the slots `touching` touch a wall grain and `near` are near a
    // wall without touching; every other slot is away from the walls.
    void step(WallImpactMeter& m, const std::set<int>& touching, const std::set<int>& near = {}) {
        std::vector<unsigned char> mark(id.size(), 0);
        std::vector<int> list;
        for (int i : near) mark[std::size_t(i)] = 1, list.push_back(i);
        for (int i : touching) mark[std::size_t(i)] = 2, list.push_back(i);
        m.step(true, list.data(), list.size(), mark.data(), id.data(), inv_mass.data(),
               [&](std::size_t i) { return WallImpactMeter::Velocity{vx[i], vy[i]}; });
    }
};

WallImpactMeter meter_of(std::size_t n) {
    WallImpactMeter m;
    for (std::size_t i = 0; i < n; ++i) m.add_grain();
    return m;
}

// A grain pressed against the wall by a constant force f_y for k steps gets Δv_y = k f_y dt / m,
// whatever else acts on it (the meter sees only the wall's impulse).
TEST(WallImpactMeter, ConstantWallForceGivesImpulseOverMass) {
    const double mass = 2e-6, dt = 1e-5, fy = 0.3;
    const int k = 7;
    WallImpactMeter m = meter_of(1);
    Grains g(1, mass);
    for (int s = 0; s < k; ++s) {
        m.add_impulse(0, fy * dt); // (two wall grains would call twice)
        g.step(m, {0});
        m.end_step(dt);
    }
    g.step(m, {}, {0}); // still near the wall, no longer touching: the impact ends
    m.end_step(dt);
    const WallImpactStats& w = m.stats();
    EXPECT_EQ(w.impacts, 1);
    EXPECT_EQ(w.completed, 1);
    EXPECT_NEAR(w.sum_dvy, k * fy * dt / mass, 1e-14 * k * fy * dt / mass); // 10.5 m/s
    EXPECT_NEAR(w.time, (k + 1) * dt, 1e-20);
}

// An impact is counted as begun in the step the grain starts to touch, with |v_x|, |v_y| of that
// step (not of later ones), and as completed in the step it touches no wall grain, also when it
// has then left the walls' reach at once. Resetting clears the counts but not an impact under way.
TEST(WallImpactMeter, ImpactBeginsWhenTouchingStartsAndEndsWhenItStops) {
    const double dt = 1e-5;
    WallImpactMeter m = meter_of(1);
    Grains g(1, 1e-6);
    g.step(m, {}, {0}); // approaching
    m.end_step(dt);
    EXPECT_EQ(m.stats().impacts, 0);
    g.vx[0] = -0.4, g.vy[0] = -1.5;
    g.step(m, {0});
    m.end_step(dt);
    EXPECT_EQ(m.stats().impacts, 1);
    EXPECT_EQ(m.stats().completed, 0);
    g.vx[0] = 0.2, g.vy[0] = 0.7; // bounced: these are not the incoming velocities
    g.step(m, {0});
    m.end_step(dt);
    g.step(m, {}); // gone from the wall in one step
    m.end_step(dt);
    EXPECT_EQ(m.stats().impacts, 1);
    EXPECT_EQ(m.stats().completed, 1);
    EXPECT_EQ(m.stats().sum_vx_in, 0.4);
    EXPECT_EQ(m.stats().sum_vy_in, 1.5);

    g.step(m, {0}); // a second impact, begun before the reset, ends after it
    m.end_step(dt);
    m.reset_stats();
    EXPECT_EQ(m.stats().impacts, 0);
    EXPECT_EQ(m.stats().completed, 0);
    EXPECT_EQ(m.stats().sum_vy_in, 0.0);
    EXPECT_EQ(m.stats().time, 0.0);
    g.step(m, {}, {0});
    m.end_step(dt);
    EXPECT_EQ(m.stats().impacts, 0);
    EXPECT_EQ(m.stats().completed, 1);
    EXPECT_EQ(m.stats().sum_vx_in, 0.2);
}

// Impacts completed in the same step are added in id order, whatever slots hold them: Δv_y of
// 1e16, -1e16 and 1 (ids 0, 1, 2) sum to 1 in id order, to 0 with id 2 first (1 + 1e16 rounds to
// 1e16). Slot 0 holds id 2 here, slots 1 and 2 ids 0 and 1.
TEST(WallImpactMeter, CompletionsAddInIdOrderWhateverSlotHoldsThem) {
    WallImpactMeter m = meter_of(3);
    Grains g(3, 1.0);
    g.id = {2, 0, 1};
    g.step(m, {0, 1, 2});
    m.end_step(1.0);
    m.add_impulse(0, 1e16);
    m.add_impulse(1, -1e16);
    m.add_impulse(2, 1.0);
    g.step(m, {});
    m.end_step(1.0);
    EXPECT_EQ(m.stats().impacts, 3);
    EXPECT_EQ(m.stats().completed, 3);
    EXPECT_EQ(m.stats().sum_dvy, 1.0);
}

} // namespace
