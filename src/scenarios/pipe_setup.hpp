// The pipe of Schäfer & Wolf (1995) Fig. 6 as a ready engine: geometry, polydisperse grains on
// a triangular lattice at the requested area fraction, random start velocities. Shared by the
// bistable-pipe experiment and `granrepro bench soft`.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engines/soft/pipe_engine.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro {

struct PipeSpec {
    PipeGeometry geo;
    double d_mean = 1e-3;          // mean free-grain diameter [m]
    double polydispersity = 0.1;   // diameters uniform in d_mean (1 ± this) [1]
    double m_mean = 1e-6;          // mass at d_mean [kg]
    double phi = 0.55;             // area fraction between the wall crests [1]
    double mu = 0.5;               // Coulomb coefficient [1]
    FrictionNormal friction_normal = FrictionNormal::Magnitude; // reading of Eq. (2)
    double k_N = 2000, e_N = 0.9;  // [N/m], free-wall restitution [1]
    double v0 = 0, agitation = 1;  // start: mean downward speed, rms of random velocities [m/s]
    double steps_per_contact = 50; // [1]
    double skin = 0.1e-3;          // Verlet skin [m]
    // Run control (used by the experiment): [s], [m/s^2], [s], [s], [m/s]
    double window = 0.3, drift_tol = 0.3, t_average = 0.3, sample_dt = 0.005, v_abort = 300;
    // The time-step rule (used by the experiment): 0 keeps Eq. (5)'s dt for the whole run; S > 0
    // also caps dt at wall_spacing / (S v_max), S steps while the fastest grain passes one wall grain.
    double wall_steps = 0;
    std::uint64_t seed = 1, stream = 0;
};

// Free-wall restitution e_N defines gamma_N, as for Figs. 3-5 (e_N = 0.70 <=> gamma_N = 1e4 1/s
// at k_N = 2000 N/m and m = 1 mg).
LinearSpringDashpot pipe_law(double k_N, double e_N, double m_mean);

// The grains of the start: a triangular lattice between the wall crests, N sites chosen at
// random; diameters uniform in d_mean (1 ± polydispersity), masses ∝ d^2 (uniform areal density)
// with m(d_mean) = m_mean; random velocities of rms `agitation` about a mean -v0 along the pipe.
// In the order they are added to the engine [m, m/s, kg].
struct PipeStart {
    std::vector<double> x, y, vx, vy, radius, mass;
};
PipeStart pipe_start(const PipeSpec& s);

// The grains g in the pipe of s with any contact laws (a normal law and a shear law, src/models/)
// and time step dt [s].
template <class NormalLaw, class ShearLaw>
PipeEngine<NormalLaw, ShearLaw> pipe_engine(const PipeSpec& s, const PipeStart& g, const NormalLaw& normal,
                                            const ShearLaw& shear, double dt) {
    PipeEngine<NormalLaw, ShearLaw> eng(normal, shear, s.geo, dt, s.skin);
    for (std::size_t i = 0; i < g.x.size(); ++i) eng.add_grain(g.x[i], g.y[i], g.vx[i], g.vy[i], g.radius[i], g.mass[i]);
    eng.finalize();
    return eng;
}

// The pipe with its start (pipe_start).
template <class NormalLaw, class ShearLaw>
PipeEngine<NormalLaw, ShearLaw> build_pipe(const PipeSpec& s, const NormalLaw& normal, const ShearLaw& shear, double dt) {
    return pipe_engine(s, pipe_start(s), normal, shear, dt);
}

// The paper's pipe: Eq. (1)'s linear law from (k_N, e_N) and Coulomb's Eq. (2) in the reading of
// the spec, at dt = pipe_time_step(s, pipe_law(s.k_N, s.e_N, s.m_mean)): t_col / steps_per_contact
// of the stiffest (lightest free-free) pair under that law, Eq. (5) [s].
PipeEngine<LinearSpringDashpot, CoulombShear> build_pipe(const PipeSpec& s);
double pipe_time_step(const PipeSpec& s, const LinearSpringDashpot& law);

// The number of grains build_pipe places (area fraction phi of the channel between the crests),
// and whether its start lattice holds them: the up-front check of phi.
long pipe_grain_count(const PipeSpec& s);
bool pipe_lattice_fits(const PipeSpec& s);

} // namespace granrepro
