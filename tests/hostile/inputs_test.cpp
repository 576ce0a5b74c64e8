// Issue 40, input validation and what `check` prints: --dry-run gives the run's verdict (a list
// whose entries the run would name alike, a shot through the wall), a file's text is printed
// inert (terminal escapes in a claim id or a forged overridden_parameters), the project's TOML
// files are refused at file:line (1e400, a backwards range, NaN, [], a date, 31.5 for an
// integer), a claim id is never cut, and `all` does not recompute a complete result.
#include "hostile_support.hpp"

#include <chrono>
#include <fstream>
#include <hdf5.h>
#include <nlohmann/json.hpp>

#include "core/input_error.hpp"
#include "data/printable.hpp"
#include "harness/runner.hpp"
#include "io/result_writer.hpp"

using namespace hostile;
using granrepro::InputError;
using granrepro::Parameter;
using granrepro::ParameterSet;
using granrepro::RunOptions;

namespace {

// experiments/, expected/ and plots/ copied, for GRANREPRO_HOME: the real ones are never edited.
struct ProjectCopy : cli_support::TempPath {
    explicit ProjectCopy(const std::string& name) : cli_support::TempPath(name) {
        fs::create_directories(*this);
        for (const char* d : {"experiments", "expected", "plots"})
            fs::copy(fs::path(GRANREPRO_SOURCE_DIR) / d, *this / d, fs::copy_options::recursive);
    }
    std::string env() const { return "GRANREPRO_HOME=" + string(); }
    // Replaces the first `from` in `rel` (the test fails if it is absent); the line it is on.
    long replace(const std::string& rel, const std::string& from, const std::string& to) const {
        const fs::path file = *this / rel;
        std::string text = slurp(file);
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from << " not in " << file;
        if (at == std::string::npos) return 0;
        const long line = 1 + long(std::count(text.begin(), text.begin() + long(at), '\n'));
        text.replace(at, from.size(), to);
        std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
        return line;
    }
};

Outcome run_home(const ProjectCopy& home, const std::vector<std::string>& args) { return run_argv(args, {}, {home.env()}); }

bool has_raw_escape(const std::string& s) { return s.find('\x1b') != std::string::npos || s.find('\x07') != std::string::npos; }

// Rewrites a string attribute of data.h5 (HDF5's C API: the project's writer only creates files).
void set_string_attr(const fs::path& h5, const std::string& object, const std::string& name, const std::string& value) {
    const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t o = H5Oopen(f, object.c_str(), H5P_DEFAULT);
    ASSERT_GE(o, 0);
    if (H5Aexists(o, name.c_str()) > 0) H5Adelete(o, name.c_str());
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, value.empty() ? 1 : value.size());
    H5Tset_cset(t, H5T_CSET_UTF8);
    const hid_t sp = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(o, name.c_str(), t, sp, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(a, 0);
    H5Awrite(a, t, value.data());
    H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
    H5Oclose(o);
    H5Fclose(f);
}

// An entry of a list parameter, repeated: "v,v".
std::string repeated(const Parameter& p) {
    const std::string first = p.value_text().substr(0, p.value_text().find(','));
    return first + "," + first;
}

} // namespace

// Issue 40 §3: `brake-failure --set betas=100,100` passed --dry-run, then the run exited 1 with
// "result table 'collapse_beta100' added twice" and wrote nothing. Now both refuse it at load.
TEST(HostileInputsLists, RepeatedEntriesAreRefusedAtLoadWithAndWithoutDryRun) {
    const cli_support::TempPath base("hostile-lists");
    const fs::path out = base / "out";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"brake-failure", "betas=100,100"},
        {"emergency-brake", "vx_list=0.3,0.3000001"}, // one name: both are 'vx0.3'
        {"emergency-brake", "kN_scan=2000,2000"},
        {"bistable-pipe", "kN_list=2000,2000"},
    };
    for (const auto& [experiment, set] : cases) {
        const std::string name = set.substr(0, set.find('='));
        for (const bool dry : {true, false}) {
            std::vector<std::string> args{experiment, "--quiet", "--set", set, "--out", out.string()};
            if (dry) args.push_back("--dry-run");
            const Outcome o = run_argv(args);
            SCOPED_TRACE(experiment + " --set " + set + (dry ? " --dry-run" : ""));
            expect_refusal(o, 2, {"--set " + set, name + ": entries", "both named"});
            EXPECT_FALSE(fs::exists(out)) << "written for bad input";
        }
    }
}

