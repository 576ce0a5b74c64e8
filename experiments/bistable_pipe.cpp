// bistable-pipe: Schäfer & Wolf (1995) Fig. 6. Grains fall through a vertical 2D pipe between two
// rows of fixed wall grains; the steady-state mean velocity is recorded against e_N for three
// k_N, from a slow start and from a fast start.
//
// Run control. A steady state is detected from the data (the drift of the mean velocity over a
// trailing window), never assumed, and a run stops as soon as it is confirmed. Each run has a time
// budget in units of its own contact duration t_col(k_N, e_N) (Eq. 4), so every k_N gets the same
// number of time steps; a run also stops when it falls freely (accelerating at g with no wall
// impact over a whole window: a plug that no longer touches the walls never brakes again) or
// passes v_abort. Every run ends with one of three outcomes (steady, free fall, unsettled) and its
// last speed, and the figure marks the runs that did not settle instead of omitting them.
//
// In steady states the braking balance of Eq. (9), g = ṅ Δv_y, is measured, and the paper's
// construction is repeated: the steady speed predicted by the impact curve Δv_y(v_y^i) of the
// pipe's own wall at the measured v_x^i, where it equals g/ṅ. Over windows of every run, ṅ is set
// against σ_vx and ṅ Δv_y against Δv_y (the crude estimates below Eq. 9).
#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <numeric>
#include <string>
#include <tuple>

#include "analysis/curve_analysis.hpp"
#include "data/spec.hpp"
#include "engines/soft/pipe_engine.hpp"
#include "scenarios/impact_shot.hpp"
#include "scenarios/pipe_setup.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

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
    template <class V> void fields(V&& v) {
        v("width", width); v("length", length); v("length_check", length_check); v("d_wall", d_wall); v("phi", phi);
        v("wall_spacing", wall_spacing); v("d_mean", d_mean); v("polydispersity", polydispersity); v("m_mean", m_mean);
        v("mu", mu); v("g", g); v("friction_normal", friction_normal); v("kN_list", kN_list); v("eN_list", eN_list);
        v("slow_v0", slow_v0); v("fast_v0", fast_v0); v("agitation", agitation); v("v_crit_2000", v_crit_2000);
        v("v_abort", v_abort); v("steps_per_contact", steps_per_contact); v("skin", skin); v("budget_tcol", budget_tcol); v("budget_min", budget_min);
        v("window", window); v("t_average", t_average); v("sample_dt", sample_dt); v("eq9_window", eq9_window);
        v("drift_tol", drift_tol); v("hold_distance", hold_distance);
        v("agitation_vcrit", agitation_vcrit);
    }
};

// The engine's spec at the base length; k_N, e_N, the start and the stream are set per run.
PipeSpec pipe_spec(const BistablePipeSpec& b, std::uint64_t seed) {
    return {.geo = {.width = b.width, .length = std::round(b.length / b.wall_spacing) * b.wall_spacing,
                    .wall_radius = 0.5 * b.d_wall, .wall_spacing = b.wall_spacing, .gravity = b.g},
            .d_mean = b.d_mean, .polydispersity = b.polydispersity, .m_mean = b.m_mean, .phi = b.phi, .mu = b.mu,
            .friction_normal = *parse_friction_normal(b.friction_normal), .agitation = b.agitation,
            .steps_per_contact = b.steps_per_contact, .skin = b.skin, .window = b.window, .drift_tol = b.drift_tol,
            .t_average = b.t_average, .sample_dt = b.sample_dt, .v_abort = b.v_abort, .seed = seed};
}

// v_crit of Eq. (8) at k_N, from Fig. 3's maximum at 2000 N/m (v_crit ∝ sqrt(k_N)) [m/s].
double v_crit(const BistablePipeSpec& b, double k) { return b.v_crit_2000 * std::sqrt(k / 2000.0); }

// The run's time budget: budget_tcol free-wall contact durations (Eq. 4) at its own k_N, e_N, and
// at least budget_min: the stiffest pipe's flows take seconds to settle, not contact durations.
double time_budget(const BistablePipeSpec& b, double k, double e) {
    return std::max(b.budget_tcol * pipe_law(k, e, b.m_mean).collision_time(b.m_mean), b.budget_min);
}

