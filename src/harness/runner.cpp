#include "harness/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <optional>
#include <sstream>

#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/untrusted_file.hpp"
#include "harness/claims.hpp"
#include "core/provenance.hpp"
#include "harness/distributed_sweep.hpp"
#include "harness/mpi_world.hpp"
#include "harness/plotter.hpp"
#include "harness/run_log.hpp"
#include "io/durable_file.hpp"
#include "io/h5_file.hpp"
#include "io/output_lock.hpp"
#include "io/result_writer.hpp"
#include "io/staged_directory.hpp"
#include "io/write_error.hpp"

namespace fs = std::filesystem;

namespace granrepro {

const Experiment& find_experiment(const std::string& name) {
    for (const auto& e : experiment_registry())
        if (e.name == name) return e;
    throw InputError("unknown experiment '" + name + "'; known: " +
                     joined(experiment_registry(), [](const auto& e) { return e.name; }));
}

ExperimentInfo experiment_info(const std::string& name) {
    return ExperimentInfo::load(project_root() / "experiments" / (name + ".toml"));
}

std::string experiment_of_figure(const std::string& id) {
    std::string known;
    for (const auto& e : experiment_registry()) {
        for (const auto& f : experiment_info(e.name).figures) {
            if (f.id == id) return e.name;
            known += (known.empty() ? "" : ", ") + f.id;
        }
    }
    throw InputError("unknown figure '" + id + "'; known: " + known);
}

ParameterSet resolve_parameters(const std::string& name, const RunOptions& opt) {
    const Experiment& exp = find_experiment(name);
    ParameterSet params = ParameterSet::load(experiment_info(name).file, opt.scale);
    for (const auto& s : opt.sets) params.set(s);
    exp.validate(params);
    return params;
}

namespace {
fs::path expected_file(const std::string& name) { return project_root() / "expected" / (name + ".toml"); }

bool makes(const ExperimentInfo& info, const std::string& figure) {
    return std::any_of(info.figures.begin(), info.figures.end(), [&](const auto& f) { return f.id == figure; });
}

// A PNG ends with its IEND chunk; gnuplot does not report a write that ran out of space, so a
// figure cut short is found here.
bool png_complete(const fs::path& png) {
    static const std::string iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
    return read_file(png).ends_with(iend);
}

// What `check` reads is validated before it is judged: a damaged or foreign file is bad input
// (exit 2, one line naming the file and what is wrong), not a claim that failed (exit 1).
std::string json_kind(const nlohmann::json& j) {
    if (j.is_string()) return "\"" + j.get<std::string>().substr(0, 40) + "\"";
    if (j.is_object()) return "an object";
    if (j.is_array()) return "an array";
    return j.dump().substr(0, 40);
}

// The fields the readers (check, verify, report) use, by type: a damaged or forged summary.json
// is refused here naming the field, before a reader meets a value of the wrong type
// (nlohmann's type_error, exit 1).
void check_summary_fields(const nlohmann::json& j, const std::string& where) {
    auto bad = [&](const std::string& field, const nlohmann::json& v, const std::string& want) {
        throw InputError(where + "'" + field + "' must be " + want + ", found " + json_kind(v));
    };
    auto count = [](const nlohmann::json& v) { return v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0); };
    if (j.contains("schema_version")) {
        const nlohmann::json& v = j["schema_version"];
        if (!v.is_number_integer() || v.get<long long>() != 3)
            bad("schema_version", v, "3 (the summary version this build reads; docs/schema.md, \"Versions\")");
    }
    if (j.contains("seed") && !count(j["seed"]))
        bad("seed", j["seed"], "an integer >= 0");
    for (const char* f : {"code_version", "physics_hash", "command_line"})
        if (j.contains(f) && !j[f].is_string()) bad(f, j[f], "a string");
    for (const char* f : {"wall_time_s", "cpu_time_s", "total_wall_time_s", "total_cpu_time_s"})
        if (j.contains(f) && !j[f].is_number() && !j[f].is_null()) bad(f, j[f], "a number");
    for (const char* f : {"stored_points", "resumed_points", "points_without_cost"})
        if (j.contains(f) && !count(j[f])) bad(f, j[f], "an integer >= 0");
    if (j.contains("overridden_parameters")) {
        const nlohmann::json& o = j["overridden_parameters"];
        if (!o.is_object()) bad("overridden_parameters", o, "an object");
        for (auto it = o.begin(); it != o.end(); ++it)
            if (!it.value().is_string() && !it.value().is_number() && !it.value().is_boolean())
                bad("overridden_parameters/" + it.key(), it.value(), "a value (text or number)");
    }
    if (j.contains("parameters")) {
        const nlohmann::json& o = j["parameters"];
        if (!o.is_object()) bad("parameters", o, "an object");
        for (auto it = o.begin(); it != o.end(); ++it)
            if (!it.value().is_object() || !it.value().contains("value"))
                bad("parameters/" + it.key(), it.value(), "an object with a 'value'");
    }
    if (j.contains("data_h5_hash")) {
        const nlohmann::json& h = j["data_h5_hash"];
        if (!h.is_object()) bad("data_h5_hash", h, "an object");
        for (const char* f : {"scalars", "points"})
            if (h.contains(f) && !h[f].is_string()) bad(std::string("data_h5_hash/") + f, h[f], "a string");
        if (h.contains("tables")) {
            if (!h["tables"].is_object()) bad("data_h5_hash/tables", h["tables"], "an object");
            for (auto it = h["tables"].begin(); it != h["tables"].end(); ++it)
                if (!it.value().is_string()) bad("data_h5_hash/tables/" + it.key(), it.value(), "a string");
        }
    }
}

nlohmann::json read_summary(const fs::path& file, const std::string& name) {
    // Untrusted: a regular file under its cap (not a symlink to /dev/zero, not a FIFO), nested no
    // deeper than kMaxJsonDepth (100000-deep JSON overflowed the recursive parser's stack).
    nlohmann::json j = parse_untrusted_json(read_untrusted_file(file, kMaxSummaryBytes, "summary.json"), file.string());
    const std::string where = file.string() + ": ";
    if (!j.is_object())
        throw InputError(where + "not a granrepro summary (a JSON object expected, found " + json_kind(j) + ")");
    if (j.contains("schema") && j["schema"] != "granrepro-summary")
        throw InputError(where + "'schema' must be \"granrepro-summary\", found " + json_kind(j["schema"]));
    if (j.contains("experiment") && j["experiment"] != name)
        throw InputError(where + "holds results of experiment " + json_kind(j["experiment"]) + ", not \"" + name + "\"");
    if (!j.contains("scale")) throw InputError(where + "has no 'scale' (\"quick\" or \"paper\")");
    if (!j["scale"].is_string() || (j["scale"] != "quick" && j["scale"] != "paper"))
        throw InputError(where + "'scale' must be \"quick\" or \"paper\", found " + json_kind(j["scale"]));
    if (!j.contains("scalars") || !j["scalars"].is_object()) throw InputError(where + "has no 'scalars' object");
    for (auto it = j["scalars"].begin(); it != j["scalars"].end(); ++it)
        if (!it.value().is_number() && !it.value().is_null())
            throw InputError(where + "scalar '" + it.key() + "' must be a number or null, found " + json_kind(it.value()));
    check_summary_fields(j, where);
    return j;
}

// Where one of the two files disagrees with the other: bad input naming the file, what differs
// and the way out.
[[noreturn]] void disagree(const fs::path& file, const std::string& what, const std::string& name) {
    throw InputError(file.string() + ": " + what + "; rerun `granrepro " + name + "`");
}

// A stored parameter equals summary.json's: numbers by value (a real that is not finite is null in
// JSON), everything else exactly.
bool same_parameter(const nlohmann::json& stored_value, const nlohmann::json& in_summary) {
    const nlohmann::json stored = stored_parameter_as(stored_value, in_summary);
    if (stored.is_number_float() && !std::isfinite(stored.get<double>())) return in_summary.is_null();
    return stored == in_summary;
}

// data.h5's /parameters against summary.json's `parameters` (which summary_json_hash covers), name
// by name: a one-sided edit (k_N 2000 -> 3000 in data.h5) is refused naming the file and the
// parameter. `verify` also recomputes them from the stored experiment file (harness/verify.cpp).
void same_parameters(const H5File& f, const fs::path& file, const nlohmann::json& summary, const std::string& name) {
    if (!summary.contains("parameters")) return; // no summary version lacks them; nothing to compare with
    const nlohmann::json stored = read_stored_parameters(f);
    const nlohmann::json& recorded = summary["parameters"];
    for (auto it = recorded.begin(); it != recorded.end(); ++it) {
        if (!stored.contains(it.key()))
            disagree(file, "has no parameter '" + it.key() + "' in /parameters (summary.json beside it has it)", name);
        if (!same_parameter(stored[it.key()], it.value()["value"]))
            disagree(file, "parameter '" + it.key() + "' is " + stored[it.key()].dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).substr(0, 40) +
                               " in /parameters but " + it.value()["value"].dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).substr(0, 40) +
                               " in summary.json beside it (one of the two was edited)",
                     name);
    }
    for (auto it = stored.begin(); it != stored.end(); ++it)
        if (!recorded.contains(it.key()))
            disagree(file, "parameter '" + it.key() + "' in /parameters is not in summary.json beside it", name);
}

