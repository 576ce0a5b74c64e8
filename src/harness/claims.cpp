#include "harness/claims.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <toml.hpp>

#include "core/input_error.hpp"
#include "data/printable.hpp"
#include "data/toml_file.hpp"

namespace granrepro {

const char* to_string(Verdict v) {
    switch (v) {
    case Verdict::Pass: return "PASS";
    case Verdict::Fail: return "FAIL";
    case Verdict::KnownDeviation: return "DEVIATION";
    default: return "skipped";
    }
}

namespace {
std::string num(double x) { return number_text(x, 4); }

std::string band_text(const Band& b) { return b.absent ? "absent" : "[" + num(b.lo) + ", " + num(b.hi) + "]"; }

const std::string kClaimKeys[] = {"id",      "statement",       "source",         "measured",
                                  "paper",   "rel_tol",         "abs_tol",        "min",
                                  "max",     "tolerance_reason", "tolerance_kind", "scales",
                                  "known_deviation", "deviation_band", "deviation_band_reason", "deviation_band_kind",
                                  "role", "status", "figure"};

// The tolerance column shows the kind in a word, so the table stays narrow.
std::string short_kind(const std::string& kind) {
    if (kind == "paper_precision") return "paper";
    if (kind == "error_bar") return "errbar";
    if (kind == "physical_bound") return "bound";
    return kind; // "grid"
}

// A number as written: 1e400 (which toml11 reads as 1.8e308) is refused at its file:line.
double number(const toml::value& v, const std::string& file, const std::string& what) {
    return toml_number(v, file, what);
}

// [lo, hi] with lo <= hi (inf and -inf allowed).
// `what` ("claim x: deviation_band") names it in a refusal at its file:line.
Band parse_band(const toml::value& v, const std::string& where, const std::string& file, const std::string& what) {
    if (v.is_string() && v.as_string() == "absent") return Band{0, 0, true};
    if (!v.is_array() || v.as_array().size() != 2)
        throw InputError(where + " must be [lo, hi] or \"absent\"");
    const auto& a = v.as_array();
    if (!(a[0].is_integer() || a[0].is_floating()) || !(a[1].is_integer() || a[1].is_floating()))
        throw InputError(where + " must be [lo, hi] with two numbers (inf and -inf allowed)");
    const Band b{number(a[0], file, what), number(a[1], file, what)};
    if (std::isnan(b.lo) || std::isnan(b.hi) || b.lo > b.hi)
        throw InputError(where + " must be [lo, hi] with lo <= hi");
    return b;
}
} // namespace

bool Claim::applies_to(Scale scale) const {
    return scales.empty() || std::find(scales.begin(), scales.end(), to_string(scale)) != scales.end();
}

std::optional<Band> Claim::band_for(Scale scale) const {
    if (known_deviation.empty()) return std::nullopt;
    if (deviation_band) return deviation_band;
    const auto it = deviation_band_by_scale.find(to_string(scale));
    if (it == deviation_band_by_scale.end()) return std::nullopt;
    return it->second;
}

namespace {
// The per-paper counts of the headline: reproductions by verdict (and a deviation's status), the
// other roles apart; skipped claims are in neither.
void add_to_headline(std::vector<std::pair<std::string, VerdictCounts::PaperCounts>>& papers,
                     const std::vector<ClaimResult>& results) {
    for (const auto& r : results) {
        if (r.verdict == Verdict::Skipped) continue;
        const std::string paper = r.claim.publication.empty() ? "(no paper)" : r.claim.publication;
        auto it = std::find_if(papers.begin(), papers.end(), [&](const auto& p) { return p.first == paper; });
        if (it == papers.end()) it = papers.insert(papers.end(), {paper, {}});
        VerdictCounts::PaperCounts& c = it->second;
        if (r.claim.role == "reproduction") {
            ++c.statements;
            if (r.verdict == Verdict::Pass) ++c.reproduced;
            else if (r.verdict == Verdict::KnownDeviation) ++c.deviate, ++c.status[r.claim.status];
            else ++c.failed;
        } else {
            ++c.other[r.claim.role];
            if (r.verdict == Verdict::Pass) ++c.other_pass;
            else if (r.verdict == Verdict::KnownDeviation) ++c.other_deviation;
            else ++c.other_fail;
        }
    }
}

int count_of(const std::map<std::string, int>& m, const std::string& key) {
    const auto it = m.find(key);
    return it == m.end() ? 0 : it->second;
}
} // namespace

std::string VerdictCounts::headline() const {
    std::string out;
    for (const auto& [paper, c] : papers) {
        out += paper + ": " + std::to_string(c.statements) + " statements \u2014 " + std::to_string(c.reproduced) +
               " reproduced, " + std::to_string(c.deviate) + " deviate (" + std::to_string(count_of(c.status, "settled")) +
               " settled, " + std::to_string(count_of(c.status, "inherent")) + " inherent, " +
               std::to_string(count_of(c.status, "open")) + " open)" +
               (c.failed ? ", " + std::to_string(c.failed) + " FAIL" : std::string()) + "\n";
        out += paper + ", not in the headline: " + std::to_string(count_of(c.other, "identity")) + " identity, " +
               std::to_string(count_of(c.other, "calibration")) + " calibration, " +
               std::to_string(count_of(c.other, "validation")) + " validation (" + std::to_string(c.other_pass) +
               " PASS, " + std::to_string(c.other_fail) + " FAIL, " + std::to_string(c.other_deviation) + " DEVIATION)\n";
    }
    return out;
}

nlohmann::json headline_json(const VerdictCounts& counts) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [paper, c] : counts.papers) {
        nlohmann::json status = nlohmann::json::object(), other = nlohmann::json::object();
        for (const char* s : kDeviationStatuses) status[s] = count_of(c.status, s);
        for (const char* role : kClaimRoles)
            if (std::string(role) != "reproduction") other[role] = count_of(c.other, role);
        out.push_back({{"paper", paper}, {"statements", c.statements}, {"reproduced", c.reproduced},
                       {"deviate", c.deviate}, {"fail", c.failed}, {"status", status}, {"other", other},
                       {"other_verdicts", {{"PASS", c.other_pass}, {"FAIL", c.other_fail}, {"DEVIATION", c.other_deviation}}}});
    }
    return out;
}

