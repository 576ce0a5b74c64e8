// Sweeps spread over MPI ranks, job-array shards and interrupted jobs give the single-process
// result bit for bit (issue 18): every table in data.h5 and every scalar but the wall-clock ones
// and resumed_points. Small grids (--set) keep each case to seconds.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <thread>

#include "cli_support.hpp"
#include "harness/experiment.hpp"
#include "io/h5_file.hpp"

namespace fs = std::filesystem;
using granrepro::H5File;
using namespace cli_support;

namespace {

// The two quick-scale sweeps of the issue, shrunk: bistable-pipe's k_N x e_N x start grid (8
// points) with short budgets, and parameter-study's (r, t_c) x seeds (6 points) on 64 disks.
// bistable-pipe at Eq. (5)'s fixed step: these tests are about the sweep, and the default wall
// rule adds the Eq. (5) fast starts as points of their own.
const std::string kBistable =
    "bistable-pipe --scale quick --set kN_list=200,2000 --set eN_list=0.8,0.95 --set budget_tcol=4000 --set window=0.1 --set t_average=0.1 "
    "--set time_step=eq5 ";
const std::string kImpact = "impact-parameter --scale quick ";
const std::string kParamStudy = "parameter-study --scale quick --set n_side=8 --set cn_end=20 --set seeds=2 "
                                "--set fig8_r=0.5 --set fig9_t_c=1e-10,1e-5 ";

// Every table dataset and every scalar (but the wall-clock ones and the resume count) of two
// result directories.
void expect_identical(const fs::path& a, const fs::path& b) {
    ASSERT_TRUE(fs::exists(a / "data.h5")) << a;
    ASSERT_TRUE(fs::exists(b / "data.h5")) << b;
    const H5File fa = H5File::open((a / "data.h5").string()), fb = H5File::open((b / "data.h5").string());
    const auto ta = fa.open_group("tables"), tb = fb.open_group("tables");
    ASSERT_EQ(ta.children(), tb.children());
    std::size_t values = 0;
    for (const auto& t : ta.children()) {
        const auto ga = ta.open_group(t), gb = tb.open_group(t);
        ASSERT_EQ(ga.children(), gb.children()) << t;
        for (const auto& c : ga.children()) {
            if (wall_clock(c)) continue; // e.g. pipe-arching's per-seed wall_seconds column
            const auto va = ga.read_dataset(c), vb = gb.read_dataset(c);
            ASSERT_EQ(va.size(), vb.size()) << t << "/" << c;
            EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << t << "/" << c;
            values += va.size();
        }
    }
    EXPECT_GT(values, 10u);
    expect_same_scalars(a, b, "resumed_points");
}

double resumed(const fs::path& dir) { return summary(dir).at("resumed_points").get<double>(); }

std::string mpirun(int ranks) {
    // CI runs as root on 2 cores: OpenMPI needs both run-as-root variables and --oversubscribe.
    return std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") + GRANREPRO_MPIEXEC +
           " --oversubscribe -np " + std::to_string(ranks) + " ";
}

// Runs `granrepro args` (exit 0 or 1: shrunk grids may fail claims) and returns OUT/<experiment>.
fs::path single(const std::string& args, const fs::path& out, const std::string& name) {
    const Outcome o = run(args + "--quiet --threads 2 --out " + out.string());
    EXPECT_LE(o.code, 1) << o.err;
    return out / name;
}

void mpi_equals_single(const std::string& args, const std::string& name, int ranks, int threads) {
    const TempPath a(name + "-single"), b(name + "-mpi" + std::to_string(ranks));
    const fs::path ra = single(args, a, name);
    const Outcome mpi = shell(mpirun(ranks) + GRANREPRO_BINARY + " " + args + "--quiet --threads " +
                              std::to_string(threads) + " --out " + b.string());
    EXPECT_LE(mpi.code, 1) << mpi.err;
    expect_identical(ra, b / name);
    EXPECT_EQ(resumed(b / name), 0);
    EXPECT_FALSE(fs::exists(b / ("." + name + ".checkpoint")));
}

} // namespace

