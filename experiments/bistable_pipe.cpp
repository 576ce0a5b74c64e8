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
#include "core/rng_stream.hpp"
#include "engines/soft/pipe_engine.hpp"
#include "scenarios/impact_shot.hpp"
#include "scenarios/pipe_setup.hpp"
#include "experiments/work_limits.hpp"
#include "harness/experiment.hpp"
#include "harness/distributed_sweep.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

using Engine = PipeEngine<LinearSpringDashpot, CoulombShear>;

enum Outcome { kSteady = 0, kFreeFall = 1, kUnsettled = 2 };

struct RunResult {
    int outcome = kUnsettled;
    double t_steady = NAN, v_mean = NAN, v_std = NAN, v_final = NAN, t_final = NAN, accel_final = NAN;
    double sigma_vx = NAN, ndot = NAN, dvy = NAN, vx_in = NAN, vy_in = NAN, dt = NAN;
    long grains = 0;
    std::vector<double> t, v, sx;        // samples: time [s], mean v_y [m/s], rms v_x [m/s]
    std::vector<double> w_ndot, w_dvy, w_sx, w_v; // windows (Eq. 9 estimates): ṅ, Δv_y, σ_vx, v

    nlohmann::json to_json() const {
        return {{"outcome", outcome}, {"t_steady", t_steady}, {"v_mean", v_mean}, {"v_std", v_std},
                {"v_final", v_final}, {"t_final", t_final}, {"accel_final", accel_final},
                {"sigma_vx", sigma_vx}, {"ndot", ndot}, {"dvy", dvy}, {"vx_in", vx_in}, {"vy_in", vy_in},
                {"dt", dt}, {"grains", grains}, {"t", t}, {"v", v}, {"sx", sx}, {"w_ndot", w_ndot},
                {"w_dvy", w_dvy}, {"w_sx", w_sx}, {"w_v", w_v}};
    }
    static RunResult from_json(const nlohmann::json& j) {
        RunResult r;
        auto num = [&](const char* k) { return j.at(k).is_null() ? NAN : j.at(k).get<double>(); };
        auto vec = [&](const char* k) {
            std::vector<double> out;
            for (const auto& x : j.at(k)) out.push_back(x.is_null() ? NAN : x.get<double>());
            return out;
        };
        r.outcome = j.at("outcome");
        r.t_steady = num("t_steady"); r.v_mean = num("v_mean"); r.v_std = num("v_std");
        r.v_final = num("v_final"); r.t_final = num("t_final"); r.accel_final = num("accel_final");
        r.sigma_vx = num("sigma_vx"); r.ndot = num("ndot"); r.dvy = num("dvy");
        r.vx_in = num("vx_in"); r.vy_in = num("vy_in"); r.dt = num("dt");
        r.grains = j.at("grains");
        r.t = vec("t"); r.v = vec("v"); r.sx = vec("sx");
        r.w_ndot = vec("w_ndot"); r.w_dvy = vec("w_dvy"); r.w_sx = vec("w_sx"); r.w_v = vec("w_v");
        return r;
    }
};

double slope(const std::vector<double>& t, const std::vector<double>& v, std::size_t from) {
    double c0, c1, c00, c01, c11, ss;
    gsl_fit_linear(t.data() + from, 1, v.data() + from, 1, t.size() - from, &c0, &c1, &c00, &c01, &c11, &ss);
    return c1;
}

// Wall impacts per sample interval, so that any span of samples can be summed.
struct WallSamples {
    std::vector<long> impacts, completed;
    std::vector<double> sum_dvy, sum_vx, sum_vy;
    void take(Engine& eng) {
        const WallImpactStats& w = eng.wall_stats();
        impacts.push_back(w.impacts);
        completed.push_back(w.completed);
        sum_dvy.push_back(w.sum_dvy);
        sum_vx.push_back(w.sum_vx_in);
        sum_vy.push_back(w.sum_vy_in);
        eng.reset_wall_stats();
    }
    long impacts_in(std::size_t from, std::size_t to) const {
        return std::accumulate(impacts.begin() + long(from), impacts.begin() + long(to), 0L);
    }
};