// Every list of every experiment, in-process: a repeated first entry is refused naming the list.
TEST(HostileInputsLists, EveryListOfEveryExperimentRefusesARepeatedEntry) {
    int lists = 0;
    for (const auto& e : granrepro::experiment_registry()) {
        const ParameterSet defaults = ParameterSet::load(granrepro::experiment_info(e.name).file, granrepro::Scale::Quick);
        for (const Parameter& p : defaults.all()) {
            if (p.kind != Parameter::Kind::RealList) continue;
            ++lists;
            RunOptions opt;
            opt.sets = {p.name + "=" + repeated(p)};
            try {
                granrepro::resolve_parameters(e.name, opt);
                ADD_FAILURE() << e.name << " --set " << opt.sets[0] << " accepted";
            } catch (const InputError& err) {
                const std::string msg = err.what();
                EXPECT_NE(msg.find(p.name + ": entries"), std::string::npos) << e.name << ": " << msg;
                EXPECT_NE(msg.find("both named"), std::string::npos) << e.name << ": " << msg;
            }
        }
    }
    EXPECT_GE(lists, 20); // 27 lists in 8 experiments when this was written
}

// impact-parameter names its cooling runs with two decimals (r0.80), as its experiment file
// declares (name_decimals = 2): 0.801 and 0.804 are one name there, 0.81 and 0.84 are not.
TEST(HostileInputsLists, DeclaredNameDecimalsDecideWhatIsARepeat) {
    const std::string bad = "restitutions=0.801,0.804";
    expect_refusal(run_argv({"impact-parameter", "--dry-run", "--set", bad}), 2, {"restitutions: entries", "'0.80'", "2 decimals"});
    EXPECT_EQ(run_argv({"impact-parameter", "--dry-run", "--set", "restitutions=0.81,0.84"}).code, 0);
}

// Two lists that share a time: pipe-arching records a frame of both once and names its table
// pnc_t0.050 once, so the after-arch times would shift against their list.
TEST(HostileInputsLists, PipeArchingBeforeAndAfterTimesMustNotShareATime) {
    expect_refusal(run_argv({"pipe-arching", "--dry-run", "--set", "dist_times_after=0.05,0.065"}), 2,
                   {"dist_times_before 0.05 s and dist_times_after 0.05 s", "must not share a time"});
    EXPECT_EQ(run_argv({"pipe-arching", "--dry-run", "--set", "dist_times_after=0.055,0.065"}).code, 0);
}

// Issue 40 §4: emergency-brake --set vx_list=16 (and 24) ran past 60 s while --dry-run said 0: at
// the default kN_scan entry 200 the grain goes through the wall and every shot runs to max_steps.
TEST(HostileInputsEmergencyBrake, AShotThroughTheWallIsRefusedFastWithAndWithoutDryRun) {
    const cli_support::TempPath base("hostile-eb");
    const fs::path out = base / "out";
    for (const char* set : {"vx_list=16", "vx_list=24"})
        for (const bool dry : {true, false}) {
            std::vector<std::string> args{"emergency-brake", "--quiet", "--set", set, "--out", out.string()};
            if (dry) args.push_back("--dry-run");
            const auto t0 = std::chrono::steady_clock::now();
            const Outcome o = run_argv(args);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            SCOPED_TRACE(std::string(set) + (dry ? " --dry-run" : ""));
            expect_refusal(o, 2, {"vx_list = ", "kN_scan", "through the wall", "max_steps"});
            EXPECT_LT(s, 10.0) << "refused only after " << s << " s";
            EXPECT_FALSE(fs::exists(out));
        }
    // The defaults, and a fast v_x^i that stays on its side of the wall, still pass.
    EXPECT_EQ(run_argv({"emergency-brake", "--dry-run"}).code, 0);
    EXPECT_EQ(run_argv({"emergency-brake", "--dry-run", "--set", "vx_list=0.3,11"}).code, 0);
}

