#include "harness/runner.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"
#include "harness/claims.hpp"
#include "harness/plotter.hpp"
#include "io/result_writer.hpp"
#include "io/staged_directory.hpp"

namespace fs = std::filesystem;

namespace granrepro {

const Experiment& find_experiment(const std::string& name) {
    for (const auto& e : experiment_registry())
        if (e.name == name) return e;
    std::string known;
    for (const auto& e : experiment_registry()) known += (known.empty() ? "" : ", ") + e.name;
    throw InputError("unknown experiment '" + name + "'; known: " + known);
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
std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
fs::path expected_file(const std::string& name) { return project_root() / "expected" / (name + ".toml"); }
} // namespace

int run_experiment(const std::string& name, const RunOptions& opt, VerdictCounts* totals) {
    const Experiment& exp = find_experiment(name);
    const ExperimentInfo info = experiment_info(name);
    const ParameterSet params = resolve_parameters(name, opt);
    for (const auto& f : opt.figures) {
        bool found = false;
        for (const auto& fi : info.figures) found = found || fi.id == f;
        if (!found) throw InputError("figure " + f + " is not made by experiment " + name);
    }
    // Read the claims before spending time on the run: a broken file is an input error.
    const auto claims = load_claims(expected_file(name), name);
    ensure_writable_directory(opt.out, "--out");

    // The new directory replaces the old one: a figure run renders the requested figures and
    // re-renders, from the new data, every other figure the old directory had.
    const fs::path final_dir = opt.out / name;
    std::vector<std::string> to_render;
    for (const auto& f : info.figures)
        if (opt.figures.empty() || std::find(opt.figures.begin(), opt.figures.end(), f.id) != opt.figures.end() ||
            fs::exists(final_dir / (f.id + ".png")))
            to_render.push_back(f.id);

    StagedDirectory stage(final_dir);
    const fs::path work_dir = opt.out / ("." + name + ".checkpoint");
    fs::create_directories(work_dir);
    const RunContext ctx{params, opt.scale, opt.seed, opt.threads, opt.quiet, work_dir, opt.checkpoint_interval};

    const auto t0 = std::chrono::steady_clock::now();
    Result result;
    try {
        result = exp.run(ctx);
    } catch (const InputError&) {
        // A late refusal of the input fails the same way on every rerun: its checkpoints can
        // never be resumed, so no hidden .X.checkpoint/ outlives it (issue 20).
        std::error_code ec;
        fs::remove_all(work_dir, ec);
        throw;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    Provenance prov{name, info.paper, read_text(info.file), opt.scale, opt.seed, wall, opt.threads};
    write_result_h5(stage.path() / "data.h5", prov, params, result);
    write_tables_tsv(stage.path() / "tables", result);
    const auto verdicts = evaluate_claims(claims, scalars_json(result), opt.scale);
    nlohmann::json summary = summary_json(prov, params, result);
    summary["claims"] = claims_to_json(verdicts);
    {
        std::ofstream out(stage.path() / "summary.json");
        out << summary.dump(2) << "\n";
    }
    for (const auto& id : to_render) render_figure(id, stage.path(), final_dir);
    stage.commit();
    std::error_code ec;
    fs::remove_all(work_dir, ec);
    if (!opt.quiet) std::fprintf(stderr, "%s: %.1f s, results in %s\n", name.c_str(), wall, final_dir.c_str());
    std::fputs(format_claim_table(name + " (" + to_string(opt.scale) + " scale)", verdicts).c_str(), stdout);
    std::fflush(stdout);
    if (totals) totals->add(verdicts);
    return all_pass(verdicts) ? 0 : 1;
}

bool has_results(const std::string& name, const fs::path& out) { return fs::exists(out / name / "summary.json"); }

int check_experiment(const std::string& name, const fs::path& out, const CheckOptions& opt, VerdictCounts* totals) {
    find_experiment(name);
    const auto claims = load_claims(expected_file(name), name);
    const fs::path summary_path = out / name / "summary.json";
    if (!fs::exists(summary_path))
        throw InputError("check " + name + ": no results in " + (out / name).string() + "; run `granrepro " +
                         name + "` first");
    nlohmann::json summary;
    try {
        summary = nlohmann::json::parse(read_text(summary_path));
    } catch (const std::exception&) {
        throw InputError(summary_path.string() + ": not valid JSON");
    }
    if (!summary.contains("scalars") || !summary["scalars"].is_object())
        throw InputError(summary_path.string() + ": has no 'scalars' object");
    const Scale scale = parse_scale(summary.value("scale", "quick"));
    const auto verdicts = evaluate_claims(claims, summary["scalars"], scale);
    std::fputs(format_claim_table(name + " (" + to_string(scale) + " scale)", verdicts).c_str(), stdout);
    if (opt.explain) std::fputs(format_deviation_explanations(verdicts).c_str(), stdout);
    std::fflush(stdout);
    if (totals) totals->add(verdicts);
    return all_pass(verdicts) ? 0 : 1;
}

int check_all(const fs::path& out, const CheckOptions& opt) {
    int rc = 0;
    VerdictCounts totals;
    std::vector<std::string> missing;
    for (const auto& e : experiment_registry()) {
        if (!has_results(e.name, out)) {
            missing.push_back(e.name);
            continue;
        }
        rc |= check_experiment(e.name, out, opt, &totals);
    }
    std::printf("totals: %s\n", totals.text().c_str());
    std::fflush(stdout);
    if (!missing.empty()) {
        std::string names;
        for (const auto& m : missing) names += (names.empty() ? "" : ", ") + m;
        std::fprintf(stderr, "granrepro: check --all: no results in %s for %zu experiment%s: %s%s\n", out.c_str(),
                     missing.size(), missing.size() == 1 ? "" : "s", names.c_str(),
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
    ensure_writable_directory(to, "--to");
    const fs::path dest = to / name;
    fs::create_directories(dest);
    const fs::path tmp = dest / ".data.h5.partial";
    std::vector<std::string> omitted;
    try {
        omitted = write_compact_result_h5(from / "data.h5", tmp, max_values);
    } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw InputError("export " + name + ": " + (from / "data.h5").string() + ": " + e.what());
    }
    fs::rename(tmp, dest / "data.h5");
    write_file_atomically(dest / "summary.json", read_text(from / "summary.json"));
    std::string list;
    for (const auto& o : omitted) list += (list.empty() ? "" : ", ") + o;
    std::printf("export %s: %s -> %s (%.0f kB data.h5%s%s)\n", name.c_str(), from.c_str(), dest.c_str(),
                double(fs::file_size(dest / "data.h5")) / 1024.0, omitted.empty() ? "" : "; left out: ", list.c_str());
    return 0;
}

int plot_experiment(const std::string& name, const fs::path& out, const std::vector<std::string>& figures,
                    bool strict) {
    const ExperimentInfo info = experiment_info(name);
    std::string known;
    for (const auto& f : info.figures) known += (known.empty() ? "" : ", ") + f.id;
    for (const auto& id : figures) {
        bool found = false;
        for (const auto& f : info.figures) found = found || f.id == id;
        if (!found) throw InputError("--figure " + id + " is not made by experiment " + name + "; it makes " + known);
    }
    const fs::path dir = out / name;
    if (!fs::exists(dir / "tables"))
        throw InputError("plot " + name + ": no results in " + dir.string() + "; run `granrepro " + name + "` first");
    int failures = 0;
    for (const auto& f : info.figures)
        if (figures.empty() || std::find(figures.begin(), figures.end(), f.id) != figures.end()) {
            const RenderOutcome o = render_figure(f.id, dir);
            failures += o == RenderOutcome::Failed || (strict && o == RenderOutcome::Warned);
        }
    return failures ? 1 : 0;
}

} // namespace granrepro