void VerdictCounts::add(const std::vector<ClaimResult>& results) {
    for (const auto& r : results) {
        switch (r.verdict) {
        case Verdict::Pass: ++pass; break;
        case Verdict::Fail: ++fail; break;
        case Verdict::KnownDeviation: ++deviation; break;
        case Verdict::Skipped: ++skipped; break;
        }
    }
    add_to_headline(papers, results);
}

std::string VerdictCounts::closing() const {
    return headline() + "totals: " + text() + "\n" +
           (skipped ? "(skipped: claims stated for the other scale; their values are shown for information, not judged)\n" : "");
}

std::string VerdictCounts::text() const {
    return std::to_string(pass) + " PASS, " + std::to_string(fail) + " FAIL, " + std::to_string(deviation) +
           " DEVIATION, " + std::to_string(skipped) + " skipped";
}

namespace {

std::string line_of(const toml::value& v) { return " (line " + std::to_string(v.location().line()) + ")"; }

// One [[claim]] table being read: its location for messages and the checks every key shares.
struct ClaimReader {
    const toml::value& c;
    std::string where; // "<file>: claim <id>"
    std::string file;
    std::string id; // printable

    std::optional<double> number_at(const char* key) const {
        if (!c.contains(key)) return std::nullopt;
        const double x = number(c.at(key), file, "claim " + id + ": " + key);
        if (std::isnan(x)) throw InputError(where + line_of(c.at(key)) + ": " + key + " is NaN");
        return x;
    }
    void check_scale(const std::string& s, const std::string& key) const {
        if (s != "quick" && s != "paper") throw InputError(where + ": " + key + " names scale '" + s + "'; allowed: quick, paper");
    }
    // A band without its kind could be one set around our own output; the kind is checked here so
    // that no claim file can leave it out (expected/README.md, "How bands are set").
    template <class Allowed>
    std::string kind(const char* key, const Allowed& allowed) const {
        const std::string allowed_text = joined(allowed);
        if (!c.contains(key)) throw InputError(where + ": " + key + " is missing; allowed: " + allowed_text);
        const std::string value = toml::find<std::string>(c, key);
        if (std::find(std::begin(allowed), std::end(allowed), value) == std::end(allowed))
            throw InputError(where + line_of(c.at(key)) + ": " + key + " '" + value + "' is unknown; allowed: " + allowed_text);
        return value;
    }
};

// The claim's value and band: paper with rel_tol/abs_tol, or min/max, with their checks.
void read_band(const ClaimReader& r, Claim& k) {
    const toml::value& c = r.c;
    k.paper = r.number_at("paper");
    k.rel_tol = r.number_at("rel_tol");
    k.abs_tol = r.number_at("abs_tol");
    k.min = r.number_at("min");
    k.max = r.number_at("max");
    for (const auto& [key, val] : {std::pair{"rel_tol", k.rel_tol}, std::pair{"abs_tol", k.abs_tol}})
        if (val && !(*val >= 0 && std::isfinite(*val)))
            throw InputError(r.where + line_of(c.at(key)) + ": " + key + " = " + num(*val) + " must be a finite number >= 0");
    // The verdict would silently use rel_tol alone.
    if (k.rel_tol && k.abs_tol) throw InputError(r.where + line_of(c.at("abs_tol")) + ": give rel_tol or abs_tol, not both");
    if (k.paper && !std::isfinite(*k.paper))
        throw InputError(r.where + line_of(c.at("paper")) + ": paper = " + num(*k.paper) + " must be finite");
    if (k.min && k.max && *k.min > *k.max)
        throw InputError(r.where + line_of(c.at("min")) + ": min = " + num(*k.min) + " is above max = " + num(*k.max));
    const bool value_claim = k.paper && (k.rel_tol || k.abs_tol);
    const bool range_claim = k.min || k.max;
    if (!value_claim && !range_claim) throw InputError(r.where + " needs paper with rel_tol/abs_tol, or min/max");
    if (k.known_deviation.empty() && k.tolerance_reason.empty()) throw InputError(r.where + " needs a tolerance_reason");
    k.tolerance_kind = r.kind("tolerance_kind", kToleranceKinds);
}

// A known deviation's own band, its reason and kind (and none of them without a deviation).
void read_deviation(const ClaimReader& r, Claim& k) {
    const toml::value& c = r.c;
    if (c.contains("deviation_band")) {
        const toml::value& b = c.at("deviation_band");
        if (b.is_table()) {
            for (const auto& [scale, band] : b.as_table()) {
                r.check_scale(scale, "deviation_band");
                k.deviation_band_by_scale[scale] = parse_band(band, r.where + ": deviation_band." + scale, r.file,
                                                              "claim " + r.id + ": deviation_band." + scale);
            }
        } else {
            k.deviation_band = parse_band(b, r.where + ": deviation_band (or { quick = [lo, hi], paper = [lo, hi] })", r.file,
                                          "claim " + r.id + ": deviation_band");
        }
    }
    if (c.contains("deviation_band_reason")) k.deviation_band_reason = toml::find<std::string>(c, "deviation_band_reason");
    const bool has_band = k.deviation_band || !k.deviation_band_by_scale.empty();
    if (k.known_deviation.empty()) {
        if (has_band || !k.deviation_band_reason.empty() || c.contains("deviation_band_kind"))
            throw InputError(r.where + ": deviation_band (and its reason and kind) belongs only to a claim with known_deviation");
        return;
    }
    // A known deviation is a measured result: it needs its own band at every scale where the
    // claim applies, so that the deviation itself can still fail.
    for (const Scale scale : {Scale::Quick, Scale::Paper})
        if (k.applies_to(scale) && !k.band_for(scale))
            throw InputError(r.where + ": known_deviation needs deviation_band for scale " + to_string(scale) +
                             " (deviation_band = [lo, hi] or { quick = [lo, hi], paper = [lo, hi] })");
    if (k.deviation_band_reason.empty())
        throw InputError(r.where + ": known_deviation needs deviation_band_reason (where the band comes from)");
    k.deviation_band_kind = r.kind("deviation_band_kind", kDeviationBandKinds);
    bool any_absent = k.deviation_band && k.deviation_band->absent;
    for (const auto& [scale, band] : k.deviation_band_by_scale) any_absent = any_absent || band.absent;
    if (any_absent != (k.deviation_band_kind == "absent"))
        throw InputError(r.where + ": deviation_band = \"absent\" and deviation_band_kind = \"absent\" go together");
}

// The claim's role, and a known deviation's status (expected/README.md, "Roles"): missing or
// unknown is refused with the claim's line, as a headline must not count a claim of unknown kind.
void read_role_and_status(const ClaimReader& r, Claim& k) {
    const toml::value& c = r.c;
    auto one_of = [&](const char* key, const auto& allowed) {
        if (!c.contains(key))
            throw InputError(r.where + line_of(c) + ": " + key + " is missing; allowed: " + joined(allowed));
        const toml::value& v = c.at(key);
        const std::string value = v.is_string() ? v.as_string().str : std::string("(not a string)");
        if (std::find(std::begin(allowed), std::end(allowed), value) == std::end(allowed))
            throw InputError(r.where + line_of(v) + ": " + key + " '" + value + "' is unknown; allowed: " + joined(allowed));
        return value;
    };
    k.line = long(c.location().line());
    k.role = one_of("role", kClaimRoles);
    if (k.known_deviation.empty()) {
        if (c.contains("status"))
            throw InputError(r.where + line_of(c.at("status")) + ": status belongs only to a claim with known_deviation");
        return;
    }
    k.status = one_of("status", kDeviationStatuses);
}

// The claim ids a setting names: calibrated_on = "<id>" or ["<id>", ...] (one claim per scale).
std::vector<std::pair<std::string, long>> named_claims(const toml::value& table, const std::string& where) {
    std::vector<std::pair<std::string, long>> out;
    if (!table.is_table() || !table.contains("calibrated_on")) return out;
    const toml::value& v = table.at("calibrated_on");
    const long line = long(v.location().line());
    if (v.is_string()) out.emplace_back(v.as_string().str, line);
    else if (v.is_array() && !v.as_array().empty())
        for (const auto& e : v.as_array()) {
            if (!e.is_string()) break;
            out.emplace_back(e.as_string().str, line);
        }
    if (out.empty() || (v.is_array() && out.size() != v.as_array().size()))
        throw InputError(where + " (line " + std::to_string(line) + "): calibrated_on must be a claim id or a list of claim ids");
    return out;
}

// The paper of the experiment (for the headline) and the calibrations: a calibration claim is
// named by a setting of experiments/<experiment>.toml (calibrated_on = "<claim id>" on a
// [parameters.<name>] table, or on a [readings.<name>] table for a reading of the paper that no
// parameter holds, e.g. the unit of a printed number), and every calibrated_on names a
// calibration claim of this file. The experiment file is the claims file's sibling
// (<root>/experiments/<experiment>.toml); without one, no calibration claim can be named.
void check_calibrations(std::vector<Claim>& claims, const std::filesystem::path& file, const std::string& experiment) {
    const std::filesystem::path exp_file = file.parent_path().parent_path() / "experiments" / (experiment + ".toml");
    const std::string exp_where = exp_file.string();
    std::vector<std::string> named; // every id a setting names
    if (std::filesystem::exists(exp_file)) {
        const toml::value root = parse_toml_file(exp_file, "experiment file");
        if (root.is_table() && root.contains("paper") && root.at("paper").is_string()) {
            // "Luding, TASK Quarterly 2, 417 (1998)" -> "Luding 1998"
            const std::string p = root.at("paper").as_string().str;
            const auto open = p.rfind('('), close = p.rfind(')');
            std::string label = p.substr(0, p.find(','));
            if (open != std::string::npos && close != std::string::npos && close > open)
                label += " " + p.substr(open + 1, close - open - 1);
            for (auto& c : claims) c.publication = label;
        }
        for (const char* section : {"parameters", "readings"}) {
            if (!root.is_table() || !root.contains(section) || !root.at(section).is_table()) continue;
            for (const auto& [name, table] : root.at(section).as_table()) {
                const std::string where = exp_where + ": [" + section + "." + name + "]";
                if (std::string(section) == "readings") {
                    if (!table.is_table()) throw InputError(where + " must be a table");
                    for (const auto& [key, v] : table.as_table())
                        if (key != "source" && key != "calibrated_on")
                            throw InputError(where + " (line " + std::to_string(v.location().line()) + "): unknown key '" +
                                             key + "'; allowed: source, calibrated_on");
                    if (!table.contains("source") || !table.at("source").is_string() || !table.contains("calibrated_on"))
                        throw InputError(where + " (line " + std::to_string(table.location().line()) +
                                         "): a reading needs source (a string) and calibrated_on");
                }
                for (const auto& [id, line] : named_claims(table, where)) {
                    const auto it = std::find_if(claims.begin(), claims.end(), [&](const Claim& c) { return c.id == id; });
                    const std::string at = where + " (line " + std::to_string(line) + "): calibrated_on '" + id + "'";
                    if (it == claims.end()) throw InputError(at + " names no claim of " + file.string());
                    if (it->role != "calibration")
                        throw InputError(at + " names a claim whose role is '" + it->role + "'; it must be role = \"calibration\"");
                    named.push_back(id);
                }
            }
        }
    }
    for (const auto& c : claims)
        if (c.role == "calibration" && std::find(named.begin(), named.end(), c.id) == named.end())
            throw InputError(file.string() + ": claim " + c.id + " (line " + std::to_string(c.line) +
                             "): role 'calibration' but no setting of " + exp_where + " names it (calibrated_on = \"" +
                             c.id + "\" on the [parameters.<name>] it was chosen for)");
}

// The [[figure]] ids of the experiment file beside the claims file (as check_calibrations finds
// it); none without one. Its own errors are the experiment file's loader's to report.
std::vector<std::string> figures_of(const std::filesystem::path& file, const std::string& experiment) {
    const std::filesystem::path exp_file = file.parent_path().parent_path() / "experiments" / (experiment + ".toml");
    std::vector<std::string> ids;
    if (!std::filesystem::exists(exp_file)) return ids;
    const toml::value root = parse_toml_file(exp_file, "experiment file");
    if (!root.is_table() || !root.contains("figure") || !root.at("figure").is_array()) return ids;
    for (const auto& f : root.at("figure").as_array())
        if (f.is_table() && f.contains("id") && f.at("id").is_string()) ids.push_back(f.at("id").as_string().str);
    return ids;
}

// One [[claim]]: its keys, texts and measured scalar (which the experiment must declare).
Claim read_claim(const toml::value& c, const std::string& where, const std::string& experiment,
                 const DeclaredOutputs* outputs, const std::vector<std::string>& figure_ids,
                 const std::vector<Claim>& earlier_claims) {
    Claim k;
    k.id = toml::find<std::string>(c, "id");
    const ClaimReader r{c, where + ": claim " + printable(k.id), where, printable(k.id)};
    for (const auto& [key, v] : c.as_table())
        if (!std::count(std::begin(kClaimKeys), std::end(kClaimKeys), key))
            throw InputError(r.where + line_of(v) + ": unknown key '" + key + "'; allowed: " + joined(kClaimKeys));
    for (const auto& earlier : earlier_claims)
        if (earlier.id == k.id) throw InputError(r.where + line_of(c) + ": claim id given twice");
    k.statement = toml::find<std::string>(c, "statement");
    k.source = toml::find<std::string>(c, "source");
    k.measured = toml::find<std::string>(c, "measured");
    if (c.contains("tolerance_reason")) k.tolerance_reason = toml::find<std::string>(c, "tolerance_reason");
    if (c.contains("known_deviation")) k.known_deviation = toml::find<std::string>(c, "known_deviation");
    if (c.contains("scales")) k.scales = toml::find<std::vector<std::string>>(c, "scales");
    if (k.measured.empty() || k.measured.find_first_of(" \t\n") != std::string::npos)
        throw InputError(r.where + line_of(c.at("measured")) + ": measured '" + k.measured +
                         "' is not a scalar name (non-empty, no spaces)");
    if (outputs && outputs->declared() && !outputs->declares_scalar(k.measured))
        throw InputError(r.where + line_of(c.at("measured")) + ": measured '" + k.measured + "' is not an output of " +
                         experiment + " (no output handle of it makes such a scalar; `granrepro list --json` lists them)");
    for (const auto& s : k.scales) r.check_scale(s, "scales");
    if (c.contains("figure")) {
        k.figure = toml::find<std::string>(c, "figure");
        if (std::find(figure_ids.begin(), figure_ids.end(), k.figure) == figure_ids.end())
            throw InputError(r.where + line_of(c.at("figure")) + ": figure '" + printable(k.figure) + "' is not a figure of " +
                             experiment + " (experiments/" + experiment + ".toml [[figure]]); allowed: " + joined(figure_ids));
    }
    read_band(r, k);
    read_deviation(r, k);
    read_role_and_status(r, k);
    return k;
}

} // namespace

