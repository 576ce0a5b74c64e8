#include "scenarios/ed_gas.hpp"

#include <cmath>

#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"

namespace granrepro {

EdConfig rough_disk_box(double L, double r, double mu, double t_c) {
    EdConfig cfg;
    cfg.lx = cfg.ly = L;
    cfg.law.r = r;
    cfg.law.mu = mu;
    cfg.law.beta0 = mu > 0 ? 0.0 : -1.0;
    cfg.t_c = t_c;
    return cfg;
}

EquilibratedGas equilibrated_gas(double L, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                                 const std::vector<double>& radius, const std::vector<double>& mass, double vbar,
                                 double collisions_per_particle, bool rate_over_second_half) {
    EdEngine eng(rough_disk_box(L, 1.0, 0.0, 0.0), pos, vel, radius, mass);
    if (rate_over_second_half) equilibrate(eng, 0.5 * collisions_per_particle);
    const double t_from = eng.time();
    const auto c_from = eng.total_collisions();
    equilibrate(eng, rate_over_second_half ? 0.5 * collisions_per_particle : collisions_per_particle);
    const double dt = eng.time() - t_from;
    EquilibratedGas gas;
    gas.collision_rate = dt > 0 ? 2.0 * double(eng.total_collisions() - c_from) / double(mass.size()) / dt : NAN;
    gas.pos = eng.positions();
    gas.vel = eng.velocities();
    zero_momentum_and_scale(gas.vel, mass, vbar);
    return gas;
}

EquilibratedGas equilibrated_lattice_gas(double L, std::vector<Vec2> vel, const std::vector<double>& radius,
                                         const std::vector<double>& mass, double vbar, double collisions_per_particle,
                                         bool rate_over_second_half) {
    zero_momentum_and_scale(vel, mass, vbar);
    return equilibrated_gas(L, square_lattice_positions(mass.size(), L, L), vel, radius, mass, vbar,
                            collisions_per_particle, rate_over_second_half);
}

} // namespace granrepro