// data.h5 must open, carry the result schema of this experiment, agree with summary.json on
// experiment, scale, seed and code version, hold the scalars summary.json states (bit for bit;
// NaN for null), and every table must read back whole: a truncated file fails one of these.
// Each file also carries the other's content hash (docs/schema.md), so an edit of either one is
// found. Only schema_version 3 is read (a schema bump regenerates paper_figures/).
void check_data_file(const fs::path& file, const std::string& name, const fs::path& summary_file,
                     const nlohmann::json& summary) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(file, ec))) throw InputError(file.string() + ": missing (summary.json has no data file beside it)");
    try {
        const H5File f = H5File::open(file.string()); // a regular file only (no symlink, no FIFO)
        f.require_schema("granrepro-result", 3);
        if (const std::string e = f.read_string_attr("experiment"); e != name)
            throw std::runtime_error("holds results of experiment '" + e + "'");
        // A one-sided edit of these would judge the data by the wrong claims ("paper" on quick
        // data) or hide the paper-only ones as skipped.
        auto same = [&](const char* field, const nlohmann::json& in_h5, bool optional) {
            if (!summary.contains(field)) {
                if (optional) return;
                disagree(summary_file, std::string("has no '") + field + "' (data.h5 beside it has " + json_kind(in_h5) + ")",
                         name);
            }
            if (summary[field] != in_h5)
                disagree(summary_file, std::string("'") + field + "' is " + json_kind(summary[field]) +
                                           " but data.h5 beside it has " + json_kind(in_h5) + " (one of the two was edited)",
                         name);
        };
        same("experiment", name, false);
        same("scale", f.read_string_attr("scale"), false);
        same("seed", f.read_u64_attr("seed"), false);
        if (f.has_attr("code_version")) same("code_version", f.read_string_attr("code_version"), true);
        if (f.has_attr("physics_hash")) same("physics_hash", f.read_string_attr("physics_hash"), true);
        if (!f.has_attr("summary_json_hash")) throw std::runtime_error("has no summary_json_hash");
        if (f.read_string_attr("summary_json_hash") != summary_content_hash(summary))
            disagree(summary_file, "content differs from the hash data.h5 beside it recorded for it (edited since the run?)",
                     name);
        if (!summary.contains("data_h5_hash") || !summary["data_h5_hash"].is_object())
            disagree(summary_file, "has no 'data_h5_hash' object (data.h5 beside it records one)", name);
        same_parameters(f, file, summary, name);
        const nlohmann::json found = data_content_hash(file); // reads every table whole
        // The count of stored points (summary.json's hash covers it) against /points.
        if (summary.contains("stored_points")) {
            const std::size_t stored = read_points_records(file).size();
            if (summary["stored_points"] != stored)
                disagree(summary_file, "'stored_points' is " + summary["stored_points"].dump() + " but data.h5 beside it stores " +
                                           std::to_string(stored) + " points (/points/records; one of the two was edited)",
                         name);
        }
        {
            const nlohmann::json& recorded = summary["data_h5_hash"];
            if (recorded.value("scalars", "") != found["scalars"])
                disagree(file, "its scalars differ from the hash summary.json recorded for them (edited since the run?)", name);
            // The stored sweep points (/points/records) too.
            if (recorded.contains("points") != found.contains("points") ||
                (found.contains("points") && recorded["points"] != found["points"]))
                disagree(file, found.contains("points") ? "its stored sweep points (/points) differ from the hash summary.json recorded for them (edited since the run?)"
                                                        : "has no stored sweep points (/points), but summary.json records their hash",
                         name);
            const nlohmann::json tables = recorded.value("tables", nlohmann::json::object());
            const std::string omitted = f.has_attr("omitted_tables") ? f.read_string_attr("omitted_tables") : "";
            for (auto it = found["tables"].begin(); it != found["tables"].end(); ++it)
                if (!tables.contains(it.key()) || tables[it.key()] != it.value())
                    disagree(file, "table '" + it.key() + "' differs from the hash summary.json recorded for it (edited since the run?)",
                             name);
            // A compact copy (export) leaves large tables out and names them.
            for (auto it = tables.begin(); it != tables.end(); ++it)
                if (!found["tables"].contains(it.key()) && omitted.find(it.key() + " (") == std::string::npos)
                    disagree(file, "has no table '" + it.key() + "' (summary.json records it)", name);
        }
        const H5Object sc = f.open_group("scalars");
        const nlohmann::json& scalars = summary["scalars"];
        for (auto it = scalars.begin(); it != scalars.end(); ++it) {
            if (!sc.has(it.key())) throw std::runtime_error("has no scalar '" + it.key() + "' (summary.json has it)");
            const std::vector<double> v = sc.read_dataset(it.key());
            const bool same_value = v.size() == 1 && (it.value().is_null() ? !std::isfinite(v[0])
                                                                           : v[0] == it.value().get<double>());
            if (!same_value) throw std::runtime_error("scalar '" + it.key() + "' differs from summary.json");
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        throw InputError(file.string() + ": damaged or not this experiment's results (" + msg.substr(0, msg.find('\n')) +
                         "); rerun `granrepro " + name + "`");
    }
}

