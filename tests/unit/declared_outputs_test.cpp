// Declared outputs (issues 28, 44): the pattern matcher, the handles every output is written
// through (data/outputs.hpp), and the contract between those handles, the claims of
// expected/*.toml and the tables the plot scripts name literally.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/input_error.hpp"
#include "harness/claims.hpp"
#include "data/outputs.hpp"
#include "harness/experiment.hpp"
#include "harness/plotter.hpp"
#include "harness/runner.hpp"

using namespace granrepro;
namespace fs = std::filesystem;

TEST(DeclaredOutputs, NumberPlaceholderMatchesNumbersOnly) {
    EXPECT_TRUE(matches_output_pattern("v_crit_kN<n>", "v_crit_kN200"));
    EXPECT_TRUE(matches_output_pattern("v_crit_kN<n>", "v_crit_kN2e+05"));
    EXPECT_TRUE(matches_output_pattern("series_k<n>_e<n>_fast", "series_k2000_e0.85_fast"));
    EXPECT_TRUE(matches_output_pattern("rise_z_vx<n>", "rise_z_vx0.1"));
    EXPECT_TRUE(matches_output_pattern("t_col", "t_col"));
    EXPECT_FALSE(matches_output_pattern("v_crit_kN<n>", "v_crit_kN"));       // <n> is one character or more
    EXPECT_FALSE(matches_output_pattern("v_crit_kN<n>", "v_crit_kNabc"));    // not a number
    EXPECT_FALSE(matches_output_pattern("v_crit_kN<n>", "v_crit_kN200_x"));  // the whole name
    EXPECT_FALSE(matches_output_pattern("rise_z_vx<n>", "rise_z_pipe_vx0.1"));
    EXPECT_FALSE(matches_output_pattern("t_col", "t_col_k200"));
    EXPECT_FALSE(matches_output_pattern("t_col", "t_co"));
}

TEST(DeclaredOutputs, MalformedPatternsAreNamed) {
    EXPECT_EQ(output_pattern_error("v_<n>"), "");
    EXPECT_NE(output_pattern_error(""), "");
    EXPECT_NE(output_pattern_error("v_<k>"), "");
    EXPECT_NE(output_pattern_error("v_<n"), "");
    EXPECT_NE(output_pattern_error("a b"), "");
    EXPECT_NE(output_pattern_error("tables/x"), "");
}

// A handle's placeholders take numbers (number_text's, or already written) and, for <w>, its words
// only; a report that gets them wrong stops at the first quick run.
TEST(OutputHandles, FillTheirPlaceholdersWithNumbersAndTheirWords) {
    const Words readings{"magnitude", "elastic"};
    EXPECT_EQ(fill_pattern("v_crit_kN<n>", {}, {2000.0}), "v_crit_kN2000");
    EXPECT_EQ(fill_pattern("series_k<n>_e<n>", {}, {200, "0.90"}), "series_k200_e0.90");
    EXPECT_EQ(fill_pattern("eq2_<w>_v_crit", readings, {"elastic"}), "eq2_elastic_v_crit");
    EXPECT_EQ(fill_pattern("t_col", {}, {}), "t_col");
    EXPECT_THROW(fill_pattern("eq2_<w>_v_crit", readings, {"signed"}), std::logic_error); // not a word of it
    EXPECT_THROW(fill_pattern("v_kN<n>", {}, {"abc"}), std::logic_error);                 // not a number
    EXPECT_THROW(fill_pattern("v_kN<n>", {}, {}), std::logic_error);                      // too few parts
    EXPECT_THROW(fill_pattern("t_col", {}, {1.0}), std::logic_error);                     // too many
    Result r;
    r.put(ScalarOut{"x_k<n>", "m/s", "a speed", {}}, 1.5, {200}, " at k_N");
    ASSERT_EQ(r.scalars.size(), 1u);
    EXPECT_EQ(r.scalars[0].name, "x_k200");
    EXPECT_EQ(r.scalars[0].unit, "m/s");
    EXPECT_EQ(r.scalars[0].description, "a speed at k_N");
    // A name made elsewhere (carried by a sweep point) is written only by a handle that makes it.
    const TableOut snap{"snapshot_t<n>", "disks", {}}, per{"eq2_<w>_t", "a reading", readings};
    EXPECT_TRUE(makes_name(per.pattern, per.words, "eq2_elastic_t"));
    EXPECT_FALSE(makes_name(per.pattern, per.words, "eq2_signed_t"));
    EXPECT_EQ(r.table_named(snap, "snapshot_t0.050").description, "disks");
    EXPECT_THROW(r.table_named(snap, "crack_t0.050"), std::logic_error);
    EXPECT_THROW(r.table_named(snap, "snapshot_tx"), std::logic_error);
}

// A catalog holds one pattern per word, and names a malformed or repeated declaration instead of
// failing at start-up.
TEST(OutputHandles, ACatalogExpandsWordsAndNamesItsErrors) {
    constexpr Outputs cat{"declared-outputs-test"};
    cat.scalar("eq2_<w>_v", "m/s", "v", {"a", "b"});
    cat.scalar("v_k<n>", "m/s", "v");
    cat.scalar("v_k<n>", "m/s", "again");
    cat.table("bad name", "t");
    cat.scalar("no_word", "1", "words but no <w>", {"a"});
    const DeclaredOutputs& d = declared_outputs("declared-outputs-test");
    EXPECT_EQ(d.scalars, (std::vector<std::string>{"eq2_a_v", "eq2_b_v", "v_k<n>", "v_k<n>", "no_word"}));
    ASSERT_EQ(d.errors.size(), 3u);
    EXPECT_NE(d.errors[0].find("declared twice"), std::string::npos) << d.errors[0];
    EXPECT_NE(d.errors[1].find("' '"), std::string::npos) << d.errors[1];
    EXPECT_NE(d.errors[2].find("<w>"), std::string::npos) << d.errors[2];
}