// Runs one start until it is steady, falls freely, passes v_abort or exhausts its budget. Steady:
// over the trailing window the fitted slope of the mean velocity is below drift_tol [m/s^2] (braking
// balances gravity to that accuracy) and stays below it over the following averaging window.
RunResult run_pipe(const PipeSpec& s, double t_budget, double eq9_window) {
    Engine eng = build_pipe(s);
    RunResult r;
    r.dt = eng.dt();
    r.grains = long(eng.size());
    const std::size_t n = eng.size();
    const std::size_t per_window = std::size_t(std::max(3.0, std::round(s.window / s.sample_dt)));
    WallSamples walls;
    double steady_since = NAN;
    double next = s.sample_dt;
    bool free_fall = false;
    while (eng.time() < t_budget) {
        eng.step();
        if (eng.time() + 0.5 * eng.dt() < next) continue;
        next += s.sample_dt;
        double v = 0, sx = 0;
        for (std::size_t i = 0; i < n; ++i) {
            v += eng.vy()[i];
            sx += eng.vx()[i] * eng.vx()[i];
        }
        r.t.push_back(eng.time());
        r.v.push_back(v / double(n));
        r.sx.push_back(std::sqrt(sx / double(n)));
        walls.take(eng);
        if (std::abs(r.v.back()) > s.v_abort) break;
        const std::size_t m = r.t.size();
        if (m <= per_window) continue;
        const double drift = slope(r.t, r.v, m - per_window);
        // A plug in free fall: accelerating at g and not one wall impact over the window.
        if (std::abs(drift + s.geo.gravity) < s.drift_tol && walls.impacts_in(m - per_window, m) == 0) {
            free_fall = true;
            break;
        }
        if (std::isnan(steady_since)) {
            if (std::abs(drift) < s.drift_tol) steady_since = eng.time();
        } else if (eng.time() >= steady_since + s.t_average) {
            // Confirm over the averaging window itself: a plateau that happened to fill the
            // detection window but keeps drifting afterwards is not a steady state; search on.
            std::size_t from = 0;
            while (from < m && r.t[from] <= steady_since) ++from;
            if (m - from >= 3 && std::abs(slope(r.t, r.v, from)) < s.drift_tol) break;
            steady_since = NAN;
        }
    }
    const std::size_t m = r.t.size();
    r.v_final = r.v.back();
    r.t_final = r.t.back();
    r.accel_final = m > per_window ? slope(r.t, r.v, m - per_window) : NAN;
    const bool steady = !std::isnan(steady_since) && eng.time() >= steady_since + s.t_average - 1e-12;
    r.outcome = steady ? kSteady : (free_fall || r.accel_final < -(s.geo.gravity - s.drift_tol)) ? kFreeFall : kUnsettled;
    if (steady) {
        r.t_steady = steady_since;
        double sum = 0, sum2 = 0, sxs = 0, ws = 0, vxs = 0, vys = 0;
        long k = 0, impacts = 0, completed = 0;
        for (std::size_t i = 0; i < m; ++i)
            if (r.t[i] > steady_since) {
                sum += r.v[i];
                sum2 += r.v[i] * r.v[i];
                sxs += r.sx[i];
                impacts += walls.impacts[i];
                completed += walls.completed[i];
                ws += walls.sum_dvy[i];
                vxs += walls.sum_vx[i];
                vys += walls.sum_vy[i];
                ++k;
            }
        r.v_mean = sum / double(k);
        r.v_std = std::sqrt(std::max(0.0, sum2 / double(k) - r.v_mean * r.v_mean));
        r.sigma_vx = sxs / double(k);
        r.ndot = double(impacts) / (double(k) * s.sample_dt * double(n));
        if (completed > 0) {
            r.dvy = ws / double(completed);
            r.vx_in = vxs / double(completed);
            r.vy_in = vys / double(completed);
        }
    }
    // Windows of eq9_window for the estimates below Eq. (9), skipping the first (the start).
    const std::size_t per = std::size_t(std::max(1.0, std::round(eq9_window / s.sample_dt)));
    for (std::size_t a = per; a + per <= m; a += per) {
        long imp = 0, comp = 0;
        double dv = 0, sx = 0, v = 0;
        for (std::size_t i = a; i < a + per; ++i) {
            imp += walls.impacts[i];
            comp += walls.completed[i];
            dv += walls.sum_dvy[i];
            sx += r.sx[i];
            v += r.v[i];
        }
        if (comp < 20) continue; // too few impacts for a mean Δv_y
        r.w_ndot.push_back(double(imp) / (double(per) * s.sample_dt * double(n)));
        r.w_dvy.push_back(dv / double(comp));
        r.w_sx.push_back(sx / double(per));
        r.w_v.push_back(-v / double(per));
    }
    return r;
}

