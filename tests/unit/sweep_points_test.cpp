// The results' record of sweep points (data.h5 /points): the whole run's totals from the points'
// recorded costs, and the digest of large arrays in a compact copy (io/result_writer).
#include <gtest/gtest.h>

#include "io/result_writer.hpp"

using namespace granrepro;

namespace {
SweepPoint point(long i, bool resumed, double cpu, double wall, double start, const std::string& part, int rank = 0) {
    SweepPoint p;
    p.index = i;
    p.resumed = resumed;
    p.cost = {cpu, wall, start, part, rank};
    return p;
}
} // namespace

// A run resumed twice: the earlier invocations' wall time is the union of their points' spans
// (two concurrent shards count once); CPU adds the resumed points' and other ranks' costs.
TEST(SweepPoints, RunTotalsIncludeResumedPoints) {
    SweepPoints pts;
    pts.points = {point(0, true, 10, 12, 1000, "a"), point(1, true, 20, 25, 1010, "a"),  // part a: 1000..1035
                  point(2, true, 5, 30, 1020, "b"),                                      // shard b: 1020..1050
                  point(3, true, 7, 8, 2000, "c"),                                       // later: 2000..2008
                  point(4, false, 3, 4, 3000, "now"), point(5, false, 2, 2, 3000, "now", 1)}; // rank 1's
    Provenance prov;
    run_totals(prov, pts, 100.0, 50.0);
    EXPECT_DOUBLE_EQ(prov.total_wall_time_s, 100.0 + 50.0 + 8.0);
    EXPECT_DOUBLE_EQ(prov.total_cpu_time_s, 50.0 - 3.0 + (10 + 20 + 5 + 7 + 3 + 2));
    EXPECT_EQ(prov.resumed_points, 4);
    EXPECT_EQ(prov.points_without_cost, 0);
    pts.points.push_back(point(6, true, -1, -1, -1, "")); // from a point file before costs
    run_totals(prov, pts, 100.0, 50.0);
    EXPECT_EQ(prov.points_without_cost, 1);
}

TEST(SweepPoints, CompactOutcomeDigestsOnlyLargeNumberArrays) {
    nlohmann::json big = nlohmann::json::array();
    for (int i = 0; i < 12; ++i) big.push_back(i * 0.5);
    const nlohmann::json o = {{"a", 1.5}, {"small", {1, 2, 3}}, {"nested", {{{"big", big}}}}, {"big", big}};
    bool changed = false;
    const nlohmann::json c = compact_outcome(o, 10, &changed);
    EXPECT_TRUE(changed);
    EXPECT_EQ(c["a"], 1.5);
    EXPECT_EQ(c["small"], o["small"]);
    EXPECT_EQ(c["big"]["omitted_values"], 12);
    EXPECT_EQ(c["nested"][0]["big"], c["big"]);
    nlohmann::json other = o;
    other["big"][11] = 99.0;
    EXPECT_NE(compact_outcome(other, 10)["big"]["fnv1a64"], c["big"]["fnv1a64"]) << "a changed value changes the digest";
    // Positions, an array of [x, y] pairs, count as numbers too.
    nlohmann::json pairs = nlohmann::json::array();
    for (int i = 0; i < 12; ++i) pairs.push_back({i * 0.5, 1.0});
    EXPECT_EQ(compact_outcome(nlohmann::json{{"position", pairs}}, 10)["position"]["omitted_values"], 12);
    bool unchanged = false;
    EXPECT_EQ(compact_outcome(o, 100, &unchanged), o);
    EXPECT_FALSE(unchanged);
}
