#include "cli/verify_command.hpp"

#include <CLI/CLI.hpp>

#include "core/input_error.hpp"
#include "data/interval.hpp"
#include "harness/verify.hpp"

namespace granrepro {

void add_verify_command(CLI::App& app, int& rc) {
    struct Flags {
        std::string experiment, point, out = "paper_figures", threads = "1";
        bool list = false, point_only = false;
    };
    auto flags = std::make_shared<Flags>();
    CLI::App* sub = app.add_subcommand(
        "verify", "rerun one stored sweep point of committed results and compare it with the stored outcome");
    sub->add_option("experiment", flags->experiment, "experiment whose results to verify")->required();
    sub->add_option("--point", flags->point,
                    "the sweep point to rerun (default: the cheapest by recorded cost; --list shows them)")
        ->type_name("I");
    sub->add_option("--out", flags->out, "results folder holding <experiment>/")->capture_default_str();
    sub->add_flag("--list", flags->list, "list the stored points with their recorded cost; rerun nothing");
    sub->add_flag("--point-only", flags->point_only,
                  "compare the point alone, without rebuilding the experiment's scalars from it and the stored "
                  "other points (skips the experiment's serial part)");
    sub->add_option("--threads", flags->threads, "threads of the rerun (1 to 256)")
        ->capture_default_str()
        ->type_name("INT"); // read as text and parsed below, as the run commands' --threads
    sub->footer("\nSame code version as the results: bit for bit; another version: value by value, naming the\n"
                "values that moved, by how much, and the claims that read them.\n"
                "Exit codes: 0 reproduced; 1 a value differs (listed); 2 bad input, damaged results, or\n"
                "results that cannot be verified (one line).");
    sub->callback([flags, &rc] {
        VerifyOptions o;
        o.experiment = flags->experiment;
        o.out = flags->out;
        o.list = flags->list;
        o.point_only = flags->point_only;
        long v = 0;
        if (!flags->point.empty()) {
            if (flags->point.find_first_not_of("0123456789") != std::string::npos || !parse_long(flags->point, v))
                throw InputError("--point " + flags->point + ": must be a point index, an integer >= 0 (`verify " +
                                 o.experiment + " --list` shows them)");
            o.point = v;
        }
        if (flags->threads.find_first_not_of("0123456789") != std::string::npos || !parse_long(flags->threads, v) || v < 1 ||
            v > 256)
            throw InputError("--threads " + flags->threads + ": must be an integer from 1 to 256");
        o.threads = int(v);
        if (o.list && o.point) throw InputError("verify: --list shows every point; give --point without --list");
        rc = verify_experiment(o);
    });
}

} // namespace granrepro
