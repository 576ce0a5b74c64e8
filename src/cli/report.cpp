#include "cli/report.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "cli/listing.hpp"
#include "core/input_error.hpp"
#include "core/spawn.hpp"
#include "data/interval.hpp"
#include "harness/experiment.hpp"
#include "harness/runner.hpp"
#include "io/staged_directory.hpp"

namespace fs = std::filesystem;

namespace granrepro {

namespace {

// The interpreter: $GRANREPRO_PYTHON, else Debian's (its python3-jinja2 and python3-h5py are
// installed there, not in another python3 earlier on PATH such as pyenv's), else python3 on PATH.
std::string python_interpreter() {
    if (const char* p = std::getenv("GRANREPRO_PYTHON"); p && *p) return p;
    if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
    return find_in_path("python3");
}

// The claims of every experiment with results in `out`, judged as `check` judges them, with the
// figures each experiment makes: the report's input besides the results folder.
nlohmann::json report_input(const fs::path& out) {
    nlohmann::json experiments = nlohmann::json::array();
    int with_results = 0;
    for (const auto& e : experiment_registry()) {
        // OUT/<experiment> is part of the untrusted folder: nothing is read through a link.
        std::error_code ec;
        if (fs::is_symlink(fs::symlink_status(out / e.name, ec))) existing_entry(out / e.name, Entry::Folder, "results folder");
        // What `list --json` prints of it (the paper, its figures), then what the results say.
        nlohmann::json x = experiment_listing(experiment_info(e.name));
        x["has_results"] = has_results(e.name, out);
        if (x["has_results"]) {
            x.update(judged_claims(e.name, out));
            ++with_results;
        }
        experiments.push_back(x);
    }
    if (with_results == 0)
        throw InputError("report --out " + out.string() + ": no results of any experiment there (no <experiment>/summary.json); "
                         "give a results folder such as paper_figures or out");
    return {{"experiments", experiments}};
}

// A file removed when the report is done, whatever happens.
struct TemporaryFile {
    fs::path path;
    ~TemporaryFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
};

// The claims files of reports killed by SIGKILL (granrepro-report-<pid>.json in the temporary
// folder): removed when that process is gone. Only our own regular files; a live PID keeps its file.
void remove_stale_claims_files(const fs::path& tmp) {
    const std::string prefix = "granrepro-report-", suffix = ".json";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(tmp, ec)) {
        const std::string n = e.path().filename().string();
        if (n.size() <= prefix.size() + suffix.size() || !n.starts_with(prefix) || !n.ends_with(suffix)) continue;
        const std::string digits = n.substr(prefix.size(), n.size() - prefix.size() - suffix.size());
        long pid = 0;
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos || !parse_long(digits, pid)) continue;
        struct stat st {};
        if (::lstat(e.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()) continue;
        if (pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH) fs::remove(e.path(), ec);
    }
}

int make_report(const std::string& out_text, const std::string& to_text) {
    const fs::path out = out_text;
    if (!fs::is_directory(out))
        throw InputError("report --out " + out_text + ": not a folder; give a results folder such as paper_figures or out");
    const fs::path to = to_text.empty() ? out / "report" : fs::path(to_text);
    // The report folder is replaced as a whole (a rename): a link there would be replaced by the
    // report, or the report written where it points. Refused before anything is written.
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(to, ec)))
        throw InputError((to_text.empty() ? "report: " + to.string() + " (the default --to)" : "report --to " + to_text) +
                         ": a symbolic link; give the report folder itself, it is replaced as a whole");
    const nlohmann::json input = report_input(out);

    const std::string python = python_interpreter();
    if (python.empty()) {
        std::fprintf(stderr, "granrepro: report needs python3 with jinja2 and h5py (Debian: apt-get install python3 "
                             "python3-jinja2 python3-h5py); none found\n");
        return 4;
    }
    remove_stale_claims_files(fs::temp_directory_path());
    const TemporaryFile claims{fs::temp_directory_path() / ("granrepro-report-" + std::to_string(::getpid()) + ".json")};
    write_file_atomically(claims.path, input.dump());
    // The package from the data files' python/ (source tree or installed copy) before any other.
    const fs::path package = project_root() / "python";
    if (fs::exists(package / "granrepro" / "report")) {
        const char* old = std::getenv("PYTHONPATH");
        const std::string path = package.string() + (old && *old ? ":" + std::string(old) : "");
        ::setenv("PYTHONPATH", path.c_str(), 1);
    }
    // --flag=value: a folder named "-res" is a value, never read by argparse as a flag.
    const std::vector<std::string> argv = {python, "-m", "granrepro.report", "--results=" + out.string(),
                                           "--claims=" + claims.path.string(), "--to=" + to.string()};
    const int rc = run_program_with_our_output(argv);
    if (rc == kNotStarted) {
        std::fprintf(stderr, "granrepro: report: could not start %s\n", python.c_str());
        return 4;
    }
    return rc;
}

} // namespace

void add_report_subcommand(CLI::App& app, int& rc) {
    static std::string out = "paper_figures", to;
    CLI::App* sub = app.add_subcommand(
        "report", "write a static HTML report (every figure, claim, deviation and its tables) of the results in --out");
    sub->add_option("--out", out, "results folder (the experiments' <experiment>/ folders)")->capture_default_str();
    sub->add_option("--to", to, "report folder, replaced as a whole when the new report is complete (default: OUT/report)");
    sub->footer("\nExit codes: 0 report written (missing figures are listed in it and on stderr); 2 bad input (one\n"
                "line: a folder that is not a results folder, damaged results, a --to that is not a report); 3 the\n"
                "report could not be written (the previous one is untouched); 4 python3, jinja2 or h5py missing.");
    sub->callback([&rc] { rc = make_report(out, to); });
}

} // namespace granrepro