// Every experiment's catalog is well formed, and no experiment writes a name by hand: Result's
// add_scalar/add_table are for the harness and tests, so a name cannot bypass its handle.
TEST(OutputHandles, ExperimentsWriteOnlyThroughWellFormedHandles) {
    for (const auto& e : experiment_registry()) {
        const DeclaredOutputs& d = declared_outputs(e.name);
        EXPECT_TRUE(d.declared()) << e.name << " declares no output handle";
        for (const auto& why : d.errors) ADD_FAILURE() << e.name << ": " << why;
    }
    const std::regex by_name(R"(\badd_(scalar|table)\s*\()");
    int files = 0;
    for (const auto& f : fs::recursive_directory_iterator(project_root() / "experiments")) {
        if (f.path().extension() != ".cpp" && f.path().extension() != ".hpp") continue;
        std::ifstream in(f.path());
        std::stringstream text;
        text << in.rdbuf();
        EXPECT_FALSE(std::regex_search(text.str(), by_name)) << f.path() << " writes an output by name, not through a handle";
        ++files;
    }
    EXPECT_GT(files, 20);
}

// Every experiment declares its outputs, and every claim of expected/ names a declared scalar:
// experiment_claims() refuses the file otherwise (the --dry-run path).
TEST(DeclaredOutputs, EveryClaimNamesADeclaredScalar) {
    for (const auto& e : experiment_registry()) {
        const ExperimentInfo info = experiment_info(e.name);
        EXPECT_TRUE(info.outputs.declared()) << e.name;
        EXPECT_NO_THROW(experiment_claims(e.name)) << e.name;
    }
}

// A claim naming a quantity the experiment does not make is refused when the claims load, with
// the file, the claim and its line.
TEST(DeclaredOutputs, AnUndeclaredClaimIsRefusedAtLoad) {
    const fs::path file = fs::temp_directory_path() / ("declared-outputs-" + std::to_string(::getpid()) + ".toml");
    std::ofstream(file) << "experiment = \"brake-failure\"\n\n[[claim]]\nid = \"typo\"\nrole = \"reproduction\"\nstatement = \"s\"\n"
                           "source = \"s\"\nmeasured = \"v_crit_typo\"\npaper = 1.0\nrel_tol = 0.1\n"
                           "tolerance_reason = \"r\"\ntolerance_kind = \"paper_precision\"\n";
    const ExperimentInfo info = experiment_info("brake-failure");
    try {
        load_claims(file, "brake-failure", &info.outputs);
        ADD_FAILURE() << "an undeclared measured name was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("claim typo"), std::string::npos) << what;
        EXPECT_NE(what.find("(line 8)"), std::string::npos) << what;
        EXPECT_NE(what.find("v_crit_typo"), std::string::npos) << what;
    }
    EXPECT_NO_THROW(load_claims(file, "brake-failure")); // without declarations: only the claim's own form
    fs::remove(file);
}

// Every table a plot script names literally is declared by the experiment that makes the figure.
TEST(DeclaredOutputs, EveryLiteralPlotTableIsDeclared) {
    int checked = 0;
    for (const auto& e : experiment_registry()) {
        const ExperimentInfo info = experiment_info(e.name);
        for (const auto& f : info.figures) {
            std::ifstream in(project_root() / "plots" / (f.id + ".gp"));
            std::stringstream text;
            text << in.rdbuf();
            for (const auto& t : literal_tables(text.str())) {
                EXPECT_TRUE(info.outputs.declares_table(t)) << f.id << ".gp names table " << t << ", which "
                                                            << e.name << " does not declare";
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 10);
}

// A claim may name the figure it belongs to; one its experiment does not make is refused at load
// with the file and line, and the named figure decides where `figure` and the report show it.
TEST(DeclaredOutputs, AClaimNamesOneOfItsExperimentsFigures) {
    const fs::path root = fs::temp_directory_path() / ("claim-figure-" + std::to_string(::getpid()));
    fs::create_directories(root / "experiments");
    fs::create_directories(root / "expected");
    fs::copy_file(project_root() / "experiments" / "emergency-brake.toml", root / "experiments" / "emergency-brake.toml");
    const fs::path file = root / "expected" / "emergency-brake.toml";
    auto claims_naming = [&](const std::string& figure) {
        std::ofstream(file) << "experiment = \"emergency-brake\"\n\n[[claim]]\nid = \"c\"\nrole = \"reproduction\"\n"
                               "statement = \"s\"\nsource = \"Eq. (4)\"\nmeasured = \"v_crit\"\npaper = 1.0\nrel_tol = 0.1\n"
                               "tolerance_reason = \"r\"\ntolerance_kind = \"paper_precision\"\nfigure = \"" + figure + "\"\n";
        return load_claims(file, "emergency-brake");
    };
    const auto claims = claims_naming("schaefer95-fig5");
    ASSERT_EQ(claims.size(), 1u);
    EXPECT_TRUE(cites_figure(claims[0], "schaefer95-fig5")); // its source cites no figure
    EXPECT_FALSE(cites_figure(claims[0], "schaefer95-fig4"));
    try {
        claims_naming("schaefer95-fig3"); // brake-failure's
        ADD_FAILURE() << "a figure of another experiment was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("(line 13)"), std::string::npos) << what;
        EXPECT_NE(what.find("schaefer95-fig3"), std::string::npos) << what;
    }
    fs::remove_all(root);
}
