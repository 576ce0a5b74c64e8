// parameter-study: Luding (1998) Section 4.1, Figs. 8 and 9. N = 784 disks on a square lattice
// in a periodic box of side L = 50 d are equilibrated elastically (about 10 collisions per
// particle); at t = 0 the restitution is switched to r and the TCED model (Eq. 7) with threshold
// t_c takes over. Each parameter set runs until C/N, the mean number of collisions per particle,
// reaches 1000. Measured: K(t), (K_x - K_y)/K, C/N and the TC-elastic collisions against t.
//
// C/N counts a pair collision for both partners: C/N = 2 (pair collisions) / N. The cluster-growth
// run checks this reading against the paper's t = 0.64 s at C/N = 39 (experiments/cluster_growth.cpp).
//
// Why K ∝ exp(-c C/N) (text above Fig. 8): with Eq. (18), K = K0/(1 + t/t0)^2, and a collision
// rate per particle proportional to the mean speed, omega(t) = omega0 sqrt(K/K0) = omega0/(1+t/t0),
// C/N = omega0 t0 ln(1 + t/t0), so K/K0 = exp(-2 (C/N)/(omega0 t0)). Kinetic theory gives
// t0 = 4/((1 - r^2) omega0) (experiments/cooling.cpp), hence c = (1 - r^2)/2 per collision per
// particle, independent of density and of v̄: each collision removes (1 - r^2)/2 of the mean
// normal-relative energy share. The paper writes exp(-C/N), i.e. up to this constant.
#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/experiment.hpp"
#include "harness/distributed_sweep.hpp"
#include "harness/progress.hpp"
#include "harness/run_log.hpp"
#include "harness/sweep_checkpoint.hpp"

namespace granrepro::experiments {

namespace {

void validate(const ParameterSet& p) {
    const long ns = p.integer("n_side");
    if (p.real("box_over_d") / double(ns) < 1.0000001)
        p.reject(std::vector<std::string>{"box_over_d", "n_side"},
                 "box_over_d too small for a square-lattice start of n_side^2 disks (lattice spacing below d)");
    // The linked-cell grid of the ED engine has ~(box_over_d)^2 cells of one diameter.
    p.limit_work({"box_over_d"}, p.real("box_over_d") * p.real("box_over_d"), 1e8, "cells of the linked-cell grid");
    if (p.real("box_over_d") < 3.0) p.reject("box_over_d", "must be at least 3 (three cells for the minimum image)");
    {
        // Every run goes to C/N = cn_end: cn_end = 1e308 ended in "cannot create std::vector
        // larger than max_size()".
        const double n = double(ns) * double(ns);
        const double runs = double(p.integer("seeds")) * double(p.reals("fig8_r").size() + p.reals("fig9_t_c").size());
        p.limit_work({"cn_end", "n_side", "seeds", "equilibration", "fig8_r", "fig9_t_c"},
                     runs * n / 2 * (p.real("cn_end") + p.real("equilibration")), kMaxCollisions, "collisions");
    }
    for (const char* name : {"zeta_fit_early", "zeta_fit_late"}) {
        const auto& v = p.reals(name);
        if (v.size() != 2 || !(v[1] > v[0])) p.reject(name, "must be [lo, hi] with hi > lo");
    }
    if (p.reals("fig8_r").empty()) p.reject("fig8_r", "needs at least one value");
    if (p.reals("fig9_t_c").empty()) p.reject("fig9_t_c", "needs at least one value");
}

// One sweep point and what it produced.
struct Point {
    double r = 0, t_c = 0;
};

struct Trace {
    std::vector<double> t, cn, elastic_cn, kx, ky, krot;
    double wall_seconds = 0;
    double events = 0, pairs = 0;
    std::string error; // the engine's message if it stopped the run (collapse guard)

