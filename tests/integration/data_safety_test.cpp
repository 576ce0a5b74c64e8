// Nothing lost, nothing wrong, whatever happens (issue 20 items 1-3 and 8, issue 19 item 6): a
// write that fails (full disk) exits 3 with one line and leaves the previous results untouched;
// a kill inside the commit leaves complete results; a second run on the same --out is refused;
// SIGTERM saves a final checkpoint and the rerun gives the uninterrupted results; `check` refuses
// damaged results files; damaged sweep-point files are recomputed.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "cli_support.hpp"
#include "core/input_error.hpp"
#include "core/stable_hash.hpp"
#include "harness/experiment.hpp"
#include "harness/sweep_checkpoint.hpp"
#include "io/output_lock.hpp"
#include "io/staged_directory.hpp"
#include "io/write_error.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace granrepro;
using namespace cli_support;

namespace {

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Hidden folders and files that a run of `exp` may leave beside OUT/<exp> (the lock file is
// meant to stay).
std::vector<std::string> leftovers(const fs::path& out, const std::string& exp) {
    std::vector<std::string> found;
    if (!fs::exists(out)) return found;
    for (const auto& e : fs::directory_iterator(out)) {
        const std::string n = e.path().filename().string();
        if (n.rfind("." + exp + ".partial-", 0) == 0 || n.rfind("." + exp + ".old-", 0) == 0) found.push_back(n);
    }
    return found;
}

const std::string kSmallRun = "emergency-brake --quiet --set n_vy=25 --set n_positions=3 ";
const std::string kExp = "emergency-brake";

std::string shim_env(const std::string& vars) {
    // ASan (in the sanitizer build) wants its runtime first; the shim is preloaded before it.
    return "ASAN_OPTIONS=verify_asan_link_order=0 LD_PRELOAD=" + std::string(GRANREPRO_ENOSPC_SHIM) + " " + vars;
}

// A granrepro process in the background; stderr to `err`.
pid_t spawn(const std::string& args, const fs::path& err, const std::string& env = "") {
    const std::string cmd = env + " exec " + std::string(GRANREPRO_BINARY) + " " + args + " > /dev/null 2> " + err.string();
    const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
    pid_t pid = -1;
    if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) return -1;
    return pid;
}

// Exit code (128 + signal if killed by one).
int wait_for(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

template <class Pred>
bool wait_until(Pred pred, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (pred()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return pred();
}

} // namespace

// ---- stable fingerprints --------------------------------------------------------------------

TEST(StableHash, Fnv1a64MatchesThePublishedVectors) {
    // Test vectors of the FNV reference (http://www.isthe.com/chongo/src/fnv/test_fnv.c).
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
    EXPECT_EQ(hex64(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
}

// ---- sweep-point files ------------------------------------------------------------------------

TEST(SweepCheckpoint, DamagedPointFilesAreRecomputedNotTrusted) {
    const TempPath work("sweep-points");
    const ParameterSet params = ParameterSet::load(fs::path(GRANREPRO_SOURCE_DIR) / "experiments" / "pipe-arching.toml",
                                                   Scale::Quick);
    const RunContext ctx{params, Scale::Quick, 7, 1, true, work, 60.0};
    const nlohmann::json value = {{"t", {0.5, 1.25}}, {"n", 3}};
    fs::path dir;
    {
        SweepCheckpoint c(ctx);
        PointCost cost;
        cost.cpu_s = 1.5;
        cost.wall_s = 2.5;
        c.save(0, value, cost);
        c.save(1, nlohmann::json{{"t", {2.0}}, {"n", 1}}, {});
        const auto loaded = c.load(0);
        ASSERT_TRUE(loaded.has_value());
        EXPECT_EQ(loaded->value, value);
        EXPECT_EQ(loaded->cost.cpu_s, 1.5); // the recorded cost comes back with the resumed point
        EXPECT_EQ(loaded->cost.wall_s, 2.5);
        EXPECT_EQ(c.resumed(), 1);
        for (const auto& e : fs::directory_iterator(work)) dir = e.path();
    }
    ASSERT_FALSE(dir.empty());
    const std::string good0 = slurp(dir / "0.json");
    const std::string damaged[] = {"{}", "garbage", "[1,2,3]", good0.substr(0, good0.size() / 2),
                                   slurp(dir / "1.json") /* another point's file */,
                                   [&] {
                                       auto j = nlohmann::json::parse(good0);
                                       j["value"]["n"] = 4; // edited value, stale hash
                                       return j.dump();
                                   }()};
    for (const auto& text : damaged) {
        put(dir / "0.json", text);
        SweepCheckpoint c(ctx);
        EXPECT_FALSE(c.load(0).has_value()) << text;
        EXPECT_EQ(c.resumed(), 0);
    }
    put(dir / "0.json", good0);
    EXPECT_EQ(SweepCheckpoint(ctx).load(0)->value, value);
    // A version 1 file (before costs were recorded) still resumes, its cost unknown.
    auto v1 = nlohmann::json::parse(good0);
    v1["schema_version"] = 1;
    v1.erase("cost");
    put(dir / "0.json", v1.dump());
    const auto old = SweepCheckpoint(ctx).load(0);
    ASSERT_TRUE(old.has_value());
    EXPECT_EQ(old->value, value);
    EXPECT_EQ(old->cost.cpu_s, -1.0);
}

// ---- the commit ---------------------------------------------------------------------------

TEST(StagedDirectory, FallbackCommitReplacesAndLeavesNothing) {
    const TempPath dir("fallback");
    fs::create_directories(dir / "exp");
    put(dir / "exp" / "data.txt", "old");
    setenv("GRANREPRO_TEST_COMMIT_NO_EXCHANGE", "1", 1);
    {
        StagedDirectory s(dir / "exp");
        put(s.path() / "data.txt", "new");
        s.commit();
    }
    unsetenv("GRANREPRO_TEST_COMMIT_NO_EXCHANGE");
    EXPECT_EQ(slurp(dir / "exp" / "data.txt"), "new");
    EXPECT_TRUE(leftovers(dir, "exp").empty());
    {
        StagedDirectory s(dir / "exp"); // the exchange
        put(s.path() / "data.txt", "newer");
        s.commit();
    }
    EXPECT_EQ(slurp(dir / "exp" / "data.txt"), "newer");
    EXPECT_TRUE(leftovers(dir, "exp").empty());
}

TEST(StagedDirectory, LeftoversOfKilledRunsAreCleanedAndAnOnlyOldCopyRestored) {
    const TempPath dir("leftovers");
    // A kill between the two renames of a fallback commit: only the old copy and the new staging.
    fs::create_directories(dir / ".exp.old-999991");
    put(dir / ".exp.old-999991" / "data.txt", "old results");
    fs::create_directories(dir / ".exp.partial-999991");
    fs::create_directories(dir / ".exp.partial-999992");
    fs::create_directories(dir / ".other.partial-999993"); // another experiment's: not ours to touch
    clean_staging_leftovers(dir / "exp", true);
    EXPECT_EQ(slurp(dir / "exp" / "data.txt"), "old results");
    EXPECT_TRUE(leftovers(dir, "exp").empty());
    EXPECT_TRUE(fs::exists(dir / ".other.partial-999993"));
    // With results in place, an old copy is garbage.
    fs::create_directories(dir / ".exp.old-999994");
    clean_staging_leftovers(dir / "exp", true);
    EXPECT_TRUE(leftovers(dir, "exp").empty());
    EXPECT_EQ(slurp(dir / "exp" / "data.txt"), "old results");
    // Temporaries of checkpoints.
    fs::create_directories(dir / "ck" / "sweep-1");
    put(dir / "ck" / "sweep-1" / ".3.json.tmp-999995", "torn");
    put(dir / "ck" / "run-1-ed.h5.partial-999996", "torn");
    put(dir / "ck" / "sweep-1" / "2.json", "kept");
    clean_temporary_leftovers(dir / "ck");
    EXPECT_FALSE(fs::exists(dir / "ck" / "sweep-1" / ".3.json.tmp-999995"));
    EXPECT_FALSE(fs::exists(dir / "ck" / "run-1-ed.h5.partial-999996"));
    EXPECT_TRUE(fs::exists(dir / "ck" / "sweep-1" / "2.json"));
}

// ---- the lock ---------------------------------------------------------------------------------

TEST(OutputLock, ExclusiveRefusesAnyOtherSharedCoexist) {
    const TempPath dir("lock");
    fs::create_directories(dir);
    {
        const OutputLock a(dir, "exp");
        try {
            const OutputLock b(dir, "exp");
            ADD_FAILURE() << "a second exclusive lock was granted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find((dir / "exp").string() + " is being written by pid " +
                                                 std::to_string(getpid())),
                      std::string::npos)
                << e.what();
        }
        EXPECT_THROW(OutputLock(dir, "exp", OutputLock::Mode::Shared), InputError);
        EXPECT_NO_THROW(OutputLock(dir, "other")); // per experiment
    }
    {
        const OutputLock s1(dir, "exp", OutputLock::Mode::Shared);
        EXPECT_NO_THROW(OutputLock(dir, "exp", OutputLock::Mode::Shared)); // shards side by side
        EXPECT_THROW(OutputLock(dir, "exp"), InputError);                 // but never beside a whole run
    }
    EXPECT_NO_THROW(OutputLock(dir, "exp")); // released with its holder
}

// ---- the command line -------------------------------------------------------------------------

// Writes that fail as on a full disk (an LD_PRELOAD shim): exit 3, one line naming the file as the
// user knows it, the previous results byte for byte as they were, nothing hidden left behind.
TEST(DataSafety, FailedWriteExitsThreeAndKeepsThePreviousResults) {
    const TempPath out("enospc");
    ASSERT_EQ(run(kSmallRun + "--seed 1 --out " + out.string()).code, 0);
    const fs::path dir = out / kExp;
    const std::string summary = slurp(dir / "summary.json"), data = slurp(dir / "data.h5");
    struct Case {
        std::string env, file, reason;
    };
    const Case cases[] = {
        {"GRANREPRO_SHIM_FAIL_WRITE=summary.json", "summary.json", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_WRITE=summary.json GRANREPRO_SHIM_FAIL_AFTER=4096", "summary.json", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_WRITE=data.h5", "data.h5", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_WRITE=data.h5 GRANREPRO_SHIM_FAIL_AFTER=20000", "data.h5", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_WRITE=.tsv", "tables/", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_WRITE=.gp", ".gp", "no space left on device"},
        {"GRANREPRO_SHIM_FAIL_FSYNC=summary.json", "summary.json", "input/output error"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.env);
        const Outcome o = run(kSmallRun + "--seed 2 --out " + out.string(), shim_env(c.env));
        expect_one_line_exit(o, 3, {"granrepro: error: " + c.reason + " writing " + dir.string() + "/", c.file});
        EXPECT_EQ(o.err.find("HDF5-DIAG"), std::string::npos) << o.err;
        EXPECT_EQ(slurp(dir / "summary.json"), summary);
        EXPECT_EQ(slurp(dir / "data.h5"), data);
        EXPECT_TRUE(leftovers(out, kExp).empty());
    }
}

// A checkpoint that cannot be written whole is never renamed into place: the last good one stays.
TEST(DataSafety, FailedCheckpointWriteNeverReplacesTheLastGoodOne) {
    const TempPath out("enospc-ck");
    const std::string args = "cooling --scale quick --set n_side=30 --quiet --threads 1 --checkpoint-interval 0 ";
    // The first checkpoints fit, a later one does not.
    const Outcome o = run(args + "--out " + out.string(),
                          shim_env("GRANREPRO_SHIM_FAIL_WRITE=.cooling.checkpoint GRANREPRO_SHIM_FAIL_AFTER=2000000"));
    expect_one_line_exit(o, 3, {"no space left on device writing " + (out / ".cooling.checkpoint").string()});
    EXPECT_EQ(o.err.find(".partial-"), std::string::npos) << "names the temporary, not the checkpoint: " << o.err;
    int good = 0;
    for (const auto& e : fs::directory_iterator(out / ".cooling.checkpoint")) {
        if (e.is_directory()) continue; // the sweep's folder of finished points (distributed_sweep)
        EXPECT_EQ(e.path().extension(), ".h5") << "a temporary was left: " << e.path();
        EXPECT_EQ(H5File::open(e.path().string()).read_string_attr("schema"), "granrepro-cooling-run") << e.path();
        ++good;
    }
    EXPECT_GE(good, 1) << "the test needs a checkpoint that fitted";
    EXPECT_FALSE(fs::exists(out / "cooling"));
}

// A real full disk where this machine allows a small tmpfs (user and mount namespaces).
TEST(DataSafety, FullTmpfsKeepsThePreviousResults) {
    const TempPath base("tmpfs");
    fs::create_directories(base / "mnt");
    const fs::path dir = base / "mnt" / kExp;
    // One run's results fit in 256 KiB; a second copy beside them (staged, then exchanged) does not.
    const std::string mnt = (base / "mnt").string(), bin = GRANREPRO_BINARY;
    put(base / "full.sh",
        "mount -t tmpfs -o size=512k tmpfs '" + mnt + "' || exit 77\n" +
        bin + " " + kSmallRun + "--seed 1 --out '" + mnt + "' > /dev/null 2>&1 || exit 78\n" +
        "cp '" + (dir / "summary.json").string() + "' '" + (base / "before.json").string() + "'\n" +
        "dd if=/dev/zero of='" + mnt + "/filler' bs=4k count=16 2> /dev/null\n" +
        bin + " " + kSmallRun + "--seed 2 --out '" + mnt + "' > /dev/null 2> '" + (base / "err").string() + "'\n" +
        "echo $? > '" + (base / "rc").string() + "'\n" +
        "cp '" + (dir / "summary.json").string() + "' '" + (base / "after.json").string() + "'\n" +
        "ls -A '" + mnt + "' > '" + (base / "listing").string() + "'\n");
    const int code = shell("unshare -rm sh '" + (base / "full.sh").string() + "'").code;
    if (code == 77 || !fs::exists(base / "rc")) {
        GTEST_SKIP() << "cannot mount a tmpfs here (unshare -rm / mount -t tmpfs)";
    }
    ASSERT_NE(code, 78) << "the first run did not fit in the tmpfs";
    expect_one_line_exit({std::stoi(slurp(base / "rc")), slurp(base / "err"), ""}, 3,
                   {"no space left on device writing " + dir.string() + "/"});
    EXPECT_EQ(slurp(base / "after.json"), slurp(base / "before.json"));
    const std::string listing = slurp(base / "listing");
    EXPECT_EQ(listing.find(".partial-"), std::string::npos) << listing;
}

// A kill inside the commit: after the exchange the new results are complete in place; with the
// two-rename fallback, between the renames, the next run restores the old copy. Either way the
// next run leaves no hidden folder.
TEST(DataSafety, KillInTheCommitWindowLosesNoResults) {
    const TempPath out("commit-kill");
    const fs::path dir = out / kExp;
    ASSERT_EQ(run(kSmallRun + "--seed 1 --out " + out.string()).code, 0);
    const std::string first = slurp(dir / "summary.json");

    Outcome o = run(kSmallRun + "--seed 2 --out " + out.string(), "GRANREPRO_TEST_KILL_IN_COMMIT=after-exchange");
    EXPECT_EQ(o.code, 128 + SIGKILL) << "killed";
    ASSERT_TRUE(fs::exists(dir / "summary.json"));
    EXPECT_EQ(summary(dir).at("seed"), 2);
    EXPECT_EQ(leftovers(out, kExp).size(), 1u) << "the old copy, for the next run to delete";
    EXPECT_EQ(run("check " + kExp + " --out " + out.string()).code, 0);

    ASSERT_EQ(run(kSmallRun + "--seed 1 --out " + out.string()).code, 0);
    EXPECT_TRUE(leftovers(out, kExp).empty());
    // The same results again (summary.json also holds the wall time, whose printed length varies).
    const auto again = summary(dir);
    const auto before = nlohmann::json::parse(first);
    EXPECT_EQ(again.at("seed"), 1);
    EXPECT_EQ(again.at("scalars"), before.at("scalars"));

    o = run(kSmallRun + "--seed 3 --out " + out.string(),
            "GRANREPRO_TEST_COMMIT_NO_EXCHANGE=1 GRANREPRO_TEST_KILL_IN_COMMIT=between-renames");
    EXPECT_EQ(o.code, 128 + SIGKILL) << "killed";
    EXPECT_FALSE(fs::exists(dir)) << "the window the exchange closes";
    const std::string old_results = slurp(out / leftovers(out, kExp).at(0) / "summary.json") +
                                    slurp(out / leftovers(out, kExp).at(1) / "summary.json");
    EXPECT_NE(old_results.find("\"seed\": 1"), std::string::npos);
    // The next run restores the old copy first (it says so), then replaces it as usual.
    o = run("emergency-brake --set n_vy=25 --set n_positions=3 --seed 4 --out " + out.string());
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.err.find("restored " + dir.string()), std::string::npos) << o.err;
    EXPECT_EQ(summary(dir).at("seed"), 4);
    EXPECT_TRUE(leftovers(out, kExp).empty());
}

// Two runs on one --out: the second is refused at once (exit 2, one line naming the first's
// pid) and the first completes undisturbed.
TEST(DataSafety, ConcurrentRunOnTheSameOutIsRefused) {
    const TempPath out("concurrent");
    const TempPath err("concurrent-err");
    const pid_t first = spawn("cooling --scale quick --set n_side=30 --quiet --out " + out.string(), err);
    ASSERT_GT(first, 0);
    ASSERT_TRUE(wait_until([&] { return !leftovers(out, "cooling").empty(); }, 60)) << slurp(err);
    kill(first, SIGSTOP); // holds the lock for as long as the second needs, whatever the machine's speed
    const Outcome second = run("cooling --scale quick --set n_side=30 --quiet --seed 8 --out " + out.string());
    kill(first, SIGCONT);
    expect_one_line_exit(second, 2, {(out / "cooling").string() + " is being written by pid " + std::to_string(first)});
    EXPECT_LE(wait_for(first), 1) << slurp(err);
    EXPECT_TRUE(fs::exists(out / "cooling" / "summary.json"));
    EXPECT_EQ(summary(out / "cooling").at("seed"), 1);
    EXPECT_TRUE(leftovers(out, "cooling").empty());
}

// SIGTERM during a quick cooling run: the running jobs save a final checkpoint at their next
// sample time and stop (none runs to its end: no results are committed), no staging folder is
// left, exit 143 with one line; the rerun resumes and its datasets equal an uninterrupted run's
// bit for bit.
TEST(DataSafety, SigtermWritesAFinalCheckpointAndTheRerunIsIdentical) {
    const TempPath a("term-a"), b("term-b");
    const TempPath err("term-err");
    const std::string args = "cooling --scale quick --set n_side=40 --quiet --threads 2 ";
    ASSERT_LE(run(args + "--out " + a.string()).code, 1);

    // SIGTERM once the run is inside its sweep (its first checkpoint is on disk); before that,
    // cooling prepares its initial states, which no checkpoint covers.
    const pid_t pid = spawn(args + "--checkpoint-interval 0 --out " + b.string(), err);
    ASSERT_GT(pid, 0);
    ASSERT_TRUE(wait_until([&] { return h5_files(b / ".cooling.checkpoint") > 0; }, 120)) << slurp(err);
    kill(pid, SIGTERM);
    const Outcome term{wait_for(pid), slurp(err), ""};
    ASSERT_FALSE(fs::exists(b / "cooling")) << "the run ended before the signal; rc " << term.code << ": " << term.err;
    expect_one_line_exit(term, 143, {"interrupted by SIGTERM; final checkpoint written"});
    EXPECT_TRUE(leftovers(b, "cooling").empty()) << "staging folder left";
    EXPECT_GE(h5_files(b / ".cooling.checkpoint"), 1);

    const Outcome resumed = run("cooling --scale quick --set n_side=40 --threads 2 --checkpoint-interval 0 --out " + b.string());
    ASSERT_LE(resumed.code, 1) << resumed.err;
    EXPECT_NE(resumed.err.find("resuming"), std::string::npos) << resumed.err;
    EXPECT_FALSE(fs::exists(b / ".cooling.checkpoint"));
    EXPECT_TRUE(leftovers(b, "cooling").empty());
    expect_same_datasets(a / "cooling" / "data.h5", b / "cooling" / "data.h5",
                         {"tables/energy_ed/K_over_K0", "tables/energy_ed/C_over_N", "tables/energy_dsmc/K_over_K0",
                          "tables/impact_parameter_ed/P_t2", "tables/gr_ed/g_t5", "tables/sk_dsmc/S_t5",
                          "scalars/ed_C_over_N_end", "scalars/dsmc_over_ed_end"});
}

// `check` validates what it reads: exit 2 and one line naming the file and what is wrong.
TEST(DataSafety, CheckRefusesDamagedResultsFiles) {
    const TempPath out("check-damaged");
    ASSERT_EQ(run(kSmallRun + "--out " + out.string()).code, 0);
    const fs::path dir = out / kExp;
    const std::string summary = slurp(dir / "summary.json"), data = slurp(dir / "data.h5");
    ASSERT_EQ(run("check " + kExp + " --out " + out.string()).code, 0);
    struct Case {
        std::string text, must_mention;
    };
    const Case cases[] = {
        {"[1,2,3]", "a JSON object expected, found an array"},
        {"{\"scale\":5}", "'scale' must be \"quick\" or \"paper\", found 5"},
        {"{\"scale\":\"bogus\"}", "'scale' must be \"quick\" or \"paper\", found \"bogus\""},
        {"{\"scale\":\"quick\"}", "has no 'scalars' object"},
        {"{\"scale\":\"quick\",\"scalars\":{\"v_crit_vx0.3\":\"x\"}}", "scalar 'v_crit_vx0.3' must be a number or null"},
        {"garbage", "not valid JSON"},
        {summary.substr(0, summary.size() / 2), "not valid JSON"},
    };
    for (const auto& c : cases) {
        put(dir / "summary.json", c.text);
        const Outcome o = run("check " + kExp + " --out " + out.string());
        SCOPED_TRACE(c.text);
        expect_one_line_exit(o, 2, {(dir / "summary.json").string() + ": ", c.must_mention});
        EXPECT_EQ(o.err.find("--scale"), std::string::npos) << "blames a flag nobody passed: " << o.err;
    }
    put(dir / "summary.json", summary);
    for (const std::size_t keep : {data.size() / 2, data.size() - 100}) {
        put(dir / "data.h5", data.substr(0, keep));
        SCOPED_TRACE(keep);
        expect_one_line_exit(run("check " + kExp + " --out " + out.string()), 2, {(dir / "data.h5").string() + ": damaged"});
    }
    put(dir / "data.h5", data);
    EXPECT_EQ(run("check " + kExp + " --out " + out.string()).code, 0);
}

namespace {
// Opens a result file for writing, as someone editing it by hand with the HDF5 API would.
H5Object open_for_edit(const fs::path& h5) { return H5Object(H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), &H5Fclose); }

void overwrite_dataset(const fs::path& h5, const std::string& path, const std::vector<double>& values) {
    const H5Object f = open_for_edit(h5);
    ASSERT_GE(f.id(), 0);
    const H5Object d(H5Dopen2(f.id(), path.c_str(), H5P_DEFAULT), &H5Dclose);
    ASSERT_GE(d.id(), 0) << path;
    ASSERT_GE(H5Dwrite(d.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << path;
}

void overwrite_root_attr(const fs::path& h5, const std::string& name, const std::string& value) {
    const H5Object f = open_for_edit(h5);
    ASSERT_GE(H5Adelete(f.id(), name.c_str()), 0) << name;
    f.attr(name, value);
}
} // namespace

// Issue 25 item 5: summary.json and data.h5 vouch for each other. An edit of either one is exit 2
// naming the file (and the field where one is compared), never quick data judged as paper scale
// or paper-only claims hidden as skipped.
TEST(DataSafety, CheckRefusesOneSidedEdits) {
    const TempPath out("check-one-sided");
    const std::string check = "check brake-failure --out " + out.string();
    ASSERT_EQ(run("brake-failure --quiet --out " + out.string()).code, 0);
    const fs::path dir = out / "brake-failure", json_file = dir / "summary.json", h5 = dir / "data.h5";
    const std::string summary_text = slurp(json_file), data = slurp(h5);
    const nlohmann::json summary = nlohmann::json::parse(summary_text);
    ASSERT_EQ(summary.at("schema_version"), 3);
    ASSERT_TRUE(summary.at("data_h5_hash").at("tables").contains("fig3"));
    ASSERT_TRUE(summary.at("data_h5_hash").contains("points"));
    const Outcome clean = run(check);
    ASSERT_EQ(clean.code, 0) << clean.err;
    EXPECT_EQ(clean.out.find("unverified"), std::string::npos) << clean.out;
    EXPECT_EQ(clean.out.find("--set"), std::string::npos) << "a default run shows no overrides: " << clean.out;

    // The same content in another layout is the same summary.
    put(json_file, summary.dump() + "\n");
    EXPECT_EQ(run(check).code, 0);

    auto edited = [&](const char* field, const nlohmann::json& value) {
        nlohmann::json j = summary;
        j[field] = value;
        return j.dump(2);
    };
    struct Case {
        std::string text;
        std::vector<std::string> must_mention;
    };
    nlohmann::json scalars = summary.at("scalars");
    scalars["e_N_eq4"] = scalars.at("e_N_eq4").get<double>() * 1.01;
    nlohmann::json no_hash = summary;
    no_hash.erase("data_h5_hash");
    const Case cases[] = {
        {edited("scale", "paper"), {"'scale' is \"paper\" but data.h5 beside it has \"quick\""}},
        {edited("seed", 2), {"'seed' is 2 but data.h5 beside it has 1"}},
        {edited("code_version", "0.0+forged"), {"'code_version'"}},
        {edited("scalars", scalars), {"content differs from the hash data.h5"}},
        {edited("overridden_parameters", {{"mu", "0.9"}}), {"content differs from the hash data.h5"}},
        {no_hash.dump(2), {"content differs from the hash data.h5"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.text.substr(0, 200));
        put(json_file, c.text);
        std::vector<std::string> parts = c.must_mention;
        parts.push_back(json_file.string() + ": ");
        expect_one_line_exit(run(check), 2, parts);
    }
    put(json_file, summary_text);

    // data.h5 edited with the HDF5 API: a table value, a scalar, the scale.
    std::vector<double> dvy = H5File::open(h5.string()).read_dataset("tables/fig3/dvy");
    dvy[3] *= 1.5;
    overwrite_dataset(h5, "tables/fig3/dvy", dvy);
    expect_one_line_exit(run(check), 2, {h5.string() + ": ", "table 'fig3' differs from the hash summary.json recorded"});
    put(h5, data);
    overwrite_dataset(h5, "scalars/e_N_eq4", {summary.at("scalars").at("e_N_eq4").get<double>() * 1.01});
    expect_one_line_exit(run(check), 2, {h5.string() + ": ", "scalars differ from the hash summary.json recorded"});
    put(h5, data);
    overwrite_root_attr(h5, "scale", "paper");
    expect_one_line_exit(run(check), 2, {json_file.string() + ": ", "'scale' is \"quick\" but data.h5 beside it has \"paper\""});
    put(h5, data);
    // Schema 3: a stored sweep point's outcome edited (what `verify` compares with).
    {
        const H5Object f = open_for_edit(h5);
        const H5Object g(H5Gopen2(f.id(), "points", H5P_DEFAULT), &H5Gclose);
        const auto bytes = g.read_bytes("records");
        nlohmann::json records = nlohmann::json::parse(std::string(bytes.begin(), bytes.end()));
        ASSERT_FALSE(records.empty());
        records[0]["outcome"] = {{"edited", 1}};
        ASSERT_GE(H5Ldelete(g.id(), "records", H5P_DEFAULT), 0);
        g.compressed_text("records", records.dump());
    }
    expect_one_line_exit(run(check), 2, {h5.string() + ": ", "stored sweep points (/points) differ from the hash"});
    put(h5, data);
    EXPECT_EQ(run(check).code, 0);

    // A compact copy leaves tables out; what it keeps still verifies.
    const TempPath exported("check-one-sided-export");
    ASSERT_EQ(run("export brake-failure --max-table-values 100 --out " + out.string() + " --to " + exported.string()).code, 0);
    EXPECT_EQ(run("check brake-failure --out " + exported.string()).code, 0);
}

// A modified run's table names its overrides, in the run's output and in `check`'s.
TEST(DataSafety, CheckTableNamesTheOverrides) {
    const TempPath out("check-overrides");
    const Outcome ran = run(kSmallRun + "--out " + out.string());
    ASSERT_LE(ran.code, 1) << ran.err;
    const std::string line = "parameters changed from the defaults (--set): n_positions=3 n_vy=25\n";
    EXPECT_NE(ran.out.find(line), std::string::npos) << ran.out;
    const Outcome checked = run("check " + kExp + " --out " + out.string());
    EXPECT_NE(checked.out.find("check " + kExp + " (quick scale)\n  " + line), std::string::npos) << checked.out;
}

// Issue 25 item 6: previous results that cannot be removed stay as .<exp>.partial-PID; the run
// says so in one line (and the next run, which cannot remove them either, once more), and a run
// that can remove them cleans them without a word.
TEST(DataSafety, UnremovableOldResultsAreNamedOnce) {
    const TempPath out("undeletable");
    ASSERT_EQ(run("brake-failure --quiet --out " + out.string()).code, 0);
    put(out / "brake-failure" / "undeletable", "x");
    const std::string env = shim_env("GRANREPRO_SHIM_FAIL_UNLINK=undeletable");
    const Outcome first = run("brake-failure --quiet --out " + out.string(), env);
    ASSERT_EQ(first.code, 0) << first.err;
    const auto left = leftovers(out, "brake-failure");
    ASSERT_EQ(left.size(), 1u);
    expect_one_line_exit(first, 0, {"warning: cannot remove the previous results", left[0], "remove it by hand"});
    const Outcome second = run("brake-failure --quiet --out " + out.string(), env);
    expect_one_line_exit(second, 0, {"warning: cannot remove what an earlier run left", left[0]});
    const Outcome third = run("brake-failure --quiet --out " + out.string());
    EXPECT_EQ(third.code, 0);
    EXPECT_EQ(third.err, "");
    EXPECT_TRUE(leftovers(out, "brake-failure").empty());
}

// A folder name that is not UTF-8 (Latin-1 "\xff") used to end the run with exit 1 and a JSON
// library message when summary.json was written; the text keeps U+FFFD in its place and checks.
TEST(DataSafety, OutPathThatIsNotUtf8IsWrittenAndChecks) {
    const TempPath out("latin1-\xff");
    const Outcome ran = run("brake-failure --quiet --out " + out.string());
    EXPECT_EQ(ran.code, 0) << ran.err;
    EXPECT_NE(summary(out / "brake-failure").at("command_line").get<std::string>().find("\xef\xbf\xbd"), std::string::npos);
    EXPECT_EQ(run("check brake-failure --out " + out.string()).code, 0);
}
