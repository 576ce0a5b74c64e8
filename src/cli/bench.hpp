// `granrepro bench <engine>`: engine throughput, reported as the median of repeated runs.
#pragma once
#include <string>

namespace granrepro {

struct BenchOptions {
    int repeats = 5;
    double seconds = 2.0;
};

std::string bench_targets();
int run_bench(const std::string& target, const BenchOptions& opt);

} // namespace granrepro