void validate(const ParameterSet& p) {
    const auto b = read_spec<BistablePipeSpec>(p);
    for (double e : b.eN_list)
        if (!(e > 0 && e < 1)) p.reject("eN_list", "each e_N must be in (0, 1): e_N = 1 has no dashpot and Eq. (4) no solution");
    double longest_budget = 0;
    for (double k : b.kN_list)
        for (double e : b.eN_list) {
            longest_budget = std::max(longest_budget, time_budget(b, k, e));
            if (time_budget(b, k, e) < b.window + b.t_average)
                p.reject(std::vector<std::string>{"budget_tcol", "budget_min", "m_mean", "kN_list", "eN_list", "window", "t_average"},
                         "the budget of k_N = " + number_text(k) + " N/m, e_N = " + number_text(e) +
                                            " is shorter than window + t_average: no steady state could be detected");
        }
    // The start: phi of the channel as grains on a lattice (phi = 0.79 failed late with "area
    // fraction too high for a lattice start"), then every run's cost in grain-steps.
    const PipeSpec s = pipe_spec(b, 0);
    const std::vector<std::string> geometry{"phi", "width", "length", "wall_spacing", "d_mean", "polydispersity", "d_wall"};
    const long n = pipe_grain_count(s);
    p.limit_work(geometry, double(n), 1e7, "grains");
    if (n < 1) p.reject(geometry, "the channel holds no grain at this area fraction");
    if (!pipe_lattice_fits(s))
        p.reject(geometry, "the " + std::to_string(n) +
                               " grains do not fit on a triangular lattice of spacing >= d_mean (1 + polydispersity) "
                               "between the wall crests; lower phi");
    for (double k : b.kN_list)
        for (double e : b.eN_list) {
            const double dt = pipe_time_step(s, pipe_law(k, e, s.m_mean)); // build_pipe's step
            p.limit_work({"budget_tcol", "budget_min", "steps_per_contact", "kN_list", "eN_list", "phi", "width", "length", "d_mean"},
                         double(n) * time_budget(b, k, e) / dt, kMaxGrainSteps, "grain-steps in one run");
            // One sample per step at most: sample_dt = 1e-300 overflowed window/sample_dt and
            // crashed the drift fit.
            if (!(b.sample_dt >= dt))
                p.reject(std::vector<std::string>{"sample_dt", "m_mean", "kN_list", "eN_list", "steps_per_contact"},
                         "sample_dt must be at least the time step dt = " + number_text(dt) + " s (k_N = " +
                             number_text(k) + " N/m, e_N = " + number_text(e) + "): one sample per step");
        }
    if (b.wall_spacing - b.d_wall >= b.d_mean * (1 - b.polydispersity))
        p.reject(std::vector<std::string>{"wall_spacing", "d_wall", "d_mean", "polydispersity"},
                 "the gaps between wall grains (wall_spacing - d_wall) must be narrower than the smallest grain, "
                 "or grains fall through the wall");
    if (b.sample_dt > b.window / 3) p.reject("sample_dt", "must be at most window / 3 so that a drift can be fitted");
    if (b.eq9_window < b.sample_dt) p.reject("eq9_window", "must be at least sample_dt");
    // Windows become sample counts (size_t(eq9_window / sample_dt)): bounded by the budget's
    // samples, they cannot overflow (eq9_window = 1e308 hung).
    if (!(b.eq9_window <= longest_budget))
        p.reject(std::vector<std::string>{"eq9_window", "budget_tcol"},
                 "eq9_window must be at most the longest run's time budget, " + number_text(longest_budget) + " s");
    // The check pipe's grains, like the main pipe's (length_check = 1e308 aborted in GSL).
    // Estimated in double: pipe_grain_count's lround has no defined result beyond a long.
    if (b.length_check > 0)
        p.limit_work({"length_check", "phi", "width", "d_mean"}, double(n) * b.length_check / s.geo.length, 1e7, "grains");
    const double range = b.d_mean * (1 + b.polydispersity) + b.skin;
    if (b.length < 4 * range)
        p.reject(std::vector<std::string>{"length", "d_mean", "polydispersity", "skin"},
                 "length must be at least 4 interaction ranges d_mean (1 + polydispersity) + skin");
    if (b.length_check > 0 && b.length_check < 4 * range)
        p.reject("length_check", "must be 0 (off) or at least 4 interaction ranges");
    if (b.wall_spacing < b.d_wall * (1 - 1e-12)) p.reject("wall_spacing", "wall grains would overlap; must be at least d_wall");
    if (b.width < 10 * b.d_mean) p.reject("width", "must be at least 10 grain diameters");
}

using Engine = PipeEngine<LinearSpringDashpot, CoulombShear>;

enum Outcome { kSteady = 0, kFreeFall = 1, kUnsettled = 2 };

struct RunResult {
    int outcome = kUnsettled;
    double t_steady = NAN, v_mean = NAN, v_final = NAN, t_final = NAN, accel_final = NAN;
    double sigma_vx = NAN, ndot = NAN, dvy = NAN, vx_in = NAN, vy_in = NAN;
    long grains = 0, steps = 0, list_builds = 0; // Verlet-list builds: the cost of fast flows (issue 26)
    double xi_max = 0;        // largest overlap over the run, relative to the smaller diameter [1]
    double xi_steady = NAN;   // the same over the steady state [1]
    double phi_wall = NAN;    // near-wall area fraction over the steady state [1]
    std::vector<double> t, v, sx, pw, xq; // samples: time [s], mean v_y [m/s], rms v_x [m/s], near-wall area
                                          // fraction [1], largest overlap / smaller diameter since the last sample [1]
    std::vector<double> w_ndot, w_dvy, w_sx, w_v; // windows (Eq. 9 estimates): ṅ, Δv_y, σ_vx, v
    template <class V> void fields(V&& f) {
        f("outcome", outcome); f("t_steady", t_steady); f("v_mean", v_mean); f("v_final", v_final);
        f("t_final", t_final); f("accel_final", accel_final); f("sigma_vx", sigma_vx); f("ndot", ndot); f("dvy", dvy);
        f("vx_in", vx_in); f("vy_in", vy_in); f("grains", grains);
        f("steps", steps); f("list_builds", list_builds); f("xi_max", xi_max); f("xi_steady", xi_steady); f("phi_wall", phi_wall);
        f("t", t); f("v", v); f("sx", sx); f("pw", pw); f("xq", xq);
        f("w_ndot", w_ndot); f("w_dvy", w_dvy); f("w_sx", w_sx); f("w_v", w_v);
    }
};

double slope(const std::vector<double>& t, const std::vector<double>& v, std::size_t from) {
    double c0, c1, c00, c01, c11, ss;
    gsl_fit_linear(t.data() + from, 1, v.data() + from, 1, t.size() - from, &c0, &c1, &c00, &c01, &c11, &ss);
    return c1;
}

