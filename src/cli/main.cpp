// granrepro: reproduce the figures of Luding (1998) and Schäfer & Wolf (1995) and check the
// papers' claims. Exit codes: 0 success, 1 a claim failed or a run failed, 2 bad input.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/bench.hpp"
#include "core/input_error.hpp"
#include "core/provenance.hpp"
#include "harness/runner.hpp"

using namespace granrepro;

namespace {

struct CommonFlags {
    std::string scale = "quick";
    std::string out = "out";
    std::uint64_t seed = 1;
    int threads = 1;
    bool quiet = false;
    double checkpoint_interval = 60.0;
    std::vector<std::string> sets;

    void add_to(CLI::App* app, bool with_sets = true) {
        app->add_option("--scale", scale, "quick (CI, minutes) or paper (the papers' sizes)")
            ->capture_default_str();
        app->add_option("--out", out, "output directory")->capture_default_str();
        app->add_option("--seed", seed, "random seed of the run")->capture_default_str();
        app->add_option("--threads", threads, "independent sweep points run concurrently")
            ->capture_default_str()
            ->check(CLI::Range(1, 256));
        app->add_flag("--quiet", quiet, "no progress output on stderr");
        app->add_option("--checkpoint-interval", checkpoint_interval,
                        "seconds of wall time between mid-run checkpoints of long single runs [s]; "
                        "rerunning the same command resumes from the last one")
            ->capture_default_str()
            ->check(CLI::NonNegativeNumber);
        if (with_sets)
            app->add_option("--set", sets, "override a parameter: --set name=value (repeatable)")
                ->type_name("NAME=VALUE");
    }
    RunOptions options() const {
        RunOptions o;
        o.scale = parse_scale(scale);
        o.out = out;
        o.seed = seed;
        o.threads = threads;
        o.quiet = quiet;
        o.checkpoint_interval = checkpoint_interval;
        o.sets = sets;
        return o;
    }
};

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

int run_all(const RunOptions& base) {
    for (const auto& e : experiment_registry()) run_experiment(e.name, base);
    int rc = 0;
    for (const auto& e : experiment_registry()) rc |= check_experiment(e.name, base.out);
    return rc;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"granrepro: reproduce Luding (1998) and Schäfer & Wolf (1995), figure by figure"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string(code_version()));
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
        sub->footer([name = e.name] { return parameter_help(name); });
        sub->callback([&, name = e.name] { rc = run_experiment(name, common.options()); });
    }

    std::string figure_id;
    CLI::App* fig = app.add_subcommand("figure", "run what one figure needs and render only it");
    fig->add_option("id", figure_id, "figure id, e.g. schaefer95-fig3 (see `granrepro list`)")->required();
    common.add_to(fig);
    fig->callback([&] {
        RunOptions o = common.options();
        o.figures = {figure_id};
        rc = run_experiment(experiment_of_figure(figure_id), o);
    });

    std::string check_name;
    bool check_all = false;
    CLI::App* check = app.add_subcommand("check", "compare results with the papers' claims (expected/)");
    check->add_option("experiment", check_name, "experiment to check");
    check->add_flag("--all", check_all, "check every experiment");
    check->add_option("--out", common.out, "output directory")->capture_default_str();
    check->callback([&] {
        if (check_all == !check_name.empty()) throw InputError("check: give one experiment or --all");
        if (check_all) {
            for (const auto& e : experiment_registry()) rc |= check_experiment(e.name, common.out);
        } else {
            rc = check_experiment(check_name, common.out);
        }
    });

    std::string plot_name;
    std::vector<std::string> plot_figures;
    bool plot_all = false;
    CLI::App* plot = app.add_subcommand("plot", "re-render figures from existing results");
    plot->add_option("experiment", plot_name, "experiment whose figures to render");
    plot->add_flag("--all", plot_all, "every experiment");
    plot->add_option("--figure", plot_figures, "only this figure (repeatable)");
    plot->add_option("--out", common.out, "output directory")->capture_default_str();
    plot->callback([&] {
        if (plot_all == !plot_name.empty()) throw InputError("plot: give one experiment or --all");
        if (plot_all) {
            for (const auto& e : experiment_registry()) rc |= plot_experiment(e.name, common.out, plot_figures);
        } else {
            rc = plot_experiment(plot_name, common.out, plot_figures);
        }
    });

    CLI::App* all = app.add_subcommand("all", "run every experiment, render every figure, check every claim");
    common.add_to(all, false);
    all->callback([&] { rc = run_all(common.options()); });

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
    bench->add_option("--threads", bench_opt.threads, "soft: threads of the multi-core comparison")
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    bench->add_flag("--sizes", bench_opt.sizes, "soft: steps/s and memory against the number of grains");
    bench->callback([&] { rc = run_bench(bench_target, bench_opt); });

    // An unknown subcommand gets the list of known ones, in one line.
    if (argc > 1 && argv[1][0] != '-') {
        bool known = false;
        for (const auto* s : app.get_subcommands([](CLI::App*) { return true; }))
            known = known || s->get_name() == argv[1];
        if (!known) {
            std::string names;
            for (const auto* s : app.get_subcommands([](CLI::App*) { return true; }))
                names += (names.empty() ? "" : ", ") + s->get_name();
            std::fprintf(stderr, "granrepro: unknown subcommand '%s'; known: %s\n", argv[1], names.c_str());
            return 2;
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string msg = e.what();
        std::fprintf(stderr, "granrepro: %s\n", msg.substr(0, msg.find('\n')).c_str());
        return 2;
    } catch (const InputError& e) {
        std::fprintf(stderr, "granrepro: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "granrepro: error: %s\n", e.what());
        return 1;
    }
    return rc;
}