// The lines under a check table's title: the --set overrides, so that a modified run's table
// cannot pass for the default's.
std::vector<std::string> check_notes(const nlohmann::json& overrides) {
    std::vector<std::string> notes;
    if (overrides.is_object() && !overrides.empty()) {
        std::string sets;
        for (auto it = overrides.begin(); it != overrides.end(); ++it)
            sets += (sets.empty() ? "" : " ") + it.key() + "=" + (it.value().is_string() ? it.value().get<std::string>()
                                                                                         : it.value().dump());
        notes.push_back("parameters changed from the defaults (--set): " + sets);
    }
    return notes;
}

std::vector<std::string> figure_ids(const ExperimentInfo& info) {
    std::vector<std::string> ids;
    for (const auto& f : info.figures) ids.push_back(f.id);
    return ids;
}

// The figures a run renders: the requested ones (all for a plain run) and every other figure the
// directory it replaces had, re-rendered from the new data.
std::vector<std::string> figures_to_render(const ExperimentInfo& info, const RunOptions& opt, const fs::path& final_dir) {
    std::vector<std::string> ids;
    for (const auto& f : info.figures)
        if (opt.figures.empty() || std::find(opt.figures.begin(), opt.figures.end(), f.id) != opt.figures.end() ||
            fs::exists(final_dir / (f.id + ".png")))
            ids.push_back(f.id);
    return ids;
}