PipeSpec base_spec(const ParameterSet& p, std::uint64_t seed) {
    PipeSpec s{};
    s.geo.width = p.real("width");
    s.geo.wall_radius = 0.5 * p.real("d_wall");
    s.geo.wall_spacing = p.real("wall_spacing");
    s.geo.length = std::round(p.real("length") / s.geo.wall_spacing) * s.geo.wall_spacing;
    s.geo.gravity = p.real("g");
    s.d_mean = p.real("d_mean");
    s.polydispersity = p.real("polydispersity");
    s.m_mean = p.real("m_mean");
    s.phi = p.real("phi");
    s.mu = p.real("mu");
    s.friction_normal = *parse_friction_normal(p.text("friction_normal"));
    s.steps_per_contact = p.real("steps_per_contact");
    s.skin = p.real("skin");
    s.window = p.real("window");
    s.drift_tol = p.real("drift_tol");
    s.t_average = p.real("t_average");
    s.sample_dt = p.real("sample_dt");
    s.v_abort = p.real("v_abort");
    s.agitation = p.real("agitation");
    s.seed = seed;
    return s;
}

// The run's time budget: budget_tcol free-wall contact durations (Eq. 4) at its own k_N, e_N.
double time_budget(const ParameterSet& p, double k, double e) {
    const double m = p.real("m_mean");
    return p.real("budget_tcol") * pipe_law(k, e, m).collision_time(m);
}

