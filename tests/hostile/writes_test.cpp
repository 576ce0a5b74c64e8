// Writes and reads outside the named folder (issue 40, §2 and §3): a results folder may hold
// symbolic links planted to lead a write (plot's figure, log and scripts, the lock file, the
// checkpoint folder) or a read (a script copied into the results) outside it. Each is refused with
// exit 2 naming the entry, and the sentinel tree beside the folder stays as it was. Also: export
// onto its own folder, report --to a link, and --out that can never hold results.
#include "hostile_support.hpp"

#include <fcntl.h>
#include <fstream>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace hostile;

namespace {

const std::string kFigure = "schaefer95-fig3"; // brake-failure's one figure
const std::string kLinkNote = "symbolic link";

// `plot brake-failure` on a folder whose `entry` is a link to `target`: refused, naming the
// entry; the link is left as it was (not replaced, not followed).
void expect_plot_refuses(const Crafted& c, const std::string& entry, const fs::path& target) {
    const fs::path link = c.dir() / entry;
    fs::remove(link);
    fs::create_symlink(target, link);
    expect_refusal(run_argv({"plot", "brake-failure", "--out", c.out.string()}), 2, {link.string(), kLinkNote});
    EXPECT_TRUE(fs::is_symlink(link));
    c.expect_sentinel_unchanged();
}

// The shard of impact-parameter's sweep that this suite computes (1 of 8: about a second).
Outcome shard_run(const fs::path& out) {
    return run_argv({"impact-parameter", "--quiet", "--scale", "quick", "--points", "1/8", "--out", out.string()});
}

} // namespace

// The figure: gnuplot's `set output` would overwrite the victim with a PNG.
TEST(HostileWritesPlot, ALinkedPngIsRefused) {
    const Crafted c("plot-png");
    expect_plot_refuses(c, kFigure + ".png", c.sentinel.victim());
}

TEST(HostileWritesPlot, ALinkedPdfIsRefused) {
    const Crafted c("plot-pdf");
    expect_plot_refuses(c, kFigure + ".pdf", c.sentinel.victim());
}

// gnuplot's log (opened for its stderr) would truncate the victim.
TEST(HostileWritesPlot, ALinkedGnuplotLogIsRefused) {
    const Crafted c("plot-log");
    expect_plot_refuses(c, kFigure + ".gnuplot.log", c.sentinel.victim());
}

// The emitted script: the victim was overwritten, its old content copied to .edited.gp.
TEST(HostileWritesPlot, ALinkedScriptIsRefusedAndNotCopied) {
    const Crafted c("plot-gp");
    expect_plot_refuses(c, kFigure + ".gp", c.sentinel.secret());
    EXPECT_FALSE(fs::exists(fs::symlink_status(c.dir() / (kFigure + ".edited.gp"))));
}

TEST(HostileWritesPlot, ALinkedEditedScriptIsRefused) {
    const Crafted c("plot-edited-gp");
    expect_plot_refuses(c, kFigure + ".edited.gp", c.sentinel.secret());
    expect_refusal(run_argv({"plot", "brake-failure", "--edited", "--out", c.out.string()}), 2,
                   {(c.dir() / (kFigure + ".edited.gp")).string(), kLinkNote});
}

// A table gnuplot reads: the secret would be drawn into the figure.
TEST(HostileWritesPlot, ALinkedTableIsRefused) {
    const Crafted c("plot-table");
    fs::path table;
    for (const auto& e : fs::directory_iterator(c.dir() / "tables")) table = e.path();
    ASSERT_FALSE(table.empty());
    expect_plot_refuses(c, fs::relative(table, c.dir()).string(), c.sentinel.secret());
}

// A rerun reads the old folder's scripts (an edited one is kept): never through a link, and
// refused before anything is computed.
TEST(HostileWritesRun, ALinkedScriptInTheFolderARunReplacesIsRefused) {
    const Crafted c("run-gp");
    const fs::path link = c.dir() / (kFigure + ".gp");
    fs::remove(link);
    fs::create_symlink(c.sentinel.secret(), link);
    expect_refusal(run_argv({"brake-failure", "--quiet", "--scale", "quick", "--out", c.out.string()}), 2,
                   {link.string(), kLinkNote});
    EXPECT_TRUE(fs::is_symlink(link));
    c.expect_sentinel_unchanged();
}