// run.log's head: the command, the code, the experiment and every parameter.
void log_run_head(const std::string& name, const RunOptions& opt, const ParameterSet& params) {
    run_log().line("command: " + opt.command_line);
    run_log().line(std::string("granrepro ") + code_version() + " (physics " + physics_hash() + "); data files from " + project_root().string());
    run_log().line(std::string("experiment ") + name + ", scale " + to_string(opt.scale) + ", seed " +
                   std::to_string(opt.seed) + ", threads " + std::to_string(opt.threads));
    for (const auto& p : params.all())
        run_log().line("parameter " + p.name + " = " + p.value_text() + " [" + p.unit + "]" + (p.overridden ? " (--set)" : ""));
}

// The experiment's run; nothing where this process's part ends without results (a rank > 0 that
// served its points, a --points shard: its message is printed).
std::optional<Result> run_part(const Experiment& exp, const RunContext& ctx, const fs::path& work_dir) {
    try {
        return exp.run(ctx);
    } catch (const SweepServed&) {
        return std::nullopt;
    } catch (const ShardFinished& e) {
        std::printf("%s\n", e.what());
        return std::nullopt;
    } catch (const InputError&) {
        // A late refusal of the input fails the same way on every rerun: its checkpoints can
        // never be resumed, so no hidden .X.checkpoint/ outlives it (issue 20). Not so for shards
        // and `gather`: "points missing" is cured by the other shards, whose points are kept.
        if (ctx.sweep.mode == SweepPlan::Mode::All) {
            std::error_code ec;
            fs::remove_all(work_dir, ec);
        }
        throw;
    } catch (const Interrupted& e) {
        bool kept = false;
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(work_dir, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec))
            kept = kept || it->is_regular_file();
        throw Interrupted(e.signal(), std::string(e.what()) +
                                          (kept ? "; progress kept in " + work_dir.string() + ", rerun the same command to resume"
                                                : "; no checkpoint had been written yet, the rerun starts afresh"));
    }
}

// The experiment's output handles (data/outputs.hpp) must cover what the run wrote, since claims
// and plot scripts are checked against them when they load. Experiments write only through
// handles, so this holds by construction; it guards a Result made by other means (tests'
// protocols declare nothing and are not checked). Fails before anything is written.
void refuse_undeclared(const ExperimentInfo& info, const Result& result, const std::string& name) {
    if (!info.outputs.declared()) return;
    std::string undeclared;
    for (const auto& sc : result.scalars)
        if (!info.outputs.declares_scalar(sc.name)) undeclared += " scalar " + sc.name;
    for (const auto& t : result.tables)
        if (!info.outputs.declares_table(t.name)) undeclared += " table " + t.name;
    if (!undeclared.empty())
        throw std::runtime_error(name + " wrote outputs that no output handle of it declares:" + undeclared);
}

// What one run has made, for writing its results.
struct Made {
    const std::string& name;
    const ExperimentInfo& info;
    const ParameterSet& params;
    const Result& result;
    const std::vector<ClaimResult>& verdicts;
    SweepPoints& points;
    double wall = 0, cpu = 0; // [s] the run's, without writing
};