#ifdef GRANREPRO_MPIEXEC
TEST(SweepMpi, BistablePipeThreeRanksEqualsSingleRun) { mpi_equals_single(kBistable, "bistable-pipe", 3, 1); }
TEST(SweepMpi, BistablePipeTwoRanksTwoThreadsEqualsSingleRun) { mpi_equals_single(kBistable, "bistable-pipe", 2, 2); }
TEST(SweepMpi, ParameterStudyThreeRanksEqualsSingleRun) { mpi_equals_single(kParamStudy, "parameter-study", 3, 1); }
TEST(SweepMpi, ImpactParameterThreeRanksEqualsSingleRun) { mpi_equals_single(kImpact, "impact-parameter", 3, 1); }
// `all`: one sweep after another on the same ranks. A rank released from one sweep runs ahead
// into the next one's; that must not end the sweep rank 0 is still serving (it did, before
// distributed_sweep ended every sweep on all ranks together).
TEST(SweepMpi, AllThreeRanksEqualsSingleRun) {
    const TempPath a("all-single"), b("all-mpi");
    ASSERT_LE(run("all --scale quick --quiet --threads 2 --out " + a.string()).code, 1);
    const Outcome mpi = shell(mpirun(3) + GRANREPRO_BINARY + " all --scale quick --quiet --threads 1 --out " +
                              b.string());
    EXPECT_LE(mpi.code, 1) << mpi.err;
    for (const auto& e : granrepro::experiment_registry()) {
        SCOPED_TRACE(e.name);
        expect_identical(a / e.name, b / e.name);
    }
}

// The long single runs as sweep points: ED and DSMC (cooling), the two pair rules (cluster-growth).
TEST(SweepMpi, CoolingTwoRanksEqualsSingleRun) { mpi_equals_single("cooling --scale quick ", "cooling", 2, 1); }
TEST(SweepMpi, ClusterGrowthTwoRanksEqualsSingleRun) {
    mpi_equals_single("cluster-growth --scale quick ", "cluster-growth", 2, 1);
}

// A job killed after 3 of its 8 points (every rank ends, as when a node is lost) leaves those 3 in
// the checkpoint; the same command again computes only the other 5 and equals an uninterrupted run.
TEST(SweepMpi, KilledJobResumesOnlyMissingPoints) {
    const TempPath a("kill-single"), b("kill-mpi");
    const fs::path ra = single(kBistable, a, "bistable-pipe");
    const std::string cmd = mpirun(2) + GRANREPRO_BINARY + " " + kBistable + "--quiet --out " + b.string();
    EXPECT_GT(shell("GRANREPRO_INTERRUPT_AFTER_POINTS=3 " + cmd).code, 1);
    EXPECT_FALSE(fs::exists(b / "bistable-pipe"));
    EXPECT_LE(shell(cmd).code, 1);
    EXPECT_EQ(resumed(b / "bistable-pipe"), 3);
    expect_identical(ra, b / "bistable-pipe");
}
#endif

// SIGTERM once the first point is saved (one thread): no further point is handed out, the run
// exits 143 naming the points left, and the same command again computes only those and equals an
// uninterrupted run. (Before, the sweep went on computing until the watcher's grace ran out.)
TEST(SweepShards, SigtermStopsHandingOutPointsAndTheRerunResumes) {
    const TempPath a("term-single"), b("term-sweep");
    const TempPath err("term-err");
    const fs::path ra = single(kBistable, a, "bistable-pipe");
    const std::string args = kBistable + "--quiet --threads 1 --out " + b.string();
    const std::string wait_then_term = std::string(GRANREPRO_BINARY) + " " + args + " 2> " + err.string() +
                                       " & p=$!; for i in $(seq 1200); do ls " + b.string() +
                                       "/.bistable-pipe.checkpoint/sweep-*/*.json > /dev/null 2>&1 && break; "
                                       "sleep 0.05; done; kill -TERM $p; wait $p";
    EXPECT_EQ(shell("sh -c '" + wait_then_term + "'").code, 143);
    const std::string text = slurp(err);
    EXPECT_NE(text.find("interrupted by SIGTERM; "), std::string::npos) << text;
    EXPECT_NE(text.find("sweep points left for the rerun"), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(b / "bistable-pipe"));
    long saved = 0;
    for (const auto& d : fs::directory_iterator(b / ".bistable-pipe.checkpoint"))
        for (const auto& f : fs::directory_iterator(d.path())) saved += f.path().extension() == ".json";
    EXPECT_GE(saved, 1);
    EXPECT_LT(saved, 8);
    EXPECT_LE(run(args).code, 1);
    EXPECT_EQ(resumed(b / "bistable-pipe"), saved);
    expect_identical(ra, b / "bistable-pipe");
}

