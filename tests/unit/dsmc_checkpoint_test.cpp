// Determinism and checkpoint/restart of the DSMC engine: a run restored from save_state() is
// bit-identical to an uninterrupted one.
#include "gas.hpp"
#include "saved_states.hpp"
#include "theory/kinetic_theory.hpp"

#include <gtest/gtest.h>

using namespace granrepro;
using namespace granrepro::test;

namespace {

constexpr double kRho = 0.25; // area fraction of gas()

DsmcEngine gas(std::uint64_t seed, double r = 0.8, double t_c = 0.0) {
    DsmcConfig cfg;
    cfg.r = r;
    cfg.t_c = t_c;
    cfg.seed = seed;
    cfg.free_volume = DsmcFreeVolume::cell;
    cfg.displacement = true;
    cfg.resample_interval = 7;
    return uniform_dsmc_gas(2000, kRho, cfg, 5, 5); // the initial state is the same for every seed
}

// Collisions the Enskog theory of hard disks expects in the next dt: N omega / 2 with Enskog's
// rate at Henderson's g(d), T/m = <|v|^2>/2 in 2D.
double enskog_collisions(const DsmcEngine& e, double dt) {
    const double n = double(e.size());
    double v2 = 0;
    for (const auto& v : e.velocities()) v2 += norm2(v);
    const double omega = theory::enskog_collision_rate(n / (e.config().lx * e.config().ly), kD, v2 / (2.0 * n),
                                                       theory::henderson_contact_value(kRho));
    return 0.5 * n * omega * dt;
}

// A checkpoint test is only worth something if collisions happen after the restore: the resumed
// stretch must see at least half the collisions Enskog's rate predicts at its start. In an
// equilibrated gas DSMC follows Enskog's rate within a few % (tests/validation/
// dsmc_kinetic_theory_test.cpp); these unequilibrated random starts collide more (0.9 and 1.7
// times Enskog in the two tests), and cooling (r = 0.8) over the stretches lowers the rate by far
// less than a factor 2. So half is a safe lower bound, and a resumed run that stops colliding fails.
void expect_collisions_after_restore(const DsmcEngine& at_restore, const DsmcEngine& end) {
    const double expected = enskog_collisions(at_restore, end.time() - at_restore.time());
    const double seen = double(end.total_collisions() - at_restore.total_collisions());
    EXPECT_GT(expected, 100.0) << "the stretch is too short to test anything";
    EXPECT_GT(seen, 0.5 * expected) << "collisions after the restore: " << seen << ", Enskog: " << expected;
}

} // namespace

TEST(DsmcCheckpoint, SameSeedSameRunOtherSeedOtherRun) {
    auto a = gas(11), b = gas(11), c = gas(12);
    a.run_steps(120);
    b.run_steps(120);
    c.run_steps(120);
    expect_same_fields(a.save_state(), b.save_state());
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
    expect_same_fields(whole.save_state(), resumed.save_state());
    expect_collisions_after_restore(first, resumed);
    EXPECT_GT(resumed.elastic_collisions(), 0u);

    // restore_state into an engine that has run elsewhere gives the same.
    auto other = gas(99, 0.5);
    other.run_steps(10);
    other.restore_state(s);
    other.run_steps(107);
    expect_same_fields(whole.save_state(), other.save_state());
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
    expect_same_fields(whole.save_state(), resumed.save_state());
    expect_collisions_after_restore(first, resumed);
}