// Writes data.h5, the tables, summary.json and the figures into the staging folder and commits
// it: the old results stay as they were unless every write succeeded. Returns the figures the
// command asked for that were not drawn.
std::vector<std::string> write_results(const Made& m, const RunOptions& opt, const std::vector<std::string>& to_render,
                                       StagedDirectory& stage, const fs::path& final_dir,
                                       std::chrono::steady_clock::time_point t0) {
    auto requested = [&](const std::string& id) {
        return opt.figures.empty() || std::find(opt.figures.begin(), opt.figures.end(), id) != opt.figures.end();
    };
    std::vector<std::string> not_drawn;
    try {
        std::vector<std::pair<std::string, std::string>> plot_texts;
        for (const auto& id : to_render) plot_texts.emplace_back(id, read_file(project_root() / "plots" / (id + ".gp")));
        Provenance prov{m.name,  m.info.paper, read_file(m.info.file),     opt.scale, opt.seed,
                        m.wall,  opt.threads,  opt.command_line, read_file(expected_file(m.name)), plot_texts};
        prov.points = &m.points;
        run_totals(prov, m.points, m.wall, m.cpu);
        if (prov.resumed_points > 0)
            run_log().line("whole run, resumed points included: wall time " + std::to_string(prov.total_wall_time_s) +
                           " s, CPU " + std::to_string(prov.total_cpu_time_s) + " s (" +
                           std::to_string(prov.resumed_points) + " points resumed" +
                           (prov.points_without_cost ? ", " + std::to_string(prov.points_without_cost) +
                                                           " of them without a recorded cost: lower bounds"
                                                     : std::string()) +
                           ")");
        nlohmann::json summary = summary_json(prov, m.params, m.result);
        summary["claims"] = claims_to_json(m.verdicts);
        write_result_h5(stage.path() / "data.h5", prov, m.params, m.result, summary_content_hash(summary));
        write_tables_tsv(stage.path() / "tables", m.result);
        write_file_durably(stage.path() / "summary.json", summary_text(summary));
        for (const auto& id : to_render) {
            const RenderOutcome o = render_figure(id, stage.path(), final_dir);
            if ((o == RenderOutcome::Failed || o == RenderOutcome::Skipped) && requested(id)) not_drawn.push_back(id);
            const fs::path png = stage.path() / (id + ".png");
            if (fs::exists(png) && !png_complete(png)) throw WriteError(png.string(), "figure cut short (disk full?)");
        }
        const double wall_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        VerdictCounts counts;
        counts.add(m.verdicts);
        run_log().line("claims: " + counts.text());
        run_log().line("done: wall time " + std::to_string(wall_total) + " s with writing and " +
                       std::to_string(to_render.size()) + " figures");
        run_log().close();
        stage.commit();
    } catch (const WriteError& e) {
        // The failure names the file where it would have ended up.
        throw WriteError(stage.shown(e.path()).string(), e.reason());
    }
    return not_drawn;
}

// What `figure` shows of a run's claims: those whose source cites one of `figures` (claims name
// no figure of their own; see cites_figure), with a note counting the others, whose verdicts
// still decide the exit code. All of them for a plain run.
std::vector<ClaimResult> figure_claims(const std::string& name, const std::vector<std::string>& figures,
                                       const std::vector<ClaimResult>& verdicts, std::string& title,
                                       std::vector<std::string>& notes) {
    if (figures.empty()) return verdicts;
    std::vector<ClaimResult> shown, others;
    for (const auto& r : verdicts)
        (std::any_of(figures.begin(), figures.end(), [&](const auto& f) { return cites_figure(r.claim, f); }) ? shown : others)
            .push_back(r);
    title += ", figure " + joined(figures);
    VerdictCounts rest;
    rest.add(others);
    notes.push_back("the " + std::to_string(shown.size()) + " claims whose source cites " +
                    (figures.size() == 1 ? "this figure" : "these figures") + "; the other " + std::to_string(others.size()) +
                    " of " + name + ": " + rest.text() + " (`granrepro check " + name + "` lists every claim)");
    return shown;
}

// The claim table on stdout and the exit code: 1 if a claim failed, kFigureNotDrawn if a figure
// the command asked for was not drawn.
int report_run(const std::string& name, const RunOptions& opt, const ParameterSet& params,
               const std::vector<ClaimResult>& verdicts, const std::vector<std::string>& not_drawn, VerdictCounts* totals) {
    nlohmann::json sets = nlohmann::json::object();
    for (const auto& p : params.all())
        if (p.overridden) sets[p.name] = p.value_text();
    std::string title = name + " (" + to_string(opt.scale) + " scale)";
    std::vector<std::string> notes = check_notes(sets);
    const std::vector<ClaimResult> shown = figure_claims(name, opt.figures, verdicts, title, notes);
    // `figure` names what it drew: the PNG is the command's result.
    for (const auto& id : opt.figures)
        if (std::find(not_drawn.begin(), not_drawn.end(), id) == not_drawn.end())
            std::printf("figure %s: %s\n", id.c_str(), (opt.out / name / (id + ".png")).c_str());
    std::fputs(format_claim_table(title, shown, notes).c_str(), stdout);
    std::fflush(stdout);
    if (totals) totals->add(verdicts);
    throw_if_interrupted(" after the results were written to " + (opt.out / name).string());
    if (!all_pass(verdicts)) return 1;
    if (!not_drawn.empty())
        std::fprintf(stderr, "granrepro: %s: figure%s not drawn: %s (exit %d)\n", name.c_str(),
                     not_drawn.size() == 1 ? "" : "s", joined(not_drawn).c_str(), kFigureNotDrawn);
    return not_drawn.empty() ? 0 : kFigureNotDrawn;
}

} // namespace