// Wall impacts per sample interval, so that any span of samples can be summed.
struct WallSamples {
    std::vector<WallImpactStats> per_sample;
    void take(Engine& eng) {
        per_sample.push_back(eng.wall_stats());
        eng.reset_wall_stats();
    }
    WallImpactStats sum(std::size_t from, std::size_t to) const { // samples [from, to)
        WallImpactStats w;
        for (std::size_t i = from; i < to; ++i) {
            w.impacts += per_sample[i].impacts;
            w.completed += per_sample[i].completed;
            w.sum_dvy += per_sample[i].sum_dvy;
            w.sum_vx_in += per_sample[i].sum_vx_in;
            w.sum_vy_in += per_sample[i].sum_vy_in;
        }
        return w;
    }
};

double span_mean(const std::vector<double>& x, std::size_t from, std::size_t to) {
    return std::accumulate(x.begin() + long(from), x.begin() + long(to), 0.0) / double(to - from);
}

// The index of the first sample after time t (sample times increase).
std::size_t sample_after(const std::vector<double>& times, double t) {
    return std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
}

// Means over the steady state (samples after steady_since) of n grains: speed, σ_vx, wall impact
// rate ṅ per grain and the mean impact (Δv_y, incoming velocities) of Eq. (9).
void steady_means(RunResult& r, const WallSamples& walls, double steady_since, double sample_dt, std::size_t n) {
    r.t_steady = steady_since;
    const std::size_t from = sample_after(r.t, steady_since), to = r.t.size();
    const WallImpactStats w = walls.sum(from, to);
    r.v_mean = span_mean(r.v, from, to);
    r.sigma_vx = span_mean(r.sx, from, to);
    r.phi_wall = span_mean(r.pw, from, to);
    if (from < to) r.xi_steady = *std::max_element(r.xq.begin() + long(from), r.xq.begin() + long(to));
    r.ndot = double(w.impacts) / (double(to - from) * sample_dt * double(n));
    if (w.completed > 0) {
        r.dvy = w.sum_dvy / double(w.completed);
        r.vx_in = w.sum_vx_in / double(w.completed);
        r.vy_in = w.sum_vy_in / double(w.completed);
    }
}

// Windows of eq9_window for the estimates below Eq. (9), skipping the first (the start).
void eq9_windows(RunResult& r, const WallSamples& walls, double eq9_window, double sample_dt, std::size_t n) {
    const std::size_t per = std::size_t(std::max(1.0, std::round(eq9_window / sample_dt)));
    for (std::size_t a = per; a + per <= r.t.size(); a += per) {
        const WallImpactStats w = walls.sum(a, a + per);
        if (w.completed < 20) continue; // too few impacts for a mean Δv_y
        r.w_ndot.push_back(double(w.impacts) / (double(per) * sample_dt * double(n)));
        r.w_dvy.push_back(w.sum_dvy / double(w.completed));
        r.w_sx.push_back(span_mean(r.sx, a, a + per));
        r.w_v.push_back(-span_mean(r.v, a, a + per));
    }
}

// Runs one start until it is steady, falls freely, passes v_abort or exhausts its budget. Steady:
// over the trailing window the fitted slope of the mean velocity is below drift_tol [m/s^2] (braking
// balances gravity to that accuracy) and stays below it over the following hold: t_average, or
// longer for a slow state, which must keep its speed while falling hold_distance.
RunResult run_pipe(const PipeSpec& s, double t_budget, double eq9_window, double hold_distance) {
    Engine eng = build_pipe(s);
    RunResult r;
    r.grains = long(eng.size());
    const std::size_t n = eng.size();
    const std::size_t per_window = std::size_t(std::max(3.0, std::round(s.window / s.sample_dt)));
    WallSamples walls;
    double steady_since = NAN, next = s.sample_dt;
    double hold = s.t_average; // [s]
    bool free_fall = false;
    // The layer next to each wall (Eq. 9: ṅ goes with the volume fraction "near the wall"): one mean
    // diameter inward from the wall grains' crests; a grain counts whole when its centre is inside.
    const double layer_in = s.geo.wall_radius + s.d_mean, layer_area = 2 * s.d_mean * s.geo.length;
    double xi = 0; // largest overlap ratio since the last sample
    while (eng.time() < t_budget) {
        eng.step();
        xi = std::max(xi, eng.max_overlap_ratio());
        if (eng.time() + 0.5 * eng.dt() < next) continue;
        r.xq.push_back(xi);
        r.xi_max = std::max(r.xi_max, xi);
        xi = 0;
        next += s.sample_dt;
        double v = 0, sx = 0, near = 0;
        for (std::size_t i = 0; i < n; ++i) {
            v += eng.vy()[i];
            sx += eng.vx()[i] * eng.vx()[i];
            const double x = eng.x()[i], rad = eng.radius()[i];
            if (x < layer_in || x > s.geo.width - layer_in) near += M_PI * rad * rad;
        }
        r.pw.push_back(near / layer_area);
        r.t.push_back(eng.time());
        r.v.push_back(v / double(n));
        r.sx.push_back(std::sqrt(sx / double(n)));
        walls.take(eng);
        if (std::abs(r.v.back()) > s.v_abort) break;
        const std::size_t m = r.t.size();
        if (m <= per_window) continue;
        const double drift = slope(r.t, r.v, m - per_window);
        // A plug in free fall: accelerating at g and not one wall impact over the window.
        if (std::abs(drift + s.geo.gravity) < s.drift_tol && walls.sum(m - per_window, m).impacts == 0) {
            free_fall = true;
            break;
        }
        if (std::isnan(steady_since)) {
            if (std::abs(drift) < s.drift_tol) {
                steady_since = eng.time();
                // A slow state near the edge of its branch is metastable: it must hold while the
                // plug passes many wall grains, not only for t_average.
                hold = std::max(s.t_average, hold_distance / std::max(std::abs(span_mean(r.v, m - per_window, m)), 1e-300));
            }
        } else if (eng.time() >= steady_since + hold) {
            // Confirm over the averaging window itself: a plateau that happened to fill the
            // detection window but keeps drifting afterwards is not a steady state; search on.
            const std::size_t from = sample_after(r.t, steady_since);
            if (m - from >= 3 && std::abs(slope(r.t, r.v, from)) < s.drift_tol) break;
            steady_since = NAN;
        }
    }
    const std::size_t m = r.t.size();
    r.steps = eng.steps();
    r.list_builds = eng.list_builds();
    r.v_final = r.v.back();
    r.t_final = r.t.back();
    r.accel_final = m > per_window ? slope(r.t, r.v, m - per_window) : NAN;
    const bool steady = !std::isnan(steady_since) && eng.time() >= steady_since + hold - 1e-12;
    r.outcome = steady ? kSteady : (free_fall || r.accel_final < -(s.geo.gravity - s.drift_tol)) ? kFreeFall : kUnsettled;
    if (steady) steady_means(r, walls, steady_since, s.sample_dt, n);
    eq9_windows(r, walls, eq9_window, s.sample_dt, n);
    return r;
}

