// Throughput benchmark of the ED engine (wired to `granrepro bench ed`): N elastic smooth disks,
// periodic square box at area fraction `density`, equilibrated from a square lattice.
#pragma once
#include <cstddef>

namespace granrepro {

struct EdBenchResult {
    double events_per_second = 0.0;     // per CPU second
    double collisions_per_second = 0.0; // particle-particle collisions per CPU second
    double bytes_per_particle = 0.0;    // engine memory / N [B]
};

// queue: 0 = engine default (EdEngine), 1 = CalendarQueue, 2 = BinaryHeapQueue, 4 = QuaternaryHeapQueue.
// cell_size_factor: linked-cell edge in units of the diameter (>= 1; EdConfig::cell_size_factor).
EdBenchResult run_ed_benchmark(std::size_t n, double density, double seconds_budget, int queue = 0,
                               double cell_size_factor = 1.0);

} // namespace granrepro
