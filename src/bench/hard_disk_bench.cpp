#include "bench/hard_disk_bench.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>

#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"

namespace granrepro {

namespace {

constexpr double kDiameter = 1e-3, kMass = 1e-6; // [m], [kg]

// The side of the square box that n disks fill to area fraction `density` [m].
double box_side(std::size_t n, double density) {
    return kDiameter * std::sqrt(static_cast<double>(n) * std::numbers::pi / (4.0 * density));
}

// Calls step() until `budget` CPU seconds have passed (std::clock); the CPU seconds used.
template <class Step>
double run_for(double budget, Step step) {
    const std::clock_t start = std::clock();
    double used = 0.0;
    do {
        step();
        used = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    } while (used < budget);
    return used;
}

} // namespace

HardDiskBenchResult run_ed_benchmark(std::size_t n, double density, double seconds_budget) {
    if (n < 16 || !(density > 0.0) || !(density < 0.78)) throw InputError("bench ed: need N >= 16 and 0 < density < 0.78");
    const double l = box_side(n, density);
    EdConfig cfg;
    cfg.lx = cfg.ly = l;
    const std::vector<double> rad(n, 0.5 * kDiameter), mass(n, kMass);
    RngStream rng(12345, 0);
    const auto pos = square_lattice_positions(n, l, l);
    const auto vel = maxwellian_velocities(mass, 1.0, rng);
    EdEngine eng(cfg, pos, vel, rad, mass);
    equilibrate(eng, 2.0); // leave the lattice before timing

    const std::uint64_t e0 = eng.events_processed(), c0 = eng.total_collisions();
    const std::uint64_t chunk = std::max<std::uint64_t>(20000, n / 4);
    const double used = run_for(seconds_budget, [&] { eng.run_collisions(chunk); });
    return {static_cast<double>(eng.events_processed() - e0) / used,
            static_cast<double>(eng.total_collisions() - c0) / used,
            static_cast<double>(eng.memory_bytes()) / static_cast<double>(n)};
}

HardDiskBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget) {
    if (n < 16 || !(density > 0.0) || !(density < 0.82))
        throw InputError("bench dsmc: need N >= 16 and 0 < density < 0.82");
    const double l = box_side(n, density);
    RngStream rng(12345, 0);
    std::vector<Vec2> pos(n), vel(n);
    for (auto& p : pos) p = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
    for (auto& v : vel) v = {rng.normal(), rng.normal()}; // T/m = 1 m^2/s^2
    DsmcConfig cfg;
    cfg.lx = cfg.ly = l;
    DsmcEngine eng(cfg, std::move(pos), std::move(vel), std::vector<double>(n, 0.5 * kDiameter),
                   std::vector<double>(n, kMass));
    eng.run_steps(2 * cfg.resample_interval); // warm caches and allocations before timing

    const std::uint64_t c0 = eng.total_collisions();
    const double used = run_for(seconds_budget, [&] { eng.run_steps(cfg.resample_interval); });
    return {0.0, static_cast<double>(eng.total_collisions() - c0) / used,
            static_cast<double>(eng.memory_bytes()) / static_cast<double>(n)};
}

} // namespace granrepro
