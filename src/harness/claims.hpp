// The papers' claims (expected/<experiment>.toml) and their verdicts against a run's scalars.
// A claim is either a value with a relative or absolute tolerance, or a range [min, max] for a
// relation ("slope between -1.1 and -0.9"). Every tolerance carries its justification. A claim we
// cannot reproduce stays in the file as a known deviation with its reason: it is shown, not hidden,
// and it keeps a band of its own (deviation_band: the value we measure and its reproducible spread,
// for every scale or per scale), so the deviation itself is guarded and can still fail.
//
// Verdicts: measured within the paper's tolerance -> PASS; else a known deviation whose measured
// value lies in its band for the run's scale -> DEVIATION; else FAIL. A missing or non-finite
// measurement FAILs every claim; a claim restricted (scales) to other scales is skipped.
#pragma once
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "data/parameter_set.hpp"
#include "data/outputs.hpp"

namespace granrepro {

// The allowed values of tolerance_kind and deviation_band_kind (expected/README.md explains them).
inline constexpr const char* kToleranceKinds[] = {"paper_precision", "error_bar", "grid", "physical_bound"};
inline constexpr const char* kDeviationBandKinds[] = {"seed_spread", "error_bar", "grid", "single_run", "absent"};
// What a claim is (expected/README.md, "Roles"): only reproductions make the headline.
inline constexpr const char* kClaimRoles[] = {"reproduction", "identity", "calibration", "validation"};
// How far a known deviation is understood: settled by a decisive run, inherent to the model or
// method (an independent check or argument), or open (the text names the run that would decide).
inline constexpr const char* kDeviationStatuses[] = {"settled", "inherent", "open"};

// A closed interval [lo, hi]; either end may be infinite.
// A known deviation's band: [lo, hi], or "absent": the measured quantity does not exist in our
// runs (a property of a branch that no run reaches: no value, or NaN); a value appearing leaves it.
struct Band {
    double lo = 0, hi = 0;
    bool absent = false;
    bool contains(double x) const { return absent ? !std::isfinite(x) : x >= lo && x <= hi; }
};

struct Claim {
    std::string id, statement, source;
    std::string measured;        // name of the scalar in the run's summary
    std::optional<double> paper; // the paper's number, if it states one
    std::optional<double> rel_tol, abs_tol, min, max;
    std::string tolerance_reason;
    // Where the tolerance comes from (expected/README.md, "How bands are set"): one of
    // kToleranceKinds; a referee sees at once which bands rest on the paper and which on statistics.
    std::string tolerance_kind;
    std::string known_deviation;     // non-empty: not reproduced, with the reason
    std::optional<Band> deviation_band;                  // our value and spread, every scale
    std::map<std::string, Band> deviation_band_by_scale; // ... or per scale ("quick", "paper")
    std::string deviation_band_reason;                   // where the band comes from
    std::string deviation_band_kind;                     // one of kDeviationBandKinds
    std::vector<std::string> scales; // empty: every scale
    std::string role;   // one of kClaimRoles
    std::string status; // one of kDeviationStatuses, for a known deviation only
    // The figure the claim belongs to, where its source names none of its experiment's figures
    // (`figure = "luding98-fig04"`, one of experiments/<name>.toml's ids): `figure` and the
    // report show it there. Empty: the figures its source cites (cites_figure).
    std::string figure;
    long line = 0;      // of its [[claim]] table, for messages
    std::string publication; // "Luding 1998": the paper of the experiment (experiments/<name>.toml), if found

    bool applies_to(Scale scale) const;
    // The known deviation's band at this scale (nullopt: no known deviation there).
    std::optional<Band> band_for(Scale scale) const;
};

enum class Verdict { Pass, Fail, KnownDeviation, Skipped };
const char* to_string(Verdict v);

struct ClaimResult {
    Claim claim;
    std::optional<double> measured;
    Verdict verdict = Verdict::Fail;
    std::string expected_text, band_text, tolerance_text;
};

struct VerdictCounts {
    int pass = 0, fail = 0, deviation = 0, skipped = 0;
    void add(const std::vector<ClaimResult>& results);
    std::string text() const; // "N PASS, N FAIL, N DEVIATION, N skipped"
    // Per paper: the reproductions by verdict and deviation status, and the other roles apart.
    struct PaperCounts {
        int statements = 0, reproduced = 0, deviate = 0, failed = 0;
        std::map<std::string, int> status; // of the deviating reproductions
        std::map<std::string, int> other;  // identity, calibration, validation (not skipped)
        int other_pass = 0, other_fail = 0, other_deviation = 0;
    };
    std::vector<std::pair<std::string, PaperCounts>> papers; // in the order first seen
    // "Luding 1998: N statements — P reproduced, D deviate (s settled, i inherent, o open)" and,
    // on its own line, "Luding 1998, not in the headline: ..." per paper.
    std::string headline() const;
    // What check --all and all close with: the headline, "totals: <text()>", and, when some were
    // skipped, one line saying what skipped means (README, "Resuming, checking, verifying").
    std::string closing() const;
};

// Throws InputError naming the file, the claim and the key for a malformed claim, including a
// known deviation without a band (or without its reason) at a scale where it applies, and a
// missing or unknown tolerance_kind / deviation_band_kind, and, given the experiment's declared
// outputs, a claim whose measured scalar is not among them.
std::vector<Claim> load_claims(const std::filesystem::path& file, const std::string& experiment,
                               const DeclaredOutputs* outputs = nullptr);
// scalars: name -> value (null or NaN for a measurement that could not be made).
std::vector<ClaimResult> evaluate_claims(const std::vector<Claim>& claims,
                                         const nlohmann::json& scalars, Scale scale);
// One row per claim: the paper's value or relation beside our deviation band. Each note is a line
// under the title (the --set overrides, an unverified result).
std::string format_claim_table(const std::string& experiment, const std::vector<ClaimResult>& results,
                               const std::vector<std::string>& notes = {});
// The known-deviation texts and band reasons of the claims that are not PASS (`check --explain`).
std::string format_deviation_explanations(const std::vector<ClaimResult>& results);
nlohmann::json claims_to_json(const std::vector<ClaimResult>& results);
// The headline of `results` (VerdictCounts::headline as JSON): per paper, statements, reproduced,
// deviate, fail, status counts and the other roles' counts.
nlohmann::json headline_json(const VerdictCounts& counts);
bool all_pass(const std::vector<ClaimResult>& results); // known deviations and skips do not fail

// True if the claim belongs to figure_id ("schaefer95-fig4", "luding98-fig02"): the figure it
// names (Claim::figure), or else one its `source` cites ("text below Fig. 4", "Figs. 4, 5",
// "Fig. 10(a)") numbered like the end of figure_id. What `figure` and the report show of a run's claims.
bool cites_figure(const Claim& claim, const std::string& figure_id);

} // namespace granrepro
