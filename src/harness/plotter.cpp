#include "harness/plotter.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "harness/experiment.hpp"

namespace granrepro {

bool render_figure(const std::string& id, const std::filesystem::path& run_dir) {
    const auto script = project_root() / "plots" / (id + ".gp");
    std::ifstream in(script);
    if (!in) {
        std::fprintf(stderr, "granrepro: no plot script %s\n", script.c_str());
        return false;
    }
    std::stringstream body;
    body << in.rdbuf();
    const auto emitted = run_dir / (id + ".gp");
    {
        std::ofstream out(emitted);
        out << "# Emitted by granrepro from plots/" << id << ".gp; run `gnuplot " << id
            << ".gp` in this directory to re-render.\n"
            << "datadir = 'tables'\noutbase = '" << id << "'\n\n"
            << body.str();
    }
    const std::string cmd = "cd '" + run_dir.string() + "' && gnuplot '" + id + ".gp' > '" + id +
                            ".gnuplot.log' 2>&1";
    const int rc = std::system(cmd.c_str());
    if (rc != 0 || !std::filesystem::exists(run_dir / (id + ".png"))) {
        std::fprintf(stderr, "granrepro: gnuplot failed for %s (see %s.gnuplot.log)\n", id.c_str(), id.c_str());
        return false;
    }
    std::error_code ec;
    if (std::filesystem::file_size(run_dir / (id + ".gnuplot.log"), ec) == 0)
        std::filesystem::remove(run_dir / (id + ".gnuplot.log"), ec);
    return true;
}

} // namespace granrepro