// Mean Δv_y and wall grains touched of impacts on the pipe's wall row at (v_x^i, v_y^i), over 10
// start positions (Figs. 4, 5). The step is the pipe's, t_col / steps_per_contact, but never more
// than max_impact_step (half a wall grain per step, emergency-brake's rule): the construction's grid
// reaches 3 times the fastest steady speed (730 m/s at k_N = 2000, e_N = 0.95), where t_col/50
// would move it 1 mm, past a 0.66 mm wall grain, in one step.
struct ImpactMean { double dvy = 0, contacts = 0; };
ImpactMean impact_mean(const PipeSpec& base, double k, double e, double vx, double vy) {
    const LinearSpringDashpot law = pipe_law(k, e, base.m_mean);
    const double d_wall = 2 * base.geo.wall_radius;
    const double dt = std::min(law.collision_time(base.m_mean) / base.steps_per_contact, max_impact_step(d_wall, std::hypot(vx, vy)));
    ImpactSetup is{.d_free = base.d_mean, .m_free = base.m_mean, .d_wall = d_wall, .wall_spacing = base.geo.wall_spacing,
                   .x0 = 0.5 * (base.d_mean + d_wall), .vx_toward = vx, .vy = vy, .dt = dt};
    ImpactMean mean;
    const int npos = 10;
    for (int j = 0; j < npos; ++j) {
        is.y0 = is.wall_spacing * j / npos;
        const ImpactOutcome o = shoot(law, CoulombShear{base.mu, base.friction_normal}, is);
        mean.dvy += o.dvy / npos;
        mean.contacts += double(o.wall_grains) / npos;
    }
    return mean;
}

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
};
// The upward crossing of need nearest to v_meas on a log grid, NaN if none.
double stable_crossing(const std::vector<double>& grid, const std::vector<double>& dv, double need, double v_meas) {
    double best = INFINITY;
    for (std::size_t i = 1; i < grid.size(); ++i) {
        const double a = dv[i - 1] - need, b = dv[i] - need;
        if (!(a < 0 && b >= 0)) continue; // upward crossing = positive slope
        const double x = std::exp(std::log(grid[i - 1]) + a / (a - b) * (std::log(grid[i]) - std::log(grid[i - 1])));
        if (std::abs(std::log(x / v_meas)) < std::abs(std::log(best / v_meas))) best = x;
    }
    return std::isfinite(best) ? best : NAN;
}
Construction construct(const PipeSpec& base, double k, double e, const RunResult& rr) {
    Construction c;
    if (!(rr.outcome == kSteady && rr.ndot > 0 && rr.vx_in > 0 && rr.sigma_vx > 0)) return c;
    const double v_meas = -rr.v_mean, need = base.geo.gravity / rr.ndot;
    const auto grid = log_space(0.1 * v_meas, 3 * v_meas, 41);
    std::vector<double> dv(grid.size()), dv_in(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        dv[i] = impact_mean(base, k, e, rr.sigma_vx, grid[i]).dvy;
        dv_in[i] = impact_mean(base, k, e, rr.vx_in, grid[i]).dvy;
    }
    const ImpactMean at_impact = impact_mean(base, k, e, rr.vx_in, rr.vy_in);
    c.contacts = at_impact.contacts;
    c.link = rr.dvy > 0 ? at_impact.dvy / rr.dvy : NAN;
    c.v = stable_crossing(grid, dv, need, v_meas);
    c.v_vxin = stable_crossing(grid, dv_in, need, v_meas);
    c.reach = *std::max_element(dv.begin(), dv.end()) / need;
    std::size_t at = 0; // grid[at] <= v_meas < grid[at + 1]
    while (at + 2 < grid.size() && grid[at + 1] <= v_meas) ++at;
    c.slope = (dv[at + 1] - dv[at]) / (grid[at + 1] - grid[at]);
    return c;
}

struct Task { double k, e; bool fast; double length; };

std::vector<Task> make_tasks(const BistablePipeSpec& b) {
    const auto &ks = b.kN_list, &es = b.eN_list;
    std::vector<Task> tasks;
    for (double k : ks)
        for (double e : es)
            for (bool fast : {false, true}) tasks.push_back({k, e, fast, b.length});
    // The length check: the second k_N at its largest e_N, slow start, at a second pipe length.
    if (b.length_check > 0) tasks.push_back({ks.size() > 1 ? ks[1] : ks[0], es.back(), false, b.length_check});
    return tasks;
}