std::vector<Claim> load_claims(const std::filesystem::path& file, const std::string& experiment,
                               const DeclaredOutputs* outputs) {
    const std::string where = file.string();
    if (!std::filesystem::exists(file)) throw InputError(where + ": expected-claims file is missing");
    std::vector<Claim> claims;
    try {
        const auto root = parse_toml_file(file, "expected-claims file");
        for (const auto& [key, v] : root.as_table())
            if (key != "experiment" && key != "claim")
                throw InputError(where + line_of(v) + ": unknown key '" + key + "'; allowed: experiment, [[claim]]");
        if (toml::find<std::string>(root, "experiment") != experiment)
            throw InputError(where + ": 'experiment' must be \"" + experiment + "\"");
        const std::vector<std::string> figure_ids = figures_of(file, experiment);
        for (const auto& c : toml::find<toml::array>(root, "claim"))
            claims.push_back(read_claim(c, where, experiment, outputs, figure_ids, claims));
    } catch (const InputError& e) {
        if (std::string(e.what()).rfind(where, 0) == 0) throw;
        throw InputError(where + ": " + e.what());
    } catch (const std::exception& e) {
        throw InputError(toml_error_line(where, e.what()));
    }
    check_calibrations(claims, file, experiment); // its messages name the experiment file or the claim
    return claims;
}

