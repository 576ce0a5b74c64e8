// bistable-pipe: Schäfer & Wolf (1995) Fig. 6. Grains fall through a vertical 2D pipe between two
// rows of fixed wall grains; the steady-state mean velocity is recorded against e_N for three
// k_N, from a slow start and from a fast start. A steady state is detected from the data (the
// drift of the mean velocity over a trailing window), never assumed; a run that does not reach
// one by t_max is reported as such. In steady states the braking balance of Eq. (9),
// g = ṅ Δv_y, is measured, and Δv_y is compared with the impact curve of Fig. 4 evaluated at the
// pipe's own wall geometry and measured impact velocities.
#include <cmath>
#include <gsl/gsl_fit.h>
#include <numeric>
#include <string>

#include "core/rng_stream.hpp"
#include "engines/soft/pipe_engine.hpp"
#include "experiments/impact_shot.hpp"
#include "experiments/pipe_setup.hpp"
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "harness/sweep_checkpoint.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

using Engine = PipeEngine<LinearSpringDashpot, CoulombShear>;

struct RunResult {
    bool steady = false;
    double t_steady = NAN, v_mean = NAN, v_std = NAN, v_final = NAN, sigma_vx = NAN;
    double ndot = NAN, dvy = NAN, vx_in = NAN, vy_in = NAN, dt = NAN;
    long grains = 0;
    std::vector<double> t, v, sx;

    nlohmann::json to_json() const {
        return {{"steady", steady}, {"t_steady", t_steady}, {"v_mean", v_mean}, {"v_std", v_std},
                {"v_final", v_final}, {"sigma_vx", sigma_vx}, {"ndot", ndot}, {"dvy", dvy},
                {"vx_in", vx_in}, {"vy_in", vy_in}, {"dt", dt}, {"grains", grains},
                {"t", t}, {"v", v}, {"sx", sx}};
    }
    static RunResult from_json(const nlohmann::json& j) {
        RunResult r;
        auto num = [&](const char* k) { return j.at(k).is_null() ? NAN : j.at(k).get<double>(); };
        r.steady = j.at("steady");
        r.t_steady = num("t_steady"); r.v_mean = num("v_mean"); r.v_std = num("v_std");
        r.v_final = num("v_final"); r.sigma_vx = num("sigma_vx"); r.ndot = num("ndot");
        r.dvy = num("dvy"); r.vx_in = num("vx_in"); r.vy_in = num("vy_in"); r.dt = num("dt");
        r.grains = j.at("grains");
        r.t = j.at("t").get<std::vector<double>>();
        r.v = j.at("v").get<std::vector<double>>();
        r.sx = j.at("sx").get<std::vector<double>>();
        return r;
    }
};

double slope(const std::vector<double>& t, const std::vector<double>& v, std::size_t from) {
    double c0, c1, c00, c01, c11, ss;
    gsl_fit_linear(t.data() + from, 1, v.data() + from, 1, t.size() - from, &c0, &c1, &c00, &c01, &c11, &ss);
    return c1;
}

