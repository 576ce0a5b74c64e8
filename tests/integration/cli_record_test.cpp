// What a run leaves for the people who use its results elsewhere: --version with the compiler
// and library versions, run.log, provenance and typed values in data.h5, units in the TSV
// headers, gnuplot scripts that run from any directory and, once edited, are kept aside;
// and the progress reporter's timer.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli_support.hpp"
#include "harness/progress.hpp"
#include "harness/run_log.hpp"

namespace fs = std::filesystem;
using namespace cli_support;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Record, VersionNamesCompilerLibrariesAndDataFiles) {
    const Outcome v = run("--version");
    EXPECT_EQ(v.code, 0) << v.err;
    for (const char* part : {"granrepro 0.", "\ncompiler: ", "\nhdf5: 1.", "\nfftw: fftw-3", "\ngsl: 2.", "\ndata: "})
        EXPECT_TRUE(contains(v.out, part)) << part << " missing from:\n" << v.out;
}

// One brake-failure run (a second at quick scale) with an override, checked for everything it
// records; then its figures re-rendered by `plot`.
class RecordedRun : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        out_ = fresh("record");
        const auto o = run("brake-failure --quiet --seed 3 --set n_vy=20 --out " + out_.string());
        ASSERT_LE(o.code, 1) << o.err;
        dir_ = out_ / "brake-failure";
    }
    static void TearDownTestSuite() { fs::remove_all(out_); }
    static fs::path out_, dir_;
};
fs::path RecordedRun::out_, RecordedRun::dir_;

TEST_F(RecordedRun, RunLogHasCommandParametersAndWallTimes) {
    const std::string log = slurp(dir_ / "run.log");
    for (const char* part : {"command: ", "--set n_vy=20", "parameter n_vy = 20 [1] (--set)", "parameter k_N = ",
                             "run finished: wall time ", "done: wall time "})
        EXPECT_TRUE(contains(log, part)) << part << " missing from:\n" << log;
}

TEST_F(RecordedRun, DataFileKeepsTypesAndProvenance) {
    const granrepro::H5File f = granrepro::H5File::open((dir_ / "data.h5").string());
    EXPECT_EQ(f.read_u64_attr("seed"), 3u);
    const granrepro::H5Object p = f.open_group("provenance");
    EXPECT_EQ(p.read_string_attr("overridden_parameters"), "n_vy=20");
    EXPECT_TRUE(contains(p.read_string_attr("command_line"), "brake-failure --quiet --seed 3 --set n_vy=20"));
    EXPECT_TRUE(contains(p.read_string_attr("expected_file"), "[[claim]]"));
    EXPECT_TRUE(contains(p.read_string_attr("plot_schaefer95-fig3"), "datadir"));
    EXPECT_FALSE(p.read_string_attr("version_hdf5").empty());
    // An integer parameter is an integer, a scalar a scalar (rank 0).
    const hid_t d = H5Dopen2(f.id(), "parameters/n_vy", H5P_DEFAULT);
    ASSERT_GE(d, 0);
    const hid_t t = H5Dget_type(d), s = H5Dget_space(d);
    EXPECT_EQ(H5Tget_class(t), H5T_INTEGER);
    EXPECT_EQ(H5Sget_simple_extent_type(s), H5S_SCALAR);
    H5Tclose(t);
    H5Sclose(s);
    H5Dclose(d);
    EXPECT_EQ(f.read_dataset("parameters/n_vy"), std::vector<double>{20.0});
}

TEST_F(RecordedRun, TsvSecondLineCarriesTheUnits) {
    std::ifstream in(dir_ / "tables" / "fig3.tsv");
    std::string names, units;
    std::getline(in, names);
    std::getline(in, units);
    EXPECT_EQ(names.substr(0, 12), "vy_i\tdvy\tdvx");
    EXPECT_EQ(units.substr(0, 20), "# [m/s]\t[m/s]\t[m/s]\t");
}

TEST_F(RecordedRun, EmittedScriptRunsFromAnotherDirectory) {
    const fs::path png = dir_ / "schaefer95-fig3.png";
    fs::remove(png);
    const Outcome o = shell("cd / && gnuplot " + (dir_ / "schaefer95-fig3.gp").string());
    EXPECT_EQ(o.code, 0);
    EXPECT_EQ(o.out + o.err, "");
    EXPECT_TRUE(fs::exists(png));
}

// An edited script is kept as <id>.edited.gp (not lost, not run: see cli_shell_test.cpp) and the
// emitted one takes its place; removed, it is emitted afresh, and an unedited one is replaced silently.
TEST_F(RecordedRun, PlotKeepsAnEditedScriptAsideAndEmitsTheScriptAfresh) {
    const fs::path gp = dir_ / "schaefer95-fig3.gp";
    { std::ofstream(gp, std::ios::app) << "# my edit\n"; }
    const auto o = run("plot brake-failure --out " + out_.string());
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(contains(slurp(dir_ / "schaefer95-fig3.edited.gp"), "# my edit\n")) << "plot lost the edited script";
    EXPECT_FALSE(contains(slurp(gp), "# my edit"));
    EXPECT_TRUE(contains(o.err, "schaefer95-fig3.gp was edited")) << o.err;
    fs::remove(gp);
    for (int k = 0; k < 2; ++k) {
        const auto o2 = run("plot brake-failure --out " + out_.string());
        EXPECT_EQ(o2.err, "");
        EXPECT_FALSE(contains(slurp(gp), "# my edit"));
    }
}

// The timer redraws without any tick: a run whose only news is its engine time gets a progress
// line into run.log after about a second, besides the final one.
TEST(Progress, TimerReportsEngineTimeWithoutTicks) {
    const TempPath dir("progress");
    fs::create_directories(dir);
    granrepro::run_log().open(dir / "run.log");
    {
        granrepro::Progress p("demo", 2, true);
        {
            const granrepro::ProgressSlot slot(&p, 0);
            granrepro::report_engine_time(0.5, 2.0);
        }
        EXPECT_TRUE(contains(p.line(), "[demo] 0/2 done; engine time t = 0.5 of 2 s")) << p.line();
        EXPECT_TRUE(contains(p.line(), "left")) << p.line();
        std::this_thread::sleep_for(std::chrono::milliseconds(1600));
        p.done(0);
        EXPECT_TRUE(contains(p.line(), "[demo] 1/2 done;")) << p.line();
        EXPECT_FALSE(contains(p.line(), "engine time")) << "a finished point's engine time is still shown";
    }
    granrepro::run_log().close();
    const std::string log = slurp(dir / "run.log");
    std::size_t lines = 0;
    for (std::size_t at = 0; (at = log.find("progress: [demo]", at)) != std::string::npos; ++at) ++lines;
    EXPECT_EQ(lines, 2u) << log;
    EXPECT_TRUE(contains(log, "progress: [demo] 0/2 done; engine time t = 0.5 of 2 s")) << log;
}

} // namespace
