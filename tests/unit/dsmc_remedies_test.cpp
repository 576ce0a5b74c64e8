// The switchable remedies of the DSMC engine (DsmcConfig: partner, no_repeat_partner,
// mft_fraction, free_volume_block): each does what its comment says, checked collision by collision
// against bookkeeping kept outside the engine. Their physics (rates against Enskog, Haff, a2) is in
// tests/validation/dsmc_kinetic_theory_test.cpp.
#include "gas.hpp"
#include "saved_states.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

using namespace granrepro;
using namespace granrepro::test;

namespace {

DsmcEngine gas(std::size_t n, double rho, DsmcConfig cfg, std::uint64_t seed = 5) {
    cfg.seed = seed;
    return uniform_dsmc_gas(n, rho, cfg, seed, 41);
}

// Counts collisions of a pair whose members' previous collisions were with each other, from the
// records alone.
struct RepeatCounter {
    std::vector<int> last;
    std::uint64_t seen = 0, repeats = 0;
    explicit RepeatCounter(std::size_t n) : last(n, -1) {}
    void operator()(const CollisionRecord& c) {
        ++seen;
        if (last[static_cast<std::size_t>(c.i)] == c.j && last[static_cast<std::size_t>(c.j)] == c.i) ++repeats;
        last[static_cast<std::size_t>(c.i)] = c.j;
        last[static_cast<std::size_t>(c.j)] = c.i;
    }
};

} // namespace

TEST(DsmcRemedies, NoRepeatPartnerForbidsImmediateRecollisions) {
    // Paper's 2 d cells at rho = 0.25 (1.3 disks per cell): without the rule a pair that has just
    // collided is often drawn again. Checked to fail with the rule switched off in choose_partner.
    for (auto partner : {DsmcPartner::uniform, DsmcPartner::nearest}) {
        for (bool rule : {false, true}) {
            DsmcConfig cfg;
            cfg.r = 0.8;
            cfg.partner = partner;
            cfg.no_repeat_partner = rule;
            auto e = gas(4000, 0.25, cfg);
            RepeatCounter rc(e.size());
            e.run_steps(200, rc);
            ASSERT_GT(rc.seen, 5000u);
            if (rule)
                EXPECT_EQ(rc.repeats, 0u);
            else
                EXPECT_GT(rc.repeats, rc.seen / 100) << "without the rule repeats are common in 2 d cells";
            // The engine's own record of partners matches the records.
            for (std::size_t i = 0; i < e.size(); ++i)
                ASSERT_EQ(rc.last[i] < 0 ? kNoPartner : static_cast<std::uint32_t>(rc.last[i]), e.last_partners()[i]);
        }
    }
}

TEST(DsmcRemedies, NearestPartnerIsTheNearestMemberOfTheCell) {
    // Without displacement positions do not change during the collision phase of a step, so the
    // cells and distances seen by the engine are those after the step: each recorded (i, j) must
    // have no third particle of i's cell closer to i than j. Large cells (10 d, ~30 disks) make the
    // choice matter. Checked to fail with uniform partners.
    DsmcConfig cfg;
    cfg.partner = DsmcPartner::nearest;
    cfg.min_cell_diameters = 10.0;
    auto e = gas(4000, 0.25, cfg);
    std::vector<CollisionRecord> recs;
    auto keep = [&](const CollisionRecord& c) { recs.push_back(c); };
    std::uint64_t checked = 0, wrong = 0;
    for (int s = 0; s < 30; ++s) {
        recs.clear();
        e.step(keep);
        const auto& p = e.positions();
        auto cell = [&](const Vec2& q) {
            const auto ix = std::min(static_cast<std::size_t>(q.x / e.cell_width()), e.cells_x() - 1);
            const auto iy = std::min(static_cast<std::size_t>(q.y / e.cell_height()), e.cells_y() - 1);
            return iy * e.cells_x() + ix;
        };
        for (const auto& c : recs) {
            const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
            ASSERT_EQ(cell(p[i]), cell(p[j]));
            const double dij = norm2(p[j] - p[i]);
            for (std::size_t k = 0; k < p.size(); ++k)
                if (k != i && k != j && cell(p[k]) == cell(p[i]) && norm2(p[k] - p[i]) < dij) ++wrong;
            ++checked;
        }
    }
    ASSERT_GT(checked, 1000u);
    EXPECT_EQ(wrong, 0u);
}