// OUT/<experiment> a link: a run, plot and report would read (and a run replace) through it.
TEST(HostileWritesRun, ALinkedResultsFolderIsRefused) {
    const Crafted c("run-linked-dir");
    const fs::path out2 = c.base / "out2";
    fs::create_directories(out2);
    fs::create_symlink(c.dir(), out2 / "brake-failure");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"brake-failure", "--quiet", "--scale", "quick", "--out", out2.string()},
          {"plot", "brake-failure", "--out", out2.string()},
          {"report", "--out", out2.string(), "--to", (c.base / "rep").string()}})
        expect_refusal(run_argv(args), 2, {(out2 / "brake-failure").string(), kLinkNote});
    EXPECT_TRUE(fs::is_symlink(out2 / "brake-failure"));
    EXPECT_FALSE(fs::exists(c.base / "rep"));
    c.expect_sentinel_unchanged();
}

// The lock file gets our PID: through a link the victim's content was replaced by it.
TEST(HostileWritesLock, ALinkedLockFileIsRefused) {
    const Crafted c("lock");
    const fs::path lock = c.out / ".brake-failure.lock";
    fs::remove(lock);
    fs::create_symlink(c.sentinel.victim(), lock);
    expect_refusal(run_argv({"brake-failure", "--quiet", "--scale", "quick", "--out", c.out.string()}), 2,
                   {lock.string(), kLinkNote});
    expect_refusal(run_argv({"plot", "brake-failure", "--out", c.out.string()}), 2, {lock.string(), kLinkNote});
    EXPECT_TRUE(fs::is_symlink(lock));
    c.expect_sentinel_unchanged();
}

// A hard link reaches the victim as surely (a tarball may hold one).
TEST(HostileWritesLock, AHardLinkedLockFileIsRefused) {
    const Crafted c("lock-hard");
    const fs::path lock = c.out / ".brake-failure.lock";
    fs::remove(lock);
    fs::create_hard_link(c.sentinel.victim(), lock);
    expect_refusal(run_argv({"plot", "brake-failure", "--out", c.out.string()}), 2, {lock.string(), "hard links"});
    c.expect_sentinel_unchanged();
}

// `plot` takes the output lock: beside a run (or another plot) of the same folder it is refused
// at once, not left to collide with the run's commit.
TEST(HostileWritesLock, PlotTakesTheOutputLock) {
    const Crafted c("plot-lock");
    const fs::path lock = c.out / ".brake-failure.lock";
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    expect_refusal(run_argv({"plot", "brake-failure", "--out", c.out.string()}), 2, {"is being written by"});
    ::close(fd);
    EXPECT_EQ(run_argv({"plot", "brake-failure", "--out", c.out.string()}).code, 0);
}

// The checkpoint folder linked to a folder elsewhere: point files were written there and left.
TEST(HostileWritesCheckpoint, ALinkedCheckpointFolderIsRefused) {
    const Crafted c("checkpoint-dir");
    const fs::path link = c.out / ".impact-parameter.checkpoint";
    fs::create_symlink(c.sentinel.victim_dir(), link);
    expect_refusal(shard_run(c.out), 2, {link.string(), kLinkNote});
    EXPECT_TRUE(fs::is_symlink(link));
    c.expect_sentinel_unchanged();
}

// A sweep's folder inside the checkpoint folder, linked elsewhere: the same.
TEST(HostileWritesCheckpoint, ALinkedSweepFolderInsideIsRefused) {
    const Crafted c("checkpoint-inside");
    ASSERT_EQ(shard_run(c.out).code, 0); // a shard keeps its point files for `gather`
    fs::path sweep;
    for (const auto& e : fs::directory_iterator(c.out / ".impact-parameter.checkpoint"))
        if (e.is_directory()) sweep = e.path();
    ASSERT_FALSE(sweep.empty());
    fs::remove_all(sweep);
    fs::create_symlink(c.sentinel.victim_dir(), sweep);
    expect_refusal(shard_run(c.out), 2, {sweep.string(), kLinkNote});
    c.expect_sentinel_unchanged();
}

// report --to a link: the report was written, then exit 3 "the previous report is untouched" and
// a .l.partial-PID link left behind. Now nothing is written.
TEST(HostileWritesReport, ReportToALinkIsRefusedBeforeAnythingIsWritten) {
    const Crafted c("report-to-link");
    const fs::path link = c.base / "l";
    fs::create_symlink(c.sentinel.victim_dir(), link);
    expect_refusal(run_argv({"report", "--out", c.out.string(), "--to", link.string()}), 2,
                   {"report --to " + link.string(), kLinkNote});
    const fs::path default_to = c.out / "report";
    fs::create_symlink(c.sentinel.victim_dir(), default_to);
    expect_refusal(run_argv({"report", "--out", c.out.string()}), 2, {default_to.string(), kLinkNote});
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(c.base)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left.size(), 3u) << "only out, sentinel and l expected"; // no .l.partial-PID
    c.expect_sentinel_unchanged();
}

