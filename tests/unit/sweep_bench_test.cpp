// `granrepro bench sweep`'s projection: the makespan of handing points out longest first, and
// the run.log lines it reads the point costs from.
#include "bench/sweep_bench.hpp"
#include "saved_states.hpp"

#include <fstream>
#include <gtest/gtest.h>

using namespace granrepro;

TEST(SweepBench, MakespanOfLongestFirst) {
    const std::vector<double> cost = {2, 3, 2, 3, 2};
    EXPECT_DOUBLE_EQ(projected_makespan(cost, 1), 12.0); // one rank: the sum
    EXPECT_DOUBLE_EQ(projected_makespan(cost, 2), 7.0);  // 3+2+2 and 3+2
    EXPECT_DOUBLE_EQ(projected_makespan(cost, 3), 5.0);  // 3+2, 3+2, 2
    EXPECT_DOUBLE_EQ(projected_makespan(cost, 256), 3.0); // bounded by the longest point
}

TEST(SweepBench, ReadsPointCostsAndWallTimeFromRunLog) {
    const test::TempDir dir;
    const auto file = dir.path / "run.log";
    {
        std::ofstream out(file);
        out << "[      0.0 s] parameter k_N = 2000 [N/m]\n"
            << "[      1.5 s] sweep bistable-pipe: point 3 cost 1.25 CPU s (rank 0)\n"
            << "[      2.5 s] sweep bistable-pipe: point 0 cost 2.5e-01 CPU s (rank 1)\n"
            << "[      9.0 s] run finished: wall time 8.5 s\n";
        std::ofstream(file.string() + "2") << "[ 9.0 s] run finished: wall time 8.5 s, CPU 2.5 s\n";
    }
    const SweepCosts c = read_sweep_costs(file);
    std::filesystem::remove(file);
    ASSERT_EQ(c.cost.size(), 2u);
    EXPECT_EQ(c.cost[0], 1.25);
    EXPECT_EQ(c.cost[1], 0.25);
    EXPECT_EQ(c.wall, 8.5);
    EXPECT_EQ(c.serial(), 7.0);                   // 8.5 s wall, 1.5 s in points
    EXPECT_DOUBLE_EQ(c.projected(2), 7.0 + 1.25); // the longer point on one rank, the other beside it
    EXPECT_ANY_THROW(read_sweep_costs(file)); // gone: an input error naming it
    // No sweep: all of it serial, from the CPU time where the log has it (the rest was other processes).
    const SweepCosts s = read_sweep_costs(file.string() + "2");
    EXPECT_TRUE(s.cost.empty());
    EXPECT_EQ(s.serial(), 2.5);
    EXPECT_EQ(s.projected(64), 2.5);
}
