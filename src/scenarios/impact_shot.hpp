// One binary impact of a free grain on a wall of fixed grains (a single grain or an infinite
// row along y at x = 0), as in Schäfer & Wolf (1995) Figs. 2-5. Shared by the brake-failure and
// emergency-brake experiments and by the pipe experiment's link to the impact curves.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "engines/soft/few_body_engine.hpp"
#include "data/parameter_set.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro {

struct ImpactSetup {
    double d_free = 1e-3;   // free grain diameter [m]
    double m_free = 1e-6;   // free grain mass [kg]
    double d_wall = 0.66e-3;// wall grain diameter [m]
    double wall_spacing = 0;// 0: a single wall grain at the origin; > 0: a row along y [m]
    double x0 = 0, y0 = 0;  // free grain start [m]
    double vx_toward = 0;   // initial speed towards the wall line (v_x^i) [m/s]
    double vy = 0;          // initial speed along the wall (v_y^i) [m/s]
    double dt = 0;          // time step [s]
    long max_steps = 20'000'000;
};

struct ImpactOutcome {
    double dvy = 0;        // v_y^i - v_y^f: speed lost along the wall [m/s] (> 0 is braking)
    double dvx = 0;        // gain of the wall-normal velocity away from the wall [m/s]
    double dvy_shear = 0;  // the part of dvy caused by the shear (Coulomb) forces, Eq. (6) [m/s]
    int wall_grains = 0;   // distinct wall grains touched
    bool completed = false;// the grain left the wall for good within max_steps
};

// The free grain, the wall grains and their contact, Eqs. (1), (2), (5): the parameters the
// impact experiments share (experiments/brake-failure.toml, emergency-brake.toml), read once.
struct ImpactShotSpec {
    double d_free = 0, m_free = 0, d_wall = 0; // [m], [kg], [m]
    double k_N = 0;                            // [N/m]
    double gamma_N = 0;                        // [1/s]
    double mu = 0;
    FrictionNormal friction_normal = FrictionNormal::Magnitude; // reading of Eq. (2)
    double steps_per_contact = 0;              // dt = t_col / steps_per_contact, Eq. (5)
    GRANREPRO_FIELDS(d_free, m_free, d_wall, k_N, gamma_N, mu, friction_normal, steps_per_contact)
    // Centre distance at which the free grain touches a wall grain [m].
    double reach() const { return 0.5 * (d_free + d_wall); }
    CoulombShear shear() const { return {mu, friction_normal}; }
    LinearSpringDashpot law() const { return {k_N, gamma_N}; }
    // A shot of this free grain from (x0, 0) at (-vx_toward, vy); a single wall grain unless
    // wall_spacing is set.
    ImpactSetup shot(double x0, double vx_toward, double vy, double dt) const {
        return {.d_free = d_free, .m_free = m_free, .d_wall = d_wall, .x0 = x0, .vx_toward = vx_toward, .vy = vy, .dt = dt};
    }
};

// The longest step a shot at `speed` [m/s] may take [s]: one that carries the free grain at most
// half a wall grain (diameter d_wall [m]), so that no wall grain is passed between two steps of the
// few-body engine. emergency-brake refuses a grid that needs less; the pipe's construction, whose
// grid follows the measured speeds, steps finer instead.
inline double max_impact_step(double d_wall, double speed) { return 0.5 * d_wall / speed; }

// The readings of Eq. (2) that the impact experiments compare side by side.
inline constexpr std::array kFrictionNormals{FrictionNormal::Magnitude, FrictionNormal::Clipped, FrictionNormal::Elastic,
                                             FrictionNormal::Signed};

// The free-wall contact of Eq. (1) must rebound: gamma_N below 2 sqrt(k_N/m), i.e. e_N in (0, 1]
// (Eq. 4), and its time step t_col/steps_per_contact must be a positive number (k_N = 1e308
// makes it 0). Shared parameter check of the impact experiments. Returns that time step [s].
inline double validate_free_wall_law(const ParameterSet& p, const ImpactShotSpec& s) {
    const double m = s.m_free, k = s.k_N, g = s.gamma_N;
    if (!(g * g / 4 < k / m))
        p.reject(std::vector<std::string>{"gamma_N", "k_N", "m_free"},
                 "over-damped free-wall contact; gamma_N must be below 2 sqrt(k_N/m_free) = " +
                     number_text(2 * std::sqrt(k / m)) + " 1/s so that e_N is in (0, 1]");
    const double dt = s.law().collision_time(m) / s.steps_per_contact;
    if (!(dt > 0 && std::isfinite(dt)))
        p.reject(std::vector<std::string>{"k_N", "m_free", "steps_per_contact"},
                 "the time step t_col/steps_per_contact (Eq. 4) is " + number_text(dt) + " s, not a usable number");
    return dt;
}

// Refuses a single impact that could not end within ImpactSetup::max_steps: the grain must cover
// `path` [m] at `speed` [m/s] with steps of `dt` [s], plus a few contact durations of
// steps_per_contact steps each. `names` are the parameters behind it.
inline void limit_shot_steps(const ParameterSet& p, const std::vector<std::string>& names, double path, double speed,
                             double dt, double contact_steps) {
    const double steps = path / (speed * dt) + 4 * contact_steps;
    p.limit_work(names, steps, double(ImpactSetup{}.max_steps), "time steps in its slowest impact");
}

template <class NormalLaw>
ImpactOutcome shoot(const NormalLaw& law, const CoulombShear& shear, const ImpactSetup& s) {
    FewBodyEngine<NormalLaw, CoulombShear> eng(law, shear, s.dt);
    const double R = 0.5 * s.d_free, r = 0.5 * s.d_wall;
    eng.add_free({{s.x0, s.y0}, {-s.vx_toward, s.vy}, R, s.m_free});
    if (s.wall_spacing > 0) eng.add_row({0.0, 0.0, s.wall_spacing, r});
    else eng.add_fixed({{0.0, 0.0}, r});
    ImpactOutcome out;
    for (long step = 0; step < s.max_steps; ++step) {
        eng.step();
        if (eng.events().empty() || eng.active_contacts() > 0) continue;
        const SoftGrain& g = eng.grains()[0];
        // Done when no contact can follow: moving away from the wall line and outside the
        // envelope of the wall grains (a row), or separating from the single grain.
        const bool away = s.wall_spacing > 0 ? (g.v.x > 0 && g.r.x > R + r) : dot(g.r, g.v) > 0;
        if (away) {
            out.completed = true;
            break;
        }
    }
    const SoftGrain& g = eng.grains()[0];
    out.dvy = s.vy - g.v.y;
    out.dvx = g.v.x + s.vx_toward;
    out.dvy_shear = -eng.shear_dv(0).y;
    std::vector<Partner> seen;
    for (const auto& e : eng.events())
        if (e.begins && std::find(seen.begin(), seen.end(), e.partner) == seen.end()) seen.push_back(e.partner);
    out.wall_grains = int(seen.size());
    return out;
}

} // namespace granrepro