void validate(const ParameterSet& p) {
    for (double e : p.reals("eN_list"))
        if (!(e > 0 && e < 1)) p.reject("eN_list", "each e_N must be in (0, 1): e_N = 1 has no dashpot and Eq. (4) no solution");
    for (double k : p.reals("kN_list"))
        for (double e : p.reals("eN_list"))
            if (time_budget(p, k, e) < p.real("window") + p.real("t_average"))
                p.reject("budget_tcol", "the budget of k_N = " + number_text(k) + " N/m, e_N = " + number_text(e) +
                                            " is shorter than window + t_average: no steady state could be detected");
    {
        // The start: phi of the channel as grains on a lattice (phi = 0.79 failed late with "area
        // fraction too high for a lattice start"), then every run's cost in grain-steps.
        PipeSpec s = base_spec(p, 0);
        const std::vector<std::string> geometry{"phi", "width", "length", "wall_spacing", "d_mean", "polydispersity", "d_wall"};
        const long n = pipe_grain_count(s);
        p.limit_work(geometry, double(n), 1e7, "grains");
        if (n < 1) p.reject(geometry, "the channel holds no grain at this area fraction");
        if (!pipe_lattice_fits(s))
            p.reject(geometry, "the " + std::to_string(n) +
                                   " grains do not fit on a triangular lattice of spacing >= d_mean (1 + polydispersity) "
                                   "between the wall crests; lower phi");
        const double d_min = s.d_mean * (1 - s.polydispersity);
        const double m_min = s.m_mean * (d_min / s.d_mean) * (d_min / s.d_mean);
        for (double k : p.reals("kN_list"))
            for (double e : p.reals("eN_list")) {
                // build_pipe's step: the stiffest (lightest free-free) pair, Eq. (5).
                const double dt = pipe_law(k, e, s.m_mean).collision_time(0.5 * m_min) / s.steps_per_contact;
                p.limit_work({"budget_tcol", "steps_per_contact", "kN_list", "eN_list", "phi", "width", "length", "d_mean"},
                             double(n) * time_budget(p, k, e) / dt, kMaxGrainSteps, "grain-steps in one run");
                // One sample per step at most: sample_dt = 1e-300 overflowed window/sample_dt and
                // crashed the drift fit.
                if (!(p.real("sample_dt") >= dt))
                    p.reject(std::vector<std::string>{"sample_dt", "m_mean", "kN_list", "eN_list", "steps_per_contact"},
                             "sample_dt must be at least the time step dt = " + number_text(dt) + " s (k_N = " +
                                 number_text(k) + " N/m, e_N = " + number_text(e) + "): one sample per step");
            }
    }
    if (p.real("wall_spacing") - p.real("d_wall") >= p.real("d_mean") * (1 - p.real("polydispersity")))
        p.reject(std::vector<std::string>{"wall_spacing", "d_wall", "d_mean", "polydispersity"},
                 "the gaps between wall grains (wall_spacing - d_wall) must be narrower than the smallest grain, "
                 "or grains fall through the wall");
    if (p.real("sample_dt") > p.real("window") / 3)
        p.reject("sample_dt", "must be at most window / 3 so that a drift can be fitted");
    if (p.real("eq9_window") < p.real("sample_dt")) p.reject("eq9_window", "must be at least sample_dt");
    const double range = p.real("d_mean") * (1 + p.real("polydispersity")) + p.real("skin");
    if (p.real("length") < 4 * range)
        p.reject(std::vector<std::string>{"length", "d_mean", "polydispersity", "skin"},
                 "length must be at least 4 interaction ranges d_mean (1 + polydispersity) + skin");
    if (p.real("length_check") > 0 && p.real("length_check") < 4 * range)
        p.reject("length_check", "must be 0 (off) or at least 4 interaction ranges");
    if (p.real("wall_spacing") < p.real("d_wall") * (1 - 1e-12))
        p.reject("wall_spacing", "wall grains would overlap; must be at least d_wall");
    if (p.real("width") < 10 * p.real("d_mean")) p.reject("width", "must be at least 10 grain diameters");
}

std::string tag(double k, double e, const char* start) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "k%g_e%g_%s", k, e, start);
    return buf;
}