int run_experiment(const std::string& name, const RunOptions& opt, VerdictCounts* totals) {
    const Experiment& exp = find_experiment(name);
    const ExperimentInfo info = experiment_info(name);
    const ParameterSet params = resolve_parameters(name, opt);
    for (const auto& f : opt.figures)
        if (!makes(info, f)) throw InputError("figure " + f + " is not made by experiment " + name);
    // Read the claims before spending time on the run: a broken file is an input error.
    const auto claims = load_claims(expected_file(name), name, &info.outputs);
    SweepPlan plan = sweep_plan(name, opt);
    ensure_writable_directory(opt.out, "--out");

    const fs::path final_dir = opt.out / name;
    // One writer per OUT/<name> (see io/output_lock.hpp); then whatever killed runs left beside
    // it is stale and is cleaned (or, for a kill inside a fallback commit, restored).
    // Shards of one sweep share the lock (each point is its own file), a whole run or `gather`
    // holds it alone; MPI ranks other than 0 run under rank 0's lock. Only a lone holder may
    // clean leftovers: a shard's in-flight point files look like a dead run's.
    const bool shard_run = plan.mode == SweepPlan::Mode::Shard;
    const int ranks = mpi::size();
    const bool rank0 = mpi::rank() == 0;
    std::optional<OutputLock> lock;
    if (rank0) lock.emplace(opt.out, name, shard_run ? OutputLock::Mode::Shared : OutputLock::Mode::Exclusive);
    const fs::path work_dir = opt.out / ("." + name + ".checkpoint");
    // What a run reads or writes in OUT must be its own (docs/schema.md, "Trust model"): a
    // checkpoint folder linked elsewhere would get point files written there, a linked script
    // would be copied into the results. --out itself may be a link the user made.
    if (existing_entry(work_dir, Entry::Folder, "checkpoint folder")) refuse_links_below(work_dir, "checkpoint folder");
    check_plot_entries(final_dir, figure_ids(info));
    if (rank0 && !shard_run) {
        clean_staging_leftovers(final_dir, opt.quiet);
        clean_temporary_leftovers(work_dir);
    }
    const std::vector<std::string> to_render = figures_to_render(info, opt, final_dir);

    if (plan.mode != SweepPlan::Mode::All) {
        const char* what = plan.mode == SweepPlan::Mode::Gather ? "gather" : "--points";
        if (!exp.distributed)
            throw InputError(std::string(what) + ": experiment " + name + " has no distributed sweep; run it whole");
        if (ranks > 1) throw InputError(std::string(what) + " runs without mpirun (one process per shard)");
    }
    // Without a distributed sweep the experiment is rank 0's alone.
    if (!rank0 && !exp.distributed) return 0;
    plan.ranks = exp.distributed ? ranks : 1;

    // Shards and ranks > 0 write only checkpoint files (rank 0 writes them under MPI).
    std::optional<StagedDirectory> stage;
    if (rank0 && !shard_run) stage.emplace(final_dir);
    // run.log: opened in the staging folder, so it moves into place with the results (rank 0).
    struct CloseLog {
        ~CloseLog() { run_log().close(); }
    } close_log;
    if (stage) {
        run_log().open(stage->path() / "run.log");
        log_run_head(name, opt, params);
    }
    fs::create_directories(work_dir);
    RunContext ctx{params, opt.scale, opt.seed, opt.threads, opt.quiet || !rank0, work_dir, opt.checkpoint_interval};
    ctx.sweep = plan;
    SweepPoints points; // every sweep point, for the results' /points
    ctx.points = &points;

    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock(); // this process's CPU time, all threads
    const std::optional<Result> ran = run_part(exp, ctx, work_dir);
    if (!ran) return 0;
    refuse_undeclared(info, *ran, name);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    // The CPU time lets `bench sweep` tell a run's serial part from time lost to other processes.
    run_log().line("run finished: wall time " + std::to_string(wall) + " s, CPU " + std::to_string(cpu) + " s");

    const auto verdicts = evaluate_claims(claims, scalars_json(*ran), opt.scale);
    const Made made{name, info, params, *ran, verdicts, points, wall, cpu};
    const std::vector<std::string> not_drawn = write_results(made, opt, to_render, *stage, final_dir, t0);
    std::error_code ec;
    fs::remove_all(work_dir, ec);
    if (!opt.quiet) std::fprintf(stderr, "%s: %.1f s, results in %s\n", name.c_str(), wall, final_dir.c_str());
    return report_run(name, opt, params, verdicts, not_drawn, totals);
}

SweepPlan parse_points(const std::string& text) {
    SweepPlan plan;
    plan.mode = SweepPlan::Mode::Shard;
    char slash = 0, rest = 0;
    std::istringstream in(text);
    if (!(in >> plan.shard >> slash >> plan.shards) || slash != '/' || in >> rest || plan.shard < 1 ||
        plan.shards < 1 || plan.shard > plan.shards)
        throw InputError("--points " + text + ": expected I/N with 1 <= I <= N (shard I of N)");
    return plan;
}

namespace {
// A Slurm job-array variable: unset, or a whole integer in [lo, hi]. Garbage is refused by name:
// atol("abc") = 0 used to run shard 1 of 2 without a word.
std::optional<long> slurm_number(const char* var, long lo, long hi) {
    const char* text = std::getenv(var);
    if (!text) return std::nullopt;
    long x = 0;
    if (!parse_long(text, x) || x < lo || x > hi)
        throw InputError(std::string(var) + "=" + text + ": must be an integer " +
                         (hi == std::numeric_limits<long>::max() ? ">= " + std::to_string(lo)
                                                                  : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]") +
                         " (Slurm job array; outside one, unset it or pass --points I/N)");
    return x;
}
} // namespace

