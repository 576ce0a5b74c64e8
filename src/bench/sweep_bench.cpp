#include "bench/sweep_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <fcntl.h>
#include <regex>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/input_error.hpp"
#include "harness/experiment.hpp"

extern char** environ;

namespace granrepro {

namespace fs = std::filesystem;

namespace {

// Runs argv (searched in PATH), its output to /dev/null; wall seconds, or throws on failure.
double timed_run(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int err = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) throw std::runtime_error("bench sweep: cannot start " + argv[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("bench sweep: run failed (exit " + std::to_string(WEXITSTATUS(status)) + "): " + argv[0] +
                                 " ... (rerun it by hand to see why)");
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

} // namespace

SweepCosts read_sweep_costs(const fs::path& run_log) {
    std::ifstream in(run_log);
    if (!in) throw InputError("--from-log " + run_log.string() + ": cannot read it (a run.log of a sweeping experiment)");
    static const std::regex point(R"(sweep \S+: point (\d+) cost ([0-9.eE+-]+) CPU s)");
    static const std::regex wall(R"(run finished: wall time ([0-9.eE+-]+) s)");
    SweepCosts c;
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, point)) c.cost.push_back(std::stod(m[2]));
        else if (std::regex_search(line, m, wall)) c.wall = std::stod(m[1]);
    }
    if (c.cost.empty())
        throw InputError("--from-log " + run_log.string() + ": no 'sweep ...: point ... cost' lines (a run of an older "
                         "binary, a resumed run, or an experiment without a distributed sweep)");
    return c;
}

double projected_makespan(const std::vector<double>& cost, int ranks) {
    // Rank 0 hands out points in cost order as ranks become free (harness/distributed_sweep).
    std::vector<double> sorted = cost, free_at(std::size_t(std::max(1, ranks)), 0.0);
    std::sort(sorted.rbegin(), sorted.rend());
    for (double c : sorted) *std::min_element(free_at.begin(), free_at.end()) += c;
    return *std::max_element(free_at.begin(), free_at.end());
}

void print_projection(const SweepCosts& c, const std::vector<int>& ranks) {
    const double sum = std::accumulate(c.cost.begin(), c.cost.end(), 0.0);
    const double longest = *std::max_element(c.cost.begin(), c.cost.end());
    // Amdahl's serial part: what a 1-rank run spends outside the points (set-up, analysis, writing).
    const double serial = c.wall > sum ? c.wall - sum : 0.0;
    std::printf("  %zu points: sum %.4g CPU s, longest %.4g s, median %.4g s; serial part %.3g s\n", c.cost.size(), sum,
                longest, median(c.cost), serial);
    std::printf("  projected (points handed out longest first as ranks free up; wall = serial + makespan):\n");
    std::printf("  %7s %12s %10s %11s\n", "ranks", "wall [s]", "speed-up", "efficiency");
    const double t1 = serial + sum;
    for (int r : ranks) {
        const double t = serial + projected_makespan(c.cost, r);
        std::printf("  %7d %12.4g %10.3g %10.0f%%\n", r, t, t1 / t, 100.0 * t1 / t / r);
    }
    std::printf("  bound: the longest point, %.4g s (speed-up at most %.3g)\n", longest, t1 / (serial + longest));
}

void bench_sweep_report(const BenchOptions& opt) {
    const std::vector<int> projected = {1, 2, 16, 64, 256};
    if (!opt.from_log.empty()) {
        std::printf("bench sweep: projection from %s\n", opt.from_log.c_str());
        print_projection(read_sweep_costs(opt.from_log), projected);
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
        std::vector<std::string> a;
        if (ranks > 1) a = {"mpirun", "--oversubscribe", "-np", std::to_string(ranks)};
        for (const std::string& x : {self, opt.experiment, std::string("--scale"), opt.scale, std::string("--threads"),
                                     std::string("1"), std::string("--quiet"), std::string("--out"),
                                     (tmp / ("r" + std::to_string(ranks))).string()})
            a.push_back(x);
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
    print_projection(costs, projected);
}

} // namespace granrepro