// The columns of one k_N's table of Fig. 6, per start (0 slow, 1 fast) over e_N, and the
// construction's link for the slow start at the largest e_N.
enum SteadyColumn { kV, kVLast, kOutcome, kTEnd, kBalance, kSigmaVx, kNdot, kDvy, kVConstruction, kImpactSlope,
                    kContacts, kVyImpact, kVConstructionVxin, kReach, kBuildsPerStep, kXiSteady, kPhiWall, kColumns };
struct KColumns { std::vector<double> col[2][kColumns]; double link_top = NAN; };
// Over all runs: the worst Eq. (9) balance, the smallest impact-curve slope, steady states.
struct Totals { double worst_balance = 0, min_slope = INFINITY; int steady = 0; };

// One k_N of Fig. 6: both starts against e_N, with outcomes, Eq. (9) and the construction.
KColumns table_k(Result& r, const BistablePipeSpec& b, const PipeSpec& base, std::size_t ki, const std::string& kt,
                 const std::vector<RunResult>& results, Totals& tot) {
    const auto& es = b.eN_list;
    KColumns c;
    for (std::size_t ei = 0; ei < es.size(); ++ei)
        for (int f = 0; f < 2; ++f) {
            const RunResult& rr = results[(ki * es.size() + ei) * 2 + std::size_t(f)];
            const bool ok = rr.outcome == kSteady;
            const double bal = ok ? rr.ndot * rr.dvy / base.geo.gravity : NAN;
            const Construction cons = construct(base, b.kN_list[ki], es[ei], rr);
            if (f == 0 && ei + 1 == es.size()) c.link_top = cons.link;
            const double row[kColumns] = {ok ? -rr.v_mean : NAN, -rr.v_final, double(rr.outcome),
                                          ok ? rr.t_steady : rr.t_final, bal, ok ? rr.sigma_vx : NAN,
                                          ok ? rr.ndot : NAN, ok ? rr.dvy : NAN, cons.v, cons.slope, cons.contacts,
                                          ok ? rr.vy_in : NAN, cons.v_vxin, cons.reach,
                                          double(rr.list_builds) / double(std::max(1L, rr.steps)), ok ? rr.xi_steady : NAN,
                                          ok ? rr.phi_wall : NAN};
            for (int j = 0; j < kColumns; ++j) c.col[f][j].push_back(row[j]);
            if (ok) {
                ++tot.steady;
                tot.worst_balance = std::max(tot.worst_balance, std::abs(bal - 1));
                if (std::isfinite(cons.slope)) tot.min_slope = std::min(tot.min_slope, cons.slope);
            }
        }
    Table& t = r.table("steady_" + kt, "steady-state mean velocity against e_N (NaN: no steady state)");
    t.add("e_N", "1").values = es;
    const char* names[kColumns] = {"v", "v_last", "outcome", "t_end", "eq9_balance", "sigma_vx", "ndot", "dvy",
                                   "v_construction", "impact_slope", "impact_contacts", "vy_impact",
                                   "v_construction_vxin", "construction_reach", "list_builds_per_step", "xi_max_steady",
                                   "phi_wall"};
    const char* units[kColumns] = {"m/s", "m/s", "1", "s", "1", "m/s", "1/s", "m/s", "m/s", "s", "1", "m/s", "m/s", "1", "1", "1", "1"};
    for (int f = 0; f < 2; ++f)
        for (int j = 0; j < kColumns; ++j) t.add(std::string(names[j]) + (f ? "_fast" : "_slow"), units[j]).values = c.col[f][j];
    return c;
}

// The steady states of one k_N against v_crit(k_N): the slow branch (normal regime, below v_crit),
// the fast one, and where both coexist (bistability).
void report_states_k(Result& r, const std::vector<double>& es, const std::string& kt, const KColumns& c, double v_crit) {
    const auto &slow = c.col[0], &fast = c.col[1];
    // A slow start that settles above v_crit has joined the fast branch and does not count.
    double e_lowest_slow = NAN;
    int fast_steady = 0;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        if (slow[kV][ei] < v_crit) e_lowest_slow = std::isnan(e_lowest_slow) ? es[ei] : std::min(e_lowest_slow, es[ei]);
        // A fast start that falls back to the slow branch is not a state of the fast branch.
        fast_steady += fast[kOutcome][ei] == double(kSteady) && fast[kV][ei] >= v_crit;
    }
    r.scalar("impact_link_top_" + kt, c.link_top, "1",
             "slow start at the largest e_N: Δv_y of the wall's impact curve at the measured mean impact velocities "
             "over the measured Δv_y per wall impact");
    r.scalar("slow_branch_lowest_eN_" + kt, e_lowest_slow, "1",
             "smallest e_N whose slow start reached a steady state in the normal regime (below v_crit)");
    r.scalar("fast_branch_fraction_" + kt, double(fast_steady) / double(es.size()), "1",
             "fraction of e_N values whose fast start reached a steady state above v_crit (the fast branch)");
    r.scalar("v_slow_top_" + kt, slow[kV].back(), "m/s", "steady speed of the slow start at the largest e_N");
    r.scalar("v_fast_top_" + kt, fast[kV].back(), "m/s", "steady speed of the fast start at the largest e_N");
    // Bistability: at the e_N > 0.85 of the grid, the slow start reaches a steady state in the
    // normal regime (below v_crit) and the fast start one above it: two coexisting steady states.
    int bistable = 0, above_085 = 0;
    double sx_ratio = NAN;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        if (!(es[ei] > 0.85)) continue;
        ++above_085;
        if (!(slow[kV][ei] < v_crit && fast[kV][ei] >= v_crit)) continue; // NaN compares false
        ++bistable;
        sx_ratio = fast[kSigmaVx][ei] / slow[kSigmaVx][ei];
    }
    r.scalar("bistable_fraction_" + kt, above_085 ? double(bistable) / above_085 : NAN, "1",
             "fraction of the e_N > 0.85 of the grid where a slow (below v_crit) and a fast (above) steady state coexist");
    r.scalar("bistable_sigma_vx_ratio_" + kt, sx_ratio, "1", "σ_vx of the fast over the slow state at the largest bistable e_N");
    r.scalar("normal_branch_top_" + kt, slow[kV].back() < v_crit ? 1.0 : 0.0, "1",
             "1 if the slow start at the largest e_N reaches a steady state below v_crit = v_crit_2000 sqrt(k_N/2000 N/m)");
    r.scalar("bistable_eN_count_" + kt, bistable, "1",
             "e_N > 0.85 of the grid at which a slow (below v_crit) and a fast (above) steady state coexist");
}