// A folder named "-res" is a folder: it reached the Python side as an option ("--results").
TEST(HostileWritesReport, AResultsFolderNamedLikeAnOptionIsAFolder) {
    const Crafted c("report-dash");
    fs::rename(c.out, c.base / "-res");
    const Outcome o = run_argv({"report", "--out=-res", "--to=rep"}, c.base);
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err.find("--results"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::exists(c.base / "rep" / "index.html"));
}

// The claims file of a report killed by SIGKILL is removed by the next report; a live
// process's is kept.
TEST(HostileWritesReport, AKilledReportsClaimsFileIsRemovedByTheNext) {
    const Crafted c("report-stale");
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0); // its PID is now free
    const fs::path tmp = fs::temp_directory_path();
    const fs::path stale = tmp / ("granrepro-report-" + std::to_string(child) + ".json");
    const fs::path live = tmp / ("granrepro-report-" + std::to_string(::getpid()) + ".json");
    std::ofstream(stale) << "{}";
    std::ofstream(live) << "{}";
    EXPECT_EQ(run_argv({"report", "--out", c.out.string(), "--to", (c.base / "rep").string()}).code, 0);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(live));
    fs::remove(live);
    fs::remove(stale);
}

// export --to the folder it reads replaced the full data.h5 with the compact copy (exit 0).
TEST(HostileWritesExport, ExportOntoItsOwnFolderIsRefused) {
    const Crafted c("export-self");
    auto digest = [&] { return granrepro::fnv1a64(slurp(c.dir() / "data.h5")); };
    const std::uint64_t before = digest();
    const fs::path alias = c.base / "alias"; // a link the user made to the same folder
    fs::create_symlink(c.out, alias);
    for (const fs::path& to : {c.out, c.out / ".." / "out", alias})
        expect_refusal(run_argv({"export", "brake-failure", "--out", c.out.string(), "--to", to.string()}), 2,
                       {"--to " + to.string(), "same folder"});
    EXPECT_EQ(digest(), before) << "data.h5 replaced";
    c.expect_sentinel_unchanged();
}

// A file, or /proc/self, as --out: refused at load, --dry-run included (they passed it, then
// the run failed).
TEST(HostileWritesOut, AnOutThatCannotHoldResultsIsRefusedAtLoad) {
    const Crafted c("out-file");
    const fs::path afile = c.base / "afile";
    std::ofstream(afile) << "a file, not a folder\n";
    for (const std::string& out : {afile.string(), std::string("/proc/self"), (afile / "sub").string()})
        for (const bool dry : {true, false}) {
            std::vector<std::string> args{"brake-failure", "--quiet", "--scale", "quick", "--out", out};
            if (dry) args.push_back("--dry-run");
            expect_refusal(run_argv(args), 2, {"--out " + out});
        }
    EXPECT_EQ(slurp(afile), "a file, not a folder\n");
    c.expect_sentinel_unchanged();
}

// export --to a folder that is itself untrusted (the documented use is --to paper_figures): a
// linked experiment folder there is refused; a link planted under the temporary name of the
// compact copy is removed, not written through.
TEST(HostileWritesExport, ExportNeverWritesThroughALinkInTheDestination) {
    const Crafted c("export-dest");
    const fs::path to = c.base / "to";
    fs::create_directories(to);
    fs::create_symlink(c.sentinel.victim_dir(), to / "brake-failure");
    expect_refusal(run_argv({"export", "brake-failure", "--out", c.out.string(), "--to", to.string()}), 2,
                   {(to / "brake-failure").string(), kLinkNote});
    fs::remove(to / "brake-failure");
    fs::create_directories(to / "brake-failure");
    fs::create_symlink(c.sentinel.victim(), to / "brake-failure" / ".data.h5.partial");
    const Outcome o = run_argv({"export", "brake-failure", "--out", c.out.string(), "--to", to.string()});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_FALSE(fs::is_symlink(to / "brake-failure" / "data.h5"));
    c.expect_sentinel_unchanged();
}