// Issue 40 §4: terminal escapes in a claim id reached the terminal raw through `check`.
TEST(HostileInputsEscapes, AClaimIdWithTerminalEscapesIsPrintedEscaped) {
    const Crafted c("escape-id");
    const ProjectCopy home("hostile-escape-home");
    home.replace("expected/brake-failure.toml", "id = \"t_col_paper\"",
                 "id = \"t_col\\u001B]0;pwned\\u0007\\u001B[2J\\r\\u009Bx\\u202Eevil\"");
    const Outcome o = run_home(home, {"check", "brake-failure", "--out", c.out.string()});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_FALSE(has_raw_escape(o.out) || has_raw_escape(o.err)) << o.out;
    EXPECT_EQ(o.out.find('\r'), std::string::npos);
    EXPECT_NE(o.out.find("t_col\\e]0;pwned\\x07\\e[2J\\r\\u{009B}x\\u{202E}evil"), std::string::npos) << o.out;
    c.expect_sentinel_unchanged();
}

// A forged overridden_parameters (summary.json and the hash data.h5 keeps of it, both rewritten,
// as a forger would) is printed escaped under the table, whatever check makes of it.
TEST(HostileInputsEscapes, ForgedOverriddenParametersArePrintedEscaped) {
    const Crafted c("escape-sets");
    const fs::path summary_file = c.dir() / "summary.json";
    nlohmann::json summary = nlohmann::json::parse(slurp(summary_file));
    summary["overridden_parameters"] = {{"k_N\x1b[31m", "3000\x1b]8;;http://x\x07"}};
    std::ofstream(summary_file, std::ios::trunc) << granrepro::summary_text(summary);
    set_string_attr(c.dir() / "data.h5", "/", "summary_json_hash", granrepro::summary_content_hash(summary));
    set_string_attr(c.dir() / "data.h5", "/provenance", "overridden_parameters", "k_N\x1b[31m=3000\x1b]8;;http://x\x07");
    const Outcome o = run_argv({"check", "brake-failure", "--out", c.out.string()});
    EXPECT_FALSE(has_raw_escape(o.out) || has_raw_escape(o.err)) << o.code << "\n" << o.out << o.err;
    // Printed (exit 0: the note under the title) or refused (exit 2: one line naming it): escaped.
    EXPECT_NE((o.out + o.err).find("k_N\\e[31m"), std::string::npos) << o.code << "\n" << o.out << o.err;
    c.expect_sentinel_unchanged();
}

TEST(HostileInputsEscapes, PrintableKeepsTextAndEscapesControls) {
    using granrepro::printable;
    EXPECT_EQ(printable("v_crit ≈ 0.85, Δv_y \\ plain"), "v_crit ≈ 0.85, Δv_y \\ plain");
    EXPECT_EQ(printable("a\nb\tc\x1b[0m\x7f"), "a\\nb\\tc\\e[0m\\x7F");
    EXPECT_EQ(printable("\xff\xc3"), "\\xFF\\xC3");          // invalid UTF-8, a cut sequence
    EXPECT_EQ(printable("\xc0\xaf"), "\\xC0\\xAF");          // overlong '/'
    EXPECT_EQ(printable("\xc2\x9b" "1m"), "\\u{009B}1m");     // C1 CSI
    EXPECT_EQ(printable("\xe2\x80\xae" "x"), "\\u{202E}x");   // right-to-left override
}

// Issue 40 §6: ids were cut with `~` in the check table (above_vcrit_accelerates_to_emerge~).
TEST(HostileInputsTable, ALongClaimIdIsNeverCut) {
    const Crafted c("long-id");
    const ProjectCopy home("hostile-long-id-home");
    const std::string id = "t_col_paper_with_an_id_far_longer_than_the_thirty_four_columns_of_old";
    home.replace("expected/brake-failure.toml", "id = \"t_col_paper\"", "id = \"" + id + "\"");
    const Outcome o = run_home(home, {"check", "brake-failure", "--out", c.out.string()});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find(id + " "), std::string::npos) << o.out;
    EXPECT_EQ(o.out.find("~"), std::string::npos) << o.out;
}

// Issue 40 §5: `paper = 1e400` in expected/ silently became 1.8e308.
TEST(HostileInputsToml, AnOutOfRangeNumberInExpectedIsRefusedAtItsLine) {
    const Crafted c("expected-1e400");
    const ProjectCopy home("hostile-1e400-home");
    const long line = home.replace("expected/brake-failure.toml", "paper = 7.07e-5", "paper = 1e400");
    const std::string where = "expected/brake-failure.toml:" + std::to_string(line) + ":";
    expect_refusal(run_home(home, {"check", "brake-failure", "--out", c.out.string()}), 2,
                   {where, "claim t_col_paper: paper = 1e400", "out-of-range"});
    expect_refusal(run_home(home, {"brake-failure", "--dry-run"}), 2, {where, "1e400"});
    const long tiny = home.replace("expected/brake-failure.toml", "paper = 1e400", "paper = 1e-400");
    expect_refusal(run_home(home, {"brake-failure", "--dry-run"}), 2,
                   {"expected/brake-failure.toml:" + std::to_string(tiny) + ":", "1e-400", "subnormal"});
}

