// bistable-pipe (Fig. 6): a pipe run of one sweep point, and the impact shots of the paper's
// construction (Eq. 9) that a Fig. 6 point adds to its outcome.
#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <numeric>
#include <optional>

#include "analysis/curve_analysis.hpp"
#include "engines/soft/pipe_engine.hpp"
#include "experiments/bistable_pipe/spec.hpp"
#include "harness/sampled_run.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"
#include "scenarios/impact_shot.hpp"

namespace granrepro::experiments::bistable_pipe_detail {

PipeSpec pipe_spec(const BistablePipeSpec& b, std::uint64_t seed) {
    return {.geo = {.width = b.width, .length = std::round(b.length / b.wall_spacing) * b.wall_spacing,
                    .wall_radius = 0.5 * b.d_wall, .wall_spacing = b.wall_spacing, .gravity = b.g},
            .d_mean = b.d_mean, .polydispersity = b.polydispersity, .m_mean = b.m_mean, .phi = b.phi, .mu = b.mu,
            .friction_normal = *parse_friction_normal(b.friction_normal), .agitation = b.agitation,
            .steps_per_contact = b.steps_per_contact, .skin = b.skin, .window = b.window, .drift_tol = b.drift_tol,
            .t_average = b.t_average, .sample_dt = b.sample_dt, .v_abort = b.v_abort,
            .wall_steps = b.time_step == "wall" ? b.wall_steps : 0.0, .seed = seed};
}

namespace {

using Engine = PipeEngine<LinearSpringDashpot, CoulombShear>;

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

// The pipe engine takes steps; SampledRun asks for run_until. Like a step loop that tests the
// budget before each step, and ends a stretch at the first step that comes within half a step of
// t; the observer sees every step.
struct BudgetedSteps {
    Engine& eng;
    double budget; // [s]
    template <class OnStep>
    void run_until(double t, OnStep&& on_step) {
        while (eng.time() < budget) {
            eng.step();
            on_step();
            if (eng.time() + 0.5 * eng.dt() >= t) return;
        }
    }
};

} // namespace

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
    const double dt_eq5 = eng.dt();
    r.dt_min = dt_eq5;
    auto sample = [&](long, double) {
        if (eng.time() + 0.5 * eng.dt() < next) return true; // the budget ran out first
        r.xq.push_back(xi);
        r.xi_max = std::max(r.xi_max, xi);
        xi = 0;
        next += s.sample_dt;
        double v = 0, sx = 0, near = 0, v2max = 0;
        for (std::size_t i = 0; i < n; ++i) {
            v += eng.vy()[i];
            sx += eng.vx()[i] * eng.vx()[i];
            v2max = std::max(v2max, eng.vx()[i] * eng.vx()[i] + eng.vy()[i] * eng.vy()[i]);
            const double x = eng.x()[i], rad = eng.radius()[i];
            if (x < layer_in || x > s.geo.width - layer_in) near += M_PI * rad * rad;
        }
        r.pw.push_back(near / layer_area);
        r.t.push_back(eng.time());
        r.v.push_back(v / double(n));
        r.sx.push_back(std::sqrt(sx / double(n)));
        walls.take(eng);
        // The step of the next samples (time_step = "wall"): Eq. (5) resolves a head-on contact but
        // not a grain sliding past the wall grains at 100 m/s and more, which touches each for
        // only one or two steps of t_col/50; the fast states then lock where one wall period
        // takes a whole number of steps (issue 42). S steps per wall-grain passage of the fastest
        // grain resolve it (scripts/studies/bistable_pipe_dt.md).
        if (s.wall_steps > 0) {
            eng.set_dt(std::min(dt_eq5, s.geo.wall_spacing / (s.wall_steps * std::max(std::sqrt(v2max), 1e-300))));
            r.dt_min = std::min(r.dt_min, eng.dt());
        }
        if (std::abs(r.v.back()) > s.v_abort) return true;
        const std::size_t m = r.t.size();
        if (m <= per_window) return false;
        const double drift = slope(r.t, r.v, m - per_window);
        // A plug in free fall: accelerating at g and not one wall impact over the window.
        if (std::abs(drift + s.geo.gravity) < s.drift_tol && walls.sum(m - per_window, m).impacts == 0) {
            free_fall = true;
            return true;
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
            if (m - from >= 3 && std::abs(slope(r.t, r.v, from)) < s.drift_tol) return true;
            steady_since = NAN;
        }
        return false;
    };
    BudgetedSteps steps{eng, t_budget};
    SampledRun<>().run(steps, [&](long) { return std::optional(next); }, [&] { xi = std::max(xi, eng.max_overlap_ratio()); },
                       sample, t_budget);
    const std::size_t m = r.t.size();
    r.steps = eng.steps();
    r.list_builds = eng.list_builds();
    r.dt_final = eng.dt();
    r.v_final = r.v.back();
    r.t_final = r.t.back();
    r.accel_final = m > per_window ? slope(r.t, r.v, m - per_window) : NAN;
    const bool steady = !std::isnan(steady_since) && eng.time() >= steady_since + hold - 1e-12;
    r.outcome = steady ? kSteady : (free_fall || r.accel_final < -(s.geo.gravity - s.drift_tol)) ? kFreeFall : kUnsettled;
    if (steady) steady_means(r, walls, steady_since, s.sample_dt, n);
    eq9_windows(r, walls, eq9_window, s.sample_dt, n);
    return r;
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

} // namespace granrepro::experiments::bistable_pipe_detail
