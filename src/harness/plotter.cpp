#include "harness/plotter.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "harness/experiment.hpp"
#include "io/durable_file.hpp"

namespace granrepro {

RenderOutcome render_figure(const std::string& id, const std::filesystem::path& run_dir,
                            const std::filesystem::path& shown_dir) {
    const auto script = project_root() / "plots" / (id + ".gp");
    std::ifstream in(script);
    if (!in) {
        std::fprintf(stderr, "granrepro: no plot script %s\n", script.c_str());
        return RenderOutcome::Failed;
    }
    std::stringstream body;
    body << in.rdbuf();
    const auto emitted = run_dir / (id + ".gp");
    {
        std::ostringstream out;
        out << "# Emitted by granrepro from plots/" << id << ".gp; run `gnuplot " << id
            << ".gp` in this directory to re-render.\n"
            << "datadir = 'tables'\noutbase = '" << id << "'\n\n"
            << body.str();
        write_file_durably(emitted, out.str()); // a full disk is a WriteError, not a 0-byte script
    }
    const std::string cmd = "cd '" + run_dir.string() + "' && gnuplot '" + id + ".gp' > '" + id +
                            ".gnuplot.log' 2>&1";
    const int rc = std::system(cmd.c_str());
    const auto log = run_dir / (id + ".gnuplot.log");
    const auto shown_log = (shown_dir.empty() ? run_dir : shown_dir) / (id + ".gnuplot.log");
    if (rc != 0 || !std::filesystem::exists(run_dir / (id + ".png"))) {
        std::fprintf(stderr, "granrepro: gnuplot failed for %s (see %s)\n", id.c_str(), shown_log.c_str());
        return RenderOutcome::Failed;
    }
    std::error_code ec;
    if (std::filesystem::file_size(log, ec) == 0) {
        std::filesystem::remove(log, ec);
        return RenderOutcome::Clean;
    }
    // Name the warning itself: gnuplot echoes the offending command and a caret line first.
    std::ifstream log_in(log);
    std::string line, first, warning;
    while (std::getline(log_in, line)) {
        const auto b = line.find_first_not_of(" \t\r^");
        if (b == std::string::npos) continue;
        if (first.empty()) first = line.substr(b);
        if (warning.empty() && (line.find("warning") != std::string::npos || line.find("Warning") != std::string::npos))
            warning = line.substr(b);
    }
    if (!warning.empty()) first = warning;
    if (first.size() > 160) first = first.substr(0, 157) + "...";
    std::fprintf(stderr, "granrepro: gnuplot warned for %s: %s (see %s)\n", id.c_str(), first.c_str(), shown_log.c_str());
    return RenderOutcome::Warned;
}

} // namespace granrepro
