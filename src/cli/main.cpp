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
#include <memory>
#include <sstream>

#include "cli/bench.hpp"
#include "cli/listing.hpp"
#include "cli/report.hpp"
#include "cli/verify_command.hpp"
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/provenance.hpp"
#include "core/spawn.hpp"
#include "harness/mpi_world.hpp"
#include "data/interval.hpp"
#include "data/printable.hpp"
#include "harness/runner.hpp"
#include "io/staged_directory.hpp"
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
    // --points: experiments with a distributed sweep (a protocol whose points are saved, harness/protocol.hpp).
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
        // Refused at load, so --dry-run gives the run's verdict on a file or /proc/self as --out.
        check_output_directory(out, "--out");
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

int list_experiments(bool json) {
    if (json) {
        std::printf("%s\n", experiments_listing().dump(2).c_str());
        return 0;
    }
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
        // A rerun after an interruption goes on where it stopped: an experiment whose complete
        // results of this very run are in place is checked, not computed again (every rank
        // reads the same files, so all skip it together).
        int r = 0;
        if (complete_result(e.name, base)) {
            if (mpi::rank() != 0) continue;
            if (!base.quiet)
                std::fprintf(stderr, "%s: complete results of this run in %s (same scale, seed, physics and parameters): not rerun\n",
                             e.name.c_str(), (base.out / e.name).c_str());
            r = check_experiment(e.name, base.out, {}, &totals);
        } else {
            r = run_experiment(e.name, base, &totals);
        }
        rc = rc == 1 || r == 1 ? 1 : std::max(rc, r);
    }
    if (mpi::rank() == 0) std::fputs(totals.closing().c_str(), stdout);
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

// "Luding (1998) and Schäfer & Wolf (1995)": the papers of the experiment files, in registry order.
std::string papers_text() {
    std::vector<std::string> papers;
    try {
        for (const auto& e : experiment_registry())
            if (const std::string p = experiment_info(e.name).paper_short; std::find(papers.begin(), papers.end(), p) == papers.end())
                papers.push_back(p);
    } catch (const std::exception&) {
        return "the papers' figures"; // the experiment files are refused with their own message when used
    }
    std::string text;
    for (std::size_t i = 0; i < papers.size(); ++i)
        text += (i == 0 ? "" : i + 1 == papers.size() ? " and " : ", ") + papers[i];
    return text.empty() ? "the papers' figures" : text;
}

// `--version`: the code version, what it was built with, and where its data files are.
std::string version_text() {
    std::string s = std::string("granrepro ") + code_version();
    for (const auto& [what, version] : library_versions()) s += "\n" + what + ": " + version;
    const DataRoot root = find_data_root();
    s += "\ndata: " + root.path.string() + " (" + root.how + ")";
    return s;
}

// Each subcommand's options live in a state object its callback holds, so that the adders below
// can return before CLI11 parses into them.
void add_experiment_commands(CLI::App& app, CommonFlags& common, int& rc) {
    for (const auto& e : experiment_registry()) {
        std::string description = e.name;
        try {
            description = experiment_info(e.name).description;
        } catch (const std::exception&) {
        }
        CLI::App* sub = app.add_subcommand(e.name, description);
        common.add_to(sub);
        if (e.distributed) common.add_points_to(sub);
        // CLI11 prints a subcommand's footer function, then the footer it inherited from the
        // app (the data-file and exit-code paragraphs): the exit codes come from there, once.
        sub->footer([name = e.name] { return parameter_help(name); });
        sub->callback([&, name = e.name] {
            const RunOptions o = common.options();
            rc = common.dry_run ? dry_run(name, o) : run_experiment(name, o);
        });
    }
}

void add_figure_command(CLI::App& app, CommonFlags& common, int& rc) {
    auto figure_id = std::make_shared<std::string>();
    CLI::App* fig = app.add_subcommand("figure", "run what one figure needs and render only it");
    fig->add_option("id", *figure_id, "figure id, e.g. schaefer95-fig3 (see `granrepro list`)")->required();
    common.add_to(fig);
    fig->footer(kExitCodes);
    fig->callback([&, figure_id] {
        RunOptions o = common.options();
        o.figures = {*figure_id};
        const std::string name = experiment_of_figure(*figure_id);
        rc = common.dry_run ? dry_run(name, o) : run_experiment(name, o);
    });
}