std::optional<SweepPlan> slurm_array_shard() {
    const long most = std::numeric_limits<int>::max();
    const auto id = slurm_number("SLURM_ARRAY_TASK_ID", 0, std::numeric_limits<long>::max());
    const auto count = slurm_number("SLURM_ARRAY_TASK_COUNT", 1, most);
    if (!id && !count) return std::nullopt;
    if (!id || !count)
        throw InputError(std::string(id ? "SLURM_ARRAY_TASK_COUNT" : "SLURM_ARRAY_TASK_ID") + " is not set but " +
                         (id ? "SLURM_ARRAY_TASK_ID" : "SLURM_ARRAY_TASK_COUNT") +
                         " is: cannot tell which shard this task is; pass --points I/N");
    const long min = slurm_number("SLURM_ARRAY_TASK_MIN", 0, std::numeric_limits<long>::max()).value_or(0);
    const long step = slurm_number("SLURM_ARRAY_TASK_STEP", 1, std::numeric_limits<long>::max()).value_or(1);
    // Task IDs are MIN, MIN + STEP, ..., COUNT of them; shard I of COUNT is the I-th.
    if (*id < min || (*id - min) % step != 0 || (*id - min) / step >= *count)
        throw InputError("SLURM_ARRAY_TASK_ID=" + std::to_string(*id) + ": not one of the array's " +
                         std::to_string(*count) + " task IDs " + std::to_string(min) + ", " + std::to_string(min) + "+" +
                         std::to_string(step) + ", ... (SLURM_ARRAY_TASK_MIN=" + std::to_string(min) +
                         ", SLURM_ARRAY_TASK_STEP=" + std::to_string(step) + ", SLURM_ARRAY_TASK_COUNT=" +
                         std::to_string(*count) + ")");
    SweepPlan plan;
    plan.mode = SweepPlan::Mode::Shard;
    plan.shard = int((*id - min) / step + 1);
    plan.shards = int(*count);
    return plan;
}

SweepPlan sweep_plan(const std::string& name, const RunOptions& opt) {
    SweepPlan plan = opt.sweep;
    if (plan.mode == SweepPlan::Mode::All && opt.shard_from_slurm && find_experiment(name).distributed)
        if (const auto shard = slurm_array_shard()) plan = *shard;
    return plan;
}

bool has_results(const std::string& name, const fs::path& out) { return fs::exists(out / name / "summary.json"); }

std::vector<Claim> experiment_claims(const std::string& name) {
    const ExperimentInfo info = experiment_info(name);
    return load_claims(expected_file(name), name, &info.outputs);
}

nlohmann::json read_checked_summary(const std::string& name, const fs::path& out, const std::string& missing) {
    const fs::path summary_path = out / name / "summary.json";
    if (!fs::exists(summary_path))
        throw InputError(!missing.empty() ? missing
                                          : "no results of " + name + " in " + (out / name).string() + "; run `granrepro " +
                                                name + "` first");
    nlohmann::json summary = read_summary(summary_path, name);
    check_data_file(out / name / "data.h5", name, summary_path, summary);
    return summary;
}

bool complete_result(const std::string& name, const RunOptions& opt) {
    if (!opt.sets.empty() || !opt.figures.empty() || opt.sweep.mode != SweepPlan::Mode::All || !has_results(name, opt.out))
        return false;
    try {
        const nlohmann::json summary = read_checked_summary(name, opt.out);
        const nlohmann::json none = nlohmann::json::object();
        if (summary["scale"] != to_string(opt.scale) || summary.value("seed", nlohmann::json()) != opt.seed ||
            summary.value("physics_hash", "") != physics_hash() || summary.value("overridden_parameters", none) != none ||
            summary.value("parameters", none) != resolve_parameters(name, opt).to_json())
            return false;
        for (const auto& f : experiment_info(name).figures) {
            const fs::path png = opt.out / name / (f.id + ".png");
            if (!fs::is_regular_file(fs::symlink_status(png)) || !png_complete(png)) return false;
        }
        return true;
    } catch (const std::exception&) {
        return false; // damaged or foreign: the run replaces it
    }
}

int check_experiment(const std::string& name, const fs::path& out, const CheckOptions& opt, VerdictCounts* totals) {
    find_experiment(name);
    const auto claims = experiment_claims(name);
    const nlohmann::json summary = read_checked_summary(
        name, out, "check " + name + ": no results in " + (out / name).string() + "; run `granrepro " + name + "` first");
    const Scale scale = parse_scale(summary["scale"].get<std::string>());
    const auto verdicts = evaluate_claims(claims, summary["scalars"], scale);
    const auto notes = check_notes(summary.value("overridden_parameters", nlohmann::json::object()));
    std::fputs(format_claim_table(name + " (" + to_string(scale) + " scale)", verdicts, notes).c_str(), stdout);
    if (opt.explain) std::fputs(format_deviation_explanations(verdicts).c_str(), stdout);
    std::fflush(stdout);
    if (totals) totals->add(verdicts);
    return all_pass(verdicts) ? 0 : 1;
}

