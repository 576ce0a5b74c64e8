// Mid-run checkpoints as a user meets them: a run killed after a checkpoint (simulated with
// GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS) leaves no results but a checkpoint; the same command
// again resumes from it, and its results equal an uninterrupted run's bit for bit.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_support;

TEST(CliResume, ClusterGrowthResumesBitIdentical) {
    const TempPath a("cg-a"), b("cg-b");
    const std::string args = "cluster-growth --set n_side=32 --set cn_end=300 --seed 3 ";
    // A reduced run: some of its claims fail (exit 1); the datasets are what is compared.
    ASSERT_LE(run(args + "--quiet --out " + a.string()).code, 1);

    const Outcome killed = run(args + "--quiet --checkpoint-interval 0 --out " + b.string(),
                               "GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS=20");
    EXPECT_NE(killed.code, 0);
    EXPECT_NE(killed.err.find("interrupted after checkpoint 20"), std::string::npos) << killed.err;
    EXPECT_FALSE(fs::exists(b / "cluster-growth"));
    ASSERT_TRUE(fs::exists(b / ".cluster-growth.checkpoint"));

    const Outcome resumed = run(args + "--checkpoint-interval 0 --out " + b.string());
    ASSERT_LE(resumed.code, 1) << resumed.err;
    EXPECT_NE(resumed.err.find("resuming from checkpoint"), std::string::npos) << resumed.err;
    EXPECT_FALSE(fs::exists(b / ".cluster-growth.checkpoint")); // removed once the results are written

    // Every scalar except the wall-clock ones.
    expect_same_scalars(a / "cluster-growth", b / "cluster-growth", "", 20);
    // Tables from before and after the interruption.
    expect_same_datasets(a / "cluster-growth" / "data.h5", b / "cluster-growth" / "data.h5",
                         {"tables/energy/t", "tables/energy/K_over_K0", "tables/energy/elastic_C_over_N",
                          "tables/instants/C_over_N", "tables/instants/chi", "tables/instants/B",
                          "tables/instants/tail_fraction", "tables/pnc_0/P"},
                         3);
}
