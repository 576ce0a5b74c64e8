// A results folder is data, never code (issue 25): any --out is just a folder name (gnuplot runs
// without a shell), an edited figure script in a results folder runs only with `plot --edited`,
// a requested figure that is not drawn exits 4, and plot scripts name the tables of the run's
// --set values.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_support;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Every file named PWNED below `dir`.
std::vector<fs::path> pwned(const fs::path& dir) {
    std::vector<fs::path> found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename() == "PWNED") found.push_back(e.path());
    return found;
}

std::string listed(const std::vector<fs::path>& paths) {
    std::string s;
    for (const auto& p : paths) s += p.string() + "\n";
    return s;
}

// brake-failure (under a second) and `plot` into folders whose names a shell would run: a quote
// that ends shell quoting, $(...), backquotes, a newline, and a leading '-' (behind ./ and as
// --out=-...). Each renders its figure there, and nothing is run (no PWNED in the fresh cwd).
TEST(NoShell, OutWithQuotesCommandSubstitutionNewlineAndDashRendersAndRunsNothing) {
    const TempPath cwd("noshell");
    fs::create_directories(cwd);
    const std::string hostile = "o'brien';touch PWNED;'$(touch PWNED)`touch PWNED`\nx";
    for (const std::string& out : {"./-x/" + hostile, "-y" + hostile}) {
        const std::string flag = "--out=" + out;
        const Outcome run = run_argv({"brake-failure", "--quiet", flag}, cwd);
        EXPECT_EQ(run.code, 0) << run.err;
        const fs::path dir = cwd / out / "brake-failure";
        EXPECT_TRUE(fs::exists(dir / "schaefer95-fig3.png")) << out;
        fs::remove(dir / "schaefer95-fig3.png");
        const Outcome plot = run_argv({"plot", "brake-failure", flag}, cwd);
        EXPECT_EQ(plot.code, 0) << plot.err;
        EXPECT_EQ(plot.err, "");
        EXPECT_TRUE(fs::exists(dir / "schaefer95-fig3.png")) << out;
    }
    EXPECT_EQ(pwned(cwd).size(), 0u) << listed(pwned(cwd));
}

// A script edited in a results folder (say, received from someone else) is not run by a rerun
// or by `plot`: each warns once, keeps the edit as <id>.edited.gp and renders plots/<id>.gp.
// `plot --edited` runs it (then, and only then, PWNED appears: the flag works).
TEST(NoShell, EditedScriptRunsOnlyWithPlotEdited) {
    const TempPath cwd("edited");
    fs::create_directories(cwd);
    ASSERT_EQ(run_argv({"brake-failure", "--quiet", "--out", "O"}, cwd).code, 0);
    const fs::path dir = cwd / "O" / "brake-failure", gp = dir / "schaefer95-fig3.gp",
                   kept = dir / "schaefer95-fig3.edited.gp";
    const std::string attack = "system('touch PWNED')\n";
    auto edit = [&] { std::ofstream(gp, std::ios::app) << attack; };

    edit();
    Outcome o = run_argv({"brake-failure", "--quiet", "--out", "O"}, cwd);
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(contains(o.err, "O/brake-failure/schaefer95-fig3.gp was edited; rendering plots/schaefer95-fig3.gp; "
                                "`granrepro plot --edited` renders the edited one"))
        << o.err;
    EXPECT_EQ(lines(o.err), 1) << o.err;
    EXPECT_TRUE(contains(slurp(kept), attack)) << "the rerun lost the edited script";
    EXPECT_FALSE(contains(slurp(gp), attack));
    EXPECT_TRUE(fs::exists(dir / "schaefer95-fig3.png"));

    edit();
    o = run_argv({"plot", "brake-failure", "--out", "O"}, cwd);
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(contains(o.err, "schaefer95-fig3.gp was edited")) << o.err;
    EXPECT_FALSE(contains(slurp(gp), attack));
    o = run_argv({"plot", "brake-failure", "--out", "O"}, cwd);
    EXPECT_EQ(o.err, "") << "warned twice about one edit";
    EXPECT_EQ(pwned(cwd).size(), 0u) << listed(pwned(cwd));

    o = run_argv({"plot", "brake-failure", "--edited", "--out", "O"}, cwd);
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(contains(o.err, "rendering the edited script")) << o.err;
    EXPECT_EQ(pwned(cwd).size(), 1u) << "plot --edited did not render the edited script";
}

// A requested figure that is not drawn exits 4 (1 is for failed claims), naming the figure: a
// plain run and `figure` without gnuplot on PATH, `plot` with a table gone. --help says so.
TEST(FigureNotDrawn, RunFigureAndPlotExitFour) {
    const TempPath out("notdrawn");
    const std::vector<std::string> no_gnuplot{"PATH=/nonexistent"};
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"brake-failure"}, std::vector<std::string>{"figure", "schaefer95-fig3"}}) {
        std::vector<std::string> a = args;
        a.insert(a.end(), {"--quiet", "--out", out.string()});
        const Outcome o = run_argv(a, {}, no_gnuplot);
        EXPECT_EQ(o.code, 4) << o.err;
        EXPECT_TRUE(contains(o.err, "schaefer95-fig3 not drawn: gnuplot could not be started")) << o.err;
        EXPECT_TRUE(fs::exists(out / "brake-failure" / "summary.json")) << "the data are written";
        EXPECT_FALSE(fs::exists(out / "brake-failure" / "schaefer95-fig3.png"));
    }
    ASSERT_EQ(run_argv({"plot", "brake-failure", "--out", out.string()}).code, 0);
    fs::remove(out / "brake-failure" / "tables" / "fig3.tsv");
    const Outcome o = run_argv({"plot", "brake-failure", "--out", out.string()});
    EXPECT_EQ(o.code, 4) << o.err;
    EXPECT_TRUE(contains(o.err, "schaefer95-fig3 not drawn: the run made no table fig3")) << o.err;
    for (const char* sub : {"figure", "plot", "brake-failure"})
        EXPECT_TRUE(contains(run_argv({sub, "--help"}).out, "4 a figure the command was to draw was not drawn")) << sub;
}

// Fig. 8's tables are named by its t_c (run_r<r>_tc<fig8_t_c>.tsv): with --set fig8_t_c the
// figure reads the new tables (it hard-coded tc = "1e-06" before). A small run (under a second).
TEST(PlotScripts, Fig8FollowsItsTcOverride) {
    const TempPath out("fig8tc");
    const Outcome o = run_argv({"figure", "luding98-fig08", "--quiet", "--set", "fig8_t_c=2e-6", "--set", "seeds=1",
                                "--set", "cn_end=30", "--set", "fig8_r=0.9,0.5", "--set", "fig9_t_c=1e-6", "--out",
                                out.string()});
    EXPECT_LE(o.code, 1) << o.err; // so small a run fails claims (exit 1)
    const fs::path dir = out / "parameter-study";
    ASSERT_TRUE(fs::exists(dir / "tables" / "run_r0.9_tc2e-06.tsv"));
    EXPECT_TRUE(contains(slurp(dir / "luding98-fig08.gp"), "\nfig8_t_c = '2e-06'\n"));
    EXPECT_FALSE(contains(o.err, "luding98-fig08")) << o.err;
    EXPECT_TRUE(fs::exists(dir / "luding98-fig08.png"));
    const Outcome plot = run_argv({"plot", "parameter-study", "--figure", "luding98-fig08", "--out", out.string()});
    EXPECT_EQ(plot.code, 0) << plot.err;
    EXPECT_EQ(plot.err, "");
}

} // namespace