// One regime of a k_N: states faster than v_crit(k_N) (Fig. 3's maximum, scaled with sqrt(k_N) by
// Eq. 8) are the fast branch whichever start reached them. Fig. 5 says the fast branch is the
// emergency brake (>= 2 wall grains per impact), the slow one the normal regime. And the paper's
// construction against the measured speed.
void report_branch_k(Result& r, const std::vector<double>& es, const std::string& kt, const KColumns& c, double v_crit,
                     bool fast_branch) {
    double contacts = 0, ratio = 0, ratio_in = 0, reach = 0;
    int nc = 0, nr = 0, nr_in = 0, nreach = 0;
    std::vector<double> v_ln_e; // fast branch: v |ln e_N| per state
    for (const auto& col : c.col)
        for (std::size_t ei = 0; ei < es.size(); ++ei) {
            const double v = col[kV][ei];
            if (std::isnan(v) || (v > v_crit) != fast_branch) continue;
            if (std::isfinite(col[kContacts][ei])) { contacts += col[kContacts][ei]; ++nc; }
            if (std::isfinite(col[kVConstruction][ei])) { ratio += std::log(col[kVConstruction][ei] / v); ++nr; }
            if (std::isfinite(col[kVConstructionVxin][ei])) { ratio_in += std::log(col[kVConstructionVxin][ei] / v); ++nr_in; }
            if (std::isfinite(col[kReach][ei])) { reach += std::log(col[kReach][ei]); ++nreach; }
            if (fast_branch) v_ln_e.push_back(v * std::abs(std::log(es[ei])));
        }
    const std::string name = fast_branch ? "fast" : "slow";
    if (fast_branch) {
        // The fast branch's speed against 1/|ln e_N| ∝ 1/gamma_N: how much of its braking is the
        // dashpot's speed-independent friction impulse (brake-failure's high_v_plateau).
        double mean = 0, sd = 0;
        for (double x : v_ln_e) mean += x / double(v_ln_e.size());
        for (double x : v_ln_e) sd += (x - mean) * (x - mean) / double(std::max<std::size_t>(1, v_ln_e.size() - 1));
        r.scalar("fast_branch_v_ln_eN_" + kt, v_ln_e.empty() ? NAN : mean, "m/s",
                 "mean of v |ln e_N| over the fast branch's states (constant if v ∝ 1/gamma_N)");
        r.scalar("fast_branch_v_ln_eN_cv_" + kt, v_ln_e.size() > 1 ? std::sqrt(sd) / mean : NAN, "1",
                 "its coefficient of variation over the states");
    }
    r.scalar(name + "_branch_states_" + kt, nc, "1", "steady states on the " + name + " branch (either start)");
    r.scalar(name + "_branch_contacts_" + kt, nc ? contacts / nc : NAN, "1",
             "mean wall grains touched per impact at the measured impact velocities, " + name + " branch");
    r.scalar(name + "_branch_construction_ratio_" + kt, nr ? std::exp(ratio / nr) : NAN, "1",
             "geometric mean of the construction's speed (v_x^i = σ_vx) over the measured one, " + name +
                 " branch; NaN if no state has a stable intersection");
    r.scalar(name + "_branch_construction_found_" + kt, nc ? double(nr) / nc : NAN, "1",
             "fraction of the " + name + " branch's states for which the construction (v_x^i = σ_vx) finds a "
             "stable intersection within 0.1-3 times the measured speed");
    r.scalar(name + "_branch_construction_ratio_vxin_" + kt, nr_in ? std::exp(ratio_in / nr_in) : NAN, "1",
             "the same with v_x^i = the measured mean |v_x| of the wall impacts, " + name + " branch");
    r.scalar(name + "_branch_construction_reach_" + kt, nreach ? std::exp(reach / nreach) : NAN, "1",
             "geometric mean over the states of max Δv_y(v_y^i; v_x^i = σ_vx) / (g/ṅ): below 1 the paper's "
             "association gives no intersection, " + name + " branch");
}

// Fig. 6 over every k_N, and what the paper says across them.
// "If the flow ... becomes higher than v_crit, the system will accelerate to the emergency-brake
// steady state" (Summary): of the runs of one k_N whose mean speed ever exceeded v_crit, the
// fraction that ended above it (a fast steady state, or still faster than v_crit at the end).
void report_vcrit_crossings_k(Result& r, const std::string& kt, std::vector<RunResult>::const_iterator runs,
                              std::size_t count, double v_crit) {
    int crossed = 0, ended_fast = 0;
    for (std::size_t j = 0; j < count; ++j) {
        const RunResult& rr = runs[long(j)];
        // "Becomes faster": starts below v_crit (a fast start begins above it and may only fall back).
        if (rr.v.empty() || -rr.v.front() > v_crit || -*std::min_element(rr.v.begin(), rr.v.end()) <= v_crit) continue;
        ++crossed;
        ended_fast += (rr.outcome == kSteady ? -rr.v_mean : -rr.v_final) > v_crit;
    }
    r.scalar("vcrit_crossings_" + kt, crossed, "1", "runs that started below v_crit and whose mean speed exceeded it at some sample");
    r.scalar("vcrit_crossings_end_fast_" + kt, crossed ? double(ended_fast) / crossed : NAN, "1",
             "fraction of those runs that ended above v_crit (fast steady state, or faster than v_crit at the end)");
}

