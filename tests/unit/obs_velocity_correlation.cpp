// VelocityCorrelation (observables/velocity_correlation.hpp): molecular chaos gives zero, a
// velocity field smooth on the scale of r gives one, and the cell list finds the pairs the
// all-pairs loop finds.
#include "core/rng_stream.hpp"
#include "observables/velocity_correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace granrepro;

namespace {

struct Gas {
    std::vector<Vec2> pos, vel;
};

// n uniform random points in [0, Lx) x [0, Ly); velocities independent normal (sd 0.3 m/s) plus a
// drift, or, with wave_k > 0, the shear wave (U cos(k y), 0) + drift.
Gas gas(int n, double Lx, double Ly, std::uint64_t stream, double wave_k = 0.0) {
    RngStream rng(42, stream);
    Gas g;
    const Vec2 drift{0.7, -0.2}; // removed by the snapshot's mean
    for (int i = 0; i < n; ++i) {
        const Vec2 p{rng.uniform(0.0, Lx), rng.uniform(0.0, Ly)};
        g.pos.push_back(p);
        if (wave_k > 0) g.vel.push_back(Vec2{1.5 * std::cos(wave_k * p.y), 0.0} + drift);
        else g.vel.push_back(Vec2{0.3 * rng.normal(), 0.3 * rng.normal()} + drift);
    }
    return g;
}

} // namespace

// Independent velocities (molecular chaos): C_n and C_t vanish in every bin within the error.
TEST(VelocityCorrelation, IndependentVelocitiesGiveZero) {
    const double L = 30.0;
    VelocityCorrelation vc(L, L, 0.0, 3.0, 6);
    for (std::uint64_t s = 0; s < 4; ++s) {
        const Gas g = gas(3000, L, L, s);
        vc.accumulate(g.pos, g.vel);
    }
    const auto cn = vc.normal(), ct = vc.tangential(), en = vc.normal_error(), et = vc.tangential_error();
    for (std::size_t k = 0; k < cn.size(); ++k) {
        ASSERT_GT(vc.counts()[k], 1000u);
        EXPECT_LT(std::abs(cn[k]), 4 * en[k]) << "bin " << k;
        EXPECT_LT(std::abs(ct[k]), 4 * et[k]) << "bin " << k;
        // A product of two independent unit-variance normals has variance 1: the error is 1/sqrt(n).
        EXPECT_NEAR(en[k] * std::sqrt(double(vc.counts()[k])), 1.0, 0.1);
        // Approaching pairs: g_n^2 / (2 T1) is chi^2 with one degree of freedom, mean 1.
        EXPECT_NEAR(vc.approach()[k], 1.0, 4 * vc.approach_error()[k]) << "bin " << k;
        EXPECT_NEAR(double(vc.approaching_counts()[k]) / double(vc.counts()[k]), 0.5, 4 * 0.5 / std::sqrt(double(vc.counts()[k])));
    }
}

// The shear wave (U cos(k y), 0): a pair at separation r, angle phi has u_i.u_j averaging
// U^2/2 cos(k r sin phi), and T1 = U^2/4, so C_n(r) = 2 <cos(k r sin phi) cos^2 phi>_phi and
// C_t(r) = 2 <cos(k r sin phi) sin^2 phi>_phi: both 1 as k r -> 0.
TEST(VelocityCorrelation, SmoothFieldGivesOne) {
    const double L = 40.0, k = 2 * std::numbers::pi / L;
    VelocityCorrelation vc(L, L, 0.0, 2.0, 4);
    const Gas g = gas(4000, L, L, 7, k);
    vc.accumulate(g.pos, g.vel);
    const auto r = vc.centres(), cn = vc.normal(), ct = vc.tangential();
    for (std::size_t b = 0; b < r.size(); ++b) {
        double en = 0, et = 0; // the phi averages by the midpoint rule
        const int m = 2000;
        for (int i = 0; i < m; ++i) {
            const double phi = 2 * std::numbers::pi * (i + 0.5) / m, c = std::cos(k * r[b] * std::sin(phi));
            en += 2 * c * std::cos(phi) * std::cos(phi) / m;
            et += 2 * c * std::sin(phi) * std::sin(phi) / m;
        }
        // Finite sampling of positions: 4 standard errors over the bin's pairs (checked in
        // IndependentVelocitiesGiveZero).
        const auto err_n = vc.normal_error(), err_t = vc.tangential_error();
        EXPECT_NEAR(cn[b], en, 4 * err_n[b]) << "bin " << b;
        EXPECT_NEAR(ct[b], et, 4 * err_t[b]) << "bin " << b;
        // Neighbours move together: their normal relative velocity is small against sqrt(2 T1).
        EXPECT_LT(vc.approach()[b], 0.05) << "bin " << b;
    }
}

// The cell list visits exactly the pairs of the all-pairs loop.
TEST(VelocityCorrelation, CellListMatchesAllPairs) {
    const double Lx = 12.0, Ly = 9.0; // few cells: the aliasing of neighbour offsets is exercised
    VelocityCorrelation a(Lx, Ly, 0.5, 4.0, 7), b(Lx, Ly, 0.5, 4.0, 7);
    const Gas g = gas(600, Lx, Ly, 3);
    a.accumulate(g.pos, g.vel);
    b.accumulate_brute_force(g.pos, g.vel);
    EXPECT_EQ(a.counts(), b.counts());
    EXPECT_EQ(a.approaching_counts(), b.approaching_counts());
    const auto na = a.normal(), nb = b.normal(), ta = a.tangential(), tb = b.tangential();
    for (std::size_t k = 0; k < na.size(); ++k) {
        EXPECT_NEAR(na[k], nb[k], 1e-12);
        EXPECT_NEAR(ta[k], tb[k], 1e-12);
    }
}

TEST(VelocityCorrelation, RefusesBadInput) {
    EXPECT_THROW(VelocityCorrelation(10, 10, 1.0, 6.0, 5), std::invalid_argument); // r_max > L/2
    EXPECT_THROW(VelocityCorrelation(10, 10, 2.0, 1.0, 5), std::invalid_argument);
    VelocityCorrelation vc(10, 10, 0.0, 2.0, 5);
    const std::vector<Vec2> p{{1, 1}, {2, 2}}, v{{1, 0}};
    EXPECT_THROW(vc.accumulate(p, v), std::invalid_argument);
}
