// The harness: ranges, parameters and --set, claims, curve analysis, HDF5 round trip.
#include <gtest/gtest.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>
#include <unistd.h>

#include "analysis/curve_analysis.hpp"
#include "core/input_error.hpp"
#include "core/spawn.hpp"
#include "harness/claims.hpp"
#include "harness/experiment.hpp"
#include "harness/plotter.hpp"
#include "data/parameter_set.hpp"
#include "io/h5_file.hpp"
#include "io/result_writer.hpp"
#include "io/staged_directory.hpp"
#include "saved_states.hpp"

using namespace granrepro;
namespace fs = std::filesystem;

namespace {

fs::path write(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
    return p;
}

const char* kExperiment = R"toml(
name = "demo"
paper = "p"
description = "d"
[parameters.k_N]
value = 2000.0
unit = "N/m"
range = "(0, inf)"
source = "s"
[parameters.e_N]
value = 0.7
unit = "1"
range = "(0, 1]"
source = "s"
[parameters.n]
quick = 10
paper = 100
unit = "1"
range = "[3, 1000]"
source = "s"
[parameters.vx]
value = [0.1, 0.3]
unit = "m/s"
range = "(0, inf)"
source = "s"
[parameters.mode]
value = "a"
choices = ["a", "b"]
unit = "1"
source = "s"
)toml";

// A plot script's declared parameters come from the run's summary.json, written as the drivers
// write them into table names (number_text); a missing or non-numeric one is named.
TEST(PlotScripts, DeclaredParametersAreSetFromTheRunsSummary) {
    const fs::path dir = fs::temp_directory_path() / ("granrepro-plotparams-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path summary = write(dir / "summary.json", R"({"parameters": {"fig8_t_c": {"value": 2e-6},
        "fig8_r": {"value": [0.9, 0.5]}, "mode": {"value": "x"}}})");
    EXPECT_EQ(parameter_assignments("plot x\n", summary), "");
    EXPECT_EQ(parameter_assignments("# Parameters set by granrepro: fig8_r, fig8_t_c\nplot x\n", summary),
              "fig8_r = '0.9 0.5'\nfig8_t_c = '2e-06'\n");
    for (const char* bad : {"nope", "mode"}) {
        try {
            parameter_assignments(std::string("# Parameters set by granrepro: ") + bad + "\n", summary);
            ADD_FAILURE() << bad << " accepted";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("parameter ") + bad), std::string::npos) << e.what();
        }
    }
    fs::remove_all(dir);
}

