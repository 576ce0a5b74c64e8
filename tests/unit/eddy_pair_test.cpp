// The eddy-pair measure (src/analysis/eddy_pair.hpp) on constructed velocity fields: two
// co-rotating vortices on a diagonal (found, with their sense and place), counter-rotating
// vortices, shear layers of one and two wavelengths, and uncorrelated velocities (not found).
#include "analysis/eddy_pair.hpp"
#include "core/rng_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;

namespace {

constexpr double kBox = 16.0;

std::vector<Vec2> grid_points() {
    std::vector<Vec2> p;
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j) p.push_back({(i + 0.5) * kBox / 24, (j + 0.5) * kBox / 24});
    return p;
}
double mi(double d) { return d - kBox * std::round(d / kBox); }

// Gaussian vortices of circulation sign w at the given centres (minimum image).
std::vector<Vec2> vortices(const std::vector<Vec2>& p, const std::vector<std::pair<Vec2, double>>& vs) {
    std::vector<Vec2> v(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        for (const auto& [c, w] : vs) {
            const Vec2 r{mi(p[i].x - c.x), mi(p[i].y - c.y)};
            v[i] += w * std::exp(-norm2(r) / (2 * 2.0 * 2.0)) * perp(r);
        }
    return v;
}
double torus_distance(Vec2 a, Vec2 b) { return std::hypot(mi(a.x - b.x), mi(a.y - b.y)); }

} // namespace

TEST(EddyPair, RigidRotationHasRotationOne) {
    const auto p = grid_points();
    std::vector<Vec2> v;
    const Vec2 c{8.0, 8.0};
    for (const Vec2& r : p) v.push_back(-2.0 * perp(r - c)); // clockwise
    EXPECT_NEAR(region_rotation(p, v, kBox, c, 4.0), -1.0, 1e-12);
}

TEST(EddyPair, TwoCoRotatingVorticesOnADiagonal) {
    const auto p = grid_points();
    const Vec2 tl{4.0, 12.0}, br{12.0, 4.0};
    const auto v = vortices(p, {{tl, +1.0}, {br, +1.0}});
    const EddyPair e = find_eddy_pair(p, v, kBox);
    EXPECT_GT(e.strength, 0.8);
    EXPECT_EQ(e.sense, +1);
    const bool placed = (torus_distance(e.centre_a, tl) < 1.5 && torus_distance(e.centre_b, br) < 1.5) ||
                        (torus_distance(e.centre_a, br) < 1.5 && torus_distance(e.centre_b, tl) < 1.5);
    EXPECT_TRUE(placed) << e.centre_a.x << "," << e.centre_a.y << " " << e.centre_b.x << "," << e.centre_b.y;
    // The same clockwise.
    EXPECT_EQ(find_eddy_pair(p, vortices(p, {{tl, -1.0}, {br, -1.0}}), kBox).sense, -1);
}

TEST(EddyPair, CounterRotatingVorticesAreNoPair) {
    const auto p = grid_points();
    const auto v = vortices(p, {{{4.0, 12.0}, +1.0}, {{12.0, 4.0}, -1.0}});
    EXPECT_LT(find_eddy_pair(p, v, kBox).strength, 0.3);
}

TEST(EddyPair, ShearLayersAreNoPair) {
    const auto p = grid_points();
    for (int waves : {1, 2}) {
        std::vector<Vec2> v;
        for (const Vec2& r : p) v.push_back({std::sin(2 * M_PI * waves * r.y / kBox), 0.0});
        EXPECT_LT(find_eddy_pair(p, v, kBox).strength, 0.3) << waves << " wavelengths";
    }
}

TEST(EddyPair, UncorrelatedVelocitiesAreNoPairAndMatchTheirShuffles) {
    const auto p = grid_points();
    RngStream rng(3, 0);
    std::vector<Vec2> v;
    for (std::size_t i = 0; i < p.size(); ++i) v.push_back({rng.normal(), rng.normal()});
    const double e = find_eddy_pair(p, v, kBox).strength;
    EXPECT_LT(e, 0.4);
    const auto sh = shuffled_eddy_strengths(p, v, kBox, 8, 1);
    ASSERT_EQ(sh.size(), 8u);
    double mean = 0;
    for (double x : sh) mean += x / 8;
    EXPECT_NEAR(e, mean, 0.15) << "a random field is a typical draw of its shuffles";
    EXPECT_EQ(sh, shuffled_eddy_strengths(p, v, kBox, 8, 1)) << "deterministic for a seed";
    // The vortex pair stands far above its own shuffles.
    const auto vv = vortices(p, {{{4.0, 12.0}, +1.0}, {{12.0, 4.0}, +1.0}});
    for (double x : shuffled_eddy_strengths(p, vv, kBox, 8, 1)) EXPECT_LT(x, 0.5);
}
