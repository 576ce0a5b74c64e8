// bistable-pipe (Fig. 6): the spec, a run's outcome, the sweep's tasks, and what the files share.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"
#include "scenarios/pipe_setup.hpp"

namespace granrepro::experiments::bistable_pipe_detail {

// The catalog every output handle of bistable-pipe registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"bistable-pipe"};

// Units and ranges: experiments/bistable-pipe.toml. Each run's PipeSpec is built from this.
struct BistablePipeSpec {
    double width = 0, length = 0, length_check = 0, d_wall = 0, wall_spacing = 0; // [m]; length_check 0: off
    double d_mean = 0, polydispersity = 0, m_mean = 0, phi = 0, mu = 0, g = 0;    // d_mean [m], m_mean [kg], g [m/s^2]
    std::string friction_normal;                                                  // the reading of Eq. (2)
    std::vector<double> kN_list, eN_list;                                         // [N/m], [1]
    double slow_v0 = 0, fast_v0 = 0, agitation = 0, v_crit_2000 = 0, v_abort = 0; // [m/s]
    double steps_per_contact = 0, skin = 0, budget_tcol = 0, budget_min = 0; // skin [m]; budget in contact durations t_col (Eq. 4); [s]
    double window = 0, t_average = 0, sample_dt = 0, eq9_window = 0, drift_tol = 0; // [s]; drift_tol [m/s^2]
    double hold_distance = 0, agitation_vcrit = 0; // [m]: a steady state holds while falling this far; [1]
    std::string time_step;  // "eq5": dt = t_col / steps_per_contact; "wall": also resolve the wall-grain passage
    double wall_steps = 0;  // [1] steps per wall-grain passage of the fastest grain (time_step = "wall")
    double dt_check_eN = 0; // [1] the fast start at this e_N (k_N = kN_list[1]) again at 2 wall_steps; 0 = off
    GRANREPRO_FIELDS(width, length, length_check, d_wall, phi, wall_spacing, d_mean, polydispersity, m_mean, mu, g,
                     friction_normal, kN_list, eN_list, slow_v0, fast_v0, agitation, v_crit_2000, v_abort,
                     steps_per_contact, skin, budget_tcol, budget_min, window, t_average, sample_dt, eq9_window,
                     drift_tol, hold_distance, agitation_vcrit, time_step, wall_steps, dt_check_eN)
};

// The engine's spec at the base length; k_N, e_N, the start and the stream are set per run.
PipeSpec pipe_spec(const BistablePipeSpec& b, std::uint64_t seed);

// v_crit of Eq. (8) at k_N, from Fig. 3's maximum at 2000 N/m (v_crit ∝ sqrt(k_N)) [m/s].
inline double v_crit(const BistablePipeSpec& b, double k) { return b.v_crit_2000 * std::sqrt(k / 2000.0); }

// The smallest time step a run may take: Eq. (5)'s, or under time_step = "wall" the wall-grain
// passage resolved at v_abort, the fastest a run goes (the work bound of validate()) [s].
inline double smallest_time_step(const BistablePipeSpec& b, double dt_eq5) {
    return b.time_step == "wall" ? std::min(dt_eq5, b.wall_spacing / (b.wall_steps * b.v_abort)) : dt_eq5;
}

// The run's time budget: budget_tcol free-wall contact durations (Eq. 4) at its own k_N, e_N, and
// at least budget_min: the stiffest pipe's flows take seconds to settle, not contact durations.
inline double time_budget(const BistablePipeSpec& b, double k, double e) {
    return std::max(b.budget_tcol * pipe_law(k, e, b.m_mean).collision_time(b.m_mean), b.budget_min);
}

enum Outcome { kSteady = 0, kFreeFall = 1, kUnsettled = 2 };

// The paper's construction (text below Eq. 9): on the impact curve Δv_y(v_y^i) of the wall, the
// speed where Δv_y = g/ṅ with positive slope (a stable intersection) nearest to the measured mean
// speed; NaN if there is none in 0.1-3 times it. Done at two v_x^i: σ_vx (the paper's association)
// and the measured mean |v_x| of the wall impacts (grains reaching the wall are the faster ones).
// reach = max Δv_y(v_y^i; σ_vx) / (g/ṅ) over the grid: below 1 the paper's association cannot give
// an intersection at all.
struct Construction {
    double v = NAN;        // predicted steady speed at v_x^i = σ_vx [m/s]
    double v_vxin = NAN;   // predicted steady speed at v_x^i = measured mean impact |v_x| [m/s]
    double reach = NAN;    // max over the grid of Δv_y(σ_vx) / (g/ṅ) [1]
    double slope = NAN;    // d Δv_y / d v at the measured speed, v_x^i = σ_vx [s] (> 0: stable, Eq. 9 argument)
    double contacts = NAN; // wall grains touched per impact at the measured impact velocities (Fig. 5)
    double link = NAN;     // the impact curve's Δv_y at the measured impact velocities over the measured Δv_y
    GRANREPRO_FIELDS(v, v_vxin, reach, slope, contacts, link)
};

// One sweep point's outcome: the pipe run of a Task, which it names (k_N, e_N, start, role: the
// report finds runs by these, not by their place in the sweep), and for a run of Fig. 6 the
// paper's construction, made in compute because it shoots impacts (a report reads outcomes only).
struct RunResult {
    double k_N = NAN, e_N = NAN; // [N/m], [1]
    bool fast = false;           // fast start (else slow)
    int role = -1;               // TaskRole
    Construction construction;   // Fig. 6's runs only; NaN elsewhere
    int outcome = kUnsettled;
    double t_steady = NAN, v_mean = NAN, v_final = NAN, t_final = NAN, accel_final = NAN;
    double sigma_vx = NAN, ndot = NAN, dvy = NAN, vx_in = NAN, vy_in = NAN;
    long grains = 0, steps = 0, list_builds = 0; // Verlet-list builds: the cost of fast flows (issue 26)
    double dt_final = NAN;    // the time step at the end of the run [s] (it varies under time_step = "wall")
    double dt_min = NAN;      // the smallest time step of the run [s]
    double xi_max = 0;        // largest overlap over the run, relative to the smaller diameter [1]
    double xi_steady = NAN;   // the same over the steady state [1]
    double phi_wall = NAN;    // near-wall area fraction over the steady state [1]
    std::vector<double> t, v, sx, pw, xq; // samples: time [s], mean v_y [m/s], rms v_x [m/s], near-wall area
                                          // fraction [1], largest overlap / smaller diameter since the last sample [1]
    std::vector<double> w_ndot, w_dvy, w_sx, w_v; // windows (Eq. 9 estimates): ṅ, Δv_y, σ_vx, v
    GRANREPRO_FIELDS(k_N, e_N, fast, role, construction, outcome, t_steady, v_mean, v_final, t_final, accel_final,
                     sigma_vx, ndot, dvy, vx_in, vy_in, grains, steps, list_builds, dt_final, dt_min, xi_max,
                     xi_steady, phi_wall, t, v, sx, pw, xq, w_ndot, w_dvy, w_sx, w_v)
};

// One sweep point: a pipe run at k_N, e_N from a slow or a fast start, at a pipe length, with
// steps per wall-grain passage wall_steps (0: Eq. (5)'s step throughout), every step divided by
// refine. Its role: a state of
// Fig. 6 (the spec's time step), the length check, the fast start at Eq. (5)'s step drawn beside
// it (time_step = "wall" only), or the fast start at half the step (dt_check_eN).
enum TaskRole { kFig6 = 0, kLengthCheck = 1, kEq5 = 2, kDtCheck = 3 };
struct Task { double k, e; bool fast; double length; double wall_steps; int role; double refine = 1; }; // refine: dt / refine
// The index of the task of that role, k_N, e_N and start; -1 if there is none.
long find_task(const std::vector<Task>& tasks, int role, double k, double e, bool fast);
// The outcome of the run of that role, k_N, e_N and start: nullptr if there is none (find_run),
// an error if there must be one (run_at). report.cpp.
const RunResult* find_run(const std::vector<RunResult>& results, int role, double k, double e, bool fast);
const RunResult& run_at(const std::vector<RunResult>& results, int role, double k, double e, bool fast);
// What ends the name of a run's series table: its start and role ("fast_eq5"), report.cpp's <w>.
std::string series_word(bool fast, int role);

// compute.cpp: one start of the pipe until steady, free fall, v_abort or the end of its budget.
RunResult run_pipe(const PipeSpec& s, double t_budget, double eq9_window, double hold_distance);

// compute.cpp: the construction for one run (impact shots on the pipe's wall row); NaN where there
// is no steady state.
Construction construct(const PipeSpec& base, double k, double e, const RunResult& rr);

// report.cpp: Fig. 6 over every k_N, the estimates below Eq. (9), and every run's time series.
void report_fig6(Result& r, const BistablePipeSpec& b, const PipeSpec& base, const std::vector<RunResult>& results);
void report_eq9_windows(Result& r, const std::vector<RunResult>& results);
void report_series(Result& r, const std::vector<RunResult>& results);

} // namespace granrepro::experiments::bistable_pipe_detail