    nlohmann::json to_json() const {
        return {{"t", t}, {"cn", cn}, {"elastic_cn", elastic_cn}, {"kx", kx}, {"ky", ky}, {"krot", krot},
                {"wall_seconds", wall_seconds}, {"events", events}, {"pairs", pairs}, {"error", error}};
    }
    static Trace from_json(const nlohmann::json& j) {
        Trace tr;
        j.at("t").get_to(tr.t);
        j.at("cn").get_to(tr.cn);
        j.at("elastic_cn").get_to(tr.elastic_cn);
        j.at("kx").get_to(tr.kx);
        j.at("ky").get_to(tr.ky);
        j.at("krot").get_to(tr.krot);
        tr.wall_seconds = j.at("wall_seconds");
        tr.events = j.at("events");
        tr.pairs = j.at("pairs");
        tr.error = j.at("error");
        return tr;
    }
    double k(std::size_t i) const { return kx[i] + ky[i] + krot[i]; }
};

Trace run_point(const ParameterSet& p, const Point& pt, std::uint64_t seed, std::uint64_t stream) {
    const auto wall0 = std::chrono::steady_clock::now();
    const long ns = p.integer("n_side");
    const std::size_t n = std::size_t(ns * ns);
    const double d = p.real("d"), L = p.real("box_over_d") * d;
    const std::vector<double> rad(n, 0.5 * d), mass(n, p.real("mass"));
    RngStream rng(seed, stream);
    const EquilibratedGas gas = equilibrated_lattice_gas(L, rad, mass, p.real("vbar"), p.real("equilibration"), rng);

    EdConfig cfg;
    cfg.lx = cfg.ly = L;
    cfg.law.r = pt.r;
    cfg.law.mu = p.real("mu");
    cfg.law.beta0 = p.real("mu") > 0 ? 0.0 : -1.0;
    cfg.t_c = pt.t_c;
    EdEngine eng(cfg, gas.pos, gas.vel, rad, mass); // t = 0: dissipation switched on

    Trace tr;
    auto sample = [&] {
        const EdKineticEnergy k = eng.kinetic_energy();
        tr.t.push_back(eng.time());
        tr.cn.push_back(2.0 * double(eng.total_collisions()) / double(n));
        tr.elastic_cn.push_back(2.0 * double(eng.elastic_collisions()) / double(n));
        tr.kx.push_back(k.kx);
        tr.ky.push_back(k.ky);
        tr.krot.push_back(k.krot);
    };
    sample();
    const auto target = std::uint64_t(std::ceil(p.real("cn_end") * double(n) / 2.0));
    // Samples every 0.2 collisions per particle early (Fig. 8(a) is linear in C/N) and every 1 %
    // of the collisions later (Fig. 9(b) is logarithmic in C/N): ~500 samples per run.
    struct Silent {
        void operator()(const CollisionRecord&) const {}
    } silent;
    try {
        while (eng.total_collisions() < target) {
            const std::uint64_t done = eng.total_collisions();
            const std::uint64_t chunk = std::max<std::uint64_t>({1, n / 10, done / 100});
            eng.run_collisions(std::min(chunk, target - done), silent);
            sample();
        }
    } catch (const std::runtime_error& e) {
        // The collapse guard: keep what was measured and report the reason.
        tr.error = e.what();
        sample();
    }
    tr.events = double(eng.events_processed());
    tr.pairs = double(eng.total_collisions());
    tr.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return tr;
}

// ln(K/K0) at C/N = x, linearly interpolated; NaN outside the run.
double ln_k_at_cn(const Trace& tr, double x) {
    for (std::size_t i = 1; i < tr.cn.size(); ++i)
        if (tr.cn[i] >= x && tr.cn[i] > tr.cn[i - 1]) {
            const double f = (x - tr.cn[i - 1]) / (tr.cn[i] - tr.cn[i - 1]);
            return std::log(tr.k(i - 1) / tr.k(0)) * (1 - f) + std::log(tr.k(i) / tr.k(0)) * f;
        }
    return NAN;
}
// ln(K/K0) at time t (linear interpolation in log t); NaN outside the run.
double ln_k_at_t(const Trace& tr, double t) {
    for (std::size_t i = 1; i < tr.t.size(); ++i)
        if (tr.t[i] >= t && tr.t[i - 1] > 0) {
            const double f = std::log(t / tr.t[i - 1]) / std::log(tr.t[i] / tr.t[i - 1]);
            return std::log(tr.k(i - 1) / tr.k(0)) * (1 - f) + std::log(tr.k(i) / tr.k(0)) * f;
        }
    return NAN;
}

std::string label(const char* prefix, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%g", prefix, v);
    return buf;
}

struct ExpFit {
    double c = NAN, c_err = NAN;
    int points = 0;
};
// ln(K/K0) = -c C/N, a line through the origin, over C/N <= cn_max (GSL weighted-free fit).
ExpFit fit_exp(const Trace& tr, double cn_max) {
    std::vector<double> x, y;
    for (std::size_t i = 1; i < tr.cn.size(); ++i)
        if (tr.cn[i] <= cn_max) {
            x.push_back(tr.cn[i]);
            y.push_back(std::log(tr.k(i) / tr.k(0)));
        }
    ExpFit f;
    f.points = int(x.size());
    if (x.size() < 3) return f;
    double c1, cov, ss;
    gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
    f.c = -c1;
    f.c_err = std::sqrt(cov);
    return f;
}

// A curve averaged over the seeds of one parameter set: mean and standard error of
// log10(K/K0) on a grid (of C/N or of t). Geometric means, because K spans many decades and
// the seeds differ by factors, not by amounts.
struct MeanCurve {
    std::vector<double> x, mean, sem, abs_aniso;
};

template <class LnK>
MeanCurve mean_curve(const std::vector<Trace>& seeds, const std::vector<double>& grid, LnK&& lnk) {
    MeanCurve m;
    for (double x : grid) {
        std::vector<double> v;
        for (const auto& tr : seeds) {
            const double l = lnk(tr, x);
            if (!std::isfinite(l)) break;
            v.push_back(l / std::log(10.0));
        }
        if (v.size() != seeds.size()) break; // every seed must have reached x
        m.x.push_back(x);
        m.mean.push_back(gsl_stats_mean(v.data(), 1, v.size()));
        m.sem.push_back(v.size() > 1 ? gsl_stats_sd(v.data(), 1, v.size()) / std::sqrt(double(v.size())) : NAN);
    }
    return m;
}

double mean_of(const std::vector<double>& v) {
    std::vector<double> w;
    for (double x : v)
        if (std::isfinite(x)) w.push_back(x);
    return w.empty() ? NAN : gsl_stats_mean(w.data(), 1, w.size());
}
double sem_of(const std::vector<double>& v) {
    std::vector<double> w;
    for (double x : v)
        if (std::isfinite(x)) w.push_back(x);
    return w.size() > 1 ? gsl_stats_sd(w.data(), 1, w.size()) / std::sqrt(double(w.size())) : NAN;
}
double median_of(std::vector<double> v) { // NaN counts as +infinity (never happened)
    for (double& x : v)
        if (std::isnan(x)) x = INFINITY;
    std::sort(v.begin(), v.end());
    if (v.empty()) return NAN;
    const std::size_t h = v.size() / 2;
    const double med = v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
    return std::isinf(med) ? NAN : med;
}

PowerLawFit fit_zeta(const std::vector<double>& x, const std::vector<double>& log10k, double lo, double hi) {
    std::vector<double> y;
    for (double l : log10k) y.push_back(std::pow(10.0, l));
    return fit_power_law(x, y, lo, hi);
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const auto& rs = p.reals("fig8_r");
    const auto& tcs = p.reals("fig9_t_c");
    const double tc8 = p.real("fig8_t_c"), r9 = p.real("fig9_r");
    const long n_seeds = p.integer("seeds");
    // The sweep: Fig. 8's r values at t_c8, then Fig. 9's t_c values at r9, sharing the point
    // (r9, t_c8) when both figures contain it; every point with n_seeds initial states.
    std::vector<Point> points;
    std::vector<std::size_t> fig8_idx, fig9_idx;
    auto find_or_add = [&](Point q) {
        for (std::size_t k = 0; k < points.size(); ++k)
            if (points[k].r == q.r && points[k].t_c == q.t_c) return k;
        points.push_back(q);
        return points.size() - 1;
    };
    for (double r : rs) fig8_idx.push_back(find_or_add({r, tc8}));
    for (double tc : tcs) fig9_idx.push_back(find_or_add({r9, tc}));

    const long n_tasks = long(points.size()) * n_seeds;
    std::vector<std::vector<Trace>> traces(points.size(), std::vector<Trace>(std::size_t(n_seeds)));
    // Point i is (point i / n_seeds, seed i % n_seeds) with random stream i.
    std::vector<long> order(static_cast<std::size_t>(n_tasks));
    std::iota(order.begin(), order.end(), 0L);
    const auto wall0 = std::chrono::steady_clock::now();
    const SweepResult swept = distributed_sweep(ctx, "parameter-study", order, [&](long i) {
        return run_point(p, points[std::size_t(i / n_seeds)], ctx.seed, std::uint64_t(i)).to_json();
    });
    for (long i = 0; i < n_tasks; ++i)
        traces[std::size_t(i / n_seeds)][std::size_t(i % n_seeds)] = Trace::from_json(swept.points[std::size_t(i)]);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

    Result res;
    const long ns = p.integer("n_side");
    const double n = double(ns * ns), L = p.real("box_over_d");
    const double cn_end = p.real("cn_end");
    res.scalar("N", n, "1", "number of disks");
    res.scalar("rho", M_PI / 4 * n / (L * L), "1", "area fraction (pi/4) N / L^2");
    res.scalar("resumed_points", double(swept.resumed), "1", "sweep points loaded from a checkpoint");
    res.scalar("sweep_wall_seconds", wall, "s", "wall time of the sweep (all points, --threads as given)");
    double events = 0, cpu = 0, failed = 0;
    for (const auto& pt : traces)
        for (const auto& tr : pt) {
            events += tr.events;
            cpu += tr.wall_seconds;
            failed += tr.error.empty() ? 0 : 1;
            if (!tr.error.empty()) warn("parameter-study: " + tr.error);
        }
    res.scalar("events_per_second", events / cpu, "1/s", "ED events (collisions, cell crossings, stale) per second of one thread");
    res.scalar("runs_stopped_by_engine", failed, "1", "runs the collapse guard stopped before cn_end");

    // Seed 0 of every point as it ran (the paper shows single runs), and the seed means.
    const std::vector<double> cn_grid = log_space(0.1, cn_end, int(std::round(40 * std::log10(cn_end / 0.1))) + 1);
    std::vector<MeanCurve> mean_cn(points.size()), mean_t(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Trace& tr = traces[k][0];
        const Point& pt = points[k];
        const std::string tag = label("r", pt.r) + label("_tc", pt.t_c);
        {
            Table& t = res.table("run_" + tag, "seed 0: K/K0, anisotropy, C/N against t for r = " + label("", pt.r) +
                                                   ", t_c = " + label("", pt.t_c) + " s");
            std::vector<double> kk, an, line;
            const double c_th = (1 - pt.r * pt.r) / 2;
            for (std::size_t i = 0; i < tr.t.size(); ++i) {
                kk.push_back(tr.k(i) / tr.k(0));
                an.push_back((tr.kx[i] - tr.ky[i]) / (tr.kx[i] + tr.ky[i]));
                line.push_back(std::exp(-c_th * tr.cn[i]));
            }
            t.add("t", "s").values = tr.t;
            t.add("C_over_N", "1").values = tr.cn;
            t.add("elastic_C_over_N", "1").values = tr.elastic_cn;
            t.add("K_over_K0", "1").values = kk;
            t.add("anisotropy", "1").values = an;
            t.add("exp_line", "1").values = line;
        }
        mean_cn[k] = mean_curve(traces[k], cn_grid, ln_k_at_cn);
        double t_lo = INFINITY;
        for (const auto& s : traces[k]) t_lo = std::min(t_lo, s.t.back());
        const std::vector<double> t_grid = log_space(1e-3, t_lo, int(std::round(20 * std::log10(t_lo / 1e-3))) + 1);
        mean_t[k] = mean_curve(traces[k], t_grid, ln_k_at_t);
        Table& mc = res.table("mean_cn_" + tag, "log10(K/K0) against C/N, mean and standard error over the seeds");
        mc.add("C_over_N", "1").values = mean_cn[k].x;
        mc.add("log10_K_over_K0", "1").values = mean_cn[k].mean;
        mc.add("log10_K_over_K0_sem", "1").values = mean_cn[k].sem;
        Table& mt = res.table("mean_t_" + tag, "log10(K/K0) against t, mean and standard error over the seeds");
        mt.add("t", "s").values = mean_t[k].x;
        mt.add("log10_K_over_K0", "1").values = mean_t[k].mean;
        mt.add("log10_K_over_K0_sem", "1").values = mean_t[k].sem;
    }

    // ---- Fig. 8 ----------------------------------------------------------------------------
    std::vector<double> c_fit, c_err, c_th, dev, dev_err, onset, max_aniso, early_aniso;
    const double efolds = p.real("exp_fit_efolds"), check_efolds = p.real("line_check_efolds");
    const double aniso_threshold = p.real("aniso_threshold");
    for (std::size_t a = 0; a < rs.size(); ++a) {
        const double r = rs[a], cth = (1 - r * r) / 2;
        std::vector<double> cs, devs, ons, mxs, earlies;
        for (const Trace& tr : traces[fig8_idx[a]]) {
            const ExpFit f = fit_exp(tr, efolds / cth);
            cs.push_back(f.c);
            // Departure: ln(K/K_line) with this run's fitted line, where the line has decayed by
            // check_efolds (or at the end of the run if that comes first).
            const double x = std::min(check_efolds / f.c, tr.cn.back());
            devs.push_back(ln_k_at_cn(tr, x) + f.c * x);
            // Anisotropy: first C/N where |(K_x - K_y)/K| exceeds aniso_threshold; the largest |value|; the
            // mean |value| over the first 10 collisions per particle (homogeneous fluctuations).
            double on = NAN, mx = 0, early = 0;
            int ne = 0;
            for (std::size_t i = 0; i < tr.t.size(); ++i) {
                const double an = std::abs((tr.kx[i] - tr.ky[i]) / (tr.kx[i] + tr.ky[i]));
                if (std::isnan(on) && an > aniso_threshold) on = tr.cn[i];
                mx = std::max(mx, an);
                if (tr.cn[i] <= 10) {
                    early += an;
                    ++ne;
                }
            }
            ons.push_back(on);
            mxs.push_back(mx);
            earlies.push_back(ne ? early / ne : NAN);
        }
        c_fit.push_back(mean_of(cs));
        c_err.push_back(sem_of(cs));
        c_th.push_back(cth);
        dev.push_back(mean_of(devs));
        dev_err.push_back(sem_of(devs));
        onset.push_back(median_of(ons));
        max_aniso.push_back(mean_of(mxs));
        early_aniso.push_back(mean_of(earlies));
        const std::string rl = label("_r", r), rv = label("", r);
        res.scalar("c_fit" + rl, c_fit.back(), "1", "fitted c of K/K0 = exp(-c C/N) over the first exp_fit_efolds, seed mean, r = " + rv);
        res.scalar("c_fit_err" + rl, c_err.back(), "1", "its standard error over the seeds");
        res.scalar("c_over_theory" + rl, c_fit.back() / cth, "1", "fitted c over (1 - r^2)/2 from Eq. (18), r = " + rv);
        res.scalar("line_departure" + rl, dev.back(), "1", "ln(K/K_line) where the fitted line has decayed by line_check_efolds, seed mean, r = " + rv);
        res.scalar("line_departure_err" + rl, dev_err.back(), "1", "its standard error over the seeds");
        res.scalar("aniso_onset_cn" + rl, onset.back(), "1", "median over seeds of the first C/N with |K_x - K_y|/K > aniso_threshold (NaN: most never), r = " + rv);
        res.scalar("aniso_max" + rl, max_aniso.back(), "1", "seed mean of the largest |K_x - K_y|/K of a run, r = " + rv);
        res.scalar("aniso_early_mean" + rl, early_aniso.back(), "1", "mean |K_x - K_y|/K over C/N <= 10, r = " + rv);
    }
    {
        Table& f8 = res.table("fig8_summary", "per r at t_c = fig8_t_c (seed statistics): exponential fit, departure, anisotropy");
        f8.add("r", "1").values = rs;
        f8.add("c_fit", "1").values = c_fit;
        f8.add("c_fit_err", "1").values = c_err;
        f8.add("c_theory", "1").values = c_th;
        f8.add("line_departure", "1").values = dev;
        f8.add("line_departure_err", "1").values = dev_err;
        f8.add("aniso_onset_cn_median", "1").values = onset;
        f8.add("aniso_max_mean", "1").values = max_aniso;
        f8.add("aniso_early_mean", "1").values = early_aniso;
    }
    {
        double worst_early = 0, smallest_dev_strong = INFINITY, largest_dev_weak = -INFINITY;
        for (std::size_t a = 0; a < rs.size(); ++a) {
            worst_early = std::max(worst_early, early_aniso[a]);
            if (rs[a] <= 0.95 + 1e-12) smallest_dev_strong = std::min(smallest_dev_strong, dev[a]);
            else largest_dev_weak = std::max(largest_dev_weak, dev[a]);
        }
        res.scalar("aniso_early_mean_max", worst_early, "1", "largest (over r) mean |K_x - K_y|/K for C/N <= 10");
        res.scalar("line_departure_min_r_le_095", smallest_dev_strong, "1", "smallest ln(K/K_line) among r <= 0.95");
        res.scalar("line_departure_max_r_gt_095", largest_dev_weak, "1", "largest ln(K/K_line) among r > 0.95");
        // Initial slope larger for smaller r: pairs r_a > r_b with c(r_a) >= c(r_b).
        double c_viol = 0;
        for (std::size_t a = 0; a < rs.size(); ++a)
            for (std::size_t b = 0; b < rs.size(); ++b)
                if (rs[a] > rs[b] && !(c_fit[a] < c_fit[b])) ++c_viol;
        res.scalar("c_fit_order_violations", c_viol, "1", "pairs r_a > r_b whose fitted initial decay rate c is not smaller for the larger r");
        res.scalar("aniso_max_best", *std::max_element(max_aniso.begin(), max_aniso.end()), "1",
                   "largest (over r) seed-mean largest |K_x-K_y|/K: how close the shear mode comes to 1");
        // Onset ordering over pairs r_a > r_b: violated when the smaller r reaches the shear
        // mode later (medians; never = infinity; pairs where neither reaches it are not counted).
        double violations = 0, pairs = 0, max_strong = 1;
        for (std::size_t a = 0; a < rs.size(); ++a) {
            if (rs[a] <= 0.6 + 1e-12) max_strong = std::min(max_strong, max_aniso[a]);
            for (std::size_t b = 0; b < rs.size(); ++b)
                if (rs[a] > rs[b]) {
                    const double oa = std::isnan(onset[a]) ? INFINITY : onset[a];
                    const double ob = std::isnan(onset[b]) ? INFINITY : onset[b];
                    if (std::isinf(oa) && std::isinf(ob)) continue;
                    ++pairs;
                    if (ob > oa) ++violations;
                }
        }
        res.scalar("aniso_onset_order_violations", violations, "1",
                   "pairs r_a > r_b whose smaller r reaches |K_x-K_y|/K > aniso_threshold later (medians over seeds)");
        res.scalar("aniso_onset_order_fraction", pairs > 0 ? 1 - violations / pairs : NAN, "1",
                   "share of the r pairs ordered as the paper says (earlier for smaller r)");
        {
            double v = 0, np = 0;
            for (std::size_t a = 0; a < rs.size(); ++a)
                for (std::size_t b = 0; b < rs.size(); ++b)
                    if (rs[a] > rs[b] && rs[b] >= 0.6 - 1e-12) {
                        const double oa = std::isnan(onset[a]) ? INFINITY : onset[a];
                        const double ob = std::isnan(onset[b]) ? INFINITY : onset[b];
                        if (std::isinf(oa) && std::isinf(ob)) continue;
                        ++np;
                        if (ob > oa) ++v;
                    }
            res.scalar("aniso_onset_order_fraction_r_ge_06", np > 0 ? 1 - v / np : NAN, "1",
                       "as aniso_onset_order_fraction, among r >= 0.6 only");
        }
        res.scalar("aniso_max_min_r_le_06", max_strong, "1", "smallest (over r <= 0.6) seed-mean largest |K_x-K_y|/K");
    }

    // ---- Fig. 9 ----------------------------------------------------------------------------
    std::vector<double> z1, z1e, z2, z2e, k_late, k_late_e, el_frac;
    const auto& e1 = p.reals("zeta_fit_early");
    const auto& e2 = p.reals("zeta_fit_late");
    const auto& e3 = p.reals("zeta_fit_tail");
    std::vector<double> z3;
    const double t_cmp = p.real("tc_compare_time");
    // The latest time every Fig. 9 seed mean reaches: compare K there.
    double t_common = INFINITY;
    for (std::size_t b = 0; b < tcs.size(); ++b) t_common = std::min(t_common, mean_t[fig9_idx[b]].x.back());
    res.scalar("fig9_common_end_time", t_common, "s", "latest time every Fig. 9 run reached");
    auto mean_at = [](const MeanCurve& m, double x, double& sem) {
        for (std::size_t i = 1; i < m.x.size(); ++i)
            if (m.x[i] >= x) {
                const double f = std::log(x / m.x[i - 1]) / std::log(m.x[i] / m.x[i - 1]);
                sem = m.sem[i - 1] * (1 - f) + m.sem[i] * f;
                return m.mean[i - 1] * (1 - f) + m.mean[i] * f;
            }
        sem = NAN;
        return m.x.empty() || x > m.x.back() * (1 + 1e-9) ? NAN : m.mean.back();
    };
    for (std::size_t b = 0; b < tcs.size(); ++b) {
        const std::size_t k = fig9_idx[b];
        // Exponents of the seed-mean curve (log-spaced grid: equal weight per decade); their
        // uncertainty from the scatter of the single-seed exponents.
        const PowerLawFit a = fit_zeta(mean_cn[k].x, mean_cn[k].mean, e1[0], e1[1]);
        const PowerLawFit c = fit_zeta(mean_cn[k].x, mean_cn[k].mean, e2[0], e2[1]);
        const PowerLawFit tail = fit_zeta(mean_cn[k].x, mean_cn[k].mean, e3[0], e3[1]);
        z3.push_back(-tail.exponent);
        std::vector<double> sa, sc;
        for (const Trace& tr : traces[k]) {
            const MeanCurve one = mean_curve(std::vector<Trace>{tr}, cn_grid, ln_k_at_cn);
            sa.push_back(-fit_zeta(one.x, one.mean, e1[0], e1[1]).exponent);
            sc.push_back(-fit_zeta(one.x, one.mean, e2[0], e2[1]).exponent);
        }
        z1.push_back(-a.exponent);
        z1e.push_back(sem_of(sa));
        z2.push_back(-c.exponent);
        z2e.push_back(sem_of(sc));
        double se;
        k_late.push_back(mean_at(mean_t[k], t_common, se));
        k_late_e.push_back(se);
        double el = 0;
        for (const Trace& tr : traces[k]) el += tr.elastic_cn.back() / tr.cn.back();
        el_frac.push_back(el / double(traces[k].size()));
        const std::string tl = label("_tc", tcs[b]), tv = label("", tcs[b]);
        res.scalar("zeta_early" + tl, z1.back(), "1", "-d log K / d log(C/N) of the seed mean over zeta_fit_early, t_c = " + tv + " s");
        res.scalar("zeta_early_err" + tl, z1e.back(), "1", "its uncertainty: standard error of the single-seed exponents");
        res.scalar("zeta_late" + tl, z2.back(), "1", "-d log K / d log(C/N) of the seed mean over zeta_fit_late, t_c = " + tv + " s");
        res.scalar("zeta_late_err" + tl, z2e.back(), "1", "its uncertainty: standard error of the single-seed exponents");
        res.scalar("elastic_fraction" + tl, el_frac.back(), "1", "TC-elastic share of all collisions at the end (seed mean), t_c = " + tv + " s");
    }
    {
        Table& f9 = res.table("fig9_summary", "per t_c at r = fig9_r: power-law exponents of the seed-mean K against C/N");
        f9.add("t_c", "s").values = tcs;
        f9.add("zeta_early", "1").values = z1;
        f9.add("zeta_early_err", "1").values = z1e;
        f9.add("zeta_late", "1").values = z2;
        f9.add("zeta_late_err", "1").values = z2e;
        f9.add("log10_K_over_K0_at_common_end", "1").values = k_late;
        f9.add("log10_K_over_K0_at_common_end_sem", "1").values = k_late_e;
        f9.add("elastic_fraction_end", "1").values = el_frac;
    }
    {
        res.scalar("zeta_early_mean", mean_of(z1), "1", "early exponent averaged over the t_c values of Fig. 9");
        res.scalar("zeta_early_sem", sem_of(z1), "1", "its standard error from the scatter over t_c");
        res.scalar("zeta_late_mean", mean_of(z2), "1", "late exponent averaged over the t_c values of Fig. 9");
        res.scalar("zeta_late_sem", sem_of(z2), "1", "its standard error from the scatter over t_c");
        res.scalar("zeta_tail_mean", mean_of(z3), "1", "exponent of the seed-mean K over zeta_fit_tail, averaged over t_c");
        res.scalar("zeta_tail_sem", sem_of(z3), "1", "its standard error from the scatter over t_c");
        // Single-run scatter of the exponents (the paper's numbers come from single runs).
        {
            std::vector<double> all1, all2;
            for (std::size_t b = 0; b < tcs.size(); ++b)
                for (const Trace& tr : traces[fig9_idx[b]]) {
                    const MeanCurve one = mean_curve(std::vector<Trace>{tr}, cn_grid, ln_k_at_cn);
                    all1.push_back(-fit_zeta(one.x, one.mean, e1[0], e1[1]).exponent);
                    all2.push_back(-fit_zeta(one.x, one.mean, e2[0], e2[1]).exponent);
                }
            res.scalar("zeta_early_single_run_sd", sem_of(all1) * std::sqrt(double(all1.size())), "1",
                       "standard deviation of the early exponent of single runs (all seeds and t_c)");
            res.scalar("zeta_late_single_run_sd", sem_of(all2) * std::sqrt(double(all2.size())), "1",
                       "standard deviation of the late exponent of single runs (all seeds and t_c)");
        }
        // Later times: weighted least-squares slope of log10 K(t_common) against log10 t_c (GSL).
        {
            std::vector<double> x, y, w;
            for (std::size_t b = 0; b < tcs.size(); ++b)
                if (std::isfinite(k_late[b]) && k_late_e[b] > 0) {
                    x.push_back(std::log10(tcs[b]));
                    y.push_back(k_late[b]);
                    w.push_back(1 / (k_late_e[b] * k_late_e[b]));
                }
            double c0 = NAN, c1 = NAN, v00, v01, v11 = NAN, chisq;
            if (x.size() >= 3) gsl_fit_wlinear(x.data(), 1, w.data(), 1, y.data(), 1, x.size(), &c0, &c1, &v00, &v01, &v11, &chisq);
            res.scalar("tc_late_slope", c1, "1", "d log10 K / d log10 t_c at the common end time (> 0: larger t_c loses less energy)");
            res.scalar("tc_late_slope_err", std::sqrt(v11), "1", "its standard error (weights from the seed standard errors)");
            res.scalar("tc_late_slope_z", c1 / std::sqrt(v11), "1", "slope over its standard error");
        }
        // t_c independence for t <= t_cmp: the largest spread of the seed-mean log10 K among the
        // t_c values over a log-spaced set of times in [t_cmp/1000, t_cmp], in units of the
        // combined standard error of the two extreme curves (|z| of their difference).
        double spread = 0, spread_z = 0, spread_t = NAN;
        for (int s = 0; s <= 30; ++s) {
            const double t = t_cmp * std::pow(10.0, -3.0 + 0.1 * s);
            if (t > t_common) break;
            double lo = INFINITY, hi = -INFINITY, elo = 0, ehi = 0;
            for (std::size_t b = 0; b < tcs.size(); ++b) {
                double se;
                const double v = mean_at(mean_t[fig9_idx[b]], t, se);
                if (v < lo) { lo = v; elo = se; }
                if (v > hi) { hi = v; ehi = se; }
            }
            if (hi - lo > spread) {
                spread = hi - lo;
                spread_t = t;
                spread_z = spread / std::hypot(elo, ehi);
            }
        }
        res.scalar("tc_spread_log10K_early", spread, "1", "largest spread of the seed-mean log10(K/K0) among the t_c runs for t <= tc_compare_time");
        res.scalar("tc_spread_time", spread_t, "s", "time of that largest spread");
        res.scalar("tc_spread_z_early", spread_z, "1", "that spread over its standard error");
        // Sec. 6: TCED "does not affect the system's behaviour as long as t_c is small enough",
        // checked over the whole run, not only t <= tc_compare_time: the largest spread of the
        // seed-mean log10 K among the t_c <= tc_small_max runs at log-spaced times from
        // t_cmp/1000 to the latest time all runs reach, in units of the combined standard error of
        // the two extreme curves at that time; and the largest TC-elastic share among them.
        {
            double spread_all = 0, z_all = 0, t_at = NAN, el_max = 0;
            const double tc_small = p.real("tc_small_max");
            for (std::size_t b = 0; b < tcs.size(); ++b)
                if (tcs[b] <= tc_small) el_max = std::max(el_max, el_frac[b]);
            const int steps = int(std::ceil(10 * std::log10(t_common / (t_cmp / 1000))));
            for (int s = 0; s <= steps; ++s) {
                const double t = std::min(t_common, t_cmp / 1000 * std::pow(10.0, 0.1 * s));
                double lo = INFINITY, hi = -INFINITY, elo = 0, ehi = 0;
                int used = 0;
                for (std::size_t b = 0; b < tcs.size(); ++b) {
                    if (tcs[b] > tc_small) continue;
                    double se;
                    const double v = mean_at(mean_t[fig9_idx[b]], t, se);
                    if (!std::isfinite(v)) continue;
                    ++used;
                    if (v < lo) { lo = v; elo = se; }
                    if (v > hi) { hi = v; ehi = se; }
                }
                if (used < 2) continue;
                const double z = (hi - lo) / std::hypot(elo, ehi);
                if (z > z_all) { z_all = z; spread_all = hi - lo; t_at = t; }
            }
            res.scalar("tc_small_spread_z_all", z_all, "1",
                       "largest spread of the seed-mean log10(K/K0) among the runs with t_c <= tc_small_max over the whole run, in combined standard errors");
            res.scalar("tc_small_spread_log10K_all", spread_all, "1", "that spread in decades");
            res.scalar("tc_small_spread_time", t_at, "s", "time of that spread");
            res.scalar("tc_small_elastic_fraction_max", el_max, "1", "largest TC-elastic share of all collisions at the end among the runs with t_c <= tc_small_max");
        }
        // Later: K of the largest t_c against K of the smallest at the common end time.
        const auto imax = std::size_t(std::max_element(tcs.begin(), tcs.end()) - tcs.begin());
        const auto imin = std::size_t(std::min_element(tcs.begin(), tcs.end()) - tcs.begin());
        res.scalar("tc_late_log10K_gain", k_late[imax] - k_late[imin], "1",
                   "log10 K(largest t_c) - log10 K(smallest t_c) at the common end time (> 0: larger t_c lost less)");
        res.scalar("tc_late_log10K_gain_z", (k_late[imax] - k_late[imin]) / std::hypot(k_late_e[imax], k_late_e[imin]), "1",
                   "that difference over its standard error");
    }
    return res;
}

} // namespace

Experiment parameter_study() { return {"parameter-study", &validate, &run}; }

} // namespace granrepro::experiments
