// Throughput of the two hard-disk engines (`granrepro bench ed`, `bench dsmc`): N elastic smooth
// disks (d = 1 mm) in a periodic square box at area fraction `density`, Maxwellian velocities. ED
// starts from a square lattice and is equilibrated before timing; DSMC from uniform random
// positions (its particles are points for the flight, so no overlap check is needed). Both report
// the same quantities, so the two can be compared at N = 1e5, rho = 0.25.
#pragma once
#include <cstddef>

namespace granrepro {

struct HardDiskBenchResult {
    double events_per_second = 0.0;     // per CPU second (ED; DSMC has no events: 0)
    double collisions_per_second = 0.0; // particle-particle collisions per CPU second
    double bytes_per_particle = 0.0;    // engine memory / N [B]
};

HardDiskBenchResult run_ed_benchmark(std::size_t n, double density, double seconds_budget);
HardDiskBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget);

} // namespace granrepro