std::vector<ClaimResult> evaluate_claims(const std::vector<Claim>& claims, const nlohmann::json& scalars,
                                         Scale scale) {
    std::vector<ClaimResult> out;
    for (const auto& c : claims) {
        ClaimResult r;
        r.claim = c;
        if (c.paper) r.expected_text = num(*c.paper);
        if (c.min || c.max)
            r.expected_text += (r.expected_text.empty() ? "" : " ") + std::string("in [") +
                               (c.min ? num(*c.min) : "-inf") + ", " + (c.max ? num(*c.max) : "inf") + "]";
        if (c.rel_tol) r.tolerance_text = "rel " + num(*c.rel_tol);
        else if (c.abs_tol) r.tolerance_text = "abs " + num(*c.abs_tol);
        else r.tolerance_text = "range";
        const std::optional<Band> band = c.band_for(scale);
        if (band) r.band_text = band_text(*band);
        if (scalars.contains(c.measured) && scalars[c.measured].is_number())
            r.measured = scalars[c.measured].get<double>();
        const bool finite = r.measured && std::isfinite(*r.measured);
        bool ok = finite;
        if (ok && c.paper && (c.rel_tol || c.abs_tol)) {
            // A bound of exactly one grid step (0.8 against 0.7 +- 0.1) must not fail by round-off
            // (|0.8 - 0.7| = 0.10000000000000009): compare with a relative slack of 1e-12.
            const double tol = c.rel_tol ? *c.rel_tol * std::abs(*c.paper) : *c.abs_tol;
            ok = std::abs(*r.measured - *c.paper) <= tol * (1 + 1e-12) + 1e-300;
        }
        if (ok && c.min) ok = *r.measured >= *c.min;
        if (ok && c.max) ok = *r.measured <= *c.max;
        if (!c.applies_to(scale)) r.verdict = Verdict::Skipped;
        else if (ok) r.verdict = Verdict::Pass;
        // A deviation band holds a finite value, or ("absent") the lack of one: the run wrote the
        // scalar as NaN (no state to measure it on); a scalar the run did not write still fails.
        else if (band && (finite ? band->contains(*r.measured) : band->absent && scalars.contains(c.measured)))
            r.verdict = Verdict::KnownDeviation;
        else r.verdict = Verdict::Fail;
        out.push_back(std::move(r));
    }
    return out;
}