nlohmann::json judged_claims(const std::string& name, const fs::path& out) {
    find_experiment(name);
    const auto claims = load_claims(expected_file(name), name);
    const nlohmann::json summary = read_checked_summary(name, out, "report: no results in " + (out / name).string());
    const std::string scale = summary["scale"].get<std::string>();
    const auto verdicts = evaluate_claims(claims, summary["scalars"], parse_scale(scale));
    VerdictCounts counts;
    counts.add(verdicts);
    return {{"scale", scale},
            {"notes", check_notes(summary.value("overridden_parameters", nlohmann::json::object()))},
            {"claims", claims_to_json(verdicts)},
            {"headline", headline_json(counts)}};
}

int check_all(const fs::path& out, const CheckOptions& opt) {
    int rc = 0;
    VerdictCounts totals;
    std::vector<std::string> missing;
    for (const auto& e : experiment_registry()) {
        if (has_results(e.name, out)) rc |= check_experiment(e.name, out, opt, &totals);
        else missing.push_back(e.name);
    }
    std::fputs(totals.closing().c_str(), stdout);
    std::fflush(stdout);
    if (!missing.empty()) {
        std::fprintf(stderr, "granrepro: check --all: no results in %s for %zu experiment%s: %s%s\n", out.c_str(),
                     missing.size(), missing.size() == 1 ? "" : "s", joined(missing).c_str(),
                     opt.missing_ok ? " (--missing-ok: not a failure)" : " (run them first)");
        if (!opt.missing_ok) rc = 1;
    }
    return rc;
}

int export_experiment(const std::string& name, const fs::path& out, const fs::path& to, std::size_t max_values) {
    find_experiment(name);
    const fs::path from = out / name;
    if (!fs::exists(from / "summary.json") || !fs::exists(from / "data.h5"))
        throw InputError("export " + name + ": no results in " + from.string() + "; run `granrepro " + name + "` first");
    // Into the folder it reads, export would replace the full data.h5 with its compact copy.
    std::error_code same;
    if (fs::equivalent(to, out, same) || fs::equivalent(to / name, from, same))
        throw InputError("export --to " + to.string() + ": the same folder as --out " + out.string() +
                         " (the compact copy would replace the full data.h5); give another folder");
    existing_entry(from, Entry::Folder, "results folder");
    require_regular_file(from / "data.h5", "data.h5");
    // Both read as untrusted (regular files under their caps, JSON depth-bounded), before a byte is written.
    const std::string summary = read_untrusted_file(from / "summary.json", kMaxSummaryBytes, "summary.json");
    parse_untrusted_json(summary, (from / "summary.json").string());
    ensure_writable_directory(to, "--to");
    const fs::path dest = to / name;
    existing_entry(dest, Entry::Folder, "export folder"); // never written through a link
    fs::create_directories(dest);
    const fs::path tmp = dest / ".data.h5.partial";
    std::error_code gone;
    fs::remove(tmp, gone); // HDF5 creates it by name: a link planted there goes first
    std::vector<std::string> omitted;
    try {
        omitted = write_compact_result_h5(from / "data.h5", tmp, max_values);
    } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove(tmp, ec);
        if (dynamic_cast<const InputError*>(&e)) throw; // names the file already
        throw InputError("export " + name + ": " + (from / "data.h5").string() + ": " + e.what());
    }
    fs::rename(tmp, dest / "data.h5");
    write_file_atomically(dest / "summary.json", summary);
    std::printf("export %s: %s -> %s (%.0f kB data.h5%s%s)\n", name.c_str(), from.c_str(), dest.c_str(),
                double(fs::file_size(dest / "data.h5")) / 1024.0, omitted.empty() ? "" : "; left out: ",
                joined(omitted).c_str());
    return 0;
}

int plot_experiment(const std::string& name, const fs::path& out, const std::vector<std::string>& figures,
                    bool strict, bool edited) {
    const ExperimentInfo info = experiment_info(name);
    const std::string known = joined(info.figures, [](const auto& f) { return f.id; });
    for (const auto& id : figures)
        if (!makes(info, id))
            throw InputError("--figure " + id + " is not made by experiment " + name + "; it makes " + known);
    const fs::path dir = out / name;
    if (!fs::exists(dir / "tables"))
        throw InputError("plot " + name + ": no results in " + dir.string() + "; run `granrepro " + name + "` first");
    // One writer per OUT/<name>: a plot beside a run of the same experiment (which replaces the
    // folder) once exited 4; now the second of the two is refused at once (io/output_lock.hpp).
    const OutputLock lock(out, name);
    std::vector<std::string> ids;
    for (const auto& f : info.figures)
        if (figures.empty() || std::find(figures.begin(), figures.end(), f.id) != figures.end()) ids.push_back(f.id);
    check_plot_entries(dir, ids); // every figure's files before the first is drawn
    int failures = 0;
    for (const auto& id : ids) {
        const RenderOutcome o = render_figure(id, dir, {}, edited);
        failures += o == RenderOutcome::Failed || o == RenderOutcome::Skipped || (strict && o == RenderOutcome::Warned);
    }
    return failures ? kFigureNotDrawn : 0;
}

} // namespace granrepro
