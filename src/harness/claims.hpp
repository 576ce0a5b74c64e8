// The papers' claims (expected/<experiment>.toml) and their verdicts against a run's scalars.
// A claim is either a value with a relative or absolute tolerance, or a range [min, max] for a
// relation ("slope between -1.1 and -0.9"). Every tolerance carries its justification. A claim we
// cannot reproduce stays in the file as a known deviation with its reason: it is shown, not hidden.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "harness/parameter_set.hpp"

namespace granrepro {

struct Claim {
    std::string id, statement, source;
    std::string measured;        // name of the scalar in the run's summary
    std::optional<double> paper; // the paper's number, if it states one
    std::optional<double> rel_tol, abs_tol, min, max;
    std::string tolerance_reason;
    std::string known_deviation; // non-empty: not reproduced, with the reason
    std::vector<std::string> scales; // empty: every scale
};

enum class Verdict { Pass, Fail, KnownDeviation, Skipped };
const char* to_string(Verdict v);

struct ClaimResult {
    Claim claim;
    std::optional<double> measured;
    Verdict verdict = Verdict::Fail;
    std::string expected_text, tolerance_text;
};

std::vector<Claim> load_claims(const std::filesystem::path& file, const std::string& experiment);
// scalars: name -> value (NaN for a measurement that could not be made).
std::vector<ClaimResult> evaluate_claims(const std::vector<Claim>& claims,
                                         const nlohmann::json& scalars, Scale scale);
std::string format_claim_table(const std::string& experiment, const std::vector<ClaimResult>& results);
nlohmann::json claims_to_json(const std::vector<ClaimResult>& results);
bool all_pass(const std::vector<ClaimResult>& results); // known deviations and skips do not fail

} // namespace granrepro
