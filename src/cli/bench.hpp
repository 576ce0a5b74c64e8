// `granrepro bench <engine>`: engine throughput, reported as the median of repeated runs.
#pragma once
#include <string>

namespace granrepro {

struct BenchOptions {
    int repeats = 5;
    double seconds = 2.0;
    long steps = 0;     // soft: time steps of one timed run (0: the target's default)
    int threads = 2;    // soft: threads of the multi-core comparison
    bool sizes = false; // soft: cost against the number of grains instead of the LAMMPS comparison
};

std::string bench_targets();
int run_bench(const std::string& target, const BenchOptions& opt);

} // namespace granrepro
