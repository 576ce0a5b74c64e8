// Initial states for the ED engine: lattices, random non-overlapping disks, velocity
// distributions scaled to a given vbar = sqrt(2K/(N m)), and equilibration at r = 1
// (Luding 1998 Sec. 3: "first allowed to evolve with r = 1 for about 10 collisions per particle").
#pragma once
#include "core/rng_stream.hpp"
#include "core/vec2.hpp"
#include "engines/ed/ed_engine.hpp"
#include <cstddef>
#include <vector>

namespace granrepro {

// n centres on a square lattice filling [0,lx) x [0,ly) (Luding Sec. 4.1), each in the middle of
// its lattice cell; the lattice is the smallest k x k' with k k' >= n keeping the aspect ratio.
std::vector<Vec2> square_lattice_positions(std::size_t n, double lx, double ly);

// Triangular lattice (Luding Sec. 5: s = 1.01 d), rows from y0 upwards; row k holds centres
// x_min + (k odd ? spacing/2 : 0) + m spacing <= x_max. spacing [m] centre-to-centre.
std::vector<Vec2> triangular_lattice_positions(std::size_t n, double x_min, double x_max, double y0,
                                               double spacing);

// Random sequential addition of disks with the given radii [m] into the box; throws InputError
// when it cannot place a disk after max_attempts tries (too dense: use a lattice + equilibrate).
// A closed axis keeps the disks a radius away from the box edges.
std::vector<Vec2> random_positions(const std::vector<double>& radius, double lx, double ly,
                                   bool periodic_x, bool periodic_y, RngStream& rng,
                                   std::size_t max_attempts = 100000);

// Gaussian (Maxwellian) components, then zero total momentum and sqrt(2K/(N mbar)) = vbar [m/s]
// with mbar the mean mass.
std::vector<Vec2> maxwellian_velocities(const std::vector<double>& mass, double vbar, RngStream& rng);
// Components uniform in [-v0, v0] [m/s] (Luding Sec. 5), not rescaled.
std::vector<Vec2> uniform_velocities(std::size_t n, double v0, RngStream& rng);
// Remove the centre-of-mass velocity and rescale to sqrt(2K/(N mbar)) = vbar [m/s].
void zero_momentum_and_scale(std::vector<Vec2>& vel, const std::vector<double>& mass, double vbar);

// Run with perfectly elastic smooth particles (the law's elastic_version(false), for
// RoughDiskCollision r = 1, mu = 0) and walls (r_w = 1, mu_w = 0), t_c = 0, until the mean
// number of collisions per particle, sum_i count_i / N, grew by collisions_per_particle; then
// restore the laws. Observers are not called.
template <class Queue, class Collision>
void equilibrate(BasicEdEngine<Queue, Collision>& engine, double collisions_per_particle) {
    const auto saved = engine.config();
    engine.set_law(saved.law.elastic_version(false));
    engine.set_tc(0.0);
    for (std::size_t w = 0; w < saved.walls.size(); ++w) engine.set_wall_law(w, 1.0, 0.0, -1.0);
    const auto pairs = static_cast<std::uint64_t>(collisions_per_particle * static_cast<double>(engine.size()) / 2.0 + 0.5);
    engine.run_collisions(pairs);
    engine.set_law(saved.law);
    engine.set_tc(saved.t_c);
    for (std::size_t w = 0; w < saved.walls.size(); ++w)
        engine.set_wall_law(w, saved.walls[w].r, saved.walls[w].mu, saved.walls[w].beta0);
}

} // namespace granrepro
