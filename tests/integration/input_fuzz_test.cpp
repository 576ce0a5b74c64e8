// Issue 20: every value a user can give a declared parameter is either refused up front (an
// InputError: exit 2, one line naming the parameter) or accepted with a bounded cost. Each
// experiment's parameters get their range edges, 0, +-huge, NaN and inf through --set at both
// scales; the check is what `granrepro <experiment> --dry-run --set name=value` runs
// (resolve_parameters: load, --set, validate with the work estimates), in-process so that the
// ~2500 probes take seconds. A crash, a non-input exception, a multi-line or anonymous refusal,
// or a probe that takes more than 10 s fails here. The binary is run once per experiment to show
// that such a refusal is exit 2 with nothing written.
//
// Issue 25: InputFuzzRun runs the engines. Per experiment and numeric parameter, the probes
// {range edges, 0, +-1e308, +-1e-300, nan, inf} go over a quick run made short by the experiment
// file's smoke scale ([smoke] set in experiments/<name>.toml: small sizes, budgets and windows). A
// probe validation refuses must name the parameter (checked in-process, milliseconds); of the
// accepted ones the smallest and the largest run the binary. For a parameter the smoke scale sets
// (a size or budget: its upper edge is a long run by design, bounded by limit_work) only the
// smallest, and none above its smoke value. Within
// kRunSeconds a run must exit 0, 1 (a claim may fail at these sizes) or 4 (a figure not drawn:
// the stand-in gnuplot, /bin/true, keeps figures out of the cost and draws none) with
// summary.json written and no internal error, or exit 2 with one line naming the parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"
#include "core/input_error.hpp"
#include "harness/runner.hpp"

using namespace granrepro;
namespace fs = std::filesystem;

namespace {

std::string text_of(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// The probes for one parameter: its range edges, 0, +-huge, NaN and +-inf (integers also their
// extremes and a number beyond them); text parameters a value not among their choices.
std::vector<std::string> probes(const Parameter& p) {
    switch (p.kind) {
    case Parameter::Kind::Flag: return {"maybe", "2"};
    case Parameter::Kind::Text: return p.choices.empty() ? std::vector<std::string>{} : std::vector<std::string>{"bogus"};
    default: break;
    }
    std::vector<std::string> v{"0", "1e308", "-1e308", "nan", "inf", "-inf", "-1"};
    if (p.kind == Parameter::Kind::Integer)
        v.insert(v.end(), {"9223372036854775807", "-9223372036854775808", "99999999999999999999999", "2.5"});
    if (p.has_range) {
        for (double edge : {p.range.lo, p.range.hi})
            if (std::isfinite(edge)) {
                v.push_back(text_of(edge));
                v.push_back(text_of(std::nextafter(edge, 0.0)));
            }
    }
    if (p.kind == Parameter::Kind::RealList) v.push_back(p.value_text() + ",1e308");
    return v;
}

class InputFuzz : public ::testing::TestWithParam<std::string> {};

TEST_P(InputFuzz, EveryProbeIsRefusedInOneNamingLineOrAcceptedQuickly) {
    const std::string name = GetParam();
    int refused = 0, accepted = 0;
    for (Scale scale : {Scale::Quick, Scale::Paper}) {
        const ParameterSet defaults = ParameterSet::load(experiment_info(name).file, scale);
        for (const Parameter& p : defaults.all())
            for (const std::string& value : probes(p)) {
                RunOptions opt;
                opt.scale = scale;
                opt.sets = {p.name + "=" + value};
                const std::string probe = name + " --scale " + to_string(scale) + " --set " + opt.sets[0];
                const auto t0 = std::chrono::steady_clock::now();
                try {
                    resolve_parameters(name, opt);
                    ++accepted;
                } catch (const InputError& e) {
                    ++refused;
                    const std::string msg = e.what();
                    EXPECT_EQ(msg.find('\n'), std::string::npos) << probe << ": " << msg;
                    EXPECT_NE(msg.find(p.name), std::string::npos) << probe << ": the refusal does not name " << p.name
                                                                   << ": " << msg;
                    EXPECT_LT(msg.size(), 400u) << probe << ": " << msg;
                } catch (const std::exception& e) {
                    ADD_FAILURE() << probe << ": not an input error (exit 1): " << e.what();
                }
                const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                // Seconds, not minutes (a probe takes ~0.05 s; the bound leaves room for a loaded
                // CI machine).
                EXPECT_LT(s, 10.0) << probe << ": validation took " << s << " s";
            }
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(accepted, 0);
    std::printf("%s: %d probes refused, %d accepted\n", name.c_str(), refused, accepted);

    // The same refusal through the binary: exit 2, one line, nothing written.
    const cli_support::TempPath out("fuzz-" + name);
    const ParameterSet quick = ParameterSet::load(experiment_info(name).file, Scale::Quick);
    const Parameter& first = quick.all().front();
    cli_support::expect_one_line_exit(cli_support::run(name + " --quiet --set " + first.name + "=nan --out " + out.string()),
                                      2, {first.name});
    EXPECT_FALSE(fs::exists(out)) << "output written for bad input";
}

constexpr double kRunSeconds = 20; // a smoke-scale run takes ~1 s; the rest is room for a loaded machine

// The binary with `args`, stdout and stderr to files, killed after `limit` seconds (code -2);
// an argument vector, no shell.
cli_support::Outcome run_limited(const std::vector<std::string>& args, const fs::path& dir, double limit) {
    std::vector<std::string> argv_s{GRANREPRO_BINARY};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    const fs::path out = dir / "stdout", err = dir / "stderr";
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const fs::path stub = dir / "bin";
    fs::create_directories(stub);
    std::error_code ec;
    fs::create_symlink("/bin/true", stub / "gnuplot", ec);
    std::string path = "PATH=" + stub.string() + ":" + (std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin");
    std::vector<char*> envp;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("PATH=", 0) != 0) envp.push_back(*e);
    envp.push_back(path.data());
    envp.push_back(nullptr);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) return {-3, "posix_spawn failed", ""};
    const auto t0 = std::chrono::steady_clock::now();
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > limit) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return {-2, cli_support::slurp(err), ""};
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, cli_support::slurp(err), cli_support::slurp(out)};
}

