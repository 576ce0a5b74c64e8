// Throughput benchmark of the DSMC engine: N elastic smooth disks (d = 1 mm) in a periodic square
// box at area fraction `density`, uniform random positions (DSMC particles are points for the
// flight, so no overlap check is needed), Maxwellian velocities. Same quantities as the ED
// benchmark, so the two can be compared at N = 1e5, rho = 0.25.
#pragma once
#include <cstddef>

namespace granrepro {

struct DsmcBenchResult {
    double collisions_per_second = 0.0; // accepted pair collisions per CPU second
    double bytes_per_particle = 0.0;    // engine memory / N [B]
};

DsmcBenchResult run_dsmc_benchmark(std::size_t n, double density, double seconds_budget);

} // namespace granrepro
