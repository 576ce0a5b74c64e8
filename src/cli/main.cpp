// granrepro: reproduce the figures of Luding (1998) and Schäfer & Wolf (1995) and check the
// papers' claims. Exit codes: 0 every claim passed (or is a known deviation inside its band),
// 1 a claim failed (or a run failed, or check --all found experiments without results), 2 bad
// input, 3 results could not be written (disk full, I/O error; the previous results are
// untouched), 4 a requested figure was not drawn (kFigureNotDrawn), 130/143 interrupted by
// SIGINT/SIGTERM (core/interrupt.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "cli/bench.hpp"
#include "cli/report.hpp"
#include "cli/verify_command.hpp"
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/provenance.hpp"
#include "core/spawn.hpp"
#include "harness/mpi_world.hpp"
#include "data/interval.hpp"
#include "harness/runner.hpp"
#include "io/write_error.hpp"

using namespace granrepro;

namespace {

const char* const kDataFiles =
    "\nData files (experiments/, expected/, plots/) are looked up in ../share/granrepro next to the\n"
    "binary (an installed copy), then $GRANREPRO_HOME, then the source tree it was built from;\n"
    "--version prints which one is used.\n";

const char* const kExitCodes =
    "\nExit codes: 0 every claim PASS (or DEVIATION: a known deviation inside its own band);\n"
    "1 a claim FAILed (also: a run failed, or check --all / plot --all found experiments without\n"
    "results); 2 bad input (one line on stderr naming the parameter and what is allowed; also a\n"
    "damaged results file given to check, or an --out another run is writing); 3 the results could\n"
    "not be written (disk full, I/O error: one line; the previous results are untouched);\n"
    "4 a figure the command was to draw was not drawn (every figure of a run, the figure of\n"
    "`figure`, those of `plot`; gnuplot failed or is missing, or a table or parameter its script\n"
    "needs is missing; one warning per figure, the data are written; `plot --strict`: also a\n"
    "gnuplot warning; a failed claim gives 1 instead);\n"
    "130/143 interrupted by SIGINT/SIGTERM (a final checkpoint is saved where the run has one and\n"
    "the same command resumes; a second signal, or 8 s without a pause point, stops at once).";

std::string command_line; // argv joined, shell-quoted where needed
// Global flags are read as text and parsed here, not by CLI11: CLI11 wraps --seed -1 to
// 18446744073709551615, accepts --checkpoint-interval nan and answers --threads abc with
// "Value abc not in range". Each refusal is one line naming the flag and what is allowed.
std::uint64_t parse_seed(const std::string& text) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || text.size() > 20 || ec != std::errc() || end != text.data() + text.size())
        throw InputError("--seed " + text + ": must be an integer in [0, 18446744073709551615]");
    return v;
}

int parse_positive_int(const std::string& flag, const std::string& text, int max) {
    long v = 0;
    if (text.find_first_not_of("0123456789") != std::string::npos || !parse_long(text, v) || v < 1)
        throw InputError(flag + ": " + text + " is not a positive integer");
    if (v > max) throw InputError(flag + ": " + text + " is too many; allowed 1 to " + std::to_string(max));
    return int(v);
}

double parse_seconds(const std::string& flag, const std::string& text) {
    double v = 0;
    if (!parse_double(text, v) || !std::isfinite(v) || v < 0)
        throw InputError(flag + " " + text + ": must be a finite number of seconds >= 0");
    return v;
}

struct CommonFlags {
    std::string scale = "quick";
    std::string out = "out";
    std::string seed = "1";
    std::string threads = "1";
    bool quiet = false;
    bool dry_run = false;
    std::string checkpoint_interval = "60";
    std::vector<std::string> sets;
    std::string points;