void add_gather_command(CLI::App& app, CommonFlags& common, int& rc) {
    auto gather_name = std::make_shared<std::string>();
    CLI::App* gather = app.add_subcommand(
        "gather", "write the results of an experiment whose sweep points were computed by --points shards");
    gather->add_option("experiment", *gather_name, "experiment, run with the same flags as its shards")->required();
    common.add_to(gather);
    gather->footer("\nExit codes: 0 every claim PASS; 1 a claim FAILed; 2 bad input, or points missing from the\n"
                   "checkpoint (one line: 'N points missing: i, j, ...'; run their shards again).");
    gather->callback([&, gather_name] {
        RunOptions o = common.options();
        o.shard_from_slurm = false;
        o.sweep.mode = SweepPlan::Mode::Gather;
        rc = run_experiment(*gather_name, o);
    });
}

void add_check_command(CLI::App& app, CommonFlags& common, int& rc) {
    struct State {
        std::string name;
        bool every = false;
        CheckOptions opt;
    };
    auto st = std::make_shared<State>();
    CLI::App* check = app.add_subcommand("check", "compare results with the papers' claims (expected/)");
    check->footer(kExitCodes);
    check->add_option("experiment", st->name, "experiment to check");
    check->add_flag("--all", st->every, "check every experiment that has results in --out; list those that have none (exit 1)");
    check->add_flag("--missing-ok", st->opt.missing_ok,
                    "with --all: experiments without results are listed but do not fail the check");
    check->add_flag("--explain", st->opt.explain, "print each known deviation's explanation and where its band comes from");
    check->add_option("--out", common.out, "output directory (e.g. paper_figures for the committed paper-scale results)")
        ->capture_default_str();
    check->callback([&, st] {
        if (st->every == !st->name.empty()) throw InputError("check: give one experiment or --all");
        if (st->opt.missing_ok && !st->every) throw InputError("check: --missing-ok needs --all");
        rc = st->every ? check_all(common.out, st->opt) : check_experiment(st->name, common.out, st->opt);
    });
}

void add_plot_command(CLI::App& app, CommonFlags& common, int& rc) {
    struct State {
        std::string name;
        std::vector<std::string> figures;
        bool all = false, strict = false, edited = false;
    };
    auto st = std::make_shared<State>();
    CLI::App* plot = app.add_subcommand("plot", "re-render figures from existing results");
    plot->footer(kExitCodes);
    plot->add_option("experiment", st->name, "experiment whose figures to render");
    plot->add_flag("--all", st->all, "every experiment");
    plot->add_option("--figure", st->figures, "only this figure (repeatable)");
    plot->add_flag("--strict", st->strict, "exit 4 if gnuplot prints any warning for a figure");
    plot->add_flag("--edited", st->edited,
                   "render the scripts you edited (<figure>.edited.gp, or an edited <figure>.gp) instead of "
                   "the ones from plots/; without it an edited script is kept but never run, as a results "
                   "folder from elsewhere may hold gnuplot lines that run programs");
    plot->add_option("--out", common.out, "output directory")->capture_default_str();
    plot->callback([&, st] {
        if (st->all == !st->name.empty()) throw InputError("plot: give one experiment or --all");
        rc = st->all ? plot_all_experiments(common.out, st->figures, st->strict, st->edited)
                     : plot_experiment(st->name, common.out, st->figures, st->strict, st->edited);
    });
}

