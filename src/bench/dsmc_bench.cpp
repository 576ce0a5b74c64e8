#include "bench/dsmc_bench.hpp"

#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include <cmath>
#include <ctime>
#include <numbers>

namespace granrepro {

DsmcBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget) {
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
    DsmcEngine eng(cfg, std::move(pos), std::move(vel), std::vector<double>(n, 0.5 * d), std::vector<double>(n, m));
    eng.run_steps(2 * cfg.resample_interval); // warm caches and allocations before timing

    const std::uint64_t c0 = eng.total_collisions();
    const std::clock_t start = std::clock();
    double used = 0.0;
    do {
        eng.run_steps(cfg.resample_interval);
        used = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    } while (used < seconds_budget);
    return {static_cast<double>(eng.total_collisions() - c0) / used,
            static_cast<double>(eng.memory_bytes()) / static_cast<double>(n)};
}

} // namespace granrepro