    void add_to(CLI::App* app, bool with_sets = true) {
        app->add_option("--scale", scale, "quick (CI, minutes) or paper (the papers' sizes)")
            ->capture_default_str();
        app->add_option("--out", out, "output directory")->capture_default_str();
        app->add_option("--seed", seed, "random seed of the run, an integer in [0, 2^64)")
            ->capture_default_str()
            ->type_name("UINT64");
        app->add_option("--threads", threads, "independent sweep points run concurrently (1 to 256)")
            ->capture_default_str()
            ->type_name("INT");
        app->add_flag("--quiet", quiet, "no progress output on stderr");
        app->add_flag("--dry-run", dry_run,
                      "read and validate the parameters (--set), the claims and the cost estimates, "
                      "then exit 0 without running or writing anything");
        app->add_option("--checkpoint-interval", checkpoint_interval,
                        "seconds of wall time between mid-run checkpoints of long single runs [s]; "
                        "rerunning the same command resumes from the last one")
            ->capture_default_str()
            ->type_name("SECONDS");
        if (with_sets)
            app->add_option("--set", sets, "override a parameter: --set name=value (repeatable)")
                ->type_name("NAME=VALUE");
    }
    // --points: experiments with a distributed sweep (marked distributed(...) in experiments/registry.cpp).
    void add_points_to(CLI::App* app) {
        app->add_option("--points", points,
                        "compute only shard I of N of the sweep points into OUT/.<experiment>.checkpoint/, then "
                        "`granrepro gather <experiment>` (same flags) writes the results; default in a Slurm job "
                        "array: task ID of COUNT")
            ->type_name("I/N");
    }
    RunOptions options() const {
        RunOptions o;
        if (!points.empty()) o.sweep = parse_points(points);
        o.shard_from_slurm = true;
        o.scale = parse_scale(scale);
        o.out = out;
        o.seed = parse_seed(seed);
        o.threads = parse_positive_int("--threads", threads, 256);
        o.quiet = quiet;
        o.checkpoint_interval = parse_seconds("--checkpoint-interval", checkpoint_interval);
        o.sets = sets;
        o.command_line = command_line;
        return o;
    }
};

// --dry-run: everything a run checks before it starts (parameters, their relations and the
// work they imply, the claims file), and nothing written.
int dry_run(const std::string& name, const RunOptions& o) {
    resolve_parameters(name, o);
    sweep_plan(name, o);
    experiment_claims(name);
    std::printf("%s: input accepted (%s scale); --dry-run: nothing run\n", name.c_str(), to_string(o.scale));
    return 0;
}

// The parameter table shown by `granrepro <experiment> --help`.
std::string parameter_help(const std::string& name) {
    std::ostringstream os;
    try {
        const ParameterSet quick = ParameterSet::load(experiment_info(name).file, Scale::Quick);
        os << "\nParameters (--set name=value; defaults quick | paper):\n";
        for (const auto& p : quick.all()) {
            std::string def = p.quick_text == p.paper_text ? p.quick_text : p.quick_text + " | " + p.paper_text;
            os << "  " << p.name << " = " << def << " [" << p.unit << "]";
            if (p.has_range) os << "  allowed " << p.range.text;
            if (!p.choices.empty()) {
                os << "  one of";
                for (const auto& c : p.choices) os << " " << c;
            }
            os << "\n      " << p.help << "\n      source: " << p.source << "\n";
        }
    } catch (const std::exception& e) {
        os << "\n(parameters unavailable: " << e.what() << ")\n";
    }
    return os.str();
}

int list_experiments() {
    for (const auto& e : experiment_registry()) {
        const ExperimentInfo info = experiment_info(e.name);
        std::printf("%-18s %s\n%-18s   paper: %s\n", e.name.c_str(), info.description.c_str(), "", info.paper.c_str());
        for (const auto& f : info.figures) std::printf("%-18s   figure %-18s %s\n", "", f.id.c_str(), f.caption.c_str());
    }
    return 0;
}

// One check table per experiment as it finishes, then the totals.
int run_all(const RunOptions& base) {
    // Bad input anywhere stops `all` before the first run, not after an hour of runs.
    for (const auto& e : experiment_registry()) {
        resolve_parameters(e.name, base);
        experiment_claims(e.name);
    }
    int rc = 0;
    VerdictCounts totals;
    // A failed claim (1) outranks a figure not drawn (kFigureNotDrawn).
    for (const auto& e : experiment_registry()) {
        const int r = run_experiment(e.name, base, &totals);
        rc = rc == 1 || r == 1 ? 1 : std::max(rc, r);
    }
    if (mpi::rank() == 0) std::printf("totals: %s\n", totals.text().c_str());
    return rc;
}

