// DSMC sizing rules of Luding 1998 Sec. 2.4: cells of side max(lambda/2, 2d) tiling the box, and
// the time step that lets the fastest particle cross a cell in step_factor steps.
#include "core/input_error.hpp"
#include "engines/dsmc/dsmc_rules.hpp"
#include "gas.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace granrepro;
using namespace granrepro::test;

namespace {

DsmcEngine gas(std::size_t n, double rho, DsmcConfig cfg) { return uniform_dsmc_gas(n, rho, cfg, 7, 99); }

double max_speed(const DsmcEngine& e) {
    double v2 = 0.0;
    for (const auto& v : e.velocities()) v2 = std::max(v2, norm2(v));
    return std::sqrt(v2);
}

} // namespace

TEST(DsmcRules, MeanFreePathIsOneOverRootTwoNSigma) {
    // lambda = 1/(sqrt(2) n 2d chi): check against the numbers for rho = 0.01 (n = 4 rho/(pi d^2)).
    const double n = 4.0 * 0.01 / (std::numbers::pi * kD * kD);
    EXPECT_NEAR(dsmc_mean_free_path(n, kD) / kD, std::numbers::pi / (8.0 * std::sqrt(2.0) * 0.01), 1e-12);
    EXPECT_NEAR(dsmc_mean_free_path(n, kD, 2.0), 0.5 * dsmc_mean_free_path(n, kD), 1e-15);
}

TEST(DsmcRules, CellsAreHalfTheMeanFreePathWhenDilute) {
    const std::size_t n = 4000;
    const auto e = gas(n, 0.01, {});
    const double lambda = e.mean_free_path();
    ASSERT_GT(0.5 * lambda, 2.0 * kD); // dilute: lambda/2 (~13.9 d) is the binding rule
    const double side = std::min(e.cell_width(), e.cell_height());
    EXPECT_GE(side, 0.5 * lambda);
    // Largest count per side: one more cell would be smaller than lambda/2.
    EXPECT_LT(e.config().lx / static_cast<double>(e.cells_x() + 1), 0.5 * lambda);
    EXPECT_EQ(e.cells_x(), static_cast<std::size_t>(std::floor(e.config().lx / (0.5 * lambda))));
    EXPECT_DOUBLE_EQ(e.cell_width() * static_cast<double>(e.cells_x()), e.config().lx); // cells tile the box
}

TEST(DsmcRules, CellsNeverBelowTwoDiameters) {
    const auto e = gas(4000, 0.25, {});
    ASSERT_LT(0.5 * e.mean_free_path(), 2.0 * kD); // dense: the 2d floor binds
    EXPECT_GE(e.cell_width(), 2.0 * kD);
    EXPECT_GE(e.cell_height(), 2.0 * kD);
    EXPECT_LT(e.config().lx / static_cast<double>(e.cells_x() + 1), 2.0 * kD);
    // Free-volume correction shortens lambda by 1 - rho/0.82.
    DsmcConfig fv;
    fv.free_volume = DsmcFreeVolume::mean;
    const auto f = gas(4000, 0.25, fv);
    EXPECT_NEAR(f.mean_free_path() / e.mean_free_path(), 1.0 - 0.25 / 0.82, 1e-12);
}

TEST(DsmcRules, CountPerSideIsTheLargestNotBelowTheTarget) {
    EXPECT_EQ(dsmc_cells_per_side(10.0, 1.0, 0.2), 20u); // lambda/2 = 0.5 binds
    EXPECT_EQ(dsmc_cells_per_side(10.0, 1.0, 0.6), 16u); // floor binds: 10/16 = 0.625 >= 0.6
    EXPECT_EQ(dsmc_cells_per_side(3.0, 1.0, 0.2), 6u);   // a 10 x 3 box: 20 x 6 square cells
    EXPECT_EQ(dsmc_cells_per_side(0.1, 1.0, 0.2), 1u); // box smaller than a cell: one cell
}

TEST(DsmcRules, TimeStepLetsFastestParticleCrossInStepFactorSteps) {
    EXPECT_DOUBLE_EQ(dsmc_time_step(2.0, 4.0, 5.0), 0.1);
    EXPECT_TRUE(std::isinf(dsmc_time_step(2.0, 0.0, 5.0)));
    DsmcConfig cfg;
    cfg.step_factor = 7.0;
    cfg.resample_interval = 4;
    cfg.r = 0.5; // cools, so tau must grow at each re-sampling
    auto e = gas(3000, 0.1, cfg);
    const double side = std::min(e.cell_width(), e.cell_height());
    const double v0 = max_speed(e);
    e.step();
    EXPECT_DOUBLE_EQ(e.tau(), side / (7.0 * v0));
    EXPECT_DOUBLE_EQ(e.time(), e.tau());
    e.run_steps(2);
    const double tau0 = e.tau();
    EXPECT_EQ(e.tau(), tau0); // not re-sampled inside the interval
    e.step();                 // step 3; step 4 re-samples from the velocities now
    const double v_now = max_speed(e);
    e.step();
    EXPECT_DOUBLE_EQ(e.tau(), side / (7.0 * v_now));
    EXPECT_GT(e.tau(), tau0);
    EXPECT_GE(e.v_max(), 2.0 * v_now);
    if (e.vmax_raises() == 0) {
        EXPECT_DOUBLE_EQ(e.v_max(), 2.0 * v_now);
    }
}

TEST(DsmcRules, RunUntilLandsExactlyOnTheEndTime) {
    auto e = gas(500, 0.1, {});
    const double t_end = 12.345 * 1e-4;
    e.run_until(t_end);
    EXPECT_EQ(e.time(), t_end);
}

TEST(DsmcRules, BadInputThrows) {
    DsmcConfig cfg;
    EXPECT_THROW(DsmcEngine(cfg, {{0, 0}}, {{0, 0}}, {1e-3}, {1.0}), InputError);
    EXPECT_THROW(DsmcEngine(cfg, {{0, 0}, {0.5, 0.5}}, {{0, 0}}, {1e-3, 1e-3}, {1.0, 1.0}), InputError);
    cfg.r = 1.5;
    EXPECT_THROW(DsmcEngine(cfg, {{0, 0}, {0.5, 0.5}}, {{0, 0}, {1, 0}}, {1e-3, 1e-3}, {1.0, 1.0}), InputError);
}
