// Fixed-work ED run for comparing two builds (scripts/studies/ed_fixed_work.sh): N disks, area
// fraction 0.3, the set-up of `bench ed`, then a fixed number of collisions. Prints the events
// and a checksum of the final velocities.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
using namespace granrepro;
int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 10000;
    const std::uint64_t cols = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 2000000;
    const double d = 1e-3, m = 1e-6, density = 0.3;
    const double l = d * std::sqrt(double(n) * std::numbers::pi / (4.0 * density));
    EdConfig cfg; cfg.lx = cfg.ly = l;
    const std::vector<double> rad(n, 0.5 * d), mass(n, m);
    RngStream rng(12345, 0);
    const auto pos = square_lattice_positions(n, l, l);
    const auto vel = maxwellian_velocities(mass, 1.0, rng);
    EdEngine eng(cfg, pos, vel, rad, mass);
    equilibrate(eng, 2.0);
    const auto e0 = eng.events_processed();
    eng.run_collisions(cols);
    double s = 0; for (auto v : eng.velocities()) s += v.x * 1.3 + v.y;
    std::printf("events %llu checksum %.17g\n", (unsigned long long)(eng.events_processed() - e0), s);
}
