#include "bench/impact_bench.hpp"

#include <chrono>
#include <cmath>

#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"
#include "scenarios/impact_shot.hpp"

namespace granrepro {

double run_impact_benchmark(double seconds) {
    const LinearSpringDashpot law{2000.0, 1e4};
    ImpactSetup s;
    s.wall_spacing = 0.66e-3;
    s.x0 = 0.83e-3;
    s.vx_toward = 0.3;
    s.dt = law.collision_time(1e-6) / 50;
    long impacts = 0;
    const auto t0 = std::chrono::steady_clock::now();
    double elapsed = 0;
    while (elapsed < seconds) {
        s.vy = 0.1 * std::pow(400.0, (impacts % 16) / 15.0);
        s.y0 = 0.066e-3 * double(impacts % 10);
        shoot(law, CoulombShear{0.5}, s);
        ++impacts;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return double(impacts) / elapsed;
}

} // namespace granrepro
