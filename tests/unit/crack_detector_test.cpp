// The crack detector (src/analysis/crack_detector.hpp) on constructed columns: an intact
// triangular lattice (no crack), a horizontal gap, V-shaped and inverted-V gaps, a notch and a
// hole that do not cross the pipe (no crack), and a gap too close to the bottom.
// Where the two parts are internally connected through lattice gaps of 0.01 d, the exact
// opening is the smallest surface gap between a disk above the cut and one below it, computed
// here by brute force, independently of the detector's chains.
#include "analysis/crack_detector.hpp"
#include "engines/ed/ed_initial_states.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

using namespace granrepro;

namespace {

constexpr double kD = 1.0, kL = 20.2, kS = 1.01; // diameter, pipe width, lattice constant (Sec. 5)

std::vector<Vec2> lattice(std::size_t rows) {
    // Rows alternate 20 and 19 disks for L = 20.2 d, s = 1.01 d.
    return triangular_lattice_positions(rows * 39 / 2, 0.5 * kD, kL - 0.5 * kD, 0.5 * kD, kS);
}

CrackSearch search(std::size_t below = 40, std::size_t above = 40) {
    return {.diameter = kD, .width = kL, .min_below = below, .min_above = above, .max_opening = 3 * kD};
}

// Smallest surface gap between a disk with above(r) and one without.
double cross_gap(const std::vector<Vec2>& p, const std::function<bool(Vec2)>& above) {
    double g = INFINITY;
    for (const Vec2& a : p)
        for (const Vec2& b : p)
            if (above(a) && !above(b)) g = std::min(g, norm(a - b) - kD);
    return g;
}

// Lifts every disk above the line y = cut(x) by `lift`, which opens a gap along the line.
std::vector<Vec2> split(std::vector<Vec2> p, const std::function<double(double)>& cut, double lift) {
    for (Vec2& r : p)
        if (r.y > cut(r.x)) r.y += lift;
    return p;
}

} // namespace

TEST(CrackDetector, IntactLatticeHasOnlyItsOwnGaps) {
    const auto p = lattice(60);
    const Crack c = find_crack(p, search());
    EXPECT_FALSE(c.wider);
    EXPECT_NEAR(c.opening, kS - kD, 1e-9) << "the lattice's gaps are 0.01 d";
}

TEST(CrackDetector, HorizontalGap) {
    const auto base = lattice(60);
    const double y_cut = base[600].y + 0.1; // between two rows, ~30 rows up
    auto cut = [&](double) { return y_cut; };
    const auto p = split(base, cut, 1.0 * kD);
    const Crack c = find_crack(p, search());
    const double expect = cross_gap(p, [&](Vec2 r) { return r.y > y_cut + 0.5; });
    EXPECT_GT(expect, 0.9);
    EXPECT_NEAR(c.opening, expect, 1e-12);
    // The two parts are the disks below and above the cut.
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(c.side[i], p[i].y > y_cut + 0.5 ? 1 : -1) << i;
    // The course is flat, midway in the gap (rows are 0.875 d apart, the gap adds 1 d; where a
    // slice misses the row below the cut, the course drops by half a row).
    const double mid = y_cut - 0.1 + 0.5 * (kS * std::sqrt(3.0) / 2 + 1.0);
    for (double y : c.course_y) EXPECT_NEAR(y, mid, 0.5);
    EXPECT_NEAR(c.y_left, c.y_right, 0.5);
    EXPECT_LT(c.y_high - c.y_low, 0.5);
}

TEST(CrackDetector, VShapedGap) {
    const auto base = lattice(80);
    // A V along the lattice's 60-degree lines would be too steep for 20 d; 31 degrees.
    auto cut = [](double x) { return 25.0 + 0.6 * std::abs(x - 0.5 * kL); };
    const auto p = split(base, cut, 1.0 * kD);
    const Crack c = find_crack(p, search());
    const double expect = cross_gap(p, [&](Vec2 r) { return r.y > cut(r.x) + 0.5; });
    EXPECT_GT(expect, 0.4);
    EXPECT_NEAR(c.opening, expect, 1e-12);
    // The walls' ends lie 0.6 x 10.1 d = 6.1 d above the centre.
    EXPECT_NEAR(0.5 * (c.y_left + c.y_right) - c.y_low, 0.6 * 0.5 * kL, 1.5);
    EXPECT_NEAR(c.x_low, 0.5 * kL, 2.0);
    EXPECT_NEAR(c.y_low, cut(0.5 * kL) + 0.5, 1.0);
}