std::string format_claim_table(const std::string& experiment, const std::vector<ClaimResult>& results,
                               const std::vector<std::string>& notes) {
    std::ostringstream os;
    auto pad = [](std::string s, std::size_t w) {
        if (s.size() > w) s = s.substr(0, w - 1) + "~";
        return s + std::string(w - s.size(), ' ');
    };
    // The claim column is as wide as the longest id: an id is what a reader greps for in
    // expected/, so it is never cut (the other columns hold numbers and may be).
    std::size_t id_width = 34;
    for (const auto& r : results) id_width = std::max(id_width, printable(r.claim.id).size() + 1);
    os << "check " << printable(experiment) << "\n";
    for (const auto& n : notes) os << "  " << printable(n) << "\n";
    os << "  " << pad("claim", id_width) << pad("paper / relation", 22) << pad("our band (deviation)", 22)
       << pad("measured", 11) << pad("tolerance (kind)", 20) << "verdict\n";
    int explained = 0;
    for (const auto& r : results) {
        std::string measured = r.measured ? num(*r.measured) : "missing";
        if (r.measured && !std::isfinite(*r.measured)) measured = "non-finite";
        os << "  " << pad(printable(r.claim.id), id_width) << pad(r.expected_text, 22) << pad(r.band_text, 22) << pad(measured, 11)
           << pad(r.tolerance_text + " (" + short_kind(r.claim.tolerance_kind) + ")", 20) << to_string(r.verdict)
           << "\n";
        explained += !r.claim.known_deviation.empty() && r.verdict != Verdict::Pass && r.verdict != Verdict::Skipped;
    }
    if (explained)
        os << "  (" << explained << " known deviation" << (explained == 1 ? "" : "s")
           << ": the study behind each and its band are in expected/; `granrepro check "
           << printable(experiment.substr(0, experiment.find(' '))) << " --explain` prints them)\n";
    return os.str();
}

