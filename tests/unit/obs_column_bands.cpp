// ColumnBands (src/observables/column_bands.hpp): Lagrangian bands of a falling column, checked
// on hand-made frames where every mean is known.
#include "observables/column_bands.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace granrepro;

TEST(ObsColumnBands, BandsFollowTheInitialHeightsAndSplitWallDisks) {
    // Four disks: two start low (y0 = 0.2, 0.7), two high (y0 = 5.1, 5.6); bands of 1.
    const std::vector<double> y0 = {0.2, 0.7, 5.1, 5.6};
    ColumnBands b(y0, 1.0, 0.6, 10.0);
    // In the frame the low pair has moved far above the high pair: groups still follow y0.
    const std::vector<Vec2> pos = {{0.5, 30.0}, {5.0, 32.0}, {9.5, 1.0}, {5.0, 3.0}};
    const std::vector<Vec2> vel = {{0, -1.0}, {0, -3.0}, {0, -2.0}, {0, -4.0}};
    const std::vector<double> jy = {1.0, 0.0, 0.5, 0.0};
    b.add_frame(0.01, pos, vel, jy);
    ASSERT_EQ(b.frames(), 1u);
    EXPECT_DOUBLE_EQ(b.time(0), 0.01);

    const auto low = b.group(0, 0.0, 1.0);
    EXPECT_EQ(low.n, 2);
    EXPECT_EQ(low.n_wall, 1) << "x = 0.5 is within 0.6 of the left wall";
    EXPECT_DOUBLE_EQ(low.y, 31.0);
    EXPECT_DOUBLE_EQ(low.vy, -2.0);
    EXPECT_DOUBLE_EQ(low.vy_wall, -1.0);
    EXPECT_DOUBLE_EQ(low.vy_inner, -3.0);
    EXPECT_DOUBLE_EQ(low.jy, 1.0);

    const auto high = b.group(0, 5.0, 6.0);
    EXPECT_EQ(high.n, 2);
    EXPECT_EQ(high.n_wall, 1) << "x = 9.5 is within 0.6 of the right wall";
    EXPECT_DOUBLE_EQ(high.vy_wall, -2.0);
    EXPECT_DOUBLE_EQ(high.vy_inner, -4.0);
    EXPECT_DOUBLE_EQ(high.jy, 0.5);

    const auto all = b.group(0, -1.0, 10.0);
    EXPECT_EQ(all.n, 4);
    EXPECT_DOUBLE_EQ(all.vy, -2.5);
    EXPECT_DOUBLE_EQ(all.jy, 1.5);

    const auto none = b.group(0, 2.0, 4.0);
    EXPECT_EQ(none.n, 0);
    EXPECT_TRUE(std::isnan(none.y));
    EXPECT_TRUE(std::isnan(none.vy_wall));
}

TEST(ObsColumnBands, RejectsMismatchedFrames) {
    ColumnBands b({0.0, 1.0}, 1.0, 0.5, 5.0);
    EXPECT_THROW(b.add_frame(0.0, {{1, 1}}, {{0, 0}, {0, 0}}, {0, 0}), std::invalid_argument);
    EXPECT_THROW(ColumnBands({}, 1.0, 0.5, 5.0), std::invalid_argument);
    EXPECT_THROW(b.group(3, 0, 1), std::out_of_range);
}