// Runs one start to steady state (or t_max). Steady: over the trailing window the fitted slope of
// the mean velocity is below drift_tol [m/s^2], i.e. braking balances gravity to that accuracy,
// and stays below it over the following averaging window t_average.
RunResult run_pipe(const PipeSpec& s) {
    Engine eng = build_pipe(s);
    RunResult r;
    r.dt = eng.dt();
    r.grains = long(eng.size());
    const std::size_t n = eng.size();
    const long per_window = std::lround(s.window / s.sample_dt);
    double steady_since = NAN;
    double next = 0;
    while (eng.time() < s.t_max) {
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
        if (std::abs(r.v.back()) > s.v_abort) break; // far beyond the paper's range: free fall
        if (std::isnan(steady_since) && long(r.t.size()) > per_window) {
            if (std::abs(slope(r.t, r.v, r.t.size() - std::size_t(per_window))) < s.drift_tol) {
                steady_since = eng.time();
                eng.reset_wall_stats(); // Eq. (9) is measured over the averaging window only
            }
        }
        if (!std::isnan(steady_since) && eng.time() >= steady_since + s.t_average) {
            // Confirm over the averaging window itself: a plateau that happened to fill the
            // detection window but keeps drifting afterwards is not a steady state; search on.
            std::size_t from = 0;
            while (from < r.t.size() && r.t[from] <= steady_since) ++from;
            if (r.t.size() - from >= 3 && std::abs(slope(r.t, r.v, from)) < s.drift_tol) break;
            steady_since = NAN;
        }
    }
    r.v_final = r.v.back();
    if (!std::isnan(steady_since) && eng.time() >= steady_since + s.t_average - 1e-12) {
        r.steady = true;
        r.t_steady = steady_since;
        double sum = 0, sum2 = 0, sxs = 0;
        long k = 0;
        for (std::size_t i = 0; i < r.t.size(); ++i)
            if (r.t[i] > steady_since) {
                sum += r.v[i];
                sum2 += r.v[i] * r.v[i];
                sxs += r.sx[i];
                ++k;
            }
        r.v_mean = sum / double(k);
        r.v_std = std::sqrt(std::max(0.0, sum2 / double(k) - r.v_mean * r.v_mean));
        r.sigma_vx = sxs / double(k);
        const WallImpactStats& w = eng.wall_stats();
        r.ndot = double(w.impacts) / (w.time * double(n));
        if (w.completed > 0) {
            r.dvy = w.sum_dvy / double(w.completed);
            r.vx_in = w.sum_vx_in / double(w.completed);
            r.vy_in = w.sum_vy_in / double(w.completed);
        }
    }
    return r;
}

PipeSpec base_spec(const ParameterSet& p, const RunContext* ctx) {
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
    s.steps_per_contact = p.real("steps_per_contact");
    s.skin = p.real("skin");
    s.t_max = p.real("t_max");
    s.window = p.real("window");
    s.drift_tol = p.real("drift_tol");
    s.t_average = p.real("t_average");
    s.sample_dt = p.real("sample_dt");
    s.v_abort = p.real("v_abort");
    s.seed = ctx ? ctx->seed : 1;
    return s;
}