std::string format_deviation_explanations(const std::vector<ClaimResult>& results) {
    std::ostringstream os;
    for (const auto& r : results) {
        if (r.claim.known_deviation.empty() || r.verdict == Verdict::Pass || r.verdict == Verdict::Skipped) continue;
        os << "  " << printable(r.claim.id) << " (" << to_string(r.verdict) << ", band " << r.band_text << "):\n"
           << "      known deviation (" << printable(r.claim.status) << "): " << printable(r.claim.known_deviation) << "\n"
           << "      tolerance (" << printable(r.claim.tolerance_kind) << "): "
           << printable(r.claim.tolerance_reason.empty() ? "(no reason beyond the known deviation)" : r.claim.tolerance_reason)
           << "\n"
           << "      band (" << printable(r.claim.deviation_band_kind) << "): " << printable(r.claim.deviation_band_reason)
           << "\n";
    }
    return os.str();
}

nlohmann::json claims_to_json(const std::vector<ClaimResult>& results) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& r : results) {
        const bool finite = r.measured && std::isfinite(*r.measured);
        nlohmann::json j = {{"id", r.claim.id}, {"statement", r.claim.statement}, {"source", r.claim.source},
                            {"expected", r.expected_text}, {"tolerance", r.tolerance_text},
                            {"tolerance_reason", r.claim.tolerance_reason},
                            {"tolerance_kind", r.claim.tolerance_kind},
                            {"measured", finite ? nlohmann::json(*r.measured) : nlohmann::json()},
                            {"verdict", to_string(r.verdict)}, {"role", r.claim.role}};
        if (!r.claim.figure.empty()) j["figure"] = r.claim.figure;
        if (!r.claim.known_deviation.empty()) {
            j["known_deviation"] = r.claim.known_deviation;
            j["deviation_band"] = r.band_text; // text: JSON has no infinity
            j["deviation_band_reason"] = r.claim.deviation_band_reason;
            j["deviation_band_kind"] = r.claim.deviation_band_kind;
            j["status"] = r.claim.status;
        }
        arr.push_back(j);
    }
    return arr;
}

