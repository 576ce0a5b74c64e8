// Mid-run checkpoints as a user meets them: a run killed after a checkpoint (simulated with
// GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS) leaves no results but a checkpoint; the same command
// again resumes from it, and its results equal an uninterrupted run's bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "cli_support.hpp"
#include "io/h5_file.hpp"

namespace fs = std::filesystem;
using granrepro::H5File;

using cli_support::fresh;
using cli_support::Outcome;
using cli_support::run;

namespace {

nlohmann::json scalars(const fs::path& summary) {
    std::ifstream in(summary);
    return nlohmann::json::parse(in).at("scalars");
}

} // namespace

TEST(CliResume, ClusterGrowthResumesBitIdentical) {
    const fs::path a = fresh("cg-a"), b = fresh("cg-b");
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
    const auto sa = scalars(a / "cluster-growth" / "summary.json"), sb = scalars(b / "cluster-growth" / "summary.json");
    ASSERT_EQ(sa.size(), sb.size());
    int compared = 0;
    for (auto it = sa.begin(); it != sa.end(); ++it) {
        const std::string& k = it.key();
        if (k == "wall_seconds_run" || k == "wall_seconds_other_rule" || k == "events_per_second" || k == "collisions_per_second") continue;
        EXPECT_EQ(it.value().dump(), sb.at(k).dump()) << k;
        ++compared;
    }
    EXPECT_GT(compared, 20);
    // Tables from before and after the interruption.
    const H5File fa = H5File::open((a / "cluster-growth" / "data.h5").string());
    const H5File fb = H5File::open((b / "cluster-growth" / "data.h5").string());
    for (const char* ds : {"tables/energy/t", "tables/energy/K_over_K0", "tables/energy/elastic_C_over_N",
                           "tables/instants/C_over_N", "tables/instants/chi", "tables/instants/B",
                           "tables/instants/tail_fraction", "tables/pnc_0/P"}) {
        const auto va = fa.read_dataset(ds), vb = fb.read_dataset(ds);
        ASSERT_EQ(va.size(), vb.size()) << ds;
        EXPECT_GT(va.size(), 3u) << ds;
        EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << ds;
    }
    fs::remove_all(a);
    fs::remove_all(b);
}
