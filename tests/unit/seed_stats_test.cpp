// Statistics over seeds (src/analysis/seed_stats.hpp) on samples whose answers are known by hand:
// odd and even n, n = 1, empty, and both NaN policies.
#include "analysis/seed_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;

namespace {

constexpr double nan = NAN, inf = INFINITY;

TEST(SeedStats, MedianOddEvenOneEmpty) {
    EXPECT_EQ(median({3, 1, 2}), 2);
    EXPECT_EQ(median({4, 1, 3, 2}), 2.5); // mean of the two middle values
    EXPECT_EQ(median({7}), 7);
    EXPECT_TRUE(std::isnan(median({})));
}

TEST(SeedStats, MedianSkipDropsNonFinite) {
    EXPECT_EQ(median({nan, 5, 1, inf, 3}), 3);   // {1, 3, 5}
    EXPECT_EQ(median({nan, 4, -inf, 2}), 3);     // {2, 4}
    EXPECT_TRUE(std::isnan(median({nan, nan})));  // nothing left
}

TEST(SeedStats, MedianCensoredCountsNanAsNever) {
    // NaN = +inf: {1, 2, inf} has median 2, where skipping would give 1.5.
    EXPECT_EQ(median({nan, 2, 1}, NonFinite::censored), 2);
    EXPECT_EQ(median({nan, 3, 1, nan, 2}, NonFinite::censored), 3); // {1, 2, 3, inf, inf}
    // The median lands on "never": NaN, also half-way between a value and never.
    EXPECT_TRUE(std::isnan(median({nan, nan, 1}, NonFinite::censored)));
    EXPECT_TRUE(std::isnan(median({nan, 1}, NonFinite::censored)));
    EXPECT_TRUE(std::isnan(median({}, NonFinite::censored)));
}

TEST(SeedStats, QuantileInterpolatesAndCensors) {
    const std::vector<double> v{4, 1, 3, 2, 5};
    EXPECT_EQ(quantile(v, 0.0), 1);
    EXPECT_EQ(quantile(v, 0.25), 2);
    EXPECT_EQ(quantile(v, 1.0), 5);
    EXPECT_DOUBLE_EQ(quantile({1, 2}, 0.25), 1.25);
    EXPECT_EQ(quantile({nan, 1, 2, 3}, 0.25, NonFinite::censored), 1.75); // {1, 2, 3, inf}
    EXPECT_TRUE(std::isnan(quantile({nan, 1, 2, 3}, 0.75, NonFinite::censored)));
    EXPECT_EQ(quantile({nan, 1, 2, 3}, 0.75), 2.5); // skip: {1, 2, 3}
    EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(SeedStats, MeanSdSem) {
    // {2, 4, 4, 4, 5, 5, 7, 9}: mean 5, sum of squares about it 32, sd sqrt(32/7).
    const MeanSd m = mean_sd({2, 4, 4, 4, 5, 5, 7, 9});
    EXPECT_EQ(m.n, 8);
    EXPECT_DOUBLE_EQ(m.mean, 5);
    EXPECT_DOUBLE_EQ(m.sd, std::sqrt(32.0 / 7.0));
    EXPECT_DOUBLE_EQ(m.sem, std::sqrt(32.0 / 7.0) / std::sqrt(8.0));
    const MeanSd odd = mean_sd({1, 2, 6}); // mean 3, squares 4 + 1 + 9 = 14
    EXPECT_DOUBLE_EQ(odd.mean, 3);
    EXPECT_DOUBLE_EQ(odd.sd, std::sqrt(7.0));
}

TEST(SeedStats, MeanSdSmallAndNonFinite) {
    const MeanSd one = mean_sd({3.5});
    EXPECT_EQ(one.n, 1);
    EXPECT_EQ(one.mean, 3.5);
    EXPECT_TRUE(std::isnan(one.sd));
    EXPECT_TRUE(std::isnan(one.sem));
    const MeanSd none = mean_sd({});
    EXPECT_EQ(none.n, 0);
    EXPECT_TRUE(std::isnan(none.mean));
    const MeanSd skipped = mean_sd({nan, 1, inf, 3, -inf}); // {1, 3}
    EXPECT_EQ(skipped.n, 2);
    EXPECT_DOUBLE_EQ(skipped.mean, 2);
    EXPECT_DOUBLE_EQ(skipped.sd, std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(skipped.sem, 1);
}

// A censored sample (a departure that never happened) has no mean; a complete one is unaffected.
TEST(SeedStats, MeanSdCensoredHasNoMeanWithAMissingValue) {
    const MeanSd censored = mean_sd({1, nan, 3}, NonFinite::censored);
    EXPECT_EQ(censored.n, 3);
    EXPECT_TRUE(std::isnan(censored.mean));
    EXPECT_TRUE(std::isnan(censored.sd));
    EXPECT_TRUE(std::isnan(mean_sd({1, inf}, NonFinite::censored).mean));
    const MeanSd complete = mean_sd({1, 2, 6}, NonFinite::censored);
    EXPECT_DOUBLE_EQ(complete.mean, 3);
    EXPECT_DOUBLE_EQ(complete.sd, std::sqrt(7.0));
}

} // namespace
