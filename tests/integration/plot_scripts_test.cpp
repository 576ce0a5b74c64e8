// The figure scripts put no path into a shell (issue 25): a results folder whose name a shell would
// run ($(...), backquotes, quotes, a newline) is only ever a folder name to them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_support;

namespace {

// `s` as one word of a shell command line (cli_support's shell() runs one; gnuplot is no granrepro
// for run_argv).
std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::vector<fs::path> pwned(const fs::path& dir) {
    std::vector<fs::path> found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename() == "PWNED") found.push_back(e.path());
    return found;
}

// Every experiment whose script listed tables or read values through gnuplot's system() (all but
// impact-parameter and emergency-brake), cut to a few seconds, plus brake-failure: run from a
// fresh directory into an --out with quotes, $(touch PWNED), backquotes, a space and a newline.
// Then each emitted script is rendered by gnuplot given its full path (`gnuplot path/to/<id>.gp`,
// as its header offers): the path is then in datadir, which the scripts' system("ls ".datadir...)
// handed to /bin/sh. Every figure is drawn without a warning, and no PWNED appears.
TEST(ScriptsWithoutShell, FiguresRenderFromAFolderNamedLikeShellCode) {
    const TempPath cwd("noshellgp");
    fs::create_directories(cwd);
    // Two quotes, so that a shell given the path would not stop at a syntax error but run it.
    const std::string hostile = "it's o'brien $(touch PWNED)\n`touch PWNED`";
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
        {"brake-failure", {}},
        {"parameter-study", {"--set", "seeds=1", "--set", "cn_end=30", "--set", "fig8_r=0.9,0.5", "--set", "fig9_t_c=1e-6"}},
        {"bistable-pipe", {"--set", "kN_list=2000", "--set", "eN_list=0.95", "--set", "budget_tcol=2000", "--set",
                           "window=0.05", "--set", "t_average=0.05"}},
        {"cooling", {"--set", "n_side=20", "--set", "t_end=0.5", "--set", "snapshot_times=0,0.05,0.5", "--set",
                     "bd_windows=0,0.1,0.5"}},
        {"cluster-growth", {"--set", "n_side=16", "--set", "box_over_d=28", "--set", "cn_end=100", "--set",
                            "tc_compare_until=0", "--set", "snapshot_times=0.64"}},
        {"pipe-arching", {"--set", "n_seeds=1", "--set", "n_particles=400"}},
    };
    for (const auto& [experiment, sets] : runs) {
        std::vector<std::string> args{experiment, "--quiet", "--out", hostile};
        args.insert(args.end(), sets.begin(), sets.end());
        const Outcome o = run_argv(args, cwd);
        EXPECT_LE(o.code, 1) << experiment << ": " << o.err; // runs this small may fail claims
        EXPECT_EQ(o.err, "") << experiment;
    }
    int figures = 0;
    for (const auto& [experiment, sets] : runs)
        for (const auto& e : fs::directory_iterator(cwd / hostile / experiment)) {
            if (e.path().extension() != ".gp") continue;
            fs::path png = e.path();
            png.replace_extension(".png");
            ASSERT_TRUE(fs::remove(png)) << png.filename() << " was not drawn by the run";
            const Outcome o = shell("cd " + quoted(cwd.string()) + " && gnuplot " + quoted(e.path().string()));
            EXPECT_EQ(o.code, 0) << e.path().filename() << ": " << o.err;
            EXPECT_EQ(o.out + o.err, "") << e.path().filename();
            EXPECT_TRUE(fs::exists(png)) << png.filename();
            ++figures;
        }
    EXPECT_EQ(figures, 13); // every figure of the six experiments
    const auto found = pwned(cwd);
    EXPECT_EQ(found.size(), 0u) << (found.empty() ? "" : found.front().string());
}

} // namespace
