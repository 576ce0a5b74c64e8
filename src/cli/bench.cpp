#include "cli/bench.hpp"
#include "bench/soft_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/seed_stats.hpp"
#include "core/input_error.hpp"
#include "data/parameter_set.hpp"
#include "bench/hard_disk_bench.hpp"
#include "bench/impact_bench.hpp"
#include "bench/memory_latency.hpp"
#include "bench/sweep_bench.hpp"

namespace granrepro {

namespace {

// Median over opt.repeats runs of each quantity that `run` returns.
template <class Run>
std::vector<double> medians(int repeats, Run run) {
    std::vector<std::vector<double>> samples;
    for (int k = 0; k < repeats; ++k) {
        const std::vector<double> q = run();
        samples.resize(q.size());
        for (std::size_t i = 0; i < q.size(); ++i) samples[i].push_back(q[i]);
    }
    std::vector<double> out;
    for (auto& s : samples) out.push_back(median(s));
    return out;
}

void bench_impact_report(const BenchOptions& opt) {
    std::vector<double> rates;
    for (int k = 0; k < opt.repeats; ++k) rates.push_back(run_impact_benchmark(opt.seconds));
    std::sort(rates.begin(), rates.end());
    std::printf("bench impact: few-body soft-sphere impacts on a wall row (Schäfer-Wolf Fig. 4 set-up)\n"
                "  median %.4g impacts/s over %d runs (min %.4g, max %.4g)\n",
                median(rates), opt.repeats, rates.front(), rates.back());
}

// Elastic disks at rho = 0.25, periodic: events and collisions per CPU second from N = 1e3 to 1e6.
void bench_ed_report(const BenchOptions& opt) {
    std::printf("bench ed: elastic smooth disks, periodic box, rho = 0.25, one core; medians of %d runs\n", opt.repeats);
    std::printf("  %9s %14s %14s %12s %14s\n", "N", "events/s", "collisions/s", "bytes/part.", "ns/event");
    double ns_1e4 = NAN, ns_1e6 = NAN, bytes_1e4 = NAN, bytes_1e6 = NAN;
    for (std::size_t n : {std::size_t(1000), std::size_t(10000), std::size_t(100000), std::size_t(1000000)}) {
        const auto q = medians(opt.repeats, [&] {
            const HardDiskBenchResult r = run_ed_benchmark(n, 0.25, opt.seconds);
            return std::vector<double>{r.events_per_second, r.collisions_per_second, r.bytes_per_particle};
        });
        const double ns = 1e9 / q[0];
        if (n == 10000) { ns_1e4 = ns; bytes_1e4 = q[2] * double(n); }
        if (n == 1000000) { ns_1e6 = ns; bytes_1e6 = q[2] * double(n); }
        std::printf("  %9zu %14.4g %14.4g %12.0f %14.1f\n", n, q[0], q[1], q[2], ns);
    }
    std::printf("  per-event cost N = 1e6 over N = 1e4: %.2f\n", ns_1e6 / ns_1e4);
    const auto lat = medians(opt.repeats, [&] {
        return std::vector<double>{dependent_load_latency_ns(std::size_t(bytes_1e4)),
                                   dependent_load_latency_ns(std::size_t(bytes_1e6))};
    });
    std::printf("  cache-miss price on this machine (dependent random load at the engine's working set):\n"
                "    N = 1e4 (%.1f MB) %.1f ns, N = 1e6 (%.0f MB) %.1f ns, ratio %.1f\n",
                bytes_1e4 / 1e6, lat[0], bytes_1e6 / 1e6, lat[1], lat[1] / lat[0]);
}

void bench_dsmc_report(const BenchOptions& opt) {
    std::printf("bench dsmc: elastic smooth disks, periodic box, rho = 0.25, N = 1e5, one core; medians of %d runs\n",
                opt.repeats);
    const auto q = medians(opt.repeats, [&] {
        const HardDiskBenchResult r = run_dsmc_benchmark(100000, 0.25, opt.seconds);
        return std::vector<double>{r.collisions_per_second, r.bytes_per_particle};
    });
    std::printf("  collisions/s %.4g, bytes/particle %.0f\n", q[0], q[1]);
}

struct Target {
    const char* name;
    void (*run)(const BenchOptions&);
};

const Target kTargets[] = {
    {"impact", bench_impact_report},
    {"soft", bench_soft_report},
    {"ed", bench_ed_report},
    {"dsmc", bench_dsmc_report},
    {"sweep", bench_sweep_report},
};

} // namespace

std::string bench_targets() {
    return joined(kTargets, [](const Target& t) { return t.name; });
}

int run_bench(const std::string& name, const BenchOptions& opt) {
    for (const auto& t : kTargets)
        if (name == t.name) {
            t.run(opt);
            return 0;
        }
    throw InputError("bench " + name + ": unknown target; known: " + bench_targets());
}

} // namespace granrepro
