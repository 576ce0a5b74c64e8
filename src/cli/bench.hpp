// `granrepro bench <engine>`: engine throughput, reported as the median of repeated runs.
#pragma once
#include <string>

#include "bench/bench_options.hpp"

namespace granrepro {

std::string bench_targets();
int run_bench(const std::string& target, const BenchOptions& opt);

} // namespace granrepro
