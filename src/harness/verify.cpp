#include "harness/verify.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sys/stat.h>
#include <utility>
#include <unistd.h>

#include "core/input_error.hpp"
#include "core/provenance.hpp"
#include "core/untrusted_file.hpp"
#include "data/interval.hpp"
#include "harness/claims.hpp"
#include "harness/experiment.hpp"
#include "harness/run_checkpoint.hpp"
#include "harness/runner.hpp"
#include "data/toml_file.hpp"
#include "io/h5_file.hpp"
#include "io/result_writer.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace granrepro {

namespace {

// Names of values that measure time (wall or CPU seconds, rates per second, resumed points):
// not compared, as no rerun reproduces them.
bool is_timing_name(const std::string& name) {
    auto has = [&](const char* s) { return name.find(s) != std::string::npos; };
    return has("wall_seconds") || has("wall_time") || has("seconds_per") || name.ends_with("per_second") ||
           name == "resumed_points";
}

struct Diff {
    std::string path, before, after;
    double abs = NAN, rel = NAN;
};

struct Comparison {
    long compared = 0;
    std::vector<std::string> timing; // not compared
    std::vector<std::string> added;  // fields the code writes now that the stored outcome lacks
    std::vector<Diff> diffs;
};

std::string shown(const json& j) {
    const std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);
    return s.size() > 48 ? s.substr(0, 45) + "..." : s;
}

// Value by value; numbers bit for bit (their round-trip text as dump() writes it, as stored).
void compare(const json& a, const json& b, const std::string& path, Comparison& c) {
    if (a.is_number() && b.is_number()) {
        ++c.compared;
        if (a.dump() != b.dump()) {
            const double x = a.get<double>(), y = b.get<double>();
            c.diffs.push_back({path, a.dump(), b.dump(), std::fabs(y - x), x != 0 ? std::fabs((y - x) / x) : NAN});
        }
        return;
    }
    if (a.is_object() && b.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it) {
            const std::string p = path + "/" + it.key();
            if (is_timing_name(it.key())) {
                c.timing.push_back(p);
                continue;
            }
            if (!b.contains(it.key())) c.diffs.push_back({p, shown(it.value()), "(absent)"});
            else compare(it.value(), b[it.key()], p, c);
        }
        // A field the outcome gained after the results were made, left empty because the option
        // that fills it is off (e.g. cooling's velocity_correlation), is named, not counted as a
        // difference; one that holds anything is a difference as before.
        for (auto it = b.begin(); it != b.end(); ++it) {
            if (a.contains(it.key()) || is_timing_name(it.key())) continue;
            const bool empty = it.value().is_null() || ((it.value().is_array() || it.value().is_object()) && it.value().empty());
            if (empty) c.added.push_back(path + "/" + it.key());
            else c.diffs.push_back({path + "/" + it.key(), "(absent)", shown(it.value())});
        }
        return;
    }
    if (a.is_array() && b.is_array()) {
        if (a.size() != b.size())
            c.diffs.push_back({path, std::to_string(a.size()) + " entries", std::to_string(b.size()) + " entries"});
        for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) compare(a[i], b[i], path + "[" + std::to_string(i) + "]", c);
        return;
    }
    ++c.compared;
    if (a != b) c.diffs.push_back({path, shown(a), shown(b)});
}

std::string number(double x, const char* format = "%.4g") {
    if (!std::isfinite(x)) return "-";
    char b[40];
    std::snprintf(b, sizeof b, format, x);
    return b;
}

// The distinct last components of JSON paths ("/snapshots[3]/vc_n" -> "vc_n"), in first-seen order.
std::vector<std::string> leaf_names(const std::vector<std::string>& paths) {
    std::vector<std::string> names;
    for (const auto& t : paths) {
        const std::string leaf = t.substr(t.rfind('/') + 1);
        if (std::find(names.begin(), names.end(), leaf) == names.end()) names.push_back(leaf);
    }
    return names;
}