void add_export_command(CLI::App& app, CommonFlags& common, int& rc) {
    struct State {
        std::string name, to;
        bool every = false;
        std::size_t max = 50000;
    };
    auto st = std::make_shared<State>();
    CLI::App* exp_cmd = app.add_subcommand(
        "export", "copy results (summary.json and a compact data.h5 without snapshots) to another directory");
    exp_cmd->footer(kExitCodes);
    exp_cmd->add_option("experiment", st->name, "experiment to export");
    exp_cmd->add_flag("--all", st->every, "every experiment that has results in --out");
    exp_cmd->add_option("--out", common.out, "output directory of the runs")->capture_default_str();
    exp_cmd->add_option("--to", st->to, "destination, e.g. paper_figures (files go to TO/<experiment>/)")->required();
    exp_cmd->add_option("--max-table-values", st->max, "tables with more values in all are left out (snapshots)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
    exp_cmd->callback([&, st] {
        if (st->every == !st->name.empty()) throw InputError("export: give one experiment or --all");
        if (!st->every) {
            rc = export_experiment(st->name, common.out, st->to, st->max);
            return;
        }
        std::string missing;
        for (const auto& e : experiment_registry()) {
            if (has_results(e.name, common.out)) rc |= export_experiment(e.name, common.out, st->to, st->max);
            else missing += (missing.empty() ? "" : ", ") + e.name;
        }
        if (!missing.empty())
            std::fprintf(stderr, "granrepro: export --all: no results in %s for: %s\n", common.out.c_str(), missing.c_str());
    });
}

void add_all_command(CLI::App& app, CommonFlags& common, int& rc) {
    CLI::App* all = app.add_subcommand("all", "run every experiment, render every figure, check every claim");
    common.add_to(all, false);
    all->footer(kExitCodes);
    all->callback([&] {
        RunOptions o = common.options();
        o.shard_from_slurm = false;
        if (common.dry_run) {
            for (const auto& e : experiment_registry()) rc |= dry_run(e.name, o);
        } else {
            rc = run_all(o);
        }
    });
}

void add_bench_command(CLI::App& app, int& rc) {
    struct State {
        std::string target;
        BenchOptions opt;
        std::string ranks;
    };
    auto st = std::make_shared<State>();
    st->ranks = std::to_string(st->opt.ranks);
    BenchOptions& opt = st->opt;
    CLI::App* bench = app.add_subcommand("bench", "measure engine speed (medians of repeated runs)");
    bench->add_option("engine", st->target, "what to measure: " + bench_targets())->required();
    bench->add_option("--repeats", opt.repeats, "runs per figure (the median is reported)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    bench->add_option("--seconds", opt.seconds, "time budget of one run [s]")
        ->capture_default_str()
        ->check(CLI::Range(0.01, 3600.0));
    bench->add_option("--steps", opt.steps, "soft: time steps of one timed run (default 400000)")
        ->check(CLI::Range(1L, 1000000000L));
    bench->add_flag("--sizes", opt.sizes, "soft: steps/s and memory against the number of grains");
    bench->add_flag("--speeds", opt.speeds, "soft: steps/s and list builds at plug speeds of 1, 20 and 200 m/s");
    bench->add_option("--experiment", opt.experiment, "sweep: the sweeping experiment to time (default bistable-pipe)");
    bench->add_option("--scale", opt.scale, "sweep: quick (default) or paper");
    bench->add_option("--ranks", st->ranks, "sweep: MPI ranks compared with one (2 to 256, default 2)");
    bench->add_option("--from-log", opt.from_log, "sweep: project rank counts from these run.log files (one experiment, or every one of `all`) instead of running");
    bench->callback([&rc, st] {
        st->opt.ranks = parse_positive_int("--ranks", st->ranks, 256);
        parse_scale(st->opt.scale); // one line naming --scale and what is allowed
        rc = run_bench(st->target, st->opt);
    });
}

// Parses the command line and runs the chosen subcommand's callback; the exit code.
int parse_and_run(CLI::App& app, int argc, char** argv, const int& rc) {
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
        std::fprintf(stderr, "granrepro: %s\n", printable(msg.substr(0, msg.find('\n'))).c_str());
        return 2;
    } catch (const InputError& e) {
        // A refusal may quote a file's text (a claim id, a key, a path): one line, inert on a
        // terminal whatever the file holds.
        std::fprintf(stderr, "granrepro: %s\n", printable(e.what()).c_str());
        return 2;
    } catch (const WriteError& e) {
        std::fprintf(stderr, "granrepro: error: %s\n", printable(e.what()).c_str());
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
        std::fprintf(stderr, "granrepro: error: %s\n", printable(e.what()).c_str());
        return 1;
    }
    return rc;
}

} // namespace

// Everything but MPI's set-up: the command line and the subcommands.
static int run_main(int argc, char** argv) {
    command_line = argv_text(std::vector<std::string>(argv, argv + argc));
    CLI::App app{"granrepro: reproduce " + papers_text() + ", figure by figure"};
    app.footer(std::string(kDataFiles) + kExitCodes);
    app.require_subcommand(1);
    app.set_version_flag("--version", version_text());
    app.failure_message(CLI::FailureMessage::simple);

    int rc = 0;
    CommonFlags common;
    bool list_json = false;
    CLI::App* list = app.add_subcommand("list", "list experiments and figures");
    list->add_flag("--json", list_json,
                   "print one JSON document instead: {\"experiments\": [{name, description, paper, paper_key, paper_short, "
                   "paper_citation, figures: [{id, caption}], smoke: [\"name=value\", ...]}]} in registry order, read from "
                   "experiments/<name>.toml");
    list->callback([&] { rc = list_experiments(list_json); });
    add_experiment_commands(app, common, rc);
    add_figure_command(app, common, rc);
    add_gather_command(app, common, rc);
    add_check_command(app, common, rc);
    add_plot_command(app, common, rc);
    add_export_command(app, common, rc);
    add_verify_command(app, rc);
    add_all_command(app, common, rc);
    add_bench_command(app, rc);
    add_report_subcommand(app, rc);
    return parse_and_run(app, argc, argv, rc);
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
