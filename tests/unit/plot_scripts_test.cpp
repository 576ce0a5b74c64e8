// The figure scripts in plots/ run no shell and read no code (issue 25): gnuplot's system(),
// backquotes, `!`, pipes and load/call would hand a results folder's path (in datadir) to /bin/sh
// or run a file as a script. What they need to know of the folder, the emitted header tells them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <unistd.h>

#include "harness/experiment.hpp"
#include "harness/plotter.hpp"

using namespace granrepro;
namespace fs = std::filesystem;

namespace {

std::string text_of(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(PlotScripts, CallNoShellAndLoadNoFile) {
    // Comment lines are skipped (gnuplot runs nothing in them); every other line is checked whole.
    static const std::regex forbidden(
        R"(\bsystem\b|`|(^|[;{])\s*!|\b(load|call|shell|import)\b|["']\s*[<|])");
    int scripts = 0;
    for (const auto& e : fs::directory_iterator(project_root() / "plots")) {
        if (e.path().extension() != ".gp") continue;
        ++scripts;
        std::istringstream in(text_of(e.path()));
        int n = 0;
        for (std::string line; std::getline(in, line);) {
            ++n;
            const auto b = line.find_first_not_of(" \t");
            if (b == std::string::npos || line[b] == '#') continue;
            EXPECT_FALSE(std::regex_search(line, forbidden)) << e.path().filename().string() << ":" << n << ": " << line;
        }
    }
    EXPECT_GE(scripts, 17); // every figure's script was read
}

// The header lists the tables in numeric order (k_N = 200 before 2000 before 30000, t_c = 1e-06
// before 0.001), which fig6, 13 and 14 draw in; a name that could end gnuplot's quoted string,
// or a file that is no table, is not listed.
TEST(PlotScripts, EmittedHeaderListsTheTablesInNumericOrder) {
    const fs::path dir = fs::temp_directory_path() / ("granrepro-tables-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "sub.tsv");
    for (const char* name : {"steady_k2000", "steady_k30000", "steady_k200", "run_r0.6_tc0.001", "run_r0.6_tc1e-06",
                             "snapshot_t0.080", "snapshot_t0.048", "x'y", "a b", "new\nline"})
        std::ofstream(dir / (std::string(name) + ".tsv")) << "x\n";
    std::ofstream(dir / "notes.txt") << "x\n";
    const std::string emitted = emitted_script("fig", "plot 1\n", dir);
    fs::remove_all(dir);
    EXPECT_NE(emitted.find("\ntables = 'run_r0.6_tc1e-06 run_r0.6_tc0.001 snapshot_t0.048 snapshot_t0.080 "
                           "steady_k200 steady_k2000 steady_k30000'\n"),
              std::string::npos)
        << emitted;
    EXPECT_NE(emitted.find("\nhas(name) = "), std::string::npos);
    EXPECT_LT(emitted.find("\ntables = "), emitted.find("\nplot 1\n")); // set before the body uses it
}
