#include "cli/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <numeric>
#include <random>
#include <vector>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/input_error.hpp"
#include "experiments/impact_shot.hpp"
#include "experiments/pipe_setup.hpp"
#include "engines/dsmc/dsmc_bench.hpp"
#include "bench/ed_bench.hpp"
#include "engines/ed/huge_page_allocator.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro {

namespace {

struct Measurement {
    double rate;          // work units per second
    const char* unit;     // what a work unit is
};

// Few-body impacts on a wall row at the Fig. 4 parameters: impacts per second and steps per second.
Measurement bench_impact(double seconds) {
    const LinearSpringDashpot law{2000.0, 1e4};
    ImpactSetup s;
    s.wall_spacing = 0.66e-3;
    s.x0 = 0.83e-3;
    s.vx_toward = 0.3;
    s.dt = law.collision_time(1e-6) / 50;
    long impacts = 0;
    const auto t0 = std::chrono::steady_clock::now();
    double elapsed = 0;
    while (elapsed < seconds) {
        s.vy = 0.1 * std::pow(400.0, (impacts % 16) / 15.0);
        s.y0 = 0.066e-3 * double(impacts % 10);
        shoot(law, CoulombShear{0.5}, s);
        ++impacts;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return {double(impacts) / elapsed, "impacts/s"};
}

// The Fig. 6 pipe at about 1500 free grains (length 11 cm), k_N = 2000 N/m, e_N = 0.95, slow
// start: free-grain steps per second of our engine.
PipeSpec bench_pipe_spec() {
    PipeSpec s;
    s.geo.wall_spacing = 1.0e-3;
    s.geo.length = 0.111;
    s.e_N = 0.95;
    return s;
}

Measurement bench_soft(double seconds) {
    auto eng = build_pipe(bench_pipe_spec());
    const auto t0 = std::chrono::steady_clock::now();
    long steps = 0;
    double elapsed = 0;
    while (elapsed < seconds) {
        for (int k = 0; k < 200; ++k) eng.step();
        steps += 200;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return {double(steps) * double(eng.size()) / elapsed, "free-grain steps/s"};
}

// The same pipe in LAMMPS (pair gran/hooke, wall grains not integrated, fix enforce2d), if `lmp`
// is installed: writes the identical initial configuration as a data file, runs `steps` steps and
// returns free-grain steps per second from LAMMPS' own loop time. NaN when LAMMPS is absent.
double lammps_free_grain_rate(long steps) {
    if (std::system("command -v lmp > /dev/null 2>&1") != 0) return NAN;
    const PipeSpec spec = bench_pipe_spec();
    auto eng = build_pipe(spec);
    const auto dir = std::filesystem::temp_directory_path() / ("granrepro-lammps-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const long n_free = long(eng.size());
    const long n_wall_row = std::lround(spec.geo.length / spec.geo.wall_spacing);
    {
        std::ofstream data(dir / "pipe.data");
        data.precision(12);
        data << "granrepro pipe\n\n" << n_free + 2 * n_wall_row << " atoms\n2 atom types\n\n"
             << -2e-3 << " " << spec.geo.width + 2e-3 << " xlo xhi\n0 " << spec.geo.length << " ylo yhi\n"
             << "-0.5e-3 0.5e-3 zlo zhi\n\nAtoms # sphere\n\n";
        // LAMMPS reads the density of a data file per volume, m = density * 4/3 pi r^3, also in 2d.
        for (long i = 0; i < n_free; ++i) {
            const double r = eng.radius()[std::size_t(i)];
            data << i + 1 << " 1 " << 2 * r << " " << eng.mass()[std::size_t(i)] / (4.0 / 3.0 * M_PI * r * r * r) << " "
                 << eng.x()[std::size_t(i)] << " " << eng.y()[std::size_t(i)] << " 0\n";
        }
        for (long k = 0; k < 2 * n_wall_row; ++k)
            data << n_free + k + 1 << " 2 " << 2 * spec.geo.wall_radius << " 1e6 "
                 << (k < n_wall_row ? 0.0 : spec.geo.width) << " " << double(k % n_wall_row) * spec.geo.wall_spacing
                 << " 0\n";
        data << "\nVelocities\n\n";
        for (long i = 0; i < n_free; ++i)
            data << i + 1 << " " << eng.vx()[std::size_t(i)] << " " << eng.vy()[std::size_t(i)] << " 0 0 0 0\n";
        for (long k = 0; k < 2 * n_wall_row; ++k) data << n_free + k + 1 << " 0 0 0 0 0 0\n";
    }
    const LinearSpringDashpot law = pipe_law(spec.k_N, spec.e_N, spec.m_mean);
    {
        std::ofstream in(dir / "in.pipe");
        in.precision(12);
        // gran/hooke: F_n = k_n delta - m_eff gamma_n v_n (= Eq. 1); a huge gamma_t makes the
        // tangential force always the Coulomb cap mu F_n (= Eq. 2); no history, no rotation used.
        in << "units si\ndimension 2\nboundary f p p\natom_style sphere\n"
           << "read_data pipe.data\n"
           << "group free type 1\ngroup wall type 2\n"
           << "pair_style gran/hooke " << law.k_N << " 0 " << law.gamma_N << " 1e12 " << spec.mu << " 0\n"
           << "pair_coeff * *\nneighbor " << spec.skin << " bin\nneigh_modify delay 0 every 1 check yes exclude type 2 2\n"
           << "comm_modify vel yes\n"
           << "fix grav free gravity " << spec.geo.gravity << " vector 0 -1 0\n"
           << "fix integrate free nve/sphere disc\nfix twod all enforce2d\n"
           << "timestep " << eng.dt() << "\nthermo 100000\nrun " << steps << "\n";
    }
    const std::string cmd = "cd '" + dir.string() + "' && lmp -in in.pipe -log none > lmp.out 2>&1";
    const int rc = std::system(cmd.c_str());
    double loop = NAN;
    std::ifstream out(dir / "lmp.out");
    for (std::string line; std::getline(out, line);)
        if (line.rfind("Loop time of ", 0) == 0) loop = std::atof(line.c_str() + 13);
    if (rc != 0 || !(loop > 0)) {
        std::fprintf(stderr, "granrepro: LAMMPS run failed; input and output kept in %s\n", dir.c_str());
        return NAN;
    }
    if (std::getenv("GRANREPRO_KEEP_LAMMPS")) std::fprintf(stderr, "LAMMPS files kept in %s\n", dir.c_str());
    else std::filesystem::remove_all(dir);
    return double(n_free) * double(steps) / loop;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

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

void report_simple(const char* name, const char* description, Measurement (*fn)(double), const BenchOptions& opt) {
    std::vector<double> rates;
    const char* unit = "";
    for (int k = 0; k < opt.repeats; ++k) {
        const Measurement m = fn(opt.seconds);
        rates.push_back(m.rate);
        unit = m.unit;
    }
    std::sort(rates.begin(), rates.end());
    std::printf("bench %s: %s\n  median %.4g %s over %d runs (min %.4g, max %.4g)\n", name, description,
                median(rates), unit, opt.repeats, rates.front(), rates.back());
}

void bench_impact_report(const BenchOptions& opt) {
    report_simple("impact", "few-body soft-sphere impacts on a wall row (Schäfer-Wolf Fig. 4 set-up)", bench_impact, opt);
}

void bench_soft_report(const BenchOptions& opt) {
    std::vector<double> ours;
    for (int k = 0; k < opt.repeats; ++k) ours.push_back(bench_soft(opt.seconds).rate);
    const double m = median(ours);
    std::printf("bench soft: many-body soft-sphere pipe, ~1500 free grains (Schäfer-Wolf Fig. 6 set-up), one core\n"
                "  granrepro: median %.4g free-grain steps/s over %d runs\n", m, opt.repeats);
    std::vector<double> lmp;
    for (int k = 0; k < opt.repeats; ++k) {
        const double rate = lammps_free_grain_rate(std::max(2000L, long(m * opt.seconds / 1500.0 / 3)));
        if (std::isnan(rate)) break;
        lmp.push_back(rate);
    }
    if (lmp.empty()) {
        std::printf("  LAMMPS: not installed (Debian package lammps) or failed; no comparison\n");
        return;
    }
    std::printf("  LAMMPS (same pipe, gran/hooke): median %.4g free-grain steps/s over %zu runs\n"
                "  ratio granrepro / LAMMPS = %.2f\n", median(lmp), lmp.size(), m / median(lmp));
}

// Latency [ns] of one dependent load at a random cache line of a `bytes` large block, allocated
// like the ED engine's arrays (huge pages): a pointer chase over a random cyclic permutation.
// This is the price of a cache miss at a given working set, which is what bounds the ED engine
// at large N (one event touches a random particle and its neighbours).
double dependent_load_latency_ns(std::size_t bytes) {
    constexpr std::size_t kLine = 64 / sizeof(std::size_t);
    const std::size_t lines = std::max<std::size_t>(2, bytes / 64);
    HugeVector<std::size_t> chain(lines * kLine);
    std::vector<std::size_t> order(lines);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
    for (std::size_t k = 0; k < lines; ++k) chain[order[k] * kLine] = order[(k + 1) % lines] * kLine;
    std::size_t p = 0;
    for (std::size_t k = 0; k < lines; ++k) p = chain[p]; // warm up: one full cycle
    const long steps = 4'000'000;
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) p = chain[p];
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (p == std::size_t(-1)) std::printf(" "); // keep the chase from being optimised away
    return dt / steps * 1e9;
}

// Elastic disks at rho = 0.25, periodic: events and collisions per CPU second from N = 1e3 to 1e6.
void bench_ed_report(const BenchOptions& opt) {
    std::printf("bench ed: elastic smooth disks, periodic box, rho = 0.25, one core; medians of %d runs\n", opt.repeats);
    std::printf("  %9s %14s %14s %12s %14s\n", "N", "events/s", "collisions/s", "bytes/part.", "ns/event");
    double ns_1e4 = NAN, ns_1e6 = NAN, bytes_1e4 = NAN, bytes_1e6 = NAN;
    for (std::size_t n : {std::size_t(1000), std::size_t(10000), std::size_t(100000), std::size_t(1000000)}) {
        const auto q = medians(opt.repeats, [&] {
            const EdBenchResult r = run_ed_benchmark(n, 0.25, opt.seconds);
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
        const DsmcBenchResult r = run_dsmc_benchmark(100000, 0.25, opt.seconds);
        return std::vector<double>{r.collisions_per_second, r.bytes_per_particle};
    });
    std::printf("  collisions/s %.4g, bytes/particle %.0f\n", q[0], q[1]);
}

struct Target {
    const char* name;
    void (*run)(const BenchOptions&);
};

const std::vector<Target>& targets() {
    static const std::vector<Target> t = {
        {"impact", bench_impact_report},
        {"soft", bench_soft_report},
        {"ed", bench_ed_report},
        {"dsmc", bench_dsmc_report},
    };
    return t;
}

} // namespace

std::string bench_targets() {
    std::string s;
    for (const auto& t : targets()) s += (s.empty() ? "" : ", ") + std::string(t.name);
    return s;
}

int run_bench(const std::string& name, const BenchOptions& opt) {
    for (const auto& t : targets())
        if (name == t.name) {
            t.run(opt);
            return 0;
        }
    throw InputError("bench " + name + ": unknown target; known: " + bench_targets());
}

} // namespace granrepro
