// Stress-shape measures of Fig. 5 (src/analysis/stress_shape.hpp): the anisotropy of one cell's
// principal stresses, and the alignment of the cells' principal axes with its Rayleigh level.
#include "analysis/stress_shape.hpp"
#include "core/rng_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;

namespace {

// A cell with compressive principal stresses s1 <= s2 <= 0 (tension-positive Eq. 9) and its
// major compression along angle theta.
CollisionalStress::Cell cell(double s1, double s2, double theta) {
    CollisionalStress::Cell c;
    c.sigma_min = s1;
    c.sigma_max = s2;
    c.axis_min = {std::cos(theta), std::sin(theta)};
    c.axis_max = {-std::sin(theta), std::cos(theta)};
    return c;
}

} // namespace

TEST(StressShape, AnisotropyIsZeroForPressureOneForUniaxial) {
    EXPECT_DOUBLE_EQ(stress_anisotropy(cell(-2, -2, 0.3)), 0.0); // a gas's isotropic pressure
    EXPECT_DOUBLE_EQ(stress_anisotropy(cell(-2, 0, 0.3)), 1.0);  // compression along one axis only
    EXPECT_DOUBLE_EQ(stress_anisotropy(cell(-3, -1, 0.3)), 0.5);  // (3 - 1) / (3 + 1)
    EXPECT_TRUE(std::isnan(stress_anisotropy(cell(0, 0, 0.3))));
}

// Principal axes are headless: theta and theta + pi are the same axis, perpendicular axes cancel.
TEST(StressShape, AlignmentTreatsAxesAsHeadless) {
    const std::vector<CollisionalStress::Cell> same{cell(-2, -1, 0.4), cell(-2, -1, 0.4 + M_PI), cell(-3, -1, 0.4)};
    EXPECT_NEAR(stress_axes_alignment(same), 1.0, 1e-12);
    const std::vector<CollisionalStress::Cell> crossed{cell(-2, -1, 0.4), cell(-2, -1, 0.4 + M_PI / 2)};
    EXPECT_NEAR(stress_axes_alignment(crossed), 0.0, 1e-12);
}

// For n = 25 random axes (Fig. 5's 5 x 5 cells) n S^2 is exponential with mean 1, so S stays
// below random_axes_level(25, p) with probability 1 - p: 2000 grids give 0.99 +- 0.0022 at
// p = 0.01 and 0.5 +- 0.011 at p = 0.5 (binomial); the bounds allow ~4.5 of those.
TEST(StressShape, RandomAxesFollowTheRayleighLevel) {
    RngStream rng(7, 0);
    const int trials = 2000;
    int below_1pc = 0, below_half = 0;
    for (int t = 0; t < trials; ++t) {
        std::vector<CollisionalStress::Cell> cells;
        for (int k = 0; k < 25; ++k) cells.push_back(cell(-2, -1, M_PI * rng.uniform()));
        const double s = stress_axes_alignment(cells);
        below_1pc += s < random_axes_level(25, 0.01);
        below_half += s < random_axes_level(25, 0.5);
    }
    EXPECT_NEAR(below_1pc / double(trials), 0.99, 0.01);
    EXPECT_NEAR(below_half / double(trials), 0.5, 0.05);
}
