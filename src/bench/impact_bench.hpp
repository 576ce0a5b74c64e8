// Few-body impacts on a wall row at the Schäfer-Wolf Fig. 4 parameters (k_N = 2000 N/m,
// gamma_N = 1e4 1/s, mu = 0.5): the cost of one impact curve point, behind `granrepro bench impact`.
#pragma once

namespace granrepro {

// Impacts per wall second over about `seconds`.
double run_impact_benchmark(double seconds);

} // namespace granrepro
