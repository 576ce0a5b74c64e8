// Throughput benchmark of the DSMC engine: N elastic smooth disks (d = 1 mm) in a periodic square
// box at area fraction `density`, uniform random positions (DSMC particles are points for the
// flight, so no overlap check is needed), Maxwellian velocities. Same quantities as the ED
// benchmark, so the two can be compared at N = 1e5, rho = 0.25.
#pragma once
#include "engines/dsmc/dsmc_config.hpp"
#include <cstddef>
#include <cstdint>

namespace granrepro {

struct DsmcBenchResult {
    std::size_t n = 0;
    double density = 0.0;              // area fraction [-]
    double cpu_seconds = 0.0;          // CPU time of the timed part [s]
    std::uint64_t steps = 0;           // time steps in the timed part
    std::uint64_t collisions = 0;      // accepted pair collisions in the timed part
    double collisions_per_second = 0.0; // per CPU second
    double steps_per_second = 0.0;
    double collisions_per_particle_step = 0.0; // [-], collisions / (N steps)
    double bytes_per_particle = 0.0;   // engine memory / N [B]
};

// free_volume / displacement switch the dense-gas corrections (off by default: plain DSMC).
DsmcBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget,
                                   DsmcFreeVolume free_volume = DsmcFreeVolume::off,
                                   bool displacement = false);

} // namespace granrepro