// Issue 40 §5: these errors in experiments/*.toml came without file:line.
TEST(HostileInputsToml, ExperimentFileErrorsNameFileAndLine) {
    struct Case {
        std::string from, to, says;
    };
    const std::vector<Case> cases = {
        {"range = \"(0, inf)\"", "range = \"(1, 0)\"", "is empty (written backwards?"}, // d_free's
        {"value = 1.0e4", "value = nan", "is NaN"},                                      // gamma_N
        {"value = [0.1, 100.0]", "value = []", "empty array"},                           // betas
        {"value = 1.0e4", "value = 1979-05-27", "unsupported type"},                     // gamma_N
        {"quick = 31", "quick = 31.5", "must be an integer"},                            // n_vy
        {"value = 1.0e4", "value = 1e400", "out-of-range"},
        {"value = 1.0e4", "value = 1e-310", "subnormal"},
        {"value = [0.1, 100.0]", "value = [100.0, 100.0]", "both named '100'"},
    };
    for (const Case& k : cases) {
        const ProjectCopy home("hostile-toml-home");
        const long line = home.replace("experiments/brake-failure.toml", k.from, k.to);
        SCOPED_TRACE(k.to);
        expect_refusal(run_home(home, {"brake-failure", "--dry-run"}), 2,
                       {"experiments/brake-failure.toml:" + std::to_string(line) + ":", k.says});
    }
}

// Issue 40 §5: gamma_N=1e-308 was refused as "must be a number in [0, inf)".
TEST(HostileInputsToml, ASubnormalOverrideIsCalledSo) {
    expect_refusal(run_argv({"brake-failure", "--dry-run", "--set", "gamma_N=1e-308"}), 2, {"gamma_N", "subnormal"});
    expect_refusal(run_argv({"brake-failure", "--dry-run", "--set", "betas=0.1,1e400"}), 2, {"betas", "beyond the largest double"});
}

// Issue 40 §4: `all`, rerun after an interruption, recomputed experiments whose complete results
// were in place. complete_result() is what `all` asks before each experiment.
TEST(HostileInputsAll, ACompleteMatchingResultIsNotRecomputed) {
    const Crafted c("all-skip");
    RunOptions opt;
    opt.out = c.out;
    EXPECT_TRUE(granrepro::complete_result("brake-failure", opt));
    RunOptions other = opt;
    other.seed = 2;
    EXPECT_FALSE(granrepro::complete_result("brake-failure", other)) << "another seed";
    other = opt;
    other.scale = granrepro::Scale::Paper;
    EXPECT_FALSE(granrepro::complete_result("brake-failure", other)) << "another scale";
    other = opt;
    other.sets = {"n_vy=5"};
    EXPECT_FALSE(granrepro::complete_result("brake-failure", other)) << "--set";
    EXPECT_FALSE(granrepro::complete_result("emergency-brake", opt)) << "no results";
    // A figure missing or cut short, or an edited summary: computed again.
    const fs::path png = c.dir() / "schaefer95-fig3.png";
    if (fs::exists(png)) {
        const std::string whole = slurp(png);
        std::ofstream(png, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);
        EXPECT_FALSE(granrepro::complete_result("brake-failure", opt)) << "a PNG cut short";
        std::ofstream(png, std::ios::binary | std::ios::trunc) << whole;
        EXPECT_TRUE(granrepro::complete_result("brake-failure", opt));
    }
    std::string summary = slurp(c.dir() / "summary.json");
    summary.replace(summary.find("\"seed\": 1"), 9, "\"seed\": 1 ");
    std::ofstream(c.dir() / "summary.json", std::ios::trunc) << summary.replace(summary.find("PASS"), 4, "FAIL");
    EXPECT_FALSE(granrepro::complete_result("brake-failure", opt)) << "an edited summary.json";
}