// Prints the outcome of one comparison; returns true if identical.
bool report(const std::string& what, const Comparison& c, bool same_version) {
    std::string timing;
    if (!c.timing.empty()) timing = "; not compared (timings, resume counts): " + joined(leaf_names(c.timing));
    if (!c.added.empty())
        timing += "; new since the results were made, empty (its option is off): " + joined(leaf_names(c.added));
    if (c.diffs.empty()) {
        std::printf("  %s: %ld values %s%s\n", what.c_str(), c.compared,
                    same_version ? "bit for bit identical" : "identical, value by value", timing.c_str());
        return true;
    }
    std::printf("  %s: %zu of %ld values differ%s:\n", what.c_str(), c.diffs.size(), c.compared, timing.c_str());
    const std::size_t shown_max = 20;
    for (std::size_t i = 0; i < c.diffs.size() && i < shown_max; ++i) {
        const Diff& d = c.diffs[i];
        std::printf("    %s: %s -> %s", d.path.empty() ? "(value)" : d.path.c_str(), d.before.c_str(), d.after.c_str());
        if (std::isfinite(d.abs)) std::printf("  (by %s, relative %s)", number(d.abs).c_str(), number(d.rel).c_str());
        std::printf("\n");
    }
    if (c.diffs.size() > shown_max) std::printf("    ... and %zu more\n", c.diffs.size() - shown_max);
    return false;
}

