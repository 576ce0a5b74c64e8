#include "bench/sweep_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <regex>
#include <unistd.h>

#include "analysis/seed_stats.hpp"
#include "core/input_error.hpp"
#include "core/spawn.hpp"
#include "harness/experiment.hpp"

namespace granrepro {

namespace fs = std::filesystem;

namespace {

// Runs argv (searched in PATH), its output to /dev/null; wall seconds, or throws on failure.
double timed_run(const std::vector<std::string>& argv) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = run_program(argv);
    if (rc == kNotStarted) throw std::runtime_error("bench sweep: cannot start " + argv[0]);
    if (rc != 0)
        throw std::runtime_error("bench sweep: run failed (exit " + std::to_string(rc) + "): " + argv[0] +
                                 " ... (rerun it by hand to see why)");
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

SweepCosts read_sweep_costs(const fs::path& run_log) {
    std::ifstream in(run_log);
    if (!in) throw InputError("--from-log " + run_log.string() + ": cannot read it (a run.log of an experiment)");
    static const std::regex point(R"(sweep \S+: point (\d+) cost ([0-9.eE+-]+) CPU s)");
    static const std::regex wall(R"(run finished: wall time ([0-9.eE+-]+) s(, CPU ([0-9.eE+-]+) s)?)");
    SweepCosts c;
    c.name = run_log.parent_path().filename().string();
    std::string line;
    std::smatch m;
    bool finished = false;
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, point)) c.cost.push_back(std::stod(m[2]));
        else if (std::regex_search(line, m, wall)) {
            c.wall = std::stod(m[1]);
            c.cpu = m[3].matched ? std::stod(m[3]) : -1.0;
            finished = true;
        }
    }
    if (!finished) throw InputError("--from-log " + run_log.string() + ": no 'run finished' line (an unfinished run)");
    return c;
}

double projected_makespan(const std::vector<double>& cost, int ranks) {
    // Rank 0 hands out points in cost order as ranks become free (harness/distributed_sweep).
    std::vector<double> sorted = cost, free_at(std::size_t(std::max(1, ranks)), 0.0);
    std::sort(sorted.rbegin(), sorted.rend());
    for (double c : sorted) *std::min_element(free_at.begin(), free_at.end()) += c;
    return *std::max_element(free_at.begin(), free_at.end());
}

double SweepCosts::serial() const {
    // Amdahl's serial part: what the run spent outside its points (set-up, analysis); all of it for
    // an experiment without a distributed sweep. From the CPU time where the log has it (a 1-thread
    // run on a busy machine has wall > CPU); a multi-rank run's log has wall < sum: 0.
    const double sum = std::accumulate(cost.begin(), cost.end(), 0.0);
    return std::max(0.0, (cpu >= 0 ? cpu : wall) - sum);
}

double SweepCosts::projected(int ranks) const { return serial() + (cost.empty() ? 0.0 : projected_makespan(cost, ranks)); }

void print_projection(const std::vector<SweepCosts>& runs, const std::vector<int>& ranks) {
    double longest = 0, serial = 0;
    for (const SweepCosts& c : runs) {
        const double sum = std::accumulate(c.cost.begin(), c.cost.end(), 0.0);
        const double top = c.cost.empty() ? 0.0 : *std::max_element(c.cost.begin(), c.cost.end());
        std::printf("  %-18s %4zu points: sum %9.4g CPU s, longest %8.4g s, median %8.4g s; serial part %8.3g s\n",
                    c.name.c_str(), c.cost.size(), sum, top, c.cost.empty() ? 0.0 : median(c.cost), c.serial());
        longest += c.serial() + top;
        serial += c.serial();
    }
    std::printf("  projected (points handed out longest first as ranks free up; wall = serial + makespan%s):\n",
                runs.size() > 1 ? ", experiments one after another" : "");
    std::printf("  %7s %12s %10s %11s\n", "ranks", "wall [s]", "speed-up", "efficiency");
    auto total = [&](int r) {
        double t = 0;
        for (const SweepCosts& c : runs) t += c.projected(r);
        return t;
    };
    for (int r : ranks)
        std::printf("  %7d %12.4g %10.3g %10.0f%%\n", r, total(r), total(1) / total(r), 100.0 * total(1) / total(r) / r);
    std::printf("  bound: serial parts plus each sweep's longest point, %.4g s (speed-up at most %.3g); serial alone %.4g s\n",
                longest, total(1) / longest, serial);
}

void bench_sweep_report(const BenchOptions& opt) {
    const std::vector<int> projected = {1, 2, 16, 64, 256};
    if (!opt.from_log.empty()) {
        std::printf("bench sweep: projection from %zu run.log file%s\n", opt.from_log.size(), opt.from_log.size() > 1 ? "s" : "");
        std::vector<SweepCosts> runs;
        for (const std::string& f : opt.from_log) runs.push_back(read_sweep_costs(f));
        print_projection(runs, projected);
        return;
    }
    bool known = false;
    for (const Experiment& e : experiment_registry()) known |= e.name == opt.experiment && e.distributed;
    if (!known) throw InputError("--experiment " + opt.experiment + ": must be an experiment with a distributed sweep");
    if (opt.ranks < 2) throw InputError("--ranks " + std::to_string(opt.ranks) + ": must be at least 2");
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const fs::path tmp = fs::temp_directory_path() / ("granrepro-bench-sweep-" + std::to_string(::getpid()));
    // One thread per rank, so that R ranks use R cores; every run starts without a checkpoint.
    auto command = [&](int ranks) {
        std::vector<std::string> a = {self, opt.experiment, "--scale", opt.scale, "--threads", "1", "--quiet", "--out",
                                      (tmp / ("r" + std::to_string(ranks))).string()};
        if (ranks > 1) a.insert(a.begin(), {"mpirun", "--oversubscribe", "-np", std::to_string(ranks)});
        return a;
    };
    if (geteuid() == 0) { // OpenMPI refuses root without both variables (CI and containers run as root)
        setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
        setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    }
    std::printf("bench sweep: %s --scale %s, 1 rank against %d ranks (mpirun, --threads 1), medians of %d runs\n",
                opt.experiment.c_str(), opt.scale.c_str(), opt.ranks, opt.repeats);
    std::vector<double> one, many;
    SweepCosts costs;
    for (int k = 0; k < opt.repeats; ++k) {
        for (int r : {1, opt.ranks}) {
            fs::remove_all(tmp / ("r" + std::to_string(r)));
            (r == 1 ? one : many).push_back(timed_run(command(r)));
        }
        costs = read_sweep_costs(tmp / "r1" / opt.experiment / "run.log");
    }
    fs::remove_all(tmp);
    costs.wall = median(one);
    std::printf("  measured wall: 1 rank %.4g s, %d ranks %.4g s: speed-up %.3g\n", median(one), opt.ranks, median(many),
                median(one) / median(many));
    print_projection({costs}, projected);
}

} // namespace granrepro
