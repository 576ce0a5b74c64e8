#include "bench/ed_bench.hpp"

#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include <cmath>
#include <ctime>

namespace granrepro {

namespace {

template <class Queue>
EdBenchResult bench(std::size_t n, double density, double budget, double csf) {
    if (n < 16 || !(density > 0.0) || !(density < 0.78)) throw InputError("bench ed: need N >= 16 and 0 < density < 0.78");
    const double d = 1e-3; // [m], the paper's diameter
    const double l = d * std::sqrt(static_cast<double>(n) * M_PI / (4.0 * density));
    EdConfig cfg;
    cfg.lx = cfg.ly = l;
    cfg.cell_size_factor = csf;
    const std::vector<double> rad(n, 0.5 * d), mass(n, 1e-6);
    RngStream rng(12345, 0);
    const auto pos = square_lattice_positions(n, l, l);
    const auto vel = maxwellian_velocities(mass, 1.0, rng);
    BasicEdEngine<Queue> eng(cfg, pos, vel, rad, mass);
    equilibrate(eng, 2.0); // leave the lattice before timing

    const std::uint64_t e0 = eng.events_processed(), c0 = eng.total_collisions();
    const std::uint64_t chunk = std::max<std::uint64_t>(20000, n / 4);
    const std::clock_t start = std::clock();
    double used = 0.0;
    do {
        eng.run_collisions(chunk);
        used = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    } while (used < budget);
    return {static_cast<double>(eng.events_processed() - e0) / used,
            static_cast<double>(eng.total_collisions() - c0) / used,
            static_cast<double>(eng.memory_bytes()) / static_cast<double>(n)};
}

} // namespace

EdBenchResult run_ed_benchmark(std::size_t n, double density, double seconds_budget, int queue,
                               double cell_size_factor) {
    switch (queue) {
    case 1: return bench<CalendarQueue>(n, density, seconds_budget, cell_size_factor);
    case 2: return bench<BinaryHeapQueue>(n, density, seconds_budget, cell_size_factor);
    case 4: return bench<QuaternaryHeapQueue>(n, density, seconds_budget, cell_size_factor);
    default: return bench<EdEngine::QueueType>(n, density, seconds_budget, cell_size_factor);
    }
}

} // namespace granrepro