// plot --all: every experiment with results; the missing ones are listed and fail.
int plot_all_experiments(const std::filesystem::path& out, const std::vector<std::string>& figures, bool strict,
                         bool edited) {
    for (const auto& f : figures) experiment_of_figure(f); // an unknown figure is bad input
    int rc = 0;
    std::string missing;
    for (const auto& e : experiment_registry()) {
        std::vector<std::string> mine;
        for (const auto& f : figures)
            if (experiment_of_figure(f) == e.name) mine.push_back(f);
        if (!figures.empty() && mine.empty()) continue;
        if (std::filesystem::exists(out / e.name / "tables")) rc = std::max(rc, plot_experiment(e.name, out, mine, strict, edited));
        else missing += (missing.empty() ? "" : ", ") + e.name;
    }
    if (!missing.empty()) {
        std::fprintf(stderr, "granrepro: plot --all: no results in %s for: %s\n", out.c_str(), missing.c_str());
        rc = 1;
    }
    return rc;
}

// `--version`: the code version, what it was built with, and where its data files are.
std::string version_text() {
    std::string s = std::string("granrepro ") + code_version();
    for (const auto& [what, version] : library_versions()) s += "\n" + what + ": " + version;
    const DataRoot root = find_data_root();
    s += "\ndata: " + root.path.string() + " (" + root.how + ")";
    return s;
}

} // namespace