// A folder under /tmp for the rerun's work (long runs inside a point may checkpoint), removed
// after. Its name carries the PID, so that one a killed verify left behind (SIGKILL runs no
// destructor) is removed by the next verify once its process is gone.
struct TempDir {
    fs::path path;
    TempDir() {
        remove_stale();
        std::string tmpl =
            (fs::temp_directory_path() / ("granrepro-verify-" + std::to_string(::getpid()) + "-XXXXXX")).string();
        if (!::mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a temporary folder in " + fs::temp_directory_path().string());
        path = tmpl;
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    // granrepro-verify-<pid>-XXXXXX folders of this user whose process no longer runs.
    static void remove_stale() {
        std::error_code ec;
        for (auto it = fs::directory_iterator(fs::temp_directory_path(), ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
            const std::string n = it->path().filename().string();
            const std::string prefix = "granrepro-verify-";
            if (!n.starts_with(prefix)) continue;
            long pid = 0;
            const std::size_t dash = n.find('-', prefix.size());
            if (dash == std::string::npos || !parse_long(n.substr(prefix.size(), dash - prefix.size()), pid) || pid <= 0) continue;
            struct stat st {};
            if (::lstat(it->path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid()) continue;
            if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue; // still running (or not ours to ask)
            std::error_code rm;
            fs::remove_all(it->path(), rm);
        }
    }
};

// The [parameters.<name>] blocks of today's experiments/<name>.toml that the recorded one lacks
// (parameters added after the results were made), as TOML text, and their names. An added
// parameter takes today's default: a new option that changes nothing unless asked for leaves the
// point as it was, and one that changes it shows as a moved value.
std::pair<std::string, std::vector<std::string>> added_parameters(const std::string& name, const fs::path& recorded) {
    const fs::path today = project_root() / "experiments" / (name + ".toml");
    const toml::value had = parse_toml_file(recorded, "recorded experiment file");
    const toml::value now = parse_toml_file(today, "experiment file");
    const auto& had_params = toml::find(had, "parameters").as_table();
    std::ifstream in(today);
    std::string text, line;
    std::vector<std::string> names;
    bool copying = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] == '[') {
            const auto close = line.find(']');
            const std::string header = line.substr(1, close == std::string::npos ? 0 : close - 1);
            const std::string key = header.rfind("parameters.", 0) == 0 ? header.substr(11) : "";
            copying = !key.empty() && toml::find(now, "parameters").as_table().count(key) && !had_params.count(key);
            if (copying) names.push_back(key);
        }
        if (copying) text += line + "\n";
    }
    return {text, names};
}

// data.h5's `experiment_file` attribute: the experiments/<name>.toml text the run read, bounded
// (kMaxTextFileBytes, kMaxTomlDepth) before it is written anywhere or parsed.
std::string recorded_experiment_file(const fs::path& h5) {
    const std::string where = h5.string() + ": experiment_file";
    const H5File f = H5File::open(h5.string());
    if (!f.has_attr("experiment_file"))
        throw InputError(h5.string() + ": has no 'experiment_file' attribute (the experiment file the run read); cannot "
                                       "recompute its parameters");
    std::string text;
    try {
        text = f.read_string_attr("experiment_file");
    } catch (const std::runtime_error& e) {
        throw InputError(where + ": " + e.what());
    }
    check_toml_depth(text, where);
    return text;
}

// The parameters as the run resolved them: the experiments/<name>.toml text stored in data.h5,
// at the recorded scale, with the recorded --set overrides (and today's defaults of parameters
// added since, named on stderr).
ParameterSet recorded_parameters(const Experiment& exp, const fs::path& h5, const std::string& toml_text,
                                 const json& summary, Scale scale, const fs::path& tmp, std::vector<std::string>& added) {
    const fs::path file = tmp / (exp.name + ".toml");
    const std::string where = h5.string() + ": experiment_file";
    std::ofstream(file) << toml_text;
    ParameterSet params;
    try {
        if (const auto [text, names] = added_parameters(exp.name, file); !text.empty()) {
            std::ofstream(file, std::ios::app) << "\n" << text;
            added = names;
            std::fprintf(stderr, "granrepro: verify %s: parameters added since the results were made take today's defaults: %s\n",
                         exp.name.c_str(), joined(names).c_str());
        }
        params = ParameterSet::load(file, scale);
    } catch (const std::exception& e) { // named as the attribute, not as the temporary copy
        const std::string msg = e.what();
        throw InputError(msg.starts_with(file.string()) ? where + msg.substr(file.string().size()) : where + ": " + msg);
    }
    const json sets = summary.value("overridden_parameters", json::object());
    for (auto it = sets.begin(); it != sets.end(); ++it) {
        try {
            params.set(it.key() + "=" + (it.value().is_string() ? it.value().get<std::string>() : it.value().dump()));
        } catch (const InputError& e) {
            throw InputError((h5.parent_path() / "summary.json").string() + ": overridden_parameters/" + it.key() + ": " + e.what());
        }
    }
    exp.validate(params);
    return params;
}

// The recomputed parameters against data.h5's /parameters (what check compared with summary.json):
// an edited stored value is a difference, never a match. Parameters added since are left out.
bool compare_parameters(const ParameterSet& params, const fs::path& h5, const std::vector<std::string>& added,
                        bool same_version) {
    json stored;
    try {
        stored = read_stored_parameters(H5File::open(h5.string()));
    } catch (const std::runtime_error& e) {
        if (dynamic_cast<const InputError*>(&e)) throw;
        throw InputError(h5.string() + ": /parameters: " + e.what());
    }
    json now = json::object();
    const json all = params.to_json();
    for (auto it = all.begin(); it != all.end(); ++it)
        if (std::find(added.begin(), added.end(), it.key()) == added.end()) now[it.key()] = it.value()["value"];
    for (auto it = stored.begin(); it != stored.end(); ++it) {
        if (!now.contains(it.key())) continue;
        const json& n = now[it.key()];
        it.value() = stored_parameter_as(it.value(), n);
        // Older files store an integer as a float: the same number is the same parameter.
        if (it.value().is_number() && n.is_number() && it.value().type() != n.type() && it.value() == n) it.value() = n;
    }
    Comparison c;
    compare(stored, now, "/parameters", c);
    return report("parameters (data.h5 /parameters against its experiment_file and overridden_parameters)", c, same_version);
}

// read_summary has checked it: an integer >= 0.
std::uint64_t recorded_seed(const json& summary) { return summary.at("seed").get<std::uint64_t>(); }

// /points/records by field, before any is used: a malformed record is bad input naming the file
// and the field (not nlohmann's type_error, exit 1).
void check_records(const json& records, const fs::path& h5) {
    const std::string where = h5.string() + ": /points/records";
    for (std::size_t i = 0; i < records.size(); ++i) {
        const json& r = records[i];
        auto bad = [&](const std::string& field, const std::string& want) {
            throw InputError(where + ": record " + std::to_string(i) + (field.empty() ? "" : ": '" + field + "'") + " must be " + want);
        };
        if (!r.is_object()) bad("", "an object");
        if (!r.contains("sweep") || !r["sweep"].is_string()) bad("sweep", "a string");
        if (!r.contains("point") || !r["point"].is_number_integer() || r["point"].get<long long>() < 0) bad("point", "an integer >= 0");
        if (!r.contains("outcome")) bad("outcome", "present");
        if (r.contains("inputs") && !r["inputs"].is_string()) bad("inputs", "a string");
        for (const char* f : {"resumed", "compacted", "persisted"})
            if (r.contains(f) && !r[f].is_boolean()) bad(f, "true or false");
        if (!r.contains("cost") || !r["cost"].is_object()) bad("cost", "an object");
        for (const char* f : {"cpu_s", "wall_s"})
            if (r["cost"].contains(f) && !r["cost"][f].is_number()) bad(std::string("cost/") + f, "a number");
    }
}

json scalars_through_json(const Result& r) { return json::parse(scalars_json(r).dump()); }

// Claims that read a moved scalar, with the verdict before and after under expected/ as it is now.
void report_claims(const std::string& name, const json& before, const json& after, const Comparison& c, Scale scale) {
    std::vector<std::string> moved;
    for (const auto& d : c.diffs) moved.push_back(d.path.substr(d.path.rfind('/') + 1));
    const auto claims = load_claims(project_root() / "expected" / (name + ".toml"), name);
    const auto v0 = evaluate_claims(claims, before, scale), v1 = evaluate_claims(claims, after, scale);
    int n = 0;
    for (std::size_t i = 0; i < claims.size(); ++i) {
        if (std::find(moved.begin(), moved.end(), claims[i].measured) == moved.end()) continue;
        if (n++ == 0) std::printf("  claims reading them:\n");
        std::printf("    %s (reads %s): %s -> %s%s\n", claims[i].id.c_str(), claims[i].measured.c_str(), to_string(v0[i].verdict),
                    to_string(v1[i].verdict), v0[i].verdict == v1[i].verdict ? "" : "  (verdict changes)");
    }
    if (n == 0 && !moved.empty()) std::printf("  no claim reads the moved scalars\n");
}

// A time in summary.json (read_summary has checked: a number or null), NaN where not known.
double seconds_of(const json& summary, const char* field) {
    return summary.contains(field) && summary[field].is_number() ? summary[field].get<double>() : NAN;
}

void list_points(const std::string& name, const json& summary, const json& records) {
    const std::string head = name + " (" + summary.value("scale", "?") + " scale, seed " + summary["seed"].dump() + ", " +
                             summary.value("code_version", "?") + ")";
    if (records.empty()) {
        std::printf("%s: no stored points\n", head.c_str());
        return;
    }
    std::printf("%s: %zu stored points; whole run %s s wall, %s s CPU (%s points resumed)\n", head.c_str(), records.size(),
                number(seconds_of(summary, "total_wall_time_s"), "%.1f").c_str(),
                number(seconds_of(summary, "total_cpu_time_s"), "%.1f").c_str(),
                summary.contains("resumed_points") ? summary["resumed_points"].dump().c_str() : "?");
    std::printf("%6s  %-18s %10s %10s  %-7s %s\n", "point", "sweep", "CPU s", "wall s", "resumed", "inputs");
    for (const auto& r : records) {
        const json& c = r["cost"];
        std::printf("%6ld  %-18s %10s %10s  %-7s %s%s\n", r["point"].get<long>(), r.value("sweep", "").c_str(),
                    number(c.value("cpu_s", -1.0) >= 0 ? c.value("cpu_s", -1.0) : NAN, "%.3f").c_str(),
                    number(c.value("wall_s", -1.0) >= 0 ? c.value("wall_s", -1.0) : NAN, "%.3f").c_str(),
                    r.value("resumed", false) ? "yes" : "no", r.value("inputs", "").c_str(),
                    r.value("compacted", false) ? "  (large arrays digested)" : "");
    }
}

// What a verification knows before it reruns anything.
struct Verification {
    Verification(const Experiment& e, const VerifyOptions& o) : exp(e), opt(o) {}
    const Experiment& exp;
    const VerifyOptions& opt;
    json summary, records;
    fs::path h5;
    Scale scale = Scale::Quick;
    std::uint64_t seed = 0;
    bool same_version = false;
    std::string versions, where;
    std::vector<std::string> added; // parameters the results' TOML lacks
    const ParameterSet* params = nullptr; // recomputed from the stored experiment file
};

// The stored point to rerun: as asked, or the cheapest by recorded CPU cost.
const json& chosen_point(const Verification& v) {
    const json* rec = nullptr;
    if (v.opt.point) {
        for (const auto& r : v.records)
            if (r["point"] == *v.opt.point) rec = &r;
        if (!rec)
            throw InputError("--point " + std::to_string(*v.opt.point) + ": " + v.where + " stores points 0 to " +
                             std::to_string(v.records.size() - 1) + " (`verify " + v.exp.name + " --list` shows them)");
        return *rec;
    }
    for (const auto& r : v.records) {
        const double c = r["cost"].value("cpu_s", -1.0);
        if (!rec || (c >= 0 && (*rec)["cost"].value("cpu_s", -1.0) > c)) rec = &r;
    }
    return *rec;
}

// The rerun of one point; with every other point of its sweep stored whole, the scalars are rebuilt
// from them as the run built them.
PointRerun point_rerun(const Verification& v, const json& rec) {
    PointRerun rerun;
    rerun.sweep = rec["sweep"].get<std::string>();
    rerun.point = rec["point"].get<long>();
    rerun.aggregate = !v.opt.point_only;
    for (const auto& r : v.records) {
        if (r["sweep"] != rerun.sweep) rerun.aggregate = false; // more than one sweep: the point alone
        else if (r["point"] != rerun.point) {
            if (r.value("compacted", false)) rerun.aggregate = false;
            rerun.stored[r["point"].get<long>()] = r["outcome"];
        }
    }
    return rerun;
}

// Compares the rerun point (and the scalars rebuilt with it) with what the results store.
bool compare_point(const Verification& v, const PointRerun& rerun, const json& rec,
                   const std::optional<Result>& result) {
    bool same = true;
    if (rerun.inputs == rec.value("inputs", "")) {
        std::printf("  inputs: fingerprint %s as recorded%s\n", rerun.inputs.c_str(),
                    v.added.empty() ? "" : (" (without the parameters added since: " + joined(v.added) + ")").c_str());
    } else {
        std::printf("  inputs: fingerprint %s, recorded %s: the parameters as read now differ from the run's\n",
                    rerun.inputs.c_str(), rec.value("inputs", "?").c_str());
        same = false;
    }
    std::printf("  cost now: %s CPU s, %s s wall\n", number(rerun.cost.cpu_s, "%.3g").c_str(), number(rerun.cost.wall_s, "%.3g").c_str());
    json fresh = rerun.outcome;
    if (rec.value("compacted", false)) {
        const H5File f = H5File::open(v.h5.string());
        const H5Object g = f.open_group("points");
        const long over = g.has_attr("compacted_arrays_over") ? g.read_long_attr("compacted_arrays_over") : long(kMaxPointArrayValues);
        fresh = compact_outcome(fresh, std::size_t(over));
    }
    Comparison point;
    compare(rec["outcome"], fresh, "", point);
    same = report("point outcome" + std::string(rec.value("compacted", false) ? " (arrays over the compaction limit by digest)" : ""),
                  point, v.same_version) && same;
    if (!result) {
        std::printf("  scalars: not rebuilt (%s)\n",
                    v.opt.point_only                             ? "--point-only"
                    : rerun.stored.size() + 1 < v.records.size() ? "the results hold more than one sweep"
                                                                 : "other points are stored with digested arrays");
        return same;
    }
    Comparison sc;
    const json before = v.summary.at("scalars"), after = scalars_through_json(*result);
    compare(before, after, "", sc);
    same = report("scalars (point " + std::to_string(rerun.point) + " recomputed, the other " +
                      std::to_string(rerun.stored.size()) + " as stored)",
                  sc, v.same_version) && same;
    if (!sc.diffs.empty()) report_claims(v.exp.name, before, after, sc, v.scale);
    return same;
}

} // namespace

