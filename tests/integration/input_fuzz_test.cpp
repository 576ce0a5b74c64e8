// Issue 20: every value a user can give a declared parameter is either refused up front (an
// InputError: exit 2, one line naming the parameter) or accepted with a bounded cost. Each
// experiment's parameters get their range edges, 0, +-huge, NaN and inf through --set at both
// scales; the check is what `granrepro <experiment> --dry-run --set name=value` runs
// (resolve_parameters: load, --set, validate with the work estimates), in-process so that the
// ~2500 probes take seconds. A crash, a non-input exception, a multi-line or anonymous refusal,
// or a probe that takes more than 10 s fails here. The binary is run once per experiment to show
// that such a refusal is exit 2 with nothing written.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
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

std::vector<std::string> experiment_names() {
    std::vector<std::string> names;
    for (const auto& e : experiment_registry()) names.push_back(e.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Experiments, InputFuzz, ::testing::ValuesIn(experiment_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string s = info.param;
                             for (char& c : s)
                                 if (c == '-') c = '_';
                             return s;
                         });

} // namespace