TEST(DsmcRemedies, FreeVolumeBlockCoveringTheBoxIsTheMeanMode) {
    // A block of all cells holds every disk, so V_0/V_block is the box's area fraction over 0.82,
    // exactly the mean mode's factor: same exposure (to round-off) and the same collisions.
    // Checked to fail when block_areas() sums one row too few.
    DsmcConfig mean;
    mean.free_volume = DsmcFreeVolume::mean;
    mean.min_cell_diameters = 8.0;
    auto a = gas(2000, 0.25, mean);
    ASSERT_EQ(a.cells_x() % 2, 1u) << "pick N so that the cell count per side is odd";
    DsmcConfig block = mean;
    block.free_volume = DsmcFreeVolume::cell;
    block.free_volume_block = static_cast<std::uint32_t>(a.cells_x());
    auto b = gas(2000, 0.25, block);
    a.run_steps(50);
    b.run_steps(50);
    EXPECT_NEAR(b.exposure() / a.exposure(), 1.0, 1e-12);
    EXPECT_EQ(a.total_collisions(), b.total_collisions());
}

TEST(DsmcRemedies, FreeVolumeBlockAveragesTheNeighbourhood) {
    // One crowded cell among empty ones: with block 1 it alone sets its own V_0; with block 3 its
    // disks are spread over 9 cells' area. 3 x 3 cells of 2 d, 8 disks in the centre cell.
    DsmcConfig cfg;
    cfg.lx = cfg.ly = 6.0 * kD;
    cfg.free_volume = DsmcFreeVolume::cell;
    cfg.resample_interval = 1u << 30;
    std::vector<Vec2> pos, vel;
    RngStream rng(1, 1);
    for (int k = 0; k < 8; ++k) {
        pos.push_back({kD * rng.uniform(2.0, 4.0), kD * rng.uniform(2.0, 4.0)});
        vel.push_back({rng.normal(), rng.normal()});
    }
    auto one = [&](std::uint32_t block) {
        DsmcConfig c = cfg;
        c.free_volume_block = block;
        DsmcEngine e(c, pos, vel, std::vector<double>(8, 0.5 * kD), std::vector<double>(8, kM));
        e.step();
        return e.exposure() / e.tau();
    };
    const double vc = 4.0 * kD * kD, disks = 8.0 * std::numbers::pi * 0.25 * kD * kD / 0.82;
    EXPECT_NEAR(one(1), 28.0 / std::max(vc - disks, 0.05 * vc), 1e-9 * one(1));
    EXPECT_NEAR(one(3), 28.0 / (vc * (1.0 - disks / (9.0 * vc))), 1e-9 * one(3));
}

TEST(DsmcRemedies, TimeStepStaysUnderTheGivenFractionOfTheMeanFreeTime) {
    // With mft_fraction f the step is at most f / omega, omega measured over the previous
    // resampling interval; in a gas at rest in the mean (elastic) omega is constant, so every
    // step after the first interval obeys tau omega <= f. Checked to fail when resample() ignores f.
    for (double f : {0.02, 0.1}) {
        DsmcConfig cfg;
        cfg.mft_fraction = f;
        cfg.free_volume = DsmcFreeVolume::mean;
        auto e = gas(4000, 0.25, cfg);
        e.run_steps(50);
        const double t0 = e.time();
        const auto c0 = e.total_collisions();
        e.run_steps(200);
        const double omega = 2.0 * static_cast<double>(e.total_collisions() - c0) / (static_cast<double>(e.size()) * (e.time() - t0));
        EXPECT_LT(e.tau() * omega, 1.1 * f); // omega fluctuates by ~1/sqrt(collisions per interval)
        EXPECT_GT(e.tau() * omega, 0.9 * f); // and the bound is what sets the step here
    }
}

TEST(DsmcRemedies, BadRemedyParametersAreRejected) {
    DsmcConfig cfg;
    cfg.free_volume_block = 2;
    EXPECT_ANY_THROW(gas(100, 0.25, cfg));
    cfg.free_volume_block = 1;
    cfg.mft_fraction = -1.0;
    EXPECT_ANY_THROW(gas(100, 0.25, cfg));
}

TEST(DsmcRemedies, StateWithRemediesResumesBitIdenticalFromFile) {
    // Every remedy on and off its default, so the last partners, the time-step bound's
    // bookkeeping and the new config fields must all survive the HDF5 file. Checked to fail
    // when write/read of last_partner or resample_collisions is dropped.
    DsmcConfig cfg;
    cfg.r = 0.8;
    cfg.partner = DsmcPartner::nearest;
    cfg.no_repeat_partner = true;
    cfg.mft_fraction = 0.05;
    cfg.free_volume = DsmcFreeVolume::cell;
    cfg.free_volume_block = 3;
    cfg.displacement = true;
    cfg.resample_interval = 7;
    auto whole = gas(1500, 0.25, cfg, 9);
    whole.run_steps(93); // not a multiple of the resampling interval
    DsmcEngine resumed(through_file(whole.save_state()));
    whole.run_steps(107);
    resumed.run_steps(107);
    EXPECT_EQ(resumed.config().partner, DsmcPartner::nearest);
    EXPECT_EQ(resumed.config().free_volume_block, 3u);
    expect_same_fields(whole.save_state(), resumed.save_state());
}