// SIGTERM while the first point is still far from its end (a 12 s point, signalled 0.5 s in): the
// engine loop stops the point after its 1 s pause, and the sweep leaves it for the rerun, ending
// with the sweep's own line, whatever the machine's speed or load (before, this one timing gave
// "inside a long engine loop" and the sweep's count of points left was lost).
TEST(SweepShards, SigtermInsideALongPointLeavesItForTheRerun) {
    const TempPath b("term-long"), err("term-long-err");
    const std::string args = "bistable-pipe --scale quick --set kN_list=200 --set eN_list=0.95 --set budget_tcol=100000 "
                             "--set window=0.1 --set t_average=0.1 --set time_step=eq5 --quiet --threads 1 --out " + b.string();
    const std::string wait_then_term = std::string(GRANREPRO_BINARY) + " " + args + " 2> " + err.string() +
                                       " & p=$!; for i in $(seq 1200); do ls -d " + b.string() +
                                       "/.bistable-pipe.checkpoint/sweep-* > /dev/null 2>&1 && break; "
                                       "sleep 0.05; done; sleep 0.5; kill -TERM $p; wait $p";
    EXPECT_EQ(shell("sh -c '" + wait_then_term + "'").code, 143);
    const std::string text = slurp(err);
    EXPECT_NE(text.find("interrupted by SIGTERM; 2 of 2 sweep points left for the rerun"), std::string::npos) << text;
    EXPECT_EQ(text.find("inside a long engine loop"), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(b / "bistable-pipe"));
}

// --points 1/2 and 2/2 into one --out, then gather: the single run's result. Gather before the
// second shard refuses (exit 2) naming the missing points.
TEST(SweepShards, ShardsPlusGatherEqualSingleRun) {
    const TempPath a("shard-single"), b("shards");
    const fs::path ra = single(kBistable, a, "bistable-pipe");
    const std::string base = kBistable + "--quiet --out " + b.string() + " ";
    ASSERT_EQ(run(base + "--points 1/2").code, 0);
    EXPECT_FALSE(fs::exists(b / "bistable-pipe"));
    const Outcome early = run("gather " + base);
    EXPECT_EQ(early.code, 2);
    EXPECT_NE(early.err.find("4 points missing: "), std::string::npos) << early.err;
    ASSERT_EQ(run(base + "--points 2/2").code, 0);
    ASSERT_LE(run("gather " + base).code, 1);
    EXPECT_EQ(resumed(b / "bistable-pipe"), 8);
    expect_identical(ra, b / "bistable-pipe");
}

// Two shards at once into one --out (as two array tasks on a shared file system), the second one
// taken from Slurm's job-array variables; then gather.
TEST(SweepShards, ConcurrentShardsFromSlurmEqualSingleRun) {
    const TempPath a("conc-single"), b("conc-shards");
    const fs::path ra = single(kParamStudy, a, "parameter-study");
    const std::string base = kParamStudy + "--quiet --out " + b.string() + " ";
    Outcome o1, o2;
    std::thread t1([&] { o1 = run(base, "SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=2"); });
    std::thread t2([&] { o2 = run(base, "SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=2"); });
    t1.join();
    t2.join();
    ASSERT_EQ(o1.code, 0) << o1.err;
    ASSERT_EQ(o2.code, 0) << o2.err;
    EXPECT_FALSE(fs::exists(b / "parameter-study"));
    ASSERT_LE(run("gather " + base).code, 1);
    EXPECT_EQ(resumed(b / "parameter-study"), 6);
    expect_identical(ra, b / "parameter-study");
}

TEST(SweepShards, BadPointsAndNonSweepingExperimentsAreInputErrors) {
    const TempPath b("bad-points");
    for (const char* p : {"0/2", "3/2", "1/0", "1-2", "1/2x"}) {
        const Outcome o = run(kBistable + "--quiet --points " + p + " --out " + b.string());
        EXPECT_EQ(o.code, 2) << p;
        EXPECT_NE(o.err.find("--points"), std::string::npos) << o.err;
    }
    const Outcome g = run("gather brake-failure --out " + b.string());
    EXPECT_EQ(g.code, 2);
    EXPECT_NE(g.err.find("no distributed sweep"), std::string::npos) << g.err;
}
