// Determinism and checkpoint/restart of the DSMC engine: a run restored from save_state() is
// bit-identical to an uninterrupted one.
#include "engines/dsmc/dsmc_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace granrepro;

namespace {

DsmcEngine gas(std::uint64_t seed, double r = 0.8, double t_c = 0.0) {
    const std::size_t n = 2000;
    const double d = 1e-3, l = d * std::sqrt(n * std::numbers::pi / (4.0 * 0.25));
    DsmcConfig cfg;
    cfg.lx = cfg.ly = l;
    cfg.r = r;
    cfg.t_c = t_c;
    cfg.seed = seed;
    cfg.free_volume = DsmcFreeVolume::cell;
    cfg.displacement = true;
    cfg.resample_interval = 7;
    RngStream rng(5, 5); // the initial state is the same for every seed
    std::vector<Vec2> pos(n), vel(n);
    for (auto& p : pos) p = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
    for (auto& v : vel) v = {rng.normal(), rng.normal()};
    return DsmcEngine(cfg, pos, vel, std::vector<double>(n, 0.5 * d), std::vector<double>(n, 1e-6));
}

void expect_identical(const DsmcEngine& a, const DsmcEngine& b) {
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.time(), b.time());
    EXPECT_EQ(a.steps(), b.steps());
    EXPECT_EQ(a.tau(), b.tau());
    EXPECT_EQ(a.v_max(), b.v_max());
    EXPECT_EQ(a.total_collisions(), b.total_collisions());
    EXPECT_EQ(a.candidates(), b.candidates());
    EXPECT_EQ(a.exposure(), b.exposure());
    EXPECT_TRUE(a.positions() == b.positions());
    EXPECT_TRUE(a.velocities() == b.velocities());
    EXPECT_TRUE(a.collision_counts() == b.collision_counts());
}

} // namespace

TEST(DsmcCheckpoint, SameSeedSameRunOtherSeedOtherRun) {
    auto a = gas(11), b = gas(11), c = gas(12);
    a.run_steps(120);
    b.run_steps(120);
    c.run_steps(120);
    expect_identical(a, b);
    EXPECT_GT(a.total_collisions(), 0u);
    EXPECT_FALSE(a.velocities() == c.velocities());
}

TEST(DsmcCheckpoint, RestoredRunIsBitIdentical) {
    auto whole = gas(21, 0.8, 2e-4);
    whole.run_steps(200);

    auto first = gas(21, 0.8, 2e-4);
    first.run_steps(93); // not a multiple of the re-sampling interval
    const DsmcState s = first.save_state();
    DsmcEngine resumed(s);
    resumed.run_steps(107);
    expect_identical(whole, resumed);
    EXPECT_GT(resumed.elastic_collisions(), 0u);

    // restore_state into an engine that has run elsewhere gives the same.
    auto other = gas(99, 0.5);
    other.run_steps(10);
    other.restore_state(s);
    other.run_steps(107);
    expect_identical(whole, other);
}

TEST(DsmcCheckpoint, RunUntilResumesBitIdentical) {
    auto whole = gas(31);
    const double t1 = 3e-4, t2 = 9e-4; // [s]
    whole.run_until(t1);
    whole.run_until(t2);
    auto first = gas(31);
    first.run_until(t1);
    DsmcEngine resumed(first.save_state());
    resumed.run_until(t2);
    expect_identical(whole, resumed);
    // Something happened after the restart: collisions, not just free flight.
    EXPECT_GT(whole.total_collisions(), first.total_collisions());
}
