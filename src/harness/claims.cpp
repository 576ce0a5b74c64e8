#include "harness/claims.hpp"

#include <cmath>
#include <sstream>
#include <toml.hpp>

#include "core/input_error.hpp"

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
std::string num(double x) {
    std::ostringstream os;
    os.precision(4);
    os << x;
    return os.str();
}
} // namespace

std::vector<Claim> load_claims(const std::filesystem::path& file, const std::string& experiment) {
    const std::string where = file.string();
    if (!std::filesystem::exists(file)) throw InputError(where + ": expected-claims file is missing");
    std::vector<Claim> claims;
    try {
        const auto root = toml::parse(where);
        if (toml::find<std::string>(root, "experiment") != experiment)
            throw InputError(where + ": 'experiment' must be \"" + experiment + "\"");
        for (const auto& c : toml::find<toml::array>(root, "claim")) {
            Claim k;
            k.id = toml::find<std::string>(c, "id");
            k.statement = toml::find<std::string>(c, "statement");
            k.source = toml::find<std::string>(c, "source");
            k.measured = toml::find<std::string>(c, "measured");
            auto opt = [&](const char* key) -> std::optional<double> {
                if (!c.contains(key)) return std::nullopt;
                const auto& v = c.at(key);
                return v.is_integer() ? double(v.as_integer()) : toml::get<double>(v);
            };
            k.paper = opt("paper");
            k.rel_tol = opt("rel_tol");
            k.abs_tol = opt("abs_tol");
            k.min = opt("min");
            k.max = opt("max");
            if (c.contains("tolerance_reason")) k.tolerance_reason = toml::find<std::string>(c, "tolerance_reason");
            if (c.contains("known_deviation")) k.known_deviation = toml::find<std::string>(c, "known_deviation");
            if (c.contains("scales")) k.scales = toml::find<std::vector<std::string>>(c, "scales");
            const bool value_claim = k.paper && (k.rel_tol || k.abs_tol);
            const bool range_claim = k.min || k.max;
            if (!value_claim && !range_claim)
                throw InputError(where + ": claim " + k.id + " needs paper with rel_tol/abs_tol, or min/max");
            if (k.known_deviation.empty() && k.tolerance_reason.empty())
                throw InputError(where + ": claim " + k.id + " needs a tolerance_reason");
            claims.push_back(std::move(k));
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        throw InputError(where + ": corrupt expected-claims file: " + msg.substr(0, msg.find('\n')));
    }
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
        if (scalars.contains(c.measured) && scalars[c.measured].is_number())
            r.measured = scalars[c.measured].get<double>();
        const bool applies = c.scales.empty() ||
                             std::find(c.scales.begin(), c.scales.end(), to_string(scale)) != c.scales.end();
        bool ok = r.measured && std::isfinite(*r.measured);
        if (ok && c.paper && (c.rel_tol || c.abs_tol)) {
            // A bound of exactly one grid step (0.8 against 0.7 +- 0.1) must not fail by round-off
            // (|0.8 - 0.7| = 0.10000000000000009): compare with a relative slack of 1e-12.
            const double tol = c.rel_tol ? *c.rel_tol * std::abs(*c.paper) : *c.abs_tol;
            ok = std::abs(*r.measured - *c.paper) <= tol * (1 + 1e-12) + 1e-300;
        }
        if (ok && c.min) ok = *r.measured >= *c.min;
        if (ok && c.max) ok = *r.measured <= *c.max;
        if (!applies) r.verdict = Verdict::Skipped;
        else if (!c.known_deviation.empty()) r.verdict = ok ? Verdict::Pass : Verdict::KnownDeviation;
        else r.verdict = ok ? Verdict::Pass : Verdict::Fail;
        out.push_back(std::move(r));
    }
    return out;
}

std::string format_claim_table(const std::string& experiment, const std::vector<ClaimResult>& results) {
    std::ostringstream os;
    auto pad = [](std::string s, std::size_t w) {
        if (s.size() > w) s = s.substr(0, w - 1) + "~";
        return s + std::string(w - s.size(), ' ');
    };
    os << "check " << experiment << "\n";
    os << "  " << pad("claim", 36) << pad("paper / relation", 24) << pad("measured", 12) << pad("tolerance", 11)
       << "verdict\n";
    for (const auto& r : results) {
        os << "  " << pad(r.claim.id, 36) << pad(r.expected_text, 24)
           << pad(r.measured ? num(*r.measured) : "missing", 12) << pad(r.tolerance_text, 11)
           << to_string(r.verdict) << "\n";
        if (r.verdict == Verdict::KnownDeviation) os << "      known deviation: " << r.claim.known_deviation << "\n";
    }
    return os.str();
}

nlohmann::json claims_to_json(const std::vector<ClaimResult>& results) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& r : results) {
        nlohmann::json j;
        j["id"] = r.claim.id;
        j["statement"] = r.claim.statement;
        j["source"] = r.claim.source;
        j["expected"] = r.expected_text;
        j["tolerance"] = r.tolerance_text;
        j["tolerance_reason"] = r.claim.tolerance_reason;
        j["measured"] = r.measured ? nlohmann::json(*r.measured) : nlohmann::json();
        j["verdict"] = to_string(r.verdict);
        if (!r.claim.known_deviation.empty()) j["known_deviation"] = r.claim.known_deviation;
        arr.push_back(j);
    }
    return arr;
}

bool all_pass(const std::vector<ClaimResult>& results) {
    for (const auto& r : results)
        if (r.verdict == Verdict::Fail) return false;
    return true;
}

} // namespace granrepro
