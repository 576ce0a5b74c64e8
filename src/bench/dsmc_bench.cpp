#include "bench/dsmc_bench.hpp"

#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include <cmath>
#include <ctime>
#include <numbers>

namespace granrepro {

DsmcBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget,
                                   DsmcFreeVolume free_volume, bool displacement) {
    if (n < 16 || !(density > 0.0) || !(density < 0.82))
        throw InputError("bench dsmc: need N >= 16 and 0 < density < 0.82");
    const double d = 1e-3, m = 1e-6; // [m], [kg]
    const double l = d * std::sqrt(static_cast<double>(n) * std::numbers::pi / (4.0 * density));
    RngStream rng(12345, 0);
    std::vector<Vec2> pos(n), vel(n);
    for (auto& p : pos) p = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
    for (auto& v : vel) v = {rng.normal(), rng.normal()}; // T/m = 1 m^2/s^2
    DsmcConfig cfg;
    cfg.lx = cfg.ly = l;
    cfg.free_volume = free_volume;
    cfg.displacement = displacement;
    DsmcEngine eng(cfg, std::move(pos), std::move(vel), std::vector<double>(n, 0.5 * d), std::vector<double>(n, m));
    eng.run_steps(2 * cfg.resample_interval); // warm caches and allocations before timing

    DsmcBenchResult r;
    r.n = n;
    r.density = density;
    const std::uint64_t c0 = eng.total_collisions(), s0 = eng.steps();
    const std::clock_t start = std::clock();
    double used = 0.0;
    do {
        eng.run_steps(cfg.resample_interval);
        used = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    } while (used < seconds_budget);
    r.cpu_seconds = used;
    r.steps = eng.steps() - s0;
    r.collisions = eng.total_collisions() - c0;
    r.collisions_per_second = static_cast<double>(r.collisions) / used;
    r.steps_per_second = static_cast<double>(r.steps) / used;
    r.collisions_per_particle_step = static_cast<double>(r.collisions) / (static_cast<double>(n) * static_cast<double>(r.steps));
    r.bytes_per_particle = static_cast<double>(eng.memory_bytes()) / static_cast<double>(n);
    return r;
}

} // namespace granrepro