// Everything but MPI's set-up: the command line and the subcommands.
static int run_main(int argc, char** argv) {
    command_line = argv_text(std::vector<std::string>(argv, argv + argc));
    CLI::App app{"granrepro: reproduce Luding (1998) and Schäfer & Wolf (1995), figure by figure"};
    app.footer(std::string(kDataFiles) + kExitCodes);
    app.require_subcommand(1);
    app.set_version_flag("--version", version_text());
    app.failure_message(CLI::FailureMessage::simple);

    int rc = 0;
    CommonFlags common;

    app.add_subcommand("list", "list experiments and figures")->callback([&] { rc = list_experiments(); });

    for (const auto& e : experiment_registry()) {
        std::string description = e.name;
        try {
            description = experiment_info(e.name).description;
        } catch (const std::exception&) {
        }
        CLI::App* sub = app.add_subcommand(e.name, description);
        common.add_to(sub);
        if (e.distributed) common.add_points_to(sub);
        sub->footer([name = e.name] { return parameter_help(name) + kExitCodes; });
        sub->callback([&, name = e.name] {
            const RunOptions o = common.options();
            rc = common.dry_run ? dry_run(name, o) : run_experiment(name, o);
        });
    }

    std::string figure_id;
    CLI::App* fig = app.add_subcommand("figure", "run what one figure needs and render only it");
    fig->add_option("id", figure_id, "figure id, e.g. schaefer95-fig3 (see `granrepro list`)")->required();
    common.add_to(fig);
    fig->footer(kExitCodes);
    fig->callback([&] {
        RunOptions o = common.options();
        o.figures = {figure_id};
        const std::string name = experiment_of_figure(figure_id);
        rc = common.dry_run ? dry_run(name, o) : run_experiment(name, o);
    });

    std::string gather_name;
    CLI::App* gather = app.add_subcommand(
        "gather", "write the results of an experiment whose sweep points were computed by --points shards");
    gather->add_option("experiment", gather_name, "experiment, run with the same flags as its shards")->required();
    common.add_to(gather);
    gather->footer("\nExit codes: 0 every claim PASS; 1 a claim FAILed; 2 bad input, or points missing from the\n"
                   "checkpoint (one line: 'N points missing: i, j, ...'; run their shards again).");
    gather->callback([&] {
        RunOptions o = common.options();
        o.shard_from_slurm = false;
        o.sweep.mode = SweepPlan::Mode::Gather;
        rc = run_experiment(gather_name, o);
    });

    std::string check_name;
    bool check_every = false;
    CheckOptions check_opt;
    CLI::App* check = app.add_subcommand("check", "compare results with the papers' claims (expected/)");
    check->footer(kExitCodes);
    check->add_option("experiment", check_name, "experiment to check");
    check->add_flag("--all", check_every,
                    "check every experiment that has results in --out; list those that have none (exit 1)");
    check->add_flag("--missing-ok", check_opt.missing_ok,
                    "with --all: experiments without results are listed but do not fail the check");
    check->add_flag("--explain", check_opt.explain,
                    "print each known deviation's explanation and where its band comes from");
    check->add_option("--out", common.out, "output directory (e.g. paper_figures for the committed paper-scale results)")
        ->capture_default_str();
    check->callback([&] {
        if (check_every == !check_name.empty()) throw InputError("check: give one experiment or --all");
        if (check_opt.missing_ok && !check_every) throw InputError("check: --missing-ok needs --all");
        rc = check_every ? check_all(common.out, check_opt) : check_experiment(check_name, common.out, check_opt);
    });

    std::string plot_name;
    std::vector<std::string> plot_figures;
    bool plot_all = false;
    CLI::App* plot = app.add_subcommand("plot", "re-render figures from existing results");
    plot->footer(kExitCodes);
    plot->add_option("experiment", plot_name, "experiment whose figures to render");
    plot->add_flag("--all", plot_all, "every experiment");
    plot->add_option("--figure", plot_figures, "only this figure (repeatable)");
    bool plot_strict = false, plot_edited = false;
    plot->add_flag("--strict", plot_strict, "exit 4 if gnuplot prints any warning for a figure");
    plot->add_flag("--edited", plot_edited,
                   "render the scripts you edited (<figure>.edited.gp, or an edited <figure>.gp) instead of "
                   "the ones from plots/; without it an edited script is kept but never run, as a results "
                   "folder from elsewhere may hold gnuplot lines that run programs");
    plot->add_option("--out", common.out, "output directory")->capture_default_str();
    plot->callback([&] {
        if (plot_all == !plot_name.empty()) throw InputError("plot: give one experiment or --all");
        rc = plot_all ? plot_all_experiments(common.out, plot_figures, plot_strict, plot_edited)
                      : plot_experiment(plot_name, common.out, plot_figures, plot_strict, plot_edited);
    });

    std::string export_name;
    bool export_every = false;
    std::string export_to;
    std::size_t export_max = 50000;
    CLI::App* exp_cmd = app.add_subcommand(
        "export", "copy results (summary.json and a compact data.h5 without snapshots) to another directory");
    exp_cmd->footer(kExitCodes);
    exp_cmd->add_option("experiment", export_name, "experiment to export");
    exp_cmd->add_flag("--all", export_every, "every experiment that has results in --out");
    exp_cmd->add_option("--out", common.out, "output directory of the runs")->capture_default_str();
    exp_cmd->add_option("--to", export_to, "destination, e.g. paper_figures (files go to TO/<experiment>/)")->required();
    exp_cmd->add_option("--max-table-values", export_max, "tables with more values in all are left out (snapshots)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
    exp_cmd->callback([&] {
        if (export_every == !export_name.empty()) throw InputError("export: give one experiment or --all");
        if (!export_every) {
            rc = export_experiment(export_name, common.out, export_to, export_max);
            return;
        }
        std::string missing;
        for (const auto& e : experiment_registry()) {
            if (has_results(e.name, common.out)) rc |= export_experiment(e.name, common.out, export_to, export_max);
            else missing += (missing.empty() ? "" : ", ") + e.name;
        }
        if (!missing.empty())
            std::fprintf(stderr, "granrepro: export --all: no results in %s for: %s\n", common.out.c_str(), missing.c_str());
    });

    add_verify_command(app, rc);

    CLI::App* all = app.add_subcommand("all", "run every experiment, render every figure, check every claim");
    common.add_to(all, false);
    all->footer(kExitCodes);
    all->callback([&] {
        RunOptions o = common.options();
        o.shard_from_slurm = false;
        if (!common.dry_run) {
            rc = run_all(o);
            return;
        }
        for (const auto& e : experiment_registry()) rc |= dry_run(e.name, o);
    });

    std::string bench_target;
    BenchOptions bench_opt;
    CLI::App* bench = app.add_subcommand("bench", "measure engine speed (medians of repeated runs)");
    bench->add_option("engine", bench_target, "what to measure: " + bench_targets())->required();
    bench->add_option("--repeats", bench_opt.repeats, "runs per figure (the median is reported)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    bench->add_option("--seconds", bench_opt.seconds, "time budget of one run [s]")
        ->capture_default_str()
        ->check(CLI::Range(0.01, 3600.0));
    bench->add_option("--steps", bench_opt.steps, "soft: time steps of one timed run (default 400000)")
        ->check(CLI::Range(1L, 1000000000L));
    std::string bench_threads = std::to_string(bench_opt.threads);
    bench->add_option("--threads", bench_threads, "soft: threads of the multi-core comparison (1 to 256)")
        ->capture_default_str()
        ->type_name("INT");
    bench->add_flag("--sizes", bench_opt.sizes, "soft: steps/s and memory against the number of grains");
    bench->add_flag("--speeds", bench_opt.speeds, "soft: steps/s and list builds at plug speeds of 1, 20 and 200 m/s");
    bench->add_option("--experiment", bench_opt.experiment, "sweep: the sweeping experiment to time (default bistable-pipe)");
    bench->add_option("--scale", bench_opt.scale, "sweep: quick (default) or paper");
    std::string bench_ranks = std::to_string(bench_opt.ranks);
    bench->add_option("--ranks", bench_ranks, "sweep: MPI ranks compared with one (2 to 256, default 2)");
    bench->add_option("--from-log", bench_opt.from_log, "sweep: project rank counts from these run.log files (one experiment, or every one of `all`) instead of running");
    bench->callback([&] {
        bench_opt.threads = parse_positive_int("--threads", bench_threads, 256);
        bench_opt.ranks = parse_positive_int("--ranks", bench_ranks, 256);
        parse_scale(bench_opt.scale); // one line naming --scale and what is allowed
        rc = run_bench(bench_target, bench_opt);
    });

    add_report_subcommand(app, rc);

    // An unknown subcommand gets the list of known ones, in one line.
    const auto subcommands = app.get_subcommands([](CLI::App*) { return true; });
    auto named = [](const CLI::App* s) { return s->get_name(); };
    if (argc > 1 && argv[1][0] != '-' &&
        std::none_of(subcommands.begin(), subcommands.end(), [&](const CLI::App* s) { return named(s) == argv[1]; })) {
        std::fprintf(stderr, "granrepro: unknown subcommand '%s'; known: %s\n", argv[1], joined(subcommands, named).c_str());
        return 2;
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) { // --help, --help-all, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string msg = e.what();
        std::fprintf(stderr, "granrepro: %s\n", msg.substr(0, msg.find('\n')).c_str());
        return 2;
    } catch (const InputError& e) {
        std::fprintf(stderr, "granrepro: %s\n", e.what());
        return 2;
    } catch (const WriteError& e) {
        std::fprintf(stderr, "granrepro: error: %s\n", e.what());
        // Not `return`: HDF5's exit handler would retry closing a file whose close failed for
        // want of space, and can crash doing so (rc 139 after the line above).
        std::fflush(nullptr);
        std::_Exit(3);
    } catch (const Interrupted& e) {
        // Held until the process ends: the watcher thread then cannot print a second line.
        interrupt_critical_mutex().lock();
        std::fprintf(stderr, "granrepro: %s\n", e.what());
        std::fflush(stderr);
        return e.exit_code();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "granrepro: error: %s\n", e.what());
        return 1;
    }
    return rc;
}

int main(int argc, char** argv) {
    // First, before any thread exists: SIGINT/SIGTERM are then handled by one watcher thread.
    install_interrupt_handling();
    // Whole lines on stdout even when it is a file: stderr messages then never split a table row.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    try {
        mpi::init(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "granrepro: %s\n", e.what());
        return 2;
    }
    const int code = run_main(argc, argv);
    mpi::finalize();
    return code;
}
