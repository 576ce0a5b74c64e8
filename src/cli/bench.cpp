#include "cli/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "core/input_error.hpp"
#include "experiments/impact_shot.hpp"
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

struct Target {
    const char* name;
    const char* description;
    std::function<Measurement(double)> run;
};

const std::vector<Target>& targets() {
    static const std::vector<Target> t = {
        {"impact", "few-body soft-sphere impacts on a wall row (Schäfer-Wolf Fig. 4 set-up)", bench_impact},
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
    for (const auto& t : targets()) {
        if (name != t.name) continue;
        std::vector<double> rates;
        const char* unit = "";
        for (int k = 0; k < opt.repeats; ++k) {
            const Measurement m = t.run(opt.seconds);
            rates.push_back(m.rate);
            unit = m.unit;
        }
        std::sort(rates.begin(), rates.end());
        std::printf("bench %s: %s\n  median %.4g %s over %d runs (min %.4g, max %.4g)\n", t.name, t.description,
                    rates[rates.size() / 2], unit, opt.repeats, rates.front(), rates.back());
        return 0;
    }
    throw InputError("bench " + name + ": unknown target; known: " + bench_targets());
}

} // namespace granrepro