// Eq. (9)'s argument: the volume fraction near the wall is "essentially a constant for fixed global
// volume fraction". Over every steady state (all k_N, both starts, one global phi): its spread.
void report_near_wall_phi(Result& r, const std::vector<RunResult>& results) {
    std::vector<double> pw;
    for (const RunResult& rr : results)
        if (rr.outcome == kSteady && std::isfinite(rr.phi_wall)) pw.push_back(rr.phi_wall);
    const auto [lo, hi] = std::minmax_element(pw.begin(), pw.end());
    const double mean = pw.empty() ? NAN : std::accumulate(pw.begin(), pw.end(), 0.0) / double(pw.size());
    r.scalar("near_wall_phi_mean", mean, "1", "mean area fraction of the layer one diameter inside the wall crests, steady states");
    r.scalar("near_wall_phi_spread", pw.size() >= 2 ? (*hi - *lo) / mean : NAN, "1",
             "(largest - smallest) / mean of that near-wall area fraction over the steady states");
}

void report_fig6(Result& r, const BistablePipeSpec& b, const PipeSpec& base, const std::vector<RunResult>& results) {
    const auto &ks = b.kN_list, &es = b.eN_list;
    Totals tot;
    for (std::size_t ki = 0; ki < ks.size(); ++ki) { // one row of the figure
        const std::string kt = "k" + number_text(ks[ki]);
        const KColumns c = table_k(r, b, base, ki, kt, results, tot);
        const double vc = v_crit(b, ks[ki]);
        report_states_k(r, es, kt, c, vc);
        for (bool fast : {false, true}) report_branch_k(r, es, kt, c, vc, fast);
        report_vcrit_crossings_k(r, kt, results.begin() + long(ki * es.size() * 2), es.size() * 2, vc);
        double xi = 0;
        for (std::size_t j = 0; j < es.size() * 2; ++j) xi = std::max(xi, results[ki * es.size() * 2 + j].xi_max);
        r.scalar("xi_max_over_d_" + kt, xi, "1",
                 "largest overlap of any contact over all runs at this k_N, over the smaller diameter (Eq. 4's xi_max)");
        double xs = NAN;
        for (std::size_t j = 0; j < es.size() * 2; ++j)
            if (const double x = results[ki * es.size() * 2 + j].xi_steady; std::isfinite(x)) xs = std::isnan(xs) ? x : std::max(xs, x);
        r.scalar("xi_max_steady_over_d_" + kt, xs, "1", "the same over the steady states only (NaN: none)");
    }
    report_near_wall_phi(r, results);
    r.scalar("steady_runs", tot.steady, "1", "runs that reached a steady state");
    // Softer grains brake earlier: the k_N = 200 fast branch against the k_N = 2000 one at the same
    // e_N (geometric mean of the speed ratio over the e_N where both fast starts settled above v_crit).
    const auto k_lo = std::find(ks.begin(), ks.end(), 200.0), k_mid = std::find(ks.begin(), ks.end(), 2000.0);
    if (k_lo != ks.end() && k_mid != ks.end()) {
        const std::size_t lo_i = std::size_t(k_lo - ks.begin()), mid_i = std::size_t(k_mid - ks.begin());
        double lr = 0;
        int nr = 0;
        for (std::size_t ei = 0; ei < es.size(); ++ei) {
            const RunResult& lo = results[(lo_i * es.size() + ei) * 2 + 1];
            const RunResult& mid = results[(mid_i * es.size() + ei) * 2 + 1];
            // Fast-branch states only: a fast start that fell back to the slow branch is not one.
            if (lo.outcome != kSteady || mid.outcome != kSteady || -lo.v_mean < v_crit(b, 200.0) ||
                -mid.v_mean < v_crit(b, 2000.0))
                continue;
            lr += std::log(lo.v_mean / mid.v_mean);
            ++nr;
        }
        r.scalar("fast_branch_k200_over_k2000", nr ? std::exp(lr / nr) : NAN, "1",
                 "geometric mean of v_fast(k_N = 200) / v_fast(k_N = 2000) over the e_N where both settled on the fast branch");
    }
    r.scalar("eq9_worst_deviation", tot.steady ? tot.worst_balance : NAN, "1", "largest |ṅ Δv_y / g - 1| over steady runs (Eq. 9)");
    r.scalar("impact_slope_min", std::isfinite(tot.min_slope) ? tot.min_slope : NAN, "s",
             "smallest slope dΔv_y/dv of the impact curve at a steady state's speed (Eq. 9 argument: > 0)");
    if (b.length_check > 0) {
        const RunResult& at_length = results[((ks.size() > 1 ? 1 : 0) * es.size() + es.size() - 1) * 2];
        const RunResult& at_check = results.back();
        r.scalar("length_check_ratio", (at_length.outcome == kSteady && at_check.outcome == kSteady) ? at_check.v_mean / at_length.v_mean : NAN, "1",
                 "steady speed at length_check over that at length (same k_N, e_N, slow start)");
    }
}