void validate(const ParameterSet& p) {
    for (double e : p.reals("eN_list"))
        if (!(e > 0 && e <= 1)) p.reject("eN_list", "each e_N must be in (0, 1]");
    if (p.real("window") + p.real("t_average") > p.real("t_max"))
        p.reject("t_max", "must exceed window + t_average so that a steady state can be detected and averaged");
    const double range = p.real("d_mean") * (1 + p.real("polydispersity")) + p.real("skin");
    if (p.real("length") < 4 * range) p.reject("length", "must be at least 4 interaction ranges");
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

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const auto& ks = p.reals("kN_list");
    const auto& es = p.reals("eN_list");
    struct Task {
        double k, e;
        bool fast;
        double length;
    };
    std::vector<Task> tasks;
    for (double k : ks)
        for (double e : es)
            for (bool fast : {false, true}) tasks.push_back({k, e, fast, p.real("length")});
    // The length check: the first k_N at its largest e_N, slow start, at a second pipe length.
    const bool length_check = p.real("length_check") > 0;
    if (length_check) tasks.push_back({ks.size() > 1 ? ks[1] : ks[0], es.back(), false, p.real("length_check")});

    std::vector<RunResult> results(tasks.size());
    SweepCheckpoint checkpoint(ctx);
    Progress progress("bistable-pipe", long(tasks.size()), ctx.quiet);
    parallel_sweep(long(tasks.size()), ctx.threads, &progress, [&](long i) {
        if (auto saved = checkpoint.load(i)) {
            results[std::size_t(i)] = RunResult::from_json(*saved);
            return;
        }
        const Task& t = tasks[std::size_t(i)];
        PipeSpec s = base_spec(p, &ctx);
        s.k_N = t.k;
        s.e_N = t.e;
        s.geo.length = std::round(t.length / s.geo.wall_spacing) * s.geo.wall_spacing;
        s.v0 = t.fast ? p.real("fast_v0") : p.real("slow_v0");
        s.agitation = p.real("agitation");
        s.stream = std::uint64_t(i);
        results[std::size_t(i)] = run_pipe(s);
        checkpoint.save(i, results[std::size_t(i)].to_json());
    });

    Result r;
    r.scalar("resumed_points", double(checkpoint.resumed()), "1", "sweep points loaded from a checkpoint");
    const double m = p.real("m_mean");
    // The paper's t_col at k_N = 200000 N/m refers to e_N = 0.70 (gamma scaled with sqrt(k_N)).
    r.scalar("t_col_k200000_e0.70", pipe_law(200000.0, 0.70, m).collision_time(m), "s",
             "free-wall contact duration at k_N = 2e5 N/m, e_N = 0.70 (Eq. 4)");

    const PipeSpec base = base_spec(p, &ctx);
    double worst_balance = 0;
    int steady_count = 0;
    for (std::size_t ki = 0; ki < ks.size(); ++ki) {
        char kt[32];
        std::snprintf(kt, sizeof kt, "k%g", ks[ki]);
        Table& t = r.table(std::string("steady_") + kt, "steady-state mean velocity against e_N (NaN: no steady state)");
        std::vector<double> e_col, slow_v, fast_v, slow_final, fast_final, slow_t, fast_t, slow_bal, fast_bal,
            slow_link, fast_link;
        double e_lowest_slow = NAN;
        int fast_steady = 0;
        // Normal regime below v_crit, emergency-brake regime above: v_crit ≈ 4 m/s at 2000 N/m
        // (Fig. 3) and ∝ sqrt(k_N) (brake-failure claim v_crit_sqrt_kN).
        const double v_crit = 4.0 * std::sqrt(ks[ki] / 2000.0);
        int bistable = 0, above_085 = 0;
        for (std::size_t ei = 0; ei < es.size(); ++ei) {
            const RunResult& slow = results[(ki * es.size() + ei) * 2];
            const RunResult& fast = results[(ki * es.size() + ei) * 2 + 1];
            e_col.push_back(es[ei]);
            slow_v.push_back(slow.steady ? -slow.v_mean : NAN);
            fast_v.push_back(fast.steady ? -fast.v_mean : NAN);
            slow_final.push_back(-slow.v_final);
            fast_final.push_back(-fast.v_final);
            slow_t.push_back(slow.t_steady);
            fast_t.push_back(fast.t_steady);
            for (const RunResult* rr : {&slow, &fast}) {
                const double bal = rr->steady ? rr->ndot * rr->dvy / base.geo.gravity : NAN;
                // Δv_y of an impact on the same wall row at the measured impact velocities (Fig. 4).
                double link = NAN;
                if (rr->steady && rr->vy_in > 0 && rr->vx_in > 0) {
                    ImpactSetup is;
                    is.d_free = base.d_mean;
                    is.m_free = base.m_mean;
                    is.d_wall = 2 * base.geo.wall_radius;
                    is.wall_spacing = base.geo.wall_spacing;
                    is.x0 = 0.5 * (is.d_free + is.d_wall);
                    is.vx_toward = rr->vx_in;
                    is.vy = rr->vy_in;
                    const LinearSpringDashpot law = pipe_law(ks[ki], es[ei], m);
                    is.dt = law.collision_time(m) / base.steps_per_contact;
                    double sum = 0;
                    const int npos = 10;
                    for (int k = 0; k < npos; ++k) {
                        is.y0 = is.wall_spacing * k / npos;
                        sum += shoot(law, CoulombShear{base.mu}, is).dvy;
                    }
                    link = (sum / npos) / rr->dvy;
                }
                (rr == &slow ? slow_bal : fast_bal).push_back(bal);
                (rr == &slow ? slow_link : fast_link).push_back(link);
                if (rr->steady) {
                    ++steady_count;
                    worst_balance = std::max(worst_balance, std::abs(bal - 1));
                }
            }
            if (slow.steady) e_lowest_slow = std::isnan(e_lowest_slow) ? es[ei] : std::min(e_lowest_slow, es[ei]);
            fast_steady += fast.steady;
            if (es[ei] > 0.85) {
                ++above_085;
                bistable += slow.steady && -slow.v_mean < v_crit && fast.steady && -fast.v_mean >= v_crit;
            }
        }
        t.add("e_N", "1").values = e_col;
        t.add("v_slow", "m/s").values = slow_v;
        t.add("v_fast", "m/s").values = fast_v;
        t.add("v_slow_final", "m/s").values = slow_final;
        t.add("v_fast_final", "m/s").values = fast_final;
        t.add("t_steady_slow", "s").values = slow_t;
        t.add("t_steady_fast", "s").values = fast_t;
        t.add("eq9_balance_slow", "1").values = slow_bal;
        t.add("eq9_balance_fast", "1").values = fast_bal;
        t.add("impact_link_slow", "1").values = slow_link;
        t.add("impact_link_fast", "1").values = fast_link;
        r.scalar(std::string("slow_branch_lowest_eN_") + kt, e_lowest_slow, "1",
                 "smallest e_N whose slow start reached a steady state");
        r.scalar(std::string("fast_branch_fraction_") + kt, double(fast_steady) / double(es.size()), "1",
                 "fraction of e_N values whose fast start reached a steady state");
        const RunResult& top_slow = results[(ki * es.size() + es.size() - 1) * 2];
        const RunResult& top_fast = results[(ki * es.size() + es.size() - 1) * 2 + 1];
        r.scalar(std::string("v_slow_top_") + kt, top_slow.steady ? -top_slow.v_mean : NAN, "m/s",
                 "steady speed of the slow start at the largest e_N");
        r.scalar(std::string("v_fast_top_") + kt, top_fast.steady ? -top_fast.v_mean : NAN, "m/s",
                 "steady speed of the fast start at the largest e_N");
        r.scalar(std::string("normal_branch_top_") + kt, top_slow.steady && -top_slow.v_mean < v_crit ? 1.0 : 0.0, "1",
                 "1 if the slow start at the largest e_N reaches a steady state below v_crit = 4 m/s sqrt(k_N/2000 N/m)");
        r.scalar(std::string("bistable_fraction_") + kt, above_085 ? double(bistable) / above_085 : NAN, "1",
                 "fraction of the e_N > 0.85 of the grid where the slow start reaches a steady state below v_crit and "
                 "the fast start one above (two coexisting steady states)");
        r.scalar(std::string("impact_link_top_") + kt, slow_link.back(), "1",
                 "Fig. 4-type impact Δv_y at the measured impact velocities over the pipe's Δv_y (slow start, largest e_N)");
    }
    r.scalar("steady_runs", steady_count, "1", "runs that reached a steady state");
    r.scalar("eq9_worst_deviation", steady_count ? worst_balance : NAN, "1",
             "largest |ṅ Δv_y / g - 1| over steady runs (Eq. 9)");
    if (length_check) {
        const RunResult& a = results[((ks.size() > 1 ? 1 : 0) * es.size() + es.size() - 1) * 2];
        const RunResult& b = results.back();
        r.scalar("length_check_ratio", (a.steady && b.steady) ? b.v_mean / a.v_mean : NAN, "1",
                 "steady speed at length_check over that at length (same k_N, e_N, slow start)");
    }
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const Task& tk = tasks[i];
        std::string name = "series_" + tag(tk.k, tk.e, tk.fast ? "fast" : "slow");
        if (length_check && i + 1 == tasks.size()) name += "_length_check";
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