// Mean Δv_y and wall grains touched of impacts on the pipe's wall row at (v_x^i, v_y^i), over 10
// start positions (Figs. 4, 5).
struct ImpactMean {
    double dvy = 0, contacts = 0;
};
ImpactMean impact_mean(const PipeSpec& base, double k, double e, double vx, double vy) {
    ImpactSetup is;
    is.d_free = base.d_mean;
    is.m_free = base.m_mean;
    is.d_wall = 2 * base.geo.wall_radius;
    is.wall_spacing = base.geo.wall_spacing;
    is.x0 = 0.5 * (is.d_free + is.d_wall);
    is.vx_toward = vx;
    is.vy = vy;
    const LinearSpringDashpot law = pipe_law(k, e, base.m_mean);
    is.dt = law.collision_time(base.m_mean) / base.steps_per_contact;
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

struct Task {
    double k, e;
    bool fast;
    double length;
};

std::vector<Task> make_tasks(const ParameterSet& p) {
    const auto& ks = p.reals("kN_list");
    const auto& es = p.reals("eN_list");
    std::vector<Task> tasks;
    for (double k : ks)
        for (double e : es)
            for (bool fast : {false, true}) tasks.push_back({k, e, fast, p.real("length")});
    // The length check: the second k_N at its largest e_N, slow start, at a second pipe length.
    if (p.real("length_check") > 0) tasks.push_back({ks.size() > 1 ? ks[1] : ks[0], es.back(), false, p.real("length_check")});
    return tasks;
}

std::vector<RunResult> run_sweep(const RunContext& ctx, const std::vector<Task>& tasks, long& resumed) {
    const ParameterSet& p = ctx.params;
    std::vector<RunResult> results(tasks.size());
    // Every budget is the same number of time steps, but runs that settle stop early: start the
    // likely long ones first (fast starts, then nearly elastic grains, then longer pipes), so that
    // the last point to start is a short one. Each point's random stream is its grid index.
    std::vector<long> order(tasks.size());
    std::iota(order.begin(), order.end(), 0L);
    auto key = [&](long i) {
        const Task& t = tasks[std::size_t(i)];
        return std::make_tuple(t.fast, t.length, t.e, t.k);
    };
    std::stable_sort(order.begin(), order.end(), [&](long a, long b) { return key(a) > key(b); });
    const SweepResult swept = distributed_sweep(ctx, "bistable-pipe", order, [&](long i) {
        const Task& t = tasks[std::size_t(i)];
        PipeSpec s = base_spec(p, ctx.seed);
        s.k_N = t.k;
        s.e_N = t.e;
        s.geo.length = std::round(t.length / s.geo.wall_spacing) * s.geo.wall_spacing;
        s.v0 = t.fast ? p.real("fast_v0") : p.real("slow_v0");
        s.stream = std::uint64_t(i);
        return run_pipe(s, time_budget(p, t.k, t.e), p.real("eq9_window")).to_json();
    });
    for (std::size_t i = 0; i < tasks.size(); ++i) results[i] = RunResult::from_json(swept.points[i]);
    resumed = swept.resumed;
    return results;
}

// One row of Fig. 6 per k_N: both starts against e_N, with outcomes, Eq. (9) and the construction.
void report_k(Result& r, const ParameterSet& p, const PipeSpec& base, double k, std::size_t ki,
              const std::vector<RunResult>& results, double& worst_balance, int& steady_count, double& min_slope) {
    const auto& es = p.reals("eN_list");
    char kt[32];
    std::snprintf(kt, sizeof kt, "k%g", k);
    Table& t = r.table(std::string("steady_") + kt, "steady-state mean velocity against e_N (NaN: no steady state)");
    std::vector<double> cols[2][14];
    double e_lowest_slow = NAN, link_top = NAN;
    int fast_steady = 0;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        for (int f = 0; f < 2; ++f) {
            const RunResult& rr = results[(ki * es.size() + ei) * 2 + std::size_t(f)];
            const bool ok = rr.outcome == kSteady;
            const double bal = ok ? rr.ndot * rr.dvy / base.geo.gravity : NAN;
            const Construction c = construct(base, k, es[ei], rr);
            if (f == 0 && ei + 1 == es.size()) link_top = c.link;
            auto& col = cols[f];
            col[0].push_back(ok ? -rr.v_mean : NAN);
            col[1].push_back(-rr.v_final);
            col[2].push_back(rr.outcome);
            col[3].push_back(ok ? rr.t_steady : rr.t_final);
            col[4].push_back(bal);
            col[5].push_back(ok ? rr.sigma_vx : NAN);
            col[6].push_back(ok ? rr.ndot : NAN);
            col[7].push_back(ok ? rr.dvy : NAN);
            col[8].push_back(c.v);
            col[9].push_back(c.slope);
            col[10].push_back(c.contacts);
            col[11].push_back(ok ? rr.vy_in : NAN);
            col[12].push_back(c.v_vxin);
            col[13].push_back(c.reach);
            if (ok) {
                ++steady_count;
                worst_balance = std::max(worst_balance, std::abs(bal - 1));
                if (std::isfinite(c.slope)) min_slope = std::min(min_slope, c.slope);
            }
        }
        // The slow branch is the normal regime: a slow start that settles above v_crit has joined
        // the fast branch and does not count.
        const double v_slow = cols[0][0].back();
        if (v_slow < p.real("v_crit_2000") * std::sqrt(k / 2000.0))
            e_lowest_slow = std::isnan(e_lowest_slow) ? es[ei] : std::min(e_lowest_slow, es[ei]);
        fast_steady += results[(ki * es.size() + ei) * 2 + 1].outcome == kSteady;
    }
    t.add("e_N", "1").values = es;
    const char* names[14] = {"v", "v_last", "outcome", "t_end", "eq9_balance", "sigma_vx", "ndot", "dvy",
                             "v_construction", "impact_slope", "impact_contacts", "vy_impact",
                             "v_construction_vxin", "construction_reach"};
    const char* units[14] = {"m/s", "m/s", "1", "s", "1", "m/s", "1/s", "m/s", "m/s", "s", "1", "m/s", "m/s", "1"};
    for (int f = 0; f < 2; ++f)
        for (int c = 0; c < 14; ++c)
            t.add(std::string(names[c]) + (f ? "_fast" : "_slow"), units[c]).values = cols[f][c];
    r.scalar(std::string("impact_link_top_") + kt, link_top, "1",
             "slow start at the largest e_N: Δv_y of the wall's impact curve at the measured mean impact velocities "
             "over the measured Δv_y per wall impact");
    r.scalar(std::string("slow_branch_lowest_eN_") + kt, e_lowest_slow, "1",
             "smallest e_N whose slow start reached a steady state in the normal regime (below v_crit)");
    r.scalar(std::string("fast_branch_fraction_") + kt, double(fast_steady) / double(es.size()), "1",
             "fraction of e_N values whose fast start reached a steady state");
    r.scalar(std::string("v_slow_top_") + kt, cols[0][0].back(), "m/s", "steady speed of the slow start at the largest e_N");
    r.scalar(std::string("v_fast_top_") + kt, cols[1][0].back(), "m/s", "steady speed of the fast start at the largest e_N");
    // Bistability: at the e_N > 0.85 of the grid, the slow start reaches a steady state in the
    // normal regime (below v_crit) and the fast start one above it: two coexisting steady states.
    const double v_crit = p.real("v_crit_2000") * std::sqrt(k / 2000.0);
    int bistable = 0, above_085 = 0;
    double sx_ratio = NAN;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        if (!(es[ei] > 0.85)) continue;
        ++above_085;
        if (!(cols[0][0][ei] < v_crit && cols[1][0][ei] >= v_crit)) continue; // NaN compares false
        ++bistable;
        sx_ratio = cols[1][5][ei] / cols[0][5][ei];
    }
    r.scalar(std::string("bistable_fraction_") + kt, above_085 ? double(bistable) / above_085 : NAN, "1",
             "fraction of the e_N > 0.85 of the grid where a slow (below v_crit) and a fast (above) steady state coexist");
    r.scalar(std::string("bistable_sigma_vx_ratio_") + kt, sx_ratio, "1",
             "σ_vx of the fast over the slow state at the largest bistable e_N");
    r.scalar(std::string("normal_branch_top_") + kt, cols[0][0].back() < v_crit ? 1.0 : 0.0, "1",
             "1 if the slow start at the largest e_N reaches a steady state below v_crit = v_crit_2000 sqrt(k_N/2000 N/m)");
    // Which regime each branch is in: states faster than v_crit(k_N) (Fig. 3's maximum, scaled
    // with sqrt(k_N) by Eq. 8) are counted as the fast branch whichever start reached them. Fig. 5
    // says the fast branch is the emergency brake (>= 2 wall grains per impact), the slow one the
    // normal regime. And the paper's construction against the measured speed, per branch.
    for (int b = 0; b < 2; ++b) {
        double contacts = 0, ratio = 0, ratio_in = 0, reach = 0;
        int nc = 0, nr = 0, nr_in = 0, nreach = 0;
        for (int f = 0; f < 2; ++f)
            for (std::size_t ei = 0; ei < es.size(); ++ei) {
                const double v = cols[f][0][ei];
                if (std::isnan(v) || (v > v_crit) != (b == 1)) continue;
                if (std::isfinite(cols[f][10][ei])) { contacts += cols[f][10][ei]; ++nc; }
                if (std::isfinite(cols[f][8][ei])) { ratio += std::log(cols[f][8][ei] / v); ++nr; }
                if (std::isfinite(cols[f][12][ei])) { ratio_in += std::log(cols[f][12][ei] / v); ++nr_in; }
                if (std::isfinite(cols[f][13][ei])) { reach += std::log(cols[f][13][ei]); ++nreach; }
            }
        const std::string name = b ? "fast" : "slow";
        if (b == 1) {
            // The fast branch's speed against 1/|ln e_N| ∝ 1/gamma_N: how much of its braking is
            // the dashpot's speed-independent friction impulse (brake-failure's high_v_plateau).
            std::vector<double> a;
            for (int f = 0; f < 2; ++f)
                for (std::size_t ei = 0; ei < es.size(); ++ei)
                    if (cols[f][0][ei] > v_crit) a.push_back(cols[f][0][ei] * std::abs(std::log(es[ei])));
            double mean = 0, sd = 0;
            for (double x : a) mean += x / double(a.size());
            for (double x : a) sd += (x - mean) * (x - mean) / double(std::max<std::size_t>(1, a.size() - 1));
            r.scalar("fast_branch_v_ln_eN_" + std::string(kt), a.empty() ? NAN : mean, "m/s",
                     "mean of v |ln e_N| over the fast branch's states (constant if v ∝ 1/gamma_N)");
            r.scalar("fast_branch_v_ln_eN_cv_" + std::string(kt), a.size() > 1 ? std::sqrt(sd) / mean : NAN, "1",
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
    r.scalar(std::string("bistable_eN_count_") + kt, bistable, "1",
             "e_N > 0.85 of the grid at which a slow (below v_crit) and a fast (above) steady state coexist");
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const auto& ks = p.reals("kN_list");
    const auto& es = p.reals("eN_list");
    const std::vector<Task> tasks = make_tasks(p);
    long resumed = 0;
    const std::vector<RunResult> results = run_sweep(ctx, tasks, resumed);

    Result r;
    r.scalar("resumed_points", double(resumed), "1", "sweep points loaded from a checkpoint");
    const double m = p.real("m_mean");
    // The paper's t_col at k_N = 200000 N/m refers to e_N = 0.70 (gamma scaled with sqrt(k_N)).
    r.scalar("t_col_k200000_e0.70", pipe_law(200000.0, 0.70, m).collision_time(m), "s",
             "free-wall contact duration at k_N = 2e5 N/m, e_N = 0.70 (Eq. 4)");

    const PipeSpec base = base_spec(p, ctx.seed);
    double worst_balance = 0, min_slope = INFINITY;
    int steady_count = 0;
    for (std::size_t ki = 0; ki < ks.size(); ++ki)
        report_k(r, p, base, ks[ki], ki, results, worst_balance, steady_count, min_slope);
    r.scalar("steady_runs", steady_count, "1", "runs that reached a steady state");
    // Softer grains brake earlier: the k_N = 200 fast branch against the k_N = 2000 one at the same
    // e_N (geometric mean of the speed ratio over the e_N where both fast starts settled).
    const auto k_lo = std::find(ks.begin(), ks.end(), 200.0), k_mid = std::find(ks.begin(), ks.end(), 2000.0);
    if (k_lo != ks.end() && k_mid != ks.end()) {
        const std::size_t a = std::size_t(k_lo - ks.begin()), b = std::size_t(k_mid - ks.begin());
        double lr = 0;
        int nr = 0;
        for (std::size_t ei = 0; ei < es.size(); ++ei) {
            const RunResult& lo = results[(a * es.size() + ei) * 2 + 1];
            const RunResult& mid = results[(b * es.size() + ei) * 2 + 1];
            if (lo.outcome != kSteady || mid.outcome != kSteady) continue;
            lr += std::log(lo.v_mean / mid.v_mean);
            ++nr;
        }
        r.scalar("fast_branch_k200_over_k2000", nr ? std::exp(lr / nr) : NAN, "1",
                 "geometric mean of v_fast(k_N = 200) / v_fast(k_N = 2000) over the e_N where both settled");
    }
    r.scalar("eq9_worst_deviation", steady_count ? worst_balance : NAN, "1",
             "largest |ṅ Δv_y / g - 1| over steady runs (Eq. 9)");
    r.scalar("impact_slope_min", std::isfinite(min_slope) ? min_slope : NAN, "s",
             "smallest slope dΔv_y/dv of the impact curve at a steady state's speed (Eq. 9 argument: > 0)");
    if (p.real("length_check") > 0) {
        const RunResult& a = results[((ks.size() > 1 ? 1 : 0) * es.size() + es.size() - 1) * 2];
        const RunResult& b = results.back();
        r.scalar("length_check_ratio", (a.outcome == kSteady && b.outcome == kSteady) ? b.v_mean / a.v_mean : NAN, "1",
                 "steady speed at length_check over that at length (same k_N, e_N, slow start)");
    }
    // The crude estimates below Eq. (9), over windows of every run: ṅ ∝ σ_vx, and ṅ Δv_y grows
    // about quadratically with Δv_y.
    Table& tw = r.table("eq9_windows", "ṅ, Δv_y, σ_vx and speed over windows of eq9_window, every run");
    std::vector<double> wk, wn, wd, ws, wv;
    for (std::size_t i = 0; i < tasks.size(); ++i)
        for (std::size_t j = 0; j < results[i].w_ndot.size(); ++j) {
            wk.push_back(tasks[i].k);
            wn.push_back(results[i].w_ndot[j]);
            wd.push_back(results[i].w_dvy[j]);
            ws.push_back(results[i].w_sx[j]);
            wv.push_back(results[i].w_v[j]);
        }
    tw.add("k_N", "N/m").values = wk;
    tw.add("ndot", "1/s").values = wn;
    tw.add("dvy", "m/s").values = wd;
    tw.add("sigma_vx", "m/s").values = ws;
    tw.add("v", "m/s").values = wv;
    std::vector<double> lx, ly, ld, lnd;
    for (std::size_t j = 0; j < wn.size(); ++j)
        if (wn[j] > 0 && ws[j] > 0 && wd[j] > 0) {
            lx.push_back(ws[j]);
            ly.push_back(wn[j]);
            ld.push_back(wd[j]);
            lnd.push_back(wn[j] * wd[j]);
        }
    const auto a = lx.size() >= 10 ? fit_power_law(lx, ly, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    const auto b = ld.size() >= 10 ? fit_power_law(ld, lnd, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    r.scalar("ndot_vs_sigma_vx_exponent", a.exponent, "1", "exponent of ṅ ∝ σ_vx^a over all windows");
    r.scalar("ndot_dvy_vs_dvy_exponent", b.exponent, "1", "exponent of ṅ Δv_y ∝ Δv_y^b over all windows");
    r.scalar("eq9_windows", double(lx.size()), "1", "windows in those fits");

    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const Task& tk = tasks[i];
        std::string name = "series_" + tag(tk.k, tk.e, tk.fast ? "fast" : "slow");
        if (p.real("length_check") > 0 && i + 1 == tasks.size()) name += "_length_check";
        Table& ts = r.table(name, "mean velocity and rms v_x against time");
        ts.add("t", "s").values = results[i].t;
        std::vector<double> speed(results[i].v.size());
        for (std::size_t j = 0; j < speed.size(); ++j) speed[j] = -results[i].v[j];
        ts.add("v_down", "m/s").values = speed;
        ts.add("sigma_vx", "m/s").values = results[i].sx;
    }
    r.scalar("grains", double(results.front().grains), "1", "free grains in the pipe (first run)");
    return r;
}

} // namespace

Experiment bistable_pipe() { return {"bistable-pipe", &validate, &run}; }

} // namespace granrepro::experiments
