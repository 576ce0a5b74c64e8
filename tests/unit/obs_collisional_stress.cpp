#include "core/rng_stream.hpp"
#include "observables/collisional_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;

namespace {
CollisionRecord rec(double t, int i, int j, Vec2 ri, Vec2 rj, Vec2 n, Vec2 dP) {
    return {.t = t, .i = i, .j = j, .ri = ri, .rj = rj, .n = n, .dP = dP};
}
} // namespace

TEST(ObsCollisionalStress, HandComputedCollisions) {
    // Box [0,2) x [0,1), two 1 m^2 cells, window [0, 2) s.
    CollisionalStress st(2, 1, 0.0, 0.0, 2.0, 1.0, 0.0, 2.0, /*periodic=*/false);
    // Head-on in cell 0: d = 0.2 m, dP = 3 N s along n (repulsive).
    EXPECT_TRUE(st.add(rec(0.5, 0, 1, {0.6, 0.5}, {0.4, 0.5}, {1, 0}, {3.0, 0.0})));
    // Oblique frictional in cell 1: n = +y, dP has a tangential part 0.5.
    EXPECT_TRUE(st.add(rec(1.0, 2, 3, {1.5, 0.6}, {1.5, 0.4}, {0, 1}, {0.5, 2.0})));
    // Wall at x = 2: contact point (2, 0.5), clamped into cell 1.
    EXPECT_TRUE(st.add(rec(1.5, 4, -1, {1.9, 0.5}, {2.0, 0.5}, {-1, 0}, {-1.0, 0.0})));
    // Outside the window.
    EXPECT_FALSE(st.add(rec(2.0, 0, 1, {0.6, 0.5}, {0.4, 0.5}, {1, 0}, {3.0, 0.0})));
    const auto cells = st.result();
    ASSERT_EQ(cells.size(), 2u);
    // Cell 0: (r_j - r_i)(x)dP = (-0.2, 0)(x)(3, 0) -> xx = -0.6; / (V_c = 1 m^2 * dt = 2 s).
    EXPECT_NEAR(cells[0].collisional(0, 0), -0.3, 1e-14);
    EXPECT_NEAR(cells[0].collisional(0, 1), 0.0, 1e-14);
    EXPECT_NEAR(cells[0].collisional(1, 1), 0.0, 1e-14);
    EXPECT_NEAR(cells[0].pressure(), 0.15, 1e-14);
    EXPECT_EQ(cells[0].collisions, 1u);
    // Cell 1: (0, -0.2)(x)(0.5, 2) -> yx = -0.1, yy = -0.4; wall (0.1, 0)(x)(-1, 0) -> xx = -0.1.
    const auto& s = cells[1].total;
    EXPECT_NEAR(s(0, 0), -0.05, 1e-14);
    EXPECT_NEAR(s(0, 1), 0.0, 1e-14);
    EXPECT_NEAR(s(1, 0), -0.05, 1e-14);
    EXPECT_NEAR(s(1, 1), -0.2, 1e-14);
    EXPECT_EQ(cells[1].collisions, 2u);
    // Principal stresses of the symmetric part [[-0.05, -0.025], [-0.025, -0.2]].
    const double tr = -0.25, det = 0.05 * 0.2 - 0.025 * 0.025;
    const double disc = std::sqrt(tr * tr / 4.0 - det);
    EXPECT_NEAR(cells[1].sigma_min, tr / 2.0 - disc, 1e-14);
    EXPECT_NEAR(cells[1].sigma_max, tr / 2.0 + disc, 1e-14);
    // Compressive: both principal stresses negative (tension-positive convention).
    EXPECT_LT(cells[1].sigma_max, 0.0);
    const Eigen::Matrix2d sym = 0.5 * (s + s.transpose());
    EXPECT_NEAR((sym * cells[1].axis_max - cells[1].sigma_max * cells[1].axis_max).norm(), 0.0, 1e-14);
    EXPECT_NEAR(cells[1].axis_min.dot(cells[1].axis_max), 0.0, 1e-14);
}

TEST(ObsCollisionalStress, IdealGasKineticPressure) {
    const double L = 10.0, m = 2.0, sv = 1.5; // m, kg, m/s per component
    const int N = 20000;
    RngStream rng(8, 8);
    CollisionalStress one(1, 1, 0.0, 0.0, L, L, 0.0, 1.0, true);
    CollisionalStress grid(4, 4, 0.0, 0.0, L, L, 0.0, 1.0, true);
    double sum_v2 = 0.0;
    for (int s = 0; s < 2; ++s) {
        std::vector<Vec2> x(N), v(N);
        std::vector<double> mass(N, m);
        for (int i = 0; i < N; ++i) {
            x[i] = {rng.uniform(0.0, L), rng.uniform(0.0, L)};
            v[i] = {sv * rng.normal(), sv * rng.normal()};
            sum_v2 += norm2(v[i]);
        }
        one.add_snapshot(x, v, mass);
        grid.add_snapshot(x, v, mass);
    }
    const double mean_v2 = sum_v2 / (2.0 * N);
    const auto c = one.result()[0];
    // p = N m <v^2> / (2 A) in 2D, exactly (sample <v^2>, averaged over the two snapshots).
    EXPECT_NEAR(c.pressure(), N * m * mean_v2 / (2.0 * L * L), 1e-12 * c.pressure());
    // ... and equal to its expectation N m 2 sv^2 / (2A) within the sampling error (~0.7%).
    EXPECT_NEAR(c.pressure(), N * m * sv * sv / (L * L), 0.03 * c.pressure());
    EXPECT_NEAR(c.kinetic(0, 1) / c.kinetic(0, 0), 0.0, 0.03);
    EXPECT_EQ(c.collisional, Eigen::Matrix2d::Zero());
    // The cell grid partitions the same sum: mean cell stress = whole-box stress.
    Eigen::Matrix2d mean = Eigen::Matrix2d::Zero();
    for (const auto& g : grid.result()) mean += g.kinetic / 16.0;
    EXPECT_NEAR((mean - c.kinetic).norm(), 0.0, 1e-10 * c.kinetic.norm());
}

TEST(ObsCollisionalStress, MeanFlowSubtraction) {
    std::vector<Vec2> x{{0.2, 0.2}, {0.7, 0.8}}, v{{0.0, -3.0}, {0.0, -3.0}};
    std::vector<double> m{1.0, 1.0};
    CollisionalStress raw(1, 1, 0, 0, 1, 1, 0, 1, false), fluct(1, 1, 0, 0, 1, 1, 0, 1, false, true);
    raw.add_snapshot(x, v, m);
    fluct.add_snapshot(x, v, m);
    EXPECT_DOUBLE_EQ(raw.result()[0].kinetic(1, 1), -18.0); // Eq. (9) as printed
    EXPECT_DOUBLE_EQ(fluct.result()[0].kinetic.norm(), 0.0); // a rigid fall carries no stress
}