int verify_experiment(const VerifyOptions& opt) {
    const Experiment& exp = find_experiment(opt.experiment);
    const std::string& name = exp.name;
    Verification v(exp, opt);
    v.summary = read_checked_summary(name, opt.out); // check's validation of both files
    v.h5 = opt.out / name / "data.h5";
    v.records = read_points_records(v.h5);
    check_records(v.records, v.h5);
    if (opt.list) {
        list_points(name, v.summary, v.records);
        return 0;
    }
    v.scale = parse_scale(v.summary.at("scale").get<std::string>());
    v.seed = recorded_seed(v.summary);
    const std::string recorded_version = v.summary.value("code_version", "unknown");
    // A build from a dirty tree ("-dirty") is not a version: its code is not known.
    const auto dirty = [](const std::string& s) { return s.find("dirty") != std::string::npos; };
    v.same_version = recorded_version == code_version() && !dirty(recorded_version);
    const std::string toml_text = recorded_experiment_file(v.h5); // refused before a temporary folder exists
    const TempDir tmp;
    const ParameterSet params = recorded_parameters(exp, v.h5, toml_text, v.summary, v.scale, tmp.path, v.added);
    v.params = &params;
    RunContext ctx{params, v.scale, v.seed, opt.threads, true, tmp.path / "work", 1e12};
    v.where = (opt.out / name).string();
    v.versions = "code: recorded " + recorded_version + ", now " + code_version() +
                 (v.same_version ? " (same: bit for bit)" : " (another version: value by value)");
    if (v.records.empty())
        throw InputError("verify " + name + ": " + v.where + "/data.h5 stores no sweep points; rerun `granrepro " + name +
                         " --scale " + to_string(v.scale) + "`");

    const json& rec = chosen_point(v);
    PointRerun rerun = point_rerun(v, rec);
    // Parameters added since the results were made are left out of the point's fingerprint: the
    // recorded one could not hold them.
    rerun.fingerprint_without = v.added;
    ctx.sweep.mode = SweepPlan::Mode::Verify;
    ctx.sweep.rerun = &rerun;
    const double recorded_cpu = rec["cost"].value("cpu_s", -1.0);
    std::printf("verify %s: point %ld of %zu (sweep %s; %s scale, seed %llu; recorded cost %s CPU s)\n", name.c_str(),
                rerun.point, v.records.size(), rerun.sweep.c_str(), to_string(v.scale), static_cast<unsigned long long>(v.seed),
                number(recorded_cpu >= 0 ? recorded_cpu : NAN, "%.3g").c_str());
    std::printf("  %s\n", v.versions.c_str());
    const bool params_same = compare_parameters(params, v.h5, v.added, v.same_version);
    std::fflush(stdout);
    std::optional<Result> result;
    try {
        result.emplace(exp.run(ctx));
    } catch (const PointRerunDone&) {
    }
    if (!rerun.computed) throw std::runtime_error("verify " + name + ": the experiment ran no sweep point");
    const bool same = compare_point(v, rerun, rec, result) && params_same;
    std::printf("verify %s: point %ld %s\n", name.c_str(), rerun.point,
                same ? (v.same_version ? "reproduced bit for bit" : "reproduced, value by value") : "differs");
    return same ? 0 : 1;
}

} // namespace granrepro