bool all_pass(const std::vector<ClaimResult>& results) {
    return std::none_of(results.begin(), results.end(), [](const auto& r) { return r.verdict == Verdict::Fail; });
}

namespace {

// The figure numbers a text cites: "Fig. 4", "Figs. 4, 5", "Fig. 4 and Fig. 5", "Fig. 10(a)".
std::vector<int> cited_figures(const std::string& text) {
    std::vector<int> out;
    const std::size_t n = text.size();
    auto digit = [&](std::size_t j) { return j < n && std::isdigit(static_cast<unsigned char>(text[j])); };
    for (std::size_t i = text.find("Fig"); i != std::string::npos; i = text.find("Fig", i + 1)) {
        std::size_t j = i + 3;
        if (j < n && text[j] == 's') ++j;
        if (j < n && text[j] == '.') ++j;
        while (true) {
            while (j < n && text[j] == ' ') ++j;
            if (!digit(j)) break;
            int v = 0;
            for (; digit(j); ++j) v = std::min(v * 10 + (text[j] - '0'), 100000);
            out.push_back(v);
            if (j < n && text[j] == '(') j = std::min(n, text.find(')', j) == std::string::npos ? n : text.find(')', j) + 1);
            if (text.compare(j, 2, ", ") == 0) j += 2;
            else if (text.compare(j, 5, " and ") == 0) j += 5;
            else break;
        }
    }
    return out;
}

} // namespace

bool cites_figure(const Claim& claim, const std::string& figure_id) {
    if (!claim.figure.empty()) return claim.figure == figure_id;
    const std::size_t digits = figure_id.find_last_not_of("0123456789") + 1;
    if (digits >= figure_id.size()) return false;
    const int number = std::stoi(figure_id.substr(digits, 6));
    const std::vector<int> cited = cited_figures(claim.source);
    return std::find(cited.begin(), cited.end(), number) != cited.end();
}

} // namespace granrepro