class InputFuzzRun : public ::testing::TestWithParam<std::string> {};

TEST_P(InputFuzzRun, EveryProbeRunsToAResultOrIsRefusedNamingItsParameter) {
    const std::string name = GetParam();
    // The experiment file's smoke scale ([smoke] set): without one, every probe would be a whole
    // quick run, so an experiment file that lacks it fails here.
    const std::vector<std::string> shorts = experiment_info(name).smoke;
    ASSERT_FALSE(shorts.empty()) << "experiments/" << name << ".toml has no [smoke] set (the overrides that make a quick run "
                                 << "take about a second; see the other experiment files)";
    const ParameterSet defaults = ParameterSet::load(experiment_info(name).file, Scale::Quick);
    const cli_support::TempPath dir("fuzz-run-" + name);
    fs::create_directories(dir);
    int refused = 0, ran = 0;
    const auto t_all = std::chrono::steady_clock::now();
    for (const Parameter& p : defaults.all()) {
        if (p.kind == Parameter::Kind::Text || p.kind == Parameter::Kind::Flag) continue;
        std::vector<std::string> sets;
        double budget = INFINITY; // the smoke value of a size or budget parameter: no run above it
        for (const std::string& a : shorts) {
            if (a.substr(0, a.find('=')) == p.name) budget = std::stod(a.substr(a.find('=') + 1));
            else sets.push_back(a);
        }
        std::vector<std::string> values{"0", "1e308", "-1e308", "1e-300", "-1e-300", "nan", "inf"};
        if (p.has_range)
            for (double edge : {p.range.lo, p.range.hi})
                if (std::isfinite(edge)) values.push_back(text_of(edge));
        std::vector<std::pair<double, std::string>> accepted;
        for (const std::string& v : values) {
            RunOptions opt;
            opt.sets = sets;
            opt.sets.push_back(p.name + "=" + v);
            try {
                resolve_parameters(name, opt);
                accepted.emplace_back(std::stod(v), v);
            } catch (const InputError& e) {
                ++refused;
                EXPECT_NE(std::string(e.what()).find(p.name), std::string::npos)
                    << name << " --set " << p.name << "=" << v << ": the refusal does not name it: " << e.what();
            } catch (const std::exception& e) {
                ADD_FAILURE() << name << " --set " << p.name << "=" << v << ": not an input error: " << e.what();
            }
        }
        std::erase_if(accepted, [&](const auto& a) { return a.first > budget; });
        if (accepted.empty()) continue;
        std::sort(accepted.begin(), accepted.end());
        std::vector<std::string> run_values{accepted.front().second};
        if (std::isinf(budget) && accepted.back().first != accepted.front().first) run_values.push_back(accepted.back().second);
        for (const std::string& v : run_values) {
            const fs::path out = dir / "out";
            fs::remove_all(out);
            std::vector<std::string> args{name, "--quiet", "--out", out.string()};
            for (const std::string& a : sets) args.insert(args.end(), {"--set", a});
            args.insert(args.end(), {"--set", p.name + "=" + v});
            const std::string probe = name + " --set " + p.name + "=" + v;
            const auto t0 = std::chrono::steady_clock::now();
            const cli_support::Outcome o = run_limited(args, dir, kRunSeconds);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            ++ran;
            if (o.code == 2) {
                EXPECT_EQ(cli_support::lines(o.err), 1) << probe << ": " << o.err;
                EXPECT_NE(o.err.find(p.name), std::string::npos) << probe << ": the refusal does not name it: " << o.err;
                continue;
            }
            EXPECT_NE(o.code, -2) << probe << ": still running after " << kRunSeconds << " s (killed)";
            EXPECT_TRUE(o.code == 0 || o.code == 1 || o.code == kFigureNotDrawn) << probe << ": exit " << o.code << " after " << s << " s: " << o.err;
            EXPECT_EQ(o.err.find("error:"), std::string::npos) << probe << ": " << o.err;
            EXPECT_TRUE(fs::exists(out / name / "summary.json")) << probe << ": no summary.json; exit " << o.code << ": " << o.err;
        }
    }
    EXPECT_GT(ran, 0);
    std::printf("%s: %d probes refused, %d runs, %.1f s\n", name.c_str(), refused, ran,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t_all).count());
}

std::vector<std::string> experiment_names() {
    std::vector<std::string> names;
    for (const auto& e : experiment_registry()) names.push_back(e.name);
    return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string s = info.param;
    for (char& c : s)
        if (c == '-') c = '_';
    return s;
}

INSTANTIATE_TEST_SUITE_P(Experiments, InputFuzz, ::testing::ValuesIn(experiment_names()), test_name);
// Named under Experiments/InputFuzz, which scripts/test.sh keeps out of the sanitizer pass.
INSTANTIATE_TEST_SUITE_P(Experiments, InputFuzzRun, ::testing::ValuesIn(experiment_names()), test_name);

} // namespace