// The crude estimates below Eq. (9), over windows of every run: ṅ ∝ σ_vx, and ṅ Δv_y grows
// about quadratically with Δv_y.
void report_eq9_windows(Result& r, const std::vector<Task>& tasks, const std::vector<RunResult>& results) {
    std::vector<double> wk, wn, wd, ws, wv, lx, ly, ld, lnd; // every window; those for the power-law fits
    for (std::size_t i = 0; i < tasks.size(); ++i)
        for (std::size_t j = 0; j < results[i].w_ndot.size(); ++j) {
            const double n = results[i].w_ndot[j], d = results[i].w_dvy[j], sx = results[i].w_sx[j];
            wk.push_back(tasks[i].k);
            wn.push_back(n);
            wd.push_back(d);
            ws.push_back(sx);
            wv.push_back(results[i].w_v[j]);
            if (n > 0 && sx > 0 && d > 0) {
                lx.push_back(sx);
                ly.push_back(n);
                ld.push_back(d);
                lnd.push_back(n * d);
            }
        }
    Table& tw = r.table("eq9_windows", "ṅ, Δv_y, σ_vx and speed over windows of eq9_window, every run");
    tw.add({{"k_N", "N/m", wk}, {"ndot", "1/s", wn}, {"dvy", "m/s", wd}, {"sigma_vx", "m/s", ws}, {"v", "m/s", wv}});
    const auto a = lx.size() >= 10 ? fit_power_law(lx, ly, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    const auto c = ld.size() >= 10 ? fit_power_law(ld, lnd, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    const auto sd = ld.size() >= 10 ? fit_power_law(ld, lx, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    r.scalar("ndot_vs_sigma_vx_exponent", a.exponent, "1", "exponent of ṅ ∝ σ_vx^a over all windows");
    r.scalar("ndot_dvy_vs_dvy_exponent", c.exponent, "1", "exponent of ṅ Δv_y ∝ Δv_y^b over all windows");
    r.scalar("sigma_vx_vs_dvy_exponent", sd.exponent, "1", "exponent of σ_vx ∝ Δv_y^c over all windows");
    r.scalar("eq9_windows", double(lx.size()), "1", "windows in those fits");
}

void report_series(Result& r, const BistablePipeSpec& b, const std::vector<Task>& tasks, const std::vector<RunResult>& results) {
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const bool length_check = b.length_check > 0 && i + 1 == tasks.size();
        const std::string name = "series_k" + number_text(tasks[i].k) + "_e" + number_text(tasks[i].e) +
                                 (tasks[i].fast ? "_fast" : "_slow") + (length_check ? "_length_check" : "");
        Table& ts = r.table(name, "mean velocity and rms v_x against time");
        ts.add("t", "s").values = results[i].t;
        std::vector<double> speed(results[i].v.size());
        for (std::size_t j = 0; j < speed.size(); ++j) speed[j] = -results[i].v[j];
        ts.add({{"v_down", "m/s", speed}, {"sigma_vx", "m/s", results[i].sx}});
    }
}

// Fig. 6 as a protocol (harness/protocol.hpp): one sweep point per pipe run (Task).
struct BistablePipe {
    static constexpr const char* name = "bistable-pipe";
    using Spec = BistablePipeSpec;
    using Outcome = RunResult;
    using Shared = std::vector<Task>;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static std::vector<Task> prepare(const Spec& b, const RunContext&) { return make_tasks(b); }
    // Every budget is the same number of time steps, but runs that settle stop early: start the
    // likely long ones first (fast starts, then nearly elastic grains, then longer pipes), so that
    // the last point to start is a short one.
    static std::vector<long> points(const Spec&, const std::vector<Task>& tasks) {
        std::vector<long> order(tasks.size());
        std::iota(order.begin(), order.end(), 0L);
        auto key = [&](long i) {
            const Task& t = tasks[std::size_t(i)];
            return std::make_tuple(t.fast, t.length, t.e, t.k);
        };
        std::stable_sort(order.begin(), order.end(), [&](long x, long y) { return key(x) > key(y); });
        return order;
    }
    // Each point's random stream is its grid index.
    static RunResult compute(const Spec& b, const std::vector<Task>& tasks, long i, const PointContext& ctx) {
        const Task& t = tasks[std::size_t(i)];
        PipeSpec s = pipe_spec(b, ctx.seed);
        s.k_N = t.k;
        s.e_N = t.e;
        s.geo.length = std::round(t.length / s.geo.wall_spacing) * s.geo.wall_spacing;
        s.v0 = t.fast ? b.fast_v0 : b.slow_v0;
        s.agitation = std::min(b.agitation, b.agitation_vcrit * v_crit(b, t.k));
        s.stream = std::uint64_t(i);
        return run_pipe(s, time_budget(b, t.k, t.e), b.eq9_window, b.hold_distance);
    }
    static Result report(const Spec& b, const std::vector<Task>& tasks, const Swept<RunResult>& swept, const RunContext& ctx) {
        const std::vector<RunResult>& results = swept.outcomes;
        Result r;
        r.scalar("resumed_points", double(swept.resumed), "1", "sweep points loaded from a checkpoint");
        // The paper's t_col at k_N = 200000 N/m refers to e_N = 0.70 (gamma scaled with sqrt(k_N)).
        r.scalar("t_col_k200000_e0.70", pipe_law(200000.0, 0.70, b.m_mean).collision_time(b.m_mean), "s",
                 "free-wall contact duration at k_N = 2e5 N/m, e_N = 0.70 (Eq. 4)");
        report_fig6(r, b, pipe_spec(b, ctx.seed), results);
        report_eq9_windows(r, tasks, results);
        report_series(r, b, tasks, results);
        r.scalar("grains", double(results.front().grains), "1", "free grains in the pipe (first run)");
        return r;
    }
};

} // namespace

Experiment bistable_pipe() { return protocol_experiment<BistablePipe>(); }

} // namespace granrepro::experiments