TEST(CrackDetector, InvertedVShapedGap) {
    const auto base = lattice(80);
    auto cut = [](double x) { return 32.0 - 0.6 * std::abs(x - 0.5 * kL); };
    const auto p = split(base, cut, 1.0 * kD);
    const Crack c = find_crack(p, search());
    const double expect = cross_gap(p, [&](Vec2 r) { return r.y > cut(r.x) + 0.5; });
    EXPECT_NEAR(c.opening, expect, 1e-12);
    EXPECT_NEAR(c.y_high - 0.5 * (c.y_left + c.y_right), 0.6 * 0.5 * kL, 1.5);
    EXPECT_LT(std::min(c.x_low, kL - c.x_low), 2.0) << "lowest at a wall";
}

TEST(CrackDetector, NotchFromOneWallIsNoCrack) {
    const auto base = lattice(60);
    const double y_cut = base[600].y + 0.1;
    std::vector<Vec2> p;
    // A 2-row slot from the left wall to 70 % of the width: the right side still holds.
    for (const Vec2& r : base)
        if (!(r.x < 0.7 * kL && std::abs(r.y - y_cut) < 1.0)) p.push_back(r);
    const Crack c = find_crack(p, search());
    EXPECT_NEAR(c.opening, kS - kD, 1e-9);
}

TEST(CrackDetector, HoleInTheMiddleIsNoCrack) {
    const auto base = lattice(60);
    const Vec2 centre{0.5 * kL, base[600].y};
    std::vector<Vec2> p;
    for (const Vec2& r : base)
        if (norm(r - centre) > 5.0) p.push_back(r);
    const Crack c = find_crack(p, search());
    EXPECT_NEAR(c.opening, kS - kD, 1e-9);
}

TEST(CrackDetector, GapBelowTheRequiredDisksIsNoCrack) {
    const auto base = lattice(60);
    const double y_cut = base[39].y + 0.1; // above the second row: 39 disks below
    const auto p = split(base, [&](double) { return y_cut; }, 2.0 * kD);
    EXPECT_GT(find_crack(p, search(30, 40)).opening, 1.5) << "39 disks below are enough for 30";
    EXPECT_NEAR(find_crack(p, search(80, 40)).opening, kS - kD, 1e-9) << "but not for 80";
}

TEST(CrackDetector, WiderThanResolvedAndBadInput) {
    const auto base = lattice(40);
    const double y_cut = base[390].y + 0.1;
    const auto p = split(base, [&](double) { return y_cut; }, 5.0 * kD);
    const Crack c = find_crack(p, search());
    EXPECT_TRUE(c.wider);
    EXPECT_EQ(c.opening, 3 * kD);
    EXPECT_THROW(find_crack(p, search(p.size(), 1)), std::invalid_argument);
    CrackSearch bad = search();
    bad.diameter = 0;
    EXPECT_THROW(find_crack(p, bad), std::invalid_argument);
}

TEST(CrackDetector, GapNearTheTopNeedsEnoughDisksAbove) {
    const auto base = lattice(60);
    const double y_cut = base[base.size() - 40].y - 0.1; // below the top two rows: 39 + 20 disks above
    const auto p = split(base, [&](double) { return y_cut; }, 2.0 * kD);
    ASSERT_LT(std::count_if(p.begin(), p.end(), [&](Vec2 r) { return r.y > y_cut; }), 80);
    EXPECT_GT(find_crack(p, search(40, 30)).opening, 1.5);
    EXPECT_NEAR(find_crack(p, search(40, 80)).opening, kS - kD, 1e-9);
}

// A disk floating in a wide gap: the probe must pass it above or below, so the opening is the
// wider of the floater's two gaps (if that beats the direct gap); just below the opening the
// floater belongs to the part it is closer to.
TEST(CrackDetector, LooseDiskInTheGap) {
    const auto base = lattice(60);
    const double y_cut = base[600].y + 0.1;
    auto p = split(base, [&](double) { return y_cut; }, 2.5 * kD);
    auto above = [&](Vec2 r) { return r.y > y_cut + 1.0; };
    const double direct = cross_gap(p, above);
    const Vec2 f{0.5 * kL, y_cut + 1.5};
    double fb = INFINITY, fa = INFINITY;
    for (const Vec2& r : p) (above(r) ? fa : fb) = std::min(above(r) ? fa : fb, norm(r - f) - kD);
    p.push_back(f);
    const Crack c = find_crack(p, search());
    EXPECT_LT(std::max(fa, fb), direct) << "the floater must narrow the crack for this test";
    EXPECT_NEAR(c.opening, std::max(fa, fb), 1e-12);
    EXPECT_EQ(c.side.back(), fb < fa ? -1 : +1);
}
