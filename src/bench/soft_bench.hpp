// `granrepro bench soft`: the many-body pipe engine side by side with LAMMPS (pair gran/hooke)
// on the same physics, the same start and the same steps; `--sizes`: cost against pipe size.
#pragma once
#include "bench/bench_options.hpp"

namespace granrepro {

void bench_soft_report(const BenchOptions& opt);

} // namespace granrepro