// External programs get their arguments as they are (no shell reads them), run in the given
// directory, and a program that cannot be started is told apart from one that fails.
TEST(Spawn, ArgumentsReachTheProgramUnreadByAShell) {
    const fs::path dir = fs::temp_directory_path() / ("granrepro-spawn-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string arg = "a'b;$(touch PWNED)`touch PWNED`\n-c";
    auto output = [&] {
        std::ifstream in(dir / "out");
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(run_program({"printf", "%s", arg}, dir, dir / "out"), 0);
    EXPECT_EQ(output(), arg);
    EXPECT_EQ(program_output({"printf", "%s", arg}), arg);
    EXPECT_EQ(run_program({"pwd"}, dir, dir / "out"), 0);
    EXPECT_EQ(output(), fs::canonical(dir).string() + "\n");
    EXPECT_EQ(run_program({"false"}), 1);
    EXPECT_EQ(run_program({"/nonexistent/program"}), kNotStarted);
    EXPECT_FALSE(fs::exists(dir / "PWNED"));
    fs::remove_all(dir);
}

TEST(Interval, ParsesOpenAndClosedBounds) {
    const Interval iv = Interval::parse("(0, 1]");
    EXPECT_FALSE(iv.contains(0.0));
    EXPECT_TRUE(iv.contains(1.0));
    EXPECT_TRUE(iv.contains(0.5));
    EXPECT_FALSE(iv.contains(1.0000001));
    EXPECT_TRUE(Interval::parse("[3, inf)").contains(1e300));
    EXPECT_FALSE(Interval::parse("[3, inf)").contains(NAN));
    EXPECT_THROW(Interval::parse("0..1"), InputError);
}

TEST(ParameterSet, ScalesOverridesAndErrorsNameTheParameter) {
    const test::TempDir dir;
    const fs::path f = write(dir.path / "demo.toml", kExperiment);
    ParameterSet quick = ParameterSet::load(f, Scale::Quick);
    EXPECT_EQ(quick.integer("n"), 10);
    EXPECT_EQ(ParameterSet::load(f, Scale::Paper).integer("n"), 100);
    EXPECT_EQ(quick.all().front().name, "k_N"); // file order is kept
    quick.set("k_N=5e3");
    EXPECT_DOUBLE_EQ(quick.real("k_N"), 5000.0);
    quick.set("vx=0.2,0.4,0.6");
    EXPECT_EQ(quick.reals("vx").size(), 3u);
    auto message = [&](const std::string& assignment) {
        try {
            quick.set(assignment);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("k_N=-1").find("k_N must be a number in (0, inf) [N/m]"), std::string::npos);
    EXPECT_NE(message("e_N=1.5").find("(0, 1]"), std::string::npos);
    EXPECT_NE(message("k_N=abc").find("k_N"), std::string::npos);
    EXPECT_NE(message("n=2.5").find("an integer"), std::string::npos);
    EXPECT_NE(message("mode=c").find("one of a, b"), std::string::npos);
    EXPECT_NE(message("nope=1").find("unknown parameter"), std::string::npos);
    EXPECT_NE(message("k_N").find("name=value"), std::string::npos);
    EXPECT_DOUBLE_EQ(quick.real("k_N"), 5000.0); // failed overrides change nothing
}

TEST(ParameterSet, RejectsAFileWithoutSourcesOrWithBadDefaults) {
    const test::TempDir dir;
    const fs::path f = write(dir.path / "x.toml", "[parameters.a]\nvalue = 1.0\nunit = \"m\"\n");
    EXPECT_THROW(ParameterSet::load(f, Scale::Quick), InputError);
    const fs::path g =
        write(dir.path / "y.toml", "[parameters.a]\nvalue = -1.0\nunit = \"m\"\nsource = \"s\"\nrange = \"(0, 1)\"\n");
    EXPECT_THROW(ParameterSet::load(g, Scale::Quick), InputError);
    const fs::path h = write(dir.path / "z.toml", "[parameters.a\nvalue = ");
    EXPECT_THROW(ParameterSet::load(h, Scale::Quick), InputError);
}

TEST(Claims, VerdictsForValueRangeAndKnownDeviation) {
    const test::TempDir dir;
    const fs::path f = write(dir.path / "e.toml", R"toml(
experiment = "e"
[[claim]]
id = "a"
role = "reproduction"
statement = "s"
source = "s"
measured = "x"
paper = 1.0
rel_tol = 0.1
tolerance_reason = "r"
tolerance_kind = "paper_precision"
[[claim]]
id = "b"
role = "reproduction"
statement = "s"
source = "s"
measured = "y"
min = 0.0
max = 1.0
tolerance_reason = "r"
tolerance_kind = "paper_precision"
[[claim]]
id = "c"
role = "reproduction"
statement = "s"
source = "s"
measured = "y"
paper = 5.0
abs_tol = 0.1
known_deviation = "because"
status = "open"
deviation_band = [1.5, 2.5]
deviation_band_reason = "r"
tolerance_kind = "grid"
deviation_band_kind = "grid"
[[claim]]
id = "d"
role = "reproduction"
statement = "s"
source = "s"
measured = "missing"
min = 0.0
tolerance_reason = "r"
tolerance_kind = "paper_precision"
scales = ["paper"]
)toml");
    const auto claims = load_claims(f, "e");
    ASSERT_EQ(claims.size(), 4u);
    nlohmann::json s = {{"x", 1.05}, {"y", 2.0}};
    auto r = evaluate_claims(claims, s, Scale::Quick);
    EXPECT_EQ(r[0].verdict, Verdict::Pass);
    EXPECT_EQ(r[1].verdict, Verdict::Fail);
    EXPECT_EQ(r[2].verdict, Verdict::KnownDeviation);
    EXPECT_EQ(r[3].verdict, Verdict::Skipped);
    EXPECT_FALSE(all_pass(r));
    s["x"] = 1.2;
    s["y"] = 0.5;
    r = evaluate_claims(claims, s, Scale::Paper);
    EXPECT_EQ(r[0].verdict, Verdict::Fail);
    EXPECT_EQ(r[1].verdict, Verdict::Pass);
    EXPECT_EQ(r[3].verdict, Verdict::Fail); // a missing measurement fails
    // One grid step off counts as within abs_tol = one grid step, despite round-off ...
    Claim step = claims[0];
    step.rel_tol.reset();
    step.paper = 0.7;
    step.abs_tol = 0.1;
    EXPECT_EQ(evaluate_claims({step}, {{"x", 0.8}}, Scale::Quick)[0].verdict, Verdict::Pass);
    // ... but anything beyond it fails.
    EXPECT_EQ(evaluate_claims({step}, {{"x", 0.80001}}, Scale::Quick)[0].verdict, Verdict::Fail);
    EXPECT_THROW(load_claims(f, "other"), InputError);
    EXPECT_THROW(load_claims(dir.path / "absent.toml", "e"), InputError);
    const fs::path bad = write(dir.path / "bad.toml", "experiment = \"e\"\n[[claim]]\nid = \"a\"\n");
    EXPECT_THROW(load_claims(bad, "e"), InputError);
}

// A known deviation keeps a band of its own: within the paper's tolerance it PASSes, inside its
// band it is a DEVIATION, outside both or without a measurement it FAILs.
const char* kDeviationClaims = R"toml(
experiment = "e"
[[claim]]
id = "dev"
role = "reproduction"
statement = "s"
source = "s"
measured = "x"
paper = 1.0
abs_tol = 0.1
known_deviation = "we measure 1.5"
status = "open"
deviation_band = [1.4, 1.6]
deviation_band_reason = "mean ± 4 sigma over seeds"
tolerance_kind = "error_bar"
deviation_band_kind = "seed_spread"
[[claim]]
id = "per_scale"
role = "reproduction"
statement = "s"
source = "s"
measured = "y"
min = 10.0
known_deviation = "we measure 3 at quick and 7 at paper scale"
status = "open"
deviation_band = { quick = [2.0, 4.0], paper = [6.0, inf] }
deviation_band_reason = "r"
tolerance_kind = "paper_precision"
deviation_band_kind = "single_run"
)toml";

Verdict deviation_verdict(const nlohmann::json& scalars, Scale scale, std::size_t claim) {
    const test::TempDir dir;
    const auto claims = load_claims(write(dir.path / "e.toml", kDeviationClaims), "e");
    return evaluate_claims(claims, scalars, scale).at(claim).verdict;
}

TEST(Claims, TheClosingLinesSayWhatSkippedMeansOnlyWhenSomeWereSkipped) {
    VerdictCounts counts;
    counts.pass = 3;
    EXPECT_NE(counts.closing().find("totals: 3 PASS, 0 FAIL, 0 DEVIATION, 0 skipped\n"), std::string::npos);
    EXPECT_EQ(counts.closing().find("(skipped:"), std::string::npos);
    counts.skipped = 2;
    const std::string text = counts.closing();
    EXPECT_NE(text.find("totals: 3 PASS, 0 FAIL, 0 DEVIATION, 2 skipped\n(skipped: claims stated for the other scale"), std::string::npos)
        << text;
}

TEST(Claims, DeviationWithinPaperTolerancePasses) {
    EXPECT_EQ(deviation_verdict({{"x", 1.05}}, Scale::Quick, 0), Verdict::Pass);
    EXPECT_EQ(deviation_verdict({{"y", 12.0}}, Scale::Quick, 1), Verdict::Pass);
}

TEST(Claims, DeviationInsideItsBandIsDeviation) {
    EXPECT_EQ(deviation_verdict({{"x", 1.5}}, Scale::Paper, 0), Verdict::KnownDeviation);
    EXPECT_EQ(deviation_verdict({{"x", 1.4}}, Scale::Quick, 0), Verdict::KnownDeviation); // closed band
    EXPECT_EQ(deviation_verdict({{"y", 3.0}}, Scale::Quick, 1), Verdict::KnownDeviation);
    EXPECT_EQ(deviation_verdict({{"y", 7.0}}, Scale::Paper, 1), Verdict::KnownDeviation);
}

TEST(Claims, DeviationOutsideItsBandFails) {
    EXPECT_EQ(deviation_verdict({{"x", 1.7}}, Scale::Quick, 0), Verdict::Fail);
    EXPECT_EQ(deviation_verdict({{"x", 1.2}}, Scale::Quick, 0), Verdict::Fail);
    // The band is the one of the run's scale.
    EXPECT_EQ(deviation_verdict({{"y", 3.0}}, Scale::Paper, 1), Verdict::Fail);
    EXPECT_EQ(deviation_verdict({{"y", 7.0}}, Scale::Quick, 1), Verdict::Fail);
}

TEST(Claims, DeviationWithoutScalarFails) {
    EXPECT_EQ(deviation_verdict(nlohmann::json::object(), Scale::Quick, 0), Verdict::Fail); // removed
    EXPECT_EQ(deviation_verdict({{"x", nullptr}}, Scale::Quick, 0), Verdict::Fail);         // NaN in the run
    EXPECT_EQ(deviation_verdict({{"x", INFINITY}}, Scale::Quick, 0), Verdict::Fail);
    EXPECT_EQ(deviation_verdict({{"y", INFINITY}}, Scale::Paper, 1), Verdict::Fail); // even with hi = inf
}

// deviation_band = "absent": the quantity does not exist in our runs (a property of a branch no run
// reaches). The run's NaN (null in summary.json) is the deviation; any value, or a scalar the run
// did not write at all, fails; the band goes with deviation_band_kind = "absent" only.
TEST(Claims, AbsentBandHoldsOnlyTheLackOfAValue) {
    const test::TempDir dir;
    const std::string claim = "experiment = \"e\"\n[[claim]]\nid = \"a\"\nrole = \"reproduction\"\nstatement = \"s\"\n"
                              "source = \"s\"\nmeasured = \"z\"\nmin = 2.0\ntolerance_reason = \"r\"\n"
                              "tolerance_kind = \"physical_bound\"\nknown_deviation = \"no state\"\nstatus = \"settled\"\n"
                              "deviation_band = \"absent\"\ndeviation_band_reason = \"r\"\n";
    const auto claims = load_claims(write(dir.path / "e.toml", claim + "deviation_band_kind = \"absent\"\n"), "e");
    EXPECT_EQ(evaluate_claims(claims, {{"z", nullptr}}, Scale::Quick)[0].verdict, Verdict::KnownDeviation);
    EXPECT_EQ(evaluate_claims(claims, {{"z", 3.0}}, Scale::Quick)[0].verdict, Verdict::Pass);
    EXPECT_EQ(evaluate_claims(claims, {{"z", 1.0}}, Scale::Quick)[0].verdict, Verdict::Fail);
    EXPECT_EQ(evaluate_claims(claims, nlohmann::json::object(), Scale::Quick)[0].verdict, Verdict::Fail);
    EXPECT_EQ(evaluate_claims(claims, {{"z", nullptr}}, Scale::Quick)[0].band_text, "absent");
    EXPECT_THROW(load_claims(write(dir.path / "e.toml", claim + "deviation_band_kind = \"grid\"\n"), "e"), InputError);
}

TEST(Claims, FailingDeviationFailsTheRunAndTheTableShowsTheBand) {
    const test::TempDir dir;
    const auto claims = load_claims(write(dir.path / "e.toml", kDeviationClaims), "e");
    EXPECT_TRUE(all_pass(evaluate_claims(claims, {{"x", 1.5}, {"y", 3.0}}, Scale::Quick)));
    EXPECT_FALSE(all_pass(evaluate_claims(claims, {{"x", 1.7}, {"y", 3.0}}, Scale::Quick)));
    // The table shows the paper's relation and our band side by side.
    const std::string table = format_claim_table("e", evaluate_claims(claims, {{"x", 1.5}, {"y", 7.0}}, Scale::Paper));
    EXPECT_NE(table.find("our band"), std::string::npos) << table;
    EXPECT_NE(table.find("[1.4, 1.6]"), std::string::npos) << table;
    EXPECT_NE(table.find("[6, inf]"), std::string::npos) << table;
    EXPECT_NE(table.find("in [10, inf]"), std::string::npos) << table;
    // ... and where each tolerance comes from; --explain names both kinds with their reasons.
    EXPECT_NE(table.find("abs 0.1 (errbar)"), std::string::npos) << table;
    EXPECT_NE(table.find("range (paper)"), std::string::npos) << table;
    const std::string why =
        format_deviation_explanations(evaluate_claims(claims, {{"x", 1.5}, {"y", 7.0}}, Scale::Paper));
    EXPECT_NE(why.find("band (seed_spread): mean ± 4 sigma over seeds"), std::string::npos) << why;
    EXPECT_NE(why.find("tolerance (error_bar)"), std::string::npos) << why;
    EXPECT_NE(why.find("band (single_run): r"), std::string::npos) << why;
    VerdictCounts n;
    n.add(evaluate_claims(claims, {{"x", 1.0}, {"y", 3.0}}, Scale::Paper));
    EXPECT_EQ(n.text(), "1 PASS, 1 FAIL, 0 DEVIATION, 0 skipped");
}

TEST(Claims, MissingScalarFailsEveryClaim) {
    const test::TempDir dir;
    const auto claims = load_claims(write(dir.path / "e.toml", R"toml(
experiment = "e"
[[claim]]
id = "plain"
role = "reproduction"
statement = "s"
source = "s"
measured = "x"
max = 1.0
tolerance_reason = "r"
tolerance_kind = "paper_precision"
)toml"), "e");
    EXPECT_EQ(evaluate_claims(claims, nlohmann::json::object(), Scale::Quick)[0].verdict, Verdict::Fail);
    EXPECT_EQ(evaluate_claims(claims, {{"x", NAN}}, Scale::Quick)[0].verdict, Verdict::Fail);
    EXPECT_EQ(evaluate_claims(claims, {{"x", 0.5}}, Scale::Quick)[0].verdict, Verdict::Pass);
}

// A known deviation without its band at a scale where it applies is an input error naming the
// file, the claim and the missing key.
TEST(Claims, DeviationWithoutBandIsAnInputError) {
    const test::TempDir dir;
    const std::string head = "experiment = \"e\"\n[[claim]]\nid = \"dev\"\nrole = \"reproduction\"\nstatement = \"s\"\nsource = \"s\"\n"
                             "measured = \"x\"\npaper = 1.0\nabs_tol = 0.1\nknown_deviation = \"k\"\nstatus = \"open\"\n"
                             "tolerance_kind = \"grid\"\ndeviation_band_kind = \"grid\"\n";
    auto error = [&](const std::string& rest) {
        try {
            load_claims(write(dir.path / "e.toml", head + rest), "e");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string m = error("deviation_band_reason = \"r\"\n");
    EXPECT_NE(m.find("e.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("claim dev"), std::string::npos) << m;
    EXPECT_NE(m.find("deviation_band for scale quick"), std::string::npos) << m;
    m = error("deviation_band = { quick = [1, 2] }\ndeviation_band_reason = \"r\"\n");
    EXPECT_NE(m.find("deviation_band for scale paper"), std::string::npos) << m;
    // ... unless the claim does not apply at that scale.
    EXPECT_EQ(error("deviation_band = { quick = [1, 2] }\ndeviation_band_reason = \"r\"\nscales = [\"quick\"]\n"),
              "no error");
    m = error("deviation_band = [1, 2]\n");
    EXPECT_NE(m.find("deviation_band_reason"), std::string::npos) << m;
    EXPECT_NE(error("deviation_band = [2, 1]\ndeviation_band_reason = \"r\"\n").find("lo <= hi"), std::string::npos);
    EXPECT_NE(error("deviation_band = [1]\ndeviation_band_reason = \"r\"\n").find("[lo, hi]"), std::string::npos);
    EXPECT_NE(error("deviation_band = { huge = [1, 2] }\ndeviation_band_reason = \"r\"\n").find("huge"),
              std::string::npos);
    EXPECT_EQ(error("deviation_band = [-inf, inf]\ndeviation_band_reason = \"r\"\n"), "no error");
    // A band on a claim that is no known deviation is a mistake too.
    const fs::path plain = write(dir.path / "p.toml",
                                 "experiment = \"e\"\n[[claim]]\nid = \"p\"\nrole = \"reproduction\"\nstatement = \"s\"\nsource = \"s\"\n"
                                 "measured = \"x\"\nmax = 1.0\ntolerance_reason = \"r\"\ntolerance_kind = \"grid\"\n"
                                 "deviation_band = [0, 2]\ndeviation_band_reason = \"r\"\n");
    EXPECT_THROW(load_claims(plain, "e"), InputError);
}

// Issue 27 §4: every committed claim names where its tolerance comes from, and every known
// deviation where its band comes from, so a referee can tell a paper's precision from a band
// set by statistics (expected/README.md, "How bands are set").
TEST(Claims, EveryCommittedClaimNamesItsKinds) {
    auto allowed = [](const auto& kinds, const std::string& k) {
        return std::find(std::begin(kinds), std::end(kinds), k) != std::end(kinds);
    };
    int files = 0, claims = 0, deviations = 0;
    for (const auto& e : fs::directory_iterator(project_root() / "expected")) {
        if (e.path().extension() != ".toml") continue;
        ++files;
        for (const Claim& c : load_claims(e.path(), e.path().stem().string())) {
            SCOPED_TRACE(e.path().filename().string() + ": " + c.id);
            ++claims;
            EXPECT_TRUE(allowed(kToleranceKinds, c.tolerance_kind)) << c.tolerance_kind;
            if (c.known_deviation.empty()) {
                EXPECT_EQ(c.deviation_band_kind, "");
            } else {
                ++deviations;
                EXPECT_TRUE(allowed(kDeviationBandKinds, c.deviation_band_kind)) << c.deviation_band_kind;
            }
        }
    }
    EXPECT_EQ(files, 8);
    EXPECT_GE(claims, 173);
    // 36 since issue 27 §1/§4 turned flat_r0.90, flat_r0.95 and sigma_max_090_smallest into passes.
    EXPECT_GE(deviations, 36);
}

// Issue 41: every claim states its role and every known deviation its status; missing or unknown
// is refused with the file, the claim and its line, and a calibration claim must be named by a
// setting of the experiment file (calibrated_on), which must name a calibration claim.
TEST(Claims, MissingRoleOrStatusIsAnInputError) {
    const test::TempDir dir;
    fs::create_directories(dir.path / "expected");
    fs::create_directories(dir.path / "experiments");
    const std::string head = "experiment = \"e\"\n[[claim]]\nid = \"k\"\nstatement = \"s\"\nsource = \"s\"\n"
                             "measured = \"x\"\nmin = 0.0\ntolerance_reason = \"r\"\ntolerance_kind = \"grid\"\n";
    const std::string deviation = "known_deviation = \"k\"\ndeviation_band = [1, 2]\ndeviation_band_reason = \"r\"\n"
                                  "deviation_band_kind = \"grid\"\n";
    auto error = [&](const std::string& rest, const std::string& experiment_file = "") {
        fs::remove(dir.path / "experiments" / "e.toml");
        if (!experiment_file.empty()) write(dir.path / "experiments" / "e.toml", experiment_file);
        try {
            load_claims(write(dir.path / "expected" / "e.toml", head + rest), "e");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("role = \"reproduction\"\n"), "no error");
    EXPECT_EQ(error("role = \"identity\"\n" + deviation + "status = \"inherent\"\n"), "no error");
    const std::string roles = "reproduction, identity, calibration, validation";
    const std::string statuses = "settled, inherent, open";
    const std::string parameter = "name = \"e\"\npaper = \"Luding, TASK Quarterly 2, 417 (1998)\"\ndescription = \"d\"\n"
                                  "[parameters.g]\nvalue = 7.0\nunit = \"m/s^2\"\nsource = \"s\"\n";
    for (const auto& [rest, experiment_file, mentions] : std::vector<std::tuple<std::string, std::string, std::vector<std::string>>>{
             {"", "", {"claim k (line 2)", "role is missing", roles}},
             {"role = \"headline\"\n", "", {"claim k (line 10)", "role 'headline' is unknown", roles}},
             {"role = \"reproduction\"\n" + deviation, "", {"claim k (line 2)", "status is missing", statuses}},
             {"role = \"reproduction\"\n" + deviation + "status = \"extrapolated\"\n", "",
              {"claim k (line 15)", "status 'extrapolated' is unknown", statuses}},
             {"role = \"reproduction\"\nstatus = \"open\"\n", "", {"claim k (line 11)", "status belongs only"}},
             // A calibration nobody names, a name of no claim, a name of a claim of another role.
             {"role = \"calibration\"\n", "", {"claim k (line 2)", "no setting of", "calibrated_on = \"k\""}},
             {"role = \"calibration\"\n", parameter, {"claim k (line 2)", "no setting of", "experiments/e.toml"}},
             {"role = \"reproduction\"\n", parameter + "calibrated_on = \"k\"\n",
              {"experiments/e.toml: [parameters.g] (line 8)", "role is 'reproduction'"}},
             {"role = \"calibration\"\n", parameter + "calibrated_on = \"q\"\n", {"[parameters.g] (line 8)", "'q' names no claim"}},
             {"role = \"calibration\"\n", parameter + "calibrated_on = 5\n", {"[parameters.g] (line 8)", "a claim id or a list"}},
             {"role = \"calibration\"\n", parameter + "[readings.unit]\ncalibrated_on = \"k\"\n",
              {"[readings.unit] (line 8)", "needs source"}},
         }) {
        const std::string m = error(rest, experiment_file);
        SCOPED_TRACE(rest + " | " + experiment_file);
        EXPECT_NE(m.find("e.toml"), std::string::npos) << m;
        for (const auto& s : mentions) EXPECT_NE(m.find(s), std::string::npos) << m;
    }
    // Named by a parameter or by a reading: loaded, with the paper's short name for the headline.
    EXPECT_EQ(error("role = \"calibration\"\n", parameter + "calibrated_on = \"k\"\n"), "no error");
    EXPECT_EQ(error("role = \"calibration\"\n", parameter + "[readings.unit]\nsource = \"s\"\ncalibrated_on = [\"k\"]\n"),
              "no error");
    const auto claims = load_claims(dir.path / "expected" / "e.toml", "e");
    ASSERT_EQ(claims.size(), 1u);
    EXPECT_EQ(claims[0].publication, "Luding 1998");
    VerdictCounts counts;
    counts.add(evaluate_claims(claims, {{"x", 1.0}}, Scale::Paper));
    EXPECT_NE(counts.headline().find("Luding 1998: 0 statements"), std::string::npos) << counts.headline();
    EXPECT_NE(counts.headline().find("0 identity, 1 calibration, 0 validation (1 PASS"), std::string::npos) << counts.headline();
}

// A missing or unknown kind is refused with the file, the claim and the allowed values.
TEST(Claims, MissingOrUnknownKindIsAnInputError) {
    const test::TempDir dir;
    const std::string head = "experiment = \"e\"\n[[claim]]\nid = \"k\"\nrole = \"reproduction\"\nstatement = \"s\"\nsource = \"s\"\n"
                             "measured = \"x\"\nmin = 0.0\ntolerance_reason = \"r\"\n";
    const std::string deviation = "known_deviation = \"k\"\nstatus = \"open\"\ndeviation_band = [1, 2]\ndeviation_band_reason = \"r\"\n";
    auto error = [&](const std::string& rest) {
        try {
            load_claims(write(dir.path / "e.toml", head + rest), "e");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("tolerance_kind = \"grid\"\n"), "no error");
    EXPECT_EQ(error("tolerance_kind = \"grid\"\n" + deviation + "deviation_band_kind = \"single_run\"\n"), "no error");
    const std::string tolerance_kinds = "paper_precision, error_bar, grid, physical_bound";
    const std::string band_kinds = "seed_spread, error_bar, grid, single_run";
    for (const auto& [rest, mentions] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"", {"tolerance_kind is missing", tolerance_kinds}},
             {"tolerance_kind = \"roughly\"\n", {"tolerance_kind 'roughly' is unknown", tolerance_kinds, "line 10"}},
             {"tolerance_kind = \"seed_spread\"\n", {"tolerance_kind 'seed_spread' is unknown"}},
             {"tolerance_kind = \"grid\"\n" + deviation, {"deviation_band_kind is missing", band_kinds}},
             {"tolerance_kind = \"grid\"\n" + deviation + "deviation_band_kind = \"physical_bound\"\n",
              {"deviation_band_kind 'physical_bound' is unknown", band_kinds}},
             // A band kind without a known deviation is as wrong as a band without one.
             {"tolerance_kind = \"grid\"\ndeviation_band_kind = \"grid\"\n",
              {"deviation_band (and its reason and kind) belongs only"}},
         }) {
        const std::string m = error(rest);
        SCOPED_TRACE(rest);
        EXPECT_NE(m.find("e.toml"), std::string::npos) << m;
        EXPECT_NE(m.find("claim k"), std::string::npos) << m;
        for (const auto& s : mentions) EXPECT_NE(m.find(s), std::string::npos) << m;
    }
}

TEST(CurveAnalysis, RecoversPowerLawAndPeak) {
    const auto x = log_space(0.1, 100.0, 61);
    std::vector<double> y(x.size()), bump(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        y[i] = 3.0 * std::pow(x[i], -1.3);
        bump[i] = x[i] / (1.0 + x[i] * x[i] / 4.0); // maximum at x = 2
    }
    const auto fit = fit_power_law(x, y, 1.0, 100.0);
    EXPECT_NEAR(fit.exponent, -1.3, 1e-10);
    const Peak p = first_maximum(x, bump);
    EXPECT_NEAR(p.x, 2.0, 0.02);
    EXPECT_EQ(count_maxima(x, bump), 1);
    EXPECT_EQ(count_maxima(x, y), 0); // monotone: no interior maximum
    std::vector<double> two = bump;
    for (std::size_t i = 40; i < x.size(); ++i) two[i] += 2.0 * x[i] / (1.0 + std::pow(x[i] / 40.0, 2)) / 40.0;
    EXPECT_EQ(count_maxima(x, two), 2);
    // The crossing is interpolated linearly in log x, so y = ln x is located exactly.
    std::vector<double> lnx(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) lnx[i] = std::log(x[i]);
    EXPECT_NEAR(first_upward_crossing(x, lnx, std::log(5.0)), 5.0, 1e-9);
    EXPECT_TRUE(std::isnan(first_upward_crossing(x, lnx, 1e3)));
}

TEST(H5File, RoundTripsDatasetsAndAttributes) {
    const test::TempDir dir;
    const H5File f = test::written_h5(dir, [](const H5File& w) {
        w.attr("name", std::string("brake-failure"));
        w.attr("x", 2.5);
        const H5Object g = w.group("tables");
        g.dataset("v", {1.0, 2.0, 3.5}, "m/s");
        w.bytes("raw", {1, 2, 3});
    });
    EXPECT_EQ(f.read_string_attr("name"), "brake-failure");
    EXPECT_DOUBLE_EQ(f.read_double_attr("x"), 2.5);
    EXPECT_EQ(f.read_dataset("tables/v"), (std::vector<double>{1.0, 2.0, 3.5}));
    EXPECT_EQ(f.read_bytes("raw"), (std::vector<unsigned char>{1, 2, 3}));
}

// The compact copy committed to paper_figures/ keeps provenance, parameters, scalars and curves
// bit for bit, and leaves out (and names) only the tables above the size limit.
TEST(ResultExport, CompactCopyKeepsScalarsAndCurvesAndNamesWhatItLeavesOut) {
    const test::TempDir dir;
    const ParameterSet params = ParameterSet::load(write(dir.path / "demo.toml", kExperiment), Scale::Paper);
    Result result;
    Table& curve = result.add_table("curve", "a small curve");
    curve.add("t", "s").values = {0.0, 0.5, 1.0};
    curve.add("K", "J").values = {1.0, 0.25, 1.0 / 3.0};
    Table& snap = result.add_table("snapshot_0", "positions");
    snap.add("x", "m").values = std::vector<double>(600, 0.1);
    snap.add("y", "m").values = std::vector<double>(600, 0.2);
    result.add_scalar("slope", -0.9731, "1", "fitted slope");
    Provenance prov{"demo", "p", "file text", Scale::Paper, 7, 12.5, 2, "granrepro demo", "expected text", {}};
    write_result_h5(dir.path / "data.h5", prov, params, result, "fnv1a64:0123456789abcdef");
    const auto omitted = write_compact_result_h5(dir.path / "data.h5", dir.path / "small.h5", 1000);
    EXPECT_EQ(omitted, std::vector<std::string>{"snapshot_0"});
    const H5File f = H5File::open((dir.path / "small.h5").string());
    EXPECT_EQ(f.read_string_attr("experiment"), "demo");
    EXPECT_EQ(f.read_u64_attr("seed"), 7u);
    EXPECT_EQ(f.read_string_attr("scale"), "paper");
    EXPECT_EQ(f.read_long_attr("schema_version"), 3);
    EXPECT_EQ(f.read_string_attr("summary_json_hash"), "fnv1a64:0123456789abcdef");
    EXPECT_DOUBLE_EQ(f.read_double_attr("wall_time_s"), 12.5);
    EXPECT_EQ(f.read_dataset("scalars/slope"), std::vector<double>{-0.9731});
    EXPECT_EQ(f.read_dataset("tables/curve/K"), (std::vector<double>{1.0, 0.25, 1.0 / 3.0}));
    EXPECT_EQ(f.read_dataset("parameters/n"), std::vector<double>{100.0});
    EXPECT_FALSE(f.has("tables/snapshot_0"));
    EXPECT_NE(f.read_string_attr("omitted_tables").find("snapshot_0 (1200 values)"), std::string::npos);
    const H5Object curve_group = f.open_group("tables").open_group("curve");
    EXPECT_EQ(curve_group.read_string_attr("description"), "a small curve");
    // The x column stays the dimension scale of the others (its references point into the copy).
    {
        const hid_t t = H5Dopen2(curve_group.id(), "t", H5P_DEFAULT), k = H5Dopen2(curve_group.id(), "K", H5P_DEFAULT);
        EXPECT_GT(H5DSis_scale(t), 0);
        EXPECT_GT(H5DSis_attached(k, t, 0), 0);
        H5Dclose(t);
        H5Dclose(k);
    }
    EXPECT_LT(fs::file_size(dir.path / "small.h5"), fs::file_size(dir.path / "data.h5"));
}

TEST(StagedDirectory, LeavesNothingBehindUnlessCommitted) {
    const test::TempDir dir;
    {
        StagedDirectory s(dir.path / "exp");
        write(s.path() / "data.txt", "x");
    }
    EXPECT_FALSE(fs::exists(dir.path / "exp"));
    EXPECT_TRUE(fs::is_empty(dir.path));
    {
        StagedDirectory s(dir.path / "exp");
        write(s.path() / "data.txt", "y");
        s.commit();
    }
    EXPECT_TRUE(fs::exists(dir.path / "exp" / "data.txt"));
}

} // namespace

// A scalar or table named twice would otherwise reach HDF5 as "name already exists" half-way
// through data.h5 (the bistable-pipe merge of 2026-12 did exactly that).
TEST(Result, RefusesANameGivenTwice) {
    granrepro::Result r;
    r.add_scalar("a", 1.0, "1", "first");
    EXPECT_THROW(r.add_scalar("a", 2.0, "1", "again"), std::logic_error);
    r.add_table("t", "first");
    EXPECT_THROW(r.add_table("t", "again"), std::logic_error);
    EXPECT_EQ(r.scalars.size(), 1u);
    EXPECT_EQ(r.tables.size(), 1u);
}
