// The command line as a user meets it: bad input gives one line naming the parameter and what is
// allowed, exit code 2, and nothing written; the same seed gives bit-identical datasets.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include "cli_support.hpp"
#include "io/h5_file.hpp"

namespace fs = std::filesystem;
using granrepro::H5File;

using cli_support::fresh;
using cli_support::Outcome;
using cli_support::run;

namespace {

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

struct BadInput {
    const char* args;
    const char* must_mention;
};

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, OneLineExitTwoNothingWritten) {
    const fs::path out = fresh("bad");
    const Outcome o = run(std::string(GetParam().args) + " --out " + out.string());
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_EQ(lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(GetParam().must_mention), std::string::npos) << o.err;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "output written for bad input";
    fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(
    Cli, BadInputTest,
    ::testing::Values(BadInput{"brake-failure --set nope=1", "unknown parameter"},
                      BadInput{"brake-failure --set k_N=abc", "k_N must be a number in (0, inf)"},
                      BadInput{"brake-failure --set k_N=0", "k_N must be a number in (0, inf)"},
                      BadInput{"brake-failure --set k_N=-5", "k_N"},
                      BadInput{"brake-failure --set mu=-0.1", "mu must be a number in [0, inf)"},
                      BadInput{"brake-failure --set gamma_N=1e6", "e_N is in (0, 1]"},
                      BadInput{"brake-failure --set steps_per_contact=5", "steps_per_contact"},
                      BadInput{"brake-failure --set offset=0.9e-3", "offset"},
                      BadInput{"emergency-brake --set x_start=0.5e-3", "overlapping"},
                      BadInput{"emergency-brake --set vx_list=0.1,x", "vx_list"},
                      BadInput{"brake-failure --scale huge", "scale"},
                      BadInput{"figure schaefer95-fig99", "unknown figure"},
                      BadInput{"check no-such-experiment", "unknown experiment"}));

TEST(Cli, UnknownSubcommandIsOneLineExitTwo) {
    const Outcome o = run("frobnicate");
    EXPECT_EQ(o.code, 2);
    EXPECT_EQ(lines(o.err), 1);
    EXPECT_NE(o.err.find("unknown subcommand 'frobnicate'"), std::string::npos);
}

TEST(Cli, UnwritableOutIsRefused) {
    const Outcome o = run("brake-failure --out /proc/granrepro-cannot-write");
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_EQ(lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("--out"), std::string::npos);
}

// A copy of the project data with one expected file broken or removed.
fs::path project_copy(const std::string& name) {
    const fs::path home = fresh(name);
    fs::create_directories(home);
    for (const char* d : {"experiments", "expected", "plots"})
        fs::copy(fs::path(GRANREPRO_SOURCE_DIR) / d, home / d, fs::copy_options::recursive);
    return home;
}

TEST(Cli, CorruptOrMissingExpectedFileIsAnInputError) {
    const fs::path home = project_copy("home");
    std::ofstream(home / "expected" / "brake-failure.toml") << "experiment = \"brake-failure\"\n[[claim]\nid=";
    fs::remove(home / "expected" / "emergency-brake.toml");
    const fs::path out = fresh("exp-out");
    Outcome o = run("brake-failure --out " + out.string(), "GRANREPRO_HOME=" + home.string());
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_EQ(lines(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("brake-failure.toml"), std::string::npos) << o.err;
    o = run("emergency-brake --out " + out.string(), "GRANREPRO_HOME=" + home.string());
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_NE(o.err.find("missing"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(out / "brake-failure"));
    EXPECT_FALSE(fs::exists(out / "emergency-brake"));
    fs::remove_all(home);
    fs::remove_all(out);
}

TEST(Cli, SameSeedGivesBitIdenticalDatasets) {
    const fs::path a = fresh("det-a"), b = fresh("det-b");
    const std::string args = "emergency-brake --quiet --set n_vy=7 --set n_positions=3 --seed 7 ";
    ASSERT_EQ(run(args + "--threads 1 --out " + a.string()).code, 0);
    ASSERT_EQ(run(args + "--threads 2 --out " + b.string()).code, 0);
    const H5File fa = H5File::open((a / "emergency-brake" / "data.h5").string());
    const H5File fb = H5File::open((b / "emergency-brake" / "data.h5").string());
    for (const char* ds : {"tables/impacts_vx0.1/dvy", "tables/impacts_vx0.5/contacts", "scalars/v_crit_vx0.3"}) {
        const auto va = fa.read_dataset(ds), vb = fb.read_dataset(ds);
        ASSERT_EQ(va.size(), vb.size());
        EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << ds;
    }
    EXPECT_EQ(fa.read_string_attr("seed"), "7");
    EXPECT_EQ(fa.read_string_attr("schema"), "granrepro-result");
    fs::remove_all(a);
    fs::remove_all(b);
}

// A cooling run killed after its third mid-run checkpoint (both methods, on two threads) and
// rerun resumes from the checkpoints; its datasets equal an uninterrupted run's bit for bit.
TEST(Cli, CoolingResumesBitIdentical) {
    const fs::path a = fresh("cool-a"), b = fresh("cool-b");
    const std::string args = "cooling --scale quick --set n_side=30 ";
    ASSERT_EQ(run(args + "--quiet --out " + a.string()).code, 0);
    const Outcome killed =
        run(args + "--quiet --checkpoint-interval 0 --threads 2 --out " + b.string(),
            "GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS=3");
    EXPECT_NE(killed.code, 0) << killed.err;
    EXPECT_FALSE(fs::exists(b / "cooling"));
    int checkpoints = 0;
    for (const auto& e : fs::directory_iterator(b / ".cooling.checkpoint"))
        checkpoints += e.path().extension() == ".h5";
    EXPECT_EQ(checkpoints, 2) << "one per method";
    const Outcome resumed = run(args + "--checkpoint-interval 0 --out " + b.string());
    ASSERT_EQ(resumed.code, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("resuming"), std::string::npos) << resumed.err;
    EXPECT_FALSE(fs::exists(b / ".cooling.checkpoint"));
    const H5File fa = H5File::open((a / "cooling" / "data.h5").string());
    const H5File fb = H5File::open((b / "cooling" / "data.h5").string());
    for (const char* ds :
         {"tables/energy_ed/K_over_K0", "tables/energy_ed/C_over_N", "tables/energy_dsmc/K_over_K0",
          "tables/energy_dsmc/C_over_N", "tables/impact_parameter_ed/P_t0",
          "tables/impact_parameter_ed/P_t2", "tables/gr_ed/g_t0", "tables/gr_ed/g_t5",
          "tables/sk_dsmc/S_t5", "scalars/ed_C_over_N_end", "scalars/pbd_collisions_first",
          "scalars/dsmc_over_ed_end", "scalars/omega_equilibration_over_enskog"}) {
        const auto va = fa.read_dataset(ds), vb = fb.read_dataset(ds);
        ASSERT_EQ(va.size(), vb.size()) << ds;
        EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << ds;
    }
    fs::remove_all(a);
    fs::remove_all(b);
}

TEST(Cli, ListNamesEveryFigure) {
    const fs::path out = fresh("list");
    const std::string cmd = std::string(GRANREPRO_BINARY) + " list > " + out.string();
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream in(out);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* id : {"schaefer95-fig3", "schaefer95-fig4", "schaefer95-fig5"})
        EXPECT_NE(text.find(id), std::string::npos) << id;
    fs::remove(out);
}

} // namespace
