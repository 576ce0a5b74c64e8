// The gas of Luding's (1998) free-cooling runs (Secs. 3 and 4), shared by the cooling,
// parameter-study and cluster-growth experiments: disks in a periodic square box, brought to
// elastic equilibrium ("first allowed to evolve with r = 1 for about 10 collisions per particle")
// before dissipation is switched on at t = 0.
#pragma once
#include <vector>

#include "core/vec2.hpp"
#include "engines/ed/ed_config.hpp"

namespace granrepro {

// The periodic L x L box [m] with restitution r, Coulomb friction mu and the TC threshold t_c [s]
// of Eq. (7); rough disks (mu > 0) stick with beta0 = 0, smooth ones keep their tangential
// velocity (beta0 = -1).
EdConfig rough_disk_box(double L, double r, double mu, double t_c);

struct EquilibratedGas {
    std::vector<Vec2> pos;       // [m]
    std::vector<Vec2> vel;       // [m/s]
    double collision_rate = 0.0; // collisions per particle and second during the equilibration [1/s]
};

// Disks of the given radii and masses at pos with velocities vel in the periodic L x L box [m],
// run elastically for collisions_per_particle, then rescaled to v̄ = vbar [m/s] (the elastic run
// conserves energy; the rescale removes round-off). rate_over_second_half: the equilibration runs
// in two halves and collision_rate is that of the second, since the first collisions after a
// lattice start are rarer than in equilibrium; otherwise it is that of the whole run.
EquilibratedGas equilibrated_gas(double L, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                                 const std::vector<double>& radius, const std::vector<double>& mass, double vbar,
                                 double collisions_per_particle, bool rate_over_second_half = false);

// The same from a square lattice (Sec. 4.1) with velocities vel, first given zero momentum and
// v̄ = vbar.
EquilibratedGas equilibrated_lattice_gas(double L, std::vector<Vec2> vel, const std::vector<double>& radius,
                                         const std::vector<double>& mass, double vbar, double collisions_per_particle,
                                         bool rate_over_second_half = false);

} // namespace granrepro
