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
#include <chrono>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <numeric>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "analysis/seed_stats.hpp"
#include "core/rng_stream.hpp"
#include "data/spec.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "harness/run_log.hpp"
#include "scenarios/ed_gas.hpp"

namespace granrepro::experiments {

namespace {

// Units and ranges: experiments/parameter-study.toml.
struct ParameterStudySpec {
    long n_side = 0, seeds = 0;
    double box_over_d = 0, d = 0, mass = 0, vbar = 0, mu = 0; // L/d, [m], [kg], mean speed at t = 0 [m/s]
    double equilibration = 0, cn_end = 0;                    // collisions per particle
    std::vector<double> fig8_r, fig9_t_c;                    // fig9_t_c [s]
    double fig8_t_c = 0, fig9_r = 0;                         // fig8_t_c [s]
    double exp_fit_efolds = 0, line_check_efolds = 0, aniso_threshold = 0;
    std::vector<double> zeta_fit_early, zeta_fit_late, zeta_fit_tail; // C/N ranges [lo, hi]
    double tc_compare_time = 0, tc_small_max = 0;                      // [s]
    template <class V> void fields(V&& v) {
        v("n_side", n_side); v("seeds", seeds); v("box_over_d", box_over_d); v("d", d); v("mass", mass); v("vbar", vbar);
        v("mu", mu); v("equilibration", equilibration); v("cn_end", cn_end); v("fig8_r", fig8_r); v("fig9_t_c", fig9_t_c);
        v("fig8_t_c", fig8_t_c); v("fig9_r", fig9_r); v("exp_fit_efolds", exp_fit_efolds); v("aniso_threshold", aniso_threshold);
        v("line_check_efolds", line_check_efolds); v("zeta_fit_early", zeta_fit_early); v("zeta_fit_late", zeta_fit_late);
        v("zeta_fit_tail", zeta_fit_tail); v("tc_compare_time", tc_compare_time); v("tc_small_max", tc_small_max);
    }
};

void validate(const ParameterSet& p) {
    const auto s = read_spec<ParameterStudySpec>(p);
    if (s.box_over_d / double(s.n_side) < 1.0000001)
        p.reject(std::vector<std::string>{"box_over_d", "n_side"},
                 "box_over_d too small for a square-lattice start of n_side^2 disks (lattice spacing below d)");
    // The linked-cell grid of the ED engine has ~(box_over_d)^2 cells of one diameter.
    p.limit_work({"box_over_d"}, s.box_over_d * s.box_over_d, 1e8, "cells of the linked-cell grid");
    if (s.box_over_d < 3.0) p.reject("box_over_d", "must be at least 3 (three cells for the minimum image)");
    // Every run goes to C/N = cn_end: cn_end = 1e308 ended in "cannot create std::vector larger
    // than max_size()".
    const double n = double(s.n_side) * double(s.n_side);
    const double runs = double(s.seeds) * double(s.fig8_r.size() + s.fig9_t_c.size());
    p.limit_work({"cn_end", "n_side", "seeds", "equilibration", "fig8_r", "fig9_t_c"},
                 runs * n / 2 * (s.cn_end + s.equilibration), kMaxCollisions, "collisions");
    for (const auto& [name, v] : {std::pair{"zeta_fit_early", &s.zeta_fit_early}, std::pair{"zeta_fit_late", &s.zeta_fit_late}})
        if (v->size() != 2 || !((*v)[1] > (*v)[0])) p.reject(name, "must be [lo, hi] with hi > lo");
    if (s.fig8_r.empty()) p.reject("fig8_r", "needs at least one value");
    if (s.fig9_t_c.empty()) p.reject("fig9_t_c", "needs at least one value");
}

// One sweep point and what it produced.
struct Point { double r = 0, t_c = 0; };

struct Trace {
    std::vector<double> t, cn, elastic_cn, kx, ky, krot;
    double wall_seconds = 0, events = 0, pairs = 0;
    std::string error; // the engine's message if it stopped the run (collapse guard)
    double k(std::size_t i) const { return kx[i] + ky[i] + krot[i]; }
    template <class V> void fields(V&& v) {
        v("t", t), v("cn", cn), v("elastic_cn", elastic_cn), v("kx", kx), v("ky", ky), v("krot", krot);
        v("wall_seconds", wall_seconds), v("events", events), v("pairs", pairs), v("error", error);
    }
};

Trace run_point(const ParameterStudySpec& s, const Point& pt, std::uint64_t seed, std::uint64_t stream) {
    const auto wall0 = std::chrono::steady_clock::now();
    const std::size_t n = std::size_t(s.n_side * s.n_side);
    const double L = s.box_over_d * s.d;
    const std::vector<double> rad(n, 0.5 * s.d), mass(n, s.mass);
    RngStream rng(seed, stream);
    const EquilibratedGas gas =
        equilibrated_lattice_gas(L, maxwellian_velocities(mass, s.vbar, rng), rad, mass, s.vbar, s.equilibration);
    EdEngine eng(rough_disk_box(L, pt.r, s.mu, pt.t_c), gas.pos, gas.vel, rad, mass); // t = 0: dissipation switched on

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
    const auto target = std::uint64_t(std::ceil(s.cn_end * double(n) / 2.0));
    // Samples every 0.2 collisions per particle early (Fig. 8(a) is linear in C/N) and every 1 %
    // of the collisions later (Fig. 9(b) is logarithmic in C/N): ~500 samples per run.
    try {
        while (eng.total_collisions() < target) {
            const std::uint64_t done = eng.total_collisions();
            const std::uint64_t chunk = std::max<std::uint64_t>({1, n / 10, done / 100});
            eng.run_collisions(std::min(chunk, target - done));
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

// c of ln(K/K0) = -c C/N, a line through the origin, over C/N <= cn_max (GSL weighted-free fit);
// NaN below three points.
double fit_exp(const Trace& tr, double cn_max) {
    std::vector<double> x, y;
    for (std::size_t i = 1; i < tr.cn.size(); ++i)
        if (tr.cn[i] <= cn_max) {
            x.push_back(tr.cn[i]);
            y.push_back(std::log(tr.k(i) / tr.k(0)));
        }
    if (x.size() < 3) return NAN;
    double c1, cov, ss;
    gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
    return -c1;
}

// A curve averaged over the seeds of one parameter set: mean and standard error of
// log10(K/K0) on a grid (of C/N or of t). Geometric means, because K spans many decades and
// the seeds differ by factors, not by amounts.
struct MeanCurve {
    std::vector<double> x, mean, sem;
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
        const MeanSd ms = mean_sd(v);
        m.mean.push_back(ms.mean);
        m.sem.push_back(ms.sem);
    }
    return m;
}

template <class Row>
std::vector<double> column(const std::vector<Row>& rows, double Row::*field) {
    std::vector<double> v;
    for (const Row& row : rows) v.push_back(row.*field);
    return v;
}
PowerLawFit fit_zeta(const std::vector<double>& x, const std::vector<double>& log10k, double lo, double hi) {
    std::vector<double> y;
    for (double l : log10k) y.push_back(std::pow(10.0, l));
    return fit_power_law(x, y, lo, hi);
}

// Seed-mean log10(K/K0) of curve m at x, interpolated linearly in log x, with its standard error.
double mean_at(const MeanCurve& m, double x, double& sem) {
    for (std::size_t i = 1; i < m.x.size(); ++i)
        if (m.x[i] >= x) {
            const double f = std::log(x / m.x[i - 1]) / std::log(m.x[i] / m.x[i - 1]);
            sem = m.sem[i - 1] * (1 - f) + m.sem[i] * f;
            return m.mean[i - 1] * (1 - f) + m.mean[i] * f;
        }
    sem = NAN;
    return m.x.empty() || x > m.x.back() * (1 + 1e-9) ? NAN : m.mean.back();
}

// The sweep: Fig. 8's r values at fig8_t_c, then Fig. 9's t_c values at fig9_r, sharing the point
// (fig9_r, fig8_t_c) when both figures contain it; every point with `seeds` initial states.
struct Sweep {
    std::vector<Point> points;
    std::vector<std::size_t> fig8_idx, fig9_idx; // the point of each fig8_r, of each fig9_t_c
    std::vector<std::vector<Trace>> traces;       // [point][seed]
    std::vector<MeanCurve> mean_cn, mean_t;       // seed means per point, against C/N and t
    long resumed = 0;
    double wall = 0; // [s]
    std::chrono::steady_clock::time_point start; // of the sweep
};

// The points of the sweep; every point runs with `seeds` initial states.
Sweep make_sweep(const ParameterStudySpec& s) {
    Sweep sw;
    auto find_or_add = [&](Point q) {
        for (std::size_t k = 0; k < sw.points.size(); ++k)
            if (sw.points[k].r == q.r && sw.points[k].t_c == q.t_c) return k;
        sw.points.push_back(q);
        return sw.points.size() - 1;
    };
    for (double r : s.fig8_r) sw.fig8_idx.push_back(find_or_add({r, s.fig8_t_c}));
    for (double tc : s.fig9_t_c) sw.fig9_idx.push_back(find_or_add({s.fig9_r, tc}));
    sw.start = std::chrono::steady_clock::now();
    return sw;
}

void report_totals(Result& res, const ParameterStudySpec& s, const Sweep& sw) {
    const double n = double(s.n_side * s.n_side), L = s.box_over_d;
    res.scalar("N", n, "1", "number of disks");
    res.scalar("rho", M_PI / 4 * n / (L * L), "1", "area fraction (pi/4) N / L^2");
    res.scalar("resumed_points", double(sw.resumed), "1", "sweep points loaded from a checkpoint");
    res.scalar("sweep_wall_seconds", sw.wall, "s", "wall time of the sweep (all points, --threads as given)");
    double events = 0, cpu = 0, failed = 0;
    for (const auto& pt : sw.traces)
        for (const auto& tr : pt) {
            events += tr.events;
            cpu += tr.wall_seconds;
            failed += tr.error.empty() ? 0 : 1;
            if (!tr.error.empty()) warn("parameter-study: " + tr.error);
        }
    res.scalar("events_per_second", events / cpu, "1/s", "ED events (collisions, cell crossings, stale) per second of one thread");
    res.scalar("runs_stopped_by_engine", failed, "1", "runs the collapse guard stopped before cn_end");
}

// Seed 0 of one point as it ran (the paper shows single runs), with Eq. (18)'s line.
void report_seed0(Result& res, const Trace& tr, const Point& pt, const std::string& tag) {
    Table& t = res.table("run_" + tag, "seed 0: K/K0, anisotropy, C/N against t for r = " + number_text(pt.r) +
                                           ", t_c = " + number_text(pt.t_c) + " s");
    std::vector<double> kk, an, line;
    const double c_th = (1 - pt.r * pt.r) / 2;
    for (std::size_t i = 0; i < tr.t.size(); ++i) {
        kk.push_back(tr.k(i) / tr.k(0));
        an.push_back((tr.kx[i] - tr.ky[i]) / (tr.kx[i] + tr.ky[i]));
        line.push_back(std::exp(-c_th * tr.cn[i]));
    }
    t.add({{"t", "s", tr.t}, {"C_over_N", "1", tr.cn}, {"elastic_C_over_N", "1", tr.elastic_cn}, {"K_over_K0", "1", kk},
           {"anisotropy", "1", an}, {"exp_line", "1", line}});
}

// Every point's seed 0 and its seed means against C/N (on cn_grid) and against t.
void report_points(Result& res, Sweep& sw, const std::vector<double>& cn_grid) {
    auto mean_table = [&](const std::string& name, const char* against, const char* x, const char* unit, const MeanCurve& m) {
        Table& t = res.table(name, std::string("log10(K/K0) against ") + against + ", mean and standard error over the seeds");
        t.add(x, unit).values = m.x;
        t.add({{"log10_K_over_K0", "1", m.mean}, {"log10_K_over_K0_sem", "1", m.sem}});
    };
    for (std::size_t k = 0; k < sw.points.size(); ++k) {
        const Point& pt = sw.points[k];
        const std::string tag = "r" + number_text(pt.r) + "_tc" + number_text(pt.t_c);
        report_seed0(res, sw.traces[k][0], pt, tag);
        sw.mean_cn.push_back(mean_curve(sw.traces[k], cn_grid, ln_k_at_cn));
        double t_lo = INFINITY;
        for (const auto& s : sw.traces[k]) t_lo = std::min(t_lo, s.t.back());
        // From 1e-3 s, where Fig. 9(a)'s axis starts; a run that ends before 1 s (times scale as
        // d / vbar) gets the three decades below its end instead: from 1e-3 s its grid would run
        // backwards (d = 1e-6 m: "cannot create std::vector larger than max_size()").
        const double t_first = std::min(1e-3, 1e-3 * t_lo);
        const std::vector<double> t_grid =
            t_lo > 0 ? log_space(t_first, t_lo, int(std::round(20 * std::log10(t_lo / t_first))) + 1) : std::vector<double>{};
        sw.mean_t.push_back(mean_curve(sw.traces[k], t_grid, ln_k_at_t));
        mean_table("mean_cn_" + tag, "C/N", "C_over_N", "1", sw.mean_cn[k]);
        mean_table("mean_t_" + tag, "t", "t", "s", sw.mean_t[k]);
    }
}

// ---- Fig. 8 --------------------------------------------------------------------------------
// Fig. 8's observables of one run at restitution r (cth = (1 - r^2)/2, Eq. 18).
struct Fig8Run { double c = NAN, departure = NAN, onset = NAN, max_aniso = 0, early_aniso = NAN; };
Fig8Run fig8_run(const Trace& tr, double cth, const ParameterStudySpec& s) {
    Fig8Run o;
    o.c = fit_exp(tr, s.exp_fit_efolds / cth);
    // Departure: ln(K/K_line) with this run's fitted line, where the line has decayed by
    // line_check_efolds (or at the end of the run if that comes first).
    const double x = std::min(s.line_check_efolds / o.c, tr.cn.back());
    o.departure = ln_k_at_cn(tr, x) + o.c * x;
    // Anisotropy: first C/N where |(K_x - K_y)/K| exceeds aniso_threshold; the largest |value|; the
    // mean |value| over the first 10 collisions per particle (homogeneous fluctuations).
    double early = 0;
    int ne = 0;
    for (std::size_t i = 0; i < tr.t.size(); ++i) {
        const double an = std::abs((tr.kx[i] - tr.ky[i]) / (tr.kx[i] + tr.ky[i]));
        if (std::isnan(o.onset) && an > s.aniso_threshold) o.onset = tr.cn[i];
        o.max_aniso = std::max(o.max_aniso, an);
        if (tr.cn[i] <= 10) {
            early += an;
            ++ne;
        }
    }
    o.early_aniso = ne ? early / ne : NAN;
    return o;
}

// One fig8_r: statistics over the seeds.
struct Fig8Row { double r, c_fit, c_err, c_th, dev, dev_err, onset, max_aniso, early_aniso; };
std::vector<Fig8Row> report_fig8_rows(Result& res, const ParameterStudySpec& s, const Sweep& sw) {
    std::vector<Fig8Row> rows;
    for (std::size_t a = 0; a < s.fig8_r.size(); ++a) {
        const double r = s.fig8_r[a], cth = (1 - r * r) / 2;
        std::vector<Fig8Run> runs;
        for (const Trace& tr : sw.traces[sw.fig8_idx[a]]) runs.push_back(fig8_run(tr, cth, s));
        const MeanSd c = mean_sd(column(runs, &Fig8Run::c)), dev = mean_sd(column(runs, &Fig8Run::departure));
        const Fig8Row& f = rows.emplace_back(Fig8Row{r, c.mean, c.sem, cth, dev.mean, dev.sem,
                                                     median(column(runs, &Fig8Run::onset), NonFinite::censored),
                                                     mean_sd(column(runs, &Fig8Run::max_aniso)).mean,
                                                     mean_sd(column(runs, &Fig8Run::early_aniso)).mean});
        const std::string rv = number_text(r), rl = "_r" + rv;
        res.scalar("c_fit" + rl, f.c_fit, "1", "fitted c of K/K0 = exp(-c C/N) over the first exp_fit_efolds, seed mean, r = " + rv);
        res.scalar("c_fit_err" + rl, f.c_err, "1", "its standard error over the seeds");
        res.scalar("c_over_theory" + rl, f.c_fit / cth, "1", "fitted c over (1 - r^2)/2 from Eq. (18), r = " + rv);
        res.scalar("line_departure" + rl, f.dev, "1", "ln(K/K_line) where the fitted line has decayed by line_check_efolds, seed mean, r = " + rv);
        res.scalar("line_departure_err" + rl, f.dev_err, "1", "its standard error over the seeds");
        res.scalar("aniso_onset_cn" + rl, f.onset, "1", "median over seeds of the first C/N with |K_x - K_y|/K > aniso_threshold (NaN: most never), r = " + rv);
        res.scalar("aniso_max" + rl, f.max_aniso, "1", "seed mean of the largest |K_x - K_y|/K of a run, r = " + rv);
        res.scalar("aniso_early_mean" + rl, f.early_aniso, "1", "mean |K_x - K_y|/K over C/N <= 10, r = " + rv);
    }
    return rows;
}

// Onset ordering over pairs r_a > r_b with r_b >= r_min: share of pairs where the smaller r reaches
// the shear mode no later (median onsets; never = infinity; pairs where neither does don't count).
struct OnsetOrder {
    double violations = 0, pairs = 0;
    double fraction() const { return pairs > 0 ? 1 - violations / pairs : NAN; }
};
OnsetOrder onset_order(const std::vector<Fig8Row>& rows, double r_min) {
    OnsetOrder o;
    for (const Fig8Row& a : rows)
        for (const Fig8Row& b : rows)
            if (a.r > b.r && b.r >= r_min) {
                const double oa = std::isnan(a.onset) ? INFINITY : a.onset;
                const double ob = std::isnan(b.onset) ? INFINITY : b.onset;
                if (std::isinf(oa) && std::isinf(ob)) continue;
                ++o.pairs;
                if (ob > oa) ++o.violations;
            }
    return o;
}

// The table of Fig. 8's rows and the orderings the figure shows across r: departure from the
// line, initial slope, shear-mode onset.
void report_fig8_summary(Result& res, const std::vector<Fig8Row>& rows) {
    Table& t = res.table("fig8_summary", "per r at t_c = fig8_t_c (seed statistics): exponential fit, departure, anisotropy");
    const std::pair<const char*, double Fig8Row::*> columns[] = {
        {"r", &Fig8Row::r}, {"c_fit", &Fig8Row::c_fit}, {"c_fit_err", &Fig8Row::c_err}, {"c_theory", &Fig8Row::c_th},
        {"line_departure", &Fig8Row::dev}, {"line_departure_err", &Fig8Row::dev_err},
        {"aniso_onset_cn_median", &Fig8Row::onset}, {"aniso_max_mean", &Fig8Row::max_aniso},
        {"aniso_early_mean", &Fig8Row::early_aniso}};
    for (const auto& [name, field] : columns) t.add(name, "1").values = column(rows, field);
    double worst_early = 0, smallest_dev_strong = INFINITY, largest_dev_weak = -INFINITY, max_strong = 1, c_viol = 0;
    for (const Fig8Row& a : rows) {
        worst_early = std::max(worst_early, a.early_aniso);
        if (a.r <= 0.95 + 1e-12) smallest_dev_strong = std::min(smallest_dev_strong, a.dev);
        else largest_dev_weak = std::max(largest_dev_weak, a.dev);
        if (a.r <= 0.6 + 1e-12) max_strong = std::min(max_strong, a.max_aniso);
        // Initial slope larger for smaller r: pairs r_a > r_b with c(r_a) >= c(r_b).
        for (const Fig8Row& b : rows)
            if (a.r > b.r && !(a.c_fit < b.c_fit)) ++c_viol;
    }
    const auto max_aniso = column(rows, &Fig8Row::max_aniso);
    res.scalar("aniso_early_mean_max", worst_early, "1", "largest (over r) mean |K_x - K_y|/K for C/N <= 10");
    res.scalar("line_departure_min_r_le_095", smallest_dev_strong, "1", "smallest ln(K/K_line) among r <= 0.95");
    res.scalar("line_departure_max_r_gt_095", largest_dev_weak, "1", "largest ln(K/K_line) among r > 0.95");
    res.scalar("c_fit_order_violations", c_viol, "1", "pairs r_a > r_b whose fitted initial decay rate c is not smaller for the larger r");
    res.scalar("aniso_max_best", *std::max_element(max_aniso.begin(), max_aniso.end()), "1",
               "largest (over r) seed-mean largest |K_x-K_y|/K: how close the shear mode comes to 1");
    const OnsetOrder all = onset_order(rows, -INFINITY);
    res.scalar("aniso_onset_order_violations", all.violations, "1",
               "pairs r_a > r_b whose smaller r reaches |K_x-K_y|/K > aniso_threshold later (medians over seeds)");
    res.scalar("aniso_onset_order_fraction", all.fraction(), "1",
               "share of the r pairs ordered as the paper says (earlier for smaller r)");
    res.scalar("aniso_onset_order_fraction_r_ge_06", onset_order(rows, 0.6 - 1e-12).fraction(), "1",
               "as aniso_onset_order_fraction, among r >= 0.6 only");
    res.scalar("aniso_max_min_r_le_06", max_strong, "1", "smallest (over r <= 0.6) seed-mean largest |K_x-K_y|/K");
}

// ---- Fig. 9 --------------------------------------------------------------------------------
// One fig9_t_c: exponents of K ∝ (C/N)^-zeta (seed mean and scatter of single seeds), K at the
// common end time, TC-elastic share at the end.
struct Fig9Row { double t_c = 0, z1 = NAN, z1e = NAN, z2 = NAN, z2e = NAN, z3 = NAN, k_late = NAN, k_late_e = NAN, el_frac = NAN; };
struct Fig9 {
    std::vector<Fig9Row> rows;
    std::vector<double> single_early, single_late; // single-run exponents, every t_c and seed
    std::vector<MeanCurve> mean_t;                 // seed means against t
    double t_common = INFINITY;                    // [s] the latest time every seed mean reaches
};
Fig9 report_fig9_rows(Result& res, const ParameterStudySpec& s, const Sweep& sw, const std::vector<double>& cn_grid) {
    Fig9 f;
    const auto &e1 = s.zeta_fit_early, &e2 = s.zeta_fit_late, &e3 = s.zeta_fit_tail;
    for (std::size_t k : sw.fig9_idx) f.mean_t.push_back(sw.mean_t[k]);
    for (const MeanCurve& m : f.mean_t) f.t_common = std::min(f.t_common, m.x.empty() ? 0.0 : m.x.back());
    res.scalar("fig9_common_end_time", f.t_common, "s", "latest time every Fig. 9 run reached");
    for (std::size_t b = 0; b < s.fig9_t_c.size(); ++b) {
        const std::size_t k = sw.fig9_idx[b];
        Fig9Row& row = f.rows.emplace_back(Fig9Row{s.fig9_t_c[b]});
        // Exponents of the seed-mean curve (log-spaced grid: equal weight per decade); their
        // uncertainty from the scatter of the single-seed exponents.
        const MeanCurve& m = sw.mean_cn[k];
        row.z1 = -fit_zeta(m.x, m.mean, e1[0], e1[1]).exponent;
        row.z2 = -fit_zeta(m.x, m.mean, e2[0], e2[1]).exponent;
        row.z3 = -fit_zeta(m.x, m.mean, e3[0], e3[1]).exponent;
        std::vector<double> sa, sc;
        for (const Trace& tr : sw.traces[k]) {
            const MeanCurve one = mean_curve(std::vector<Trace>{tr}, cn_grid, ln_k_at_cn);
            sa.push_back(-fit_zeta(one.x, one.mean, e1[0], e1[1]).exponent);
            sc.push_back(-fit_zeta(one.x, one.mean, e2[0], e2[1]).exponent);
        }
        row.z1e = mean_sd(sa).sem;
        row.z2e = mean_sd(sc).sem;
        f.single_early.insert(f.single_early.end(), sa.begin(), sa.end());
        f.single_late.insert(f.single_late.end(), sc.begin(), sc.end());
        row.k_late = mean_at(f.mean_t[b], f.t_common, row.k_late_e);
        double el = 0;
        for (const Trace& tr : sw.traces[k]) el += tr.elastic_cn.back() / tr.cn.back();
        row.el_frac = el / double(sw.traces[k].size());
        const std::string tv = number_text(row.t_c), tl = "_tc" + tv;
        res.scalar("zeta_early" + tl, row.z1, "1", "-d log K / d log(C/N) of the seed mean over zeta_fit_early, t_c = " + tv + " s");
        res.scalar("zeta_early_err" + tl, row.z1e, "1", "its uncertainty: standard error of the single-seed exponents");
        res.scalar("zeta_late" + tl, row.z2, "1", "-d log K / d log(C/N) of the seed mean over zeta_fit_late, t_c = " + tv + " s");
        res.scalar("zeta_late_err" + tl, row.z2e, "1", "its uncertainty: standard error of the single-seed exponents");
        res.scalar("elastic_fraction" + tl, row.el_frac, "1", "TC-elastic share of all collisions at the end (seed mean), t_c = " + tv + " s");
    }
    return f;
}

void report_fig9_summary(Result& res, const Fig9& f) {
    Table& t = res.table("fig9_summary", "per t_c at r = fig9_r: power-law exponents of the seed-mean K against C/N");
    t.add("t_c", "s").values = column(f.rows, &Fig9Row::t_c);
    const std::pair<const char*, double Fig9Row::*> columns[] = {
        {"zeta_early", &Fig9Row::z1}, {"zeta_early_err", &Fig9Row::z1e}, {"zeta_late", &Fig9Row::z2},
        {"zeta_late_err", &Fig9Row::z2e}, {"log10_K_over_K0_at_common_end", &Fig9Row::k_late},
        {"log10_K_over_K0_at_common_end_sem", &Fig9Row::k_late_e}, {"elastic_fraction_end", &Fig9Row::el_frac}};
    for (const auto& [name, field] : columns) t.add(name, "1").values = column(f.rows, field);
    const MeanSd z1 = mean_sd(column(f.rows, &Fig9Row::z1)), z2 = mean_sd(column(f.rows, &Fig9Row::z2)),
                 z3 = mean_sd(column(f.rows, &Fig9Row::z3));
    res.scalar("zeta_early_mean", z1.mean, "1", "early exponent averaged over the t_c values of Fig. 9");
    res.scalar("zeta_early_sem", z1.sem, "1", "its standard error from the scatter over t_c");
    res.scalar("zeta_late_mean", z2.mean, "1", "late exponent averaged over the t_c values of Fig. 9");
    res.scalar("zeta_late_sem", z2.sem, "1", "its standard error from the scatter over t_c");
    res.scalar("zeta_tail_mean", z3.mean, "1", "exponent of the seed-mean K over zeta_fit_tail, averaged over t_c");
    res.scalar("zeta_tail_sem", z3.sem, "1", "its standard error from the scatter over t_c");
    // Single-run scatter of the exponents (the paper's numbers come from single runs).
    res.scalar("zeta_early_single_run_sd", mean_sd(f.single_early).sem * std::sqrt(double(f.single_early.size())), "1",
               "standard deviation of the early exponent of single runs (all seeds and t_c)");
    res.scalar("zeta_late_single_run_sd", mean_sd(f.single_late).sem * std::sqrt(double(f.single_late.size())), "1",
               "standard deviation of the late exponent of single runs (all seeds and t_c)");
}

// Later times: the weighted least-squares slope of log10 K(t_common) against log10 t_c (GSL), and
// K of the largest t_c against K of the smallest.
void report_tc_late(Result& res, const Fig9& f) {
    std::vector<double> x, y, w;
    for (const Fig9Row& row : f.rows)
        if (std::isfinite(row.k_late) && row.k_late_e > 0) {
            x.push_back(std::log10(row.t_c));
            y.push_back(row.k_late);
            w.push_back(1 / (row.k_late_e * row.k_late_e));
        }
    double c0 = NAN, c1 = NAN, v00, v01, v11 = NAN, chisq;
    if (x.size() >= 3) gsl_fit_wlinear(x.data(), 1, w.data(), 1, y.data(), 1, x.size(), &c0, &c1, &v00, &v01, &v11, &chisq);
    res.scalar("tc_late_slope", c1, "1", "d log10 K / d log10 t_c at the common end time (> 0: larger t_c loses less energy)");
    res.scalar("tc_late_slope_err", std::sqrt(v11), "1", "its standard error (weights from the seed standard errors)");
    res.scalar("tc_late_slope_z", c1 / std::sqrt(v11), "1", "slope over its standard error");
    auto by_tc = [](const Fig9Row& a, const Fig9Row& b) { return a.t_c < b.t_c; };
    const Fig9Row& hi = *std::max_element(f.rows.begin(), f.rows.end(), by_tc);
    const Fig9Row& lo = *std::min_element(f.rows.begin(), f.rows.end(), by_tc);
    res.scalar("tc_late_log10K_gain", hi.k_late - lo.k_late, "1",
               "log10 K(largest t_c) - log10 K(smallest t_c) at the common end time (> 0: larger t_c lost less)");
    res.scalar("tc_late_log10K_gain_z", (hi.k_late - lo.k_late) / std::hypot(hi.k_late_e, lo.k_late_e), "1",
               "that difference over its standard error");
}

// The widest spread of the seed-mean log10 K among the Fig. 9 runs with t_c <= tc_max that reach
// t, over the given times: widest in decades, or in units of the combined standard error of the
// two extreme curves (by_z: |z| of their difference).
struct Spread { double decades = 0, z = 0, t = NAN; };
Spread widest_spread(const Fig9& f, const std::vector<double>& times, double tc_max, bool by_z) {
    Spread w;
    for (double t : times) {
        double lo = INFINITY, hi = -INFINITY, elo = 0, ehi = 0;
        int used = 0;
        for (std::size_t b = 0; b < f.rows.size(); ++b) {
            if (f.rows[b].t_c > tc_max) continue;
            double se;
            const double v = mean_at(f.mean_t[b], t, se);
            if (!std::isfinite(v)) continue;
            ++used;
            if (v < lo) { lo = v; elo = se; }
            if (v > hi) { hi = v; ehi = se; }
        }
        if (used < 2) continue;
        const double z = (hi - lo) / std::hypot(elo, ehi);
        if (by_z ? z > w.z : hi - lo > w.decades) w = {hi - lo, z, t};
    }
    return w;
}

// Fig. 9(a): the t_c runs agree early (t <= tc_compare_time, log-spaced times from a thousandth
// of it), and by Sec. 6 those with t_c small enough agree over the whole run.
void report_tc_spread(Result& res, const ParameterStudySpec& s, const Fig9& f) {
    const double t_cmp = s.tc_compare_time;
    std::vector<double> early, whole;
    for (int i = 0; i <= 30 && t_cmp * std::pow(10.0, -3.0 + 0.1 * i) <= f.t_common; ++i)
        early.push_back(t_cmp * std::pow(10.0, -3.0 + 0.1 * i));
    const int steps = int(std::ceil(10 * std::log10(f.t_common / (t_cmp / 1000))));
    for (int i = 0; i <= steps; ++i) whole.push_back(std::min(f.t_common, t_cmp / 1000 * std::pow(10.0, 0.1 * i)));
    const Spread e = widest_spread(f, early, INFINITY, false), w = widest_spread(f, whole, s.tc_small_max, true);
    res.scalar("tc_spread_log10K_early", e.decades, "1", "largest spread of the seed-mean log10(K/K0) among the t_c runs for t <= tc_compare_time");
    res.scalar("tc_spread_time", e.t, "s", "time of that largest spread");
    res.scalar("tc_spread_z_early", e.z, "1", "that spread over its standard error");
    // Sec. 6: TCED "does not affect the system's behaviour as long as t_c is small enough".
    double el_max = 0;
    for (const Fig9Row& row : f.rows)
        if (row.t_c <= s.tc_small_max) el_max = std::max(el_max, row.el_frac);
    res.scalar("tc_small_spread_z_all", w.z, "1",
               "largest spread of the seed-mean log10(K/K0) among the runs with t_c <= tc_small_max over the whole run, in combined standard errors");
    res.scalar("tc_small_spread_log10K_all", w.decades, "1", "that spread in decades");
    res.scalar("tc_small_spread_time", w.t, "s", "time of that spread");
    res.scalar("tc_small_elastic_fraction_max", el_max, "1", "largest TC-elastic share of all collisions at the end among the runs with t_c <= tc_small_max");
}

// Sec. 4.1, "for strong dissipation one observes jumps in C/N - meaning that a few particles
// perform many collisions without affecting the global energy too much": the collision rate per
// particle between successive samples, dC/N/dt, over sqrt(K/K0) (a homogeneous gas collides at a
// rate proportional to its thermal speed), and its largest ratio to the median of the 16
// neighbouring intervals (8 on each side): 1 for a smooth C/N(t), a jump makes it several.
double cn_jump_factor(const Trace& tr) {
    std::vector<double> rate;
    for (std::size_t i = 1; i < tr.t.size(); ++i) {
        const double dt = tr.t[i] - tr.t[i - 1], km = std::sqrt(tr.k(i) * tr.k(i - 1)) / tr.k(0);
        rate.push_back(dt > 0 && km > 0 ? (tr.cn[i] - tr.cn[i - 1]) / dt / std::sqrt(km) : NAN);
    }
    double best = NAN;
    for (std::size_t i = 0; i < rate.size(); ++i) {
        if (!std::isfinite(rate[i])) continue;
        std::vector<double> nb;
        for (std::size_t j = i >= 8 ? i - 8 : 0; j < std::min(rate.size(), i + 9); ++j)
            if (j != i && std::isfinite(rate[j])) nb.push_back(rate[j]);
        if (nb.size() < 8) continue;
        const double f = rate[i] / median(nb, NonFinite::censored);
        if (std::isfinite(f)) best = std::isnan(best) ? f : std::max(best, f);
    }
    return best;
}

// Jump factors of every run of Figs. 8 and 9 (seed mean), and per seed the largest over the
// strong-dissipation runs of Fig. 8 (r <= 0.6) against the largest over the weak ones (r >= 0.9,
// Sec. 3.2's "weak dissipation"): their paired difference over its standard error.
void report_cn_jumps(Result& res, const ParameterStudySpec& s, const Sweep& sw) {
    std::vector<double> pr, ptc, mean, sem;
    for (std::size_t p = 0; p < sw.points.size(); ++p) {
        std::vector<double> f;
        for (const Trace& tr : sw.traces[p]) f.push_back(cn_jump_factor(tr));
        pr.push_back(sw.points[p].r);
        ptc.push_back(sw.points[p].t_c);
        mean.push_back(mean_sd(f).mean);
        sem.push_back(mean_sd(f).sem);
    }
    std::vector<double> strong, weak, diff;
    for (long k = 0; k < s.seeds; ++k) {
        double js = NAN, jw = NAN;
        for (std::size_t a = 0; a < s.fig8_r.size(); ++a) {
            const double f = cn_jump_factor(sw.traces[sw.fig8_idx[a]][std::size_t(k)]);
            if (!std::isfinite(f)) continue;
            if (s.fig8_r[a] <= 0.6) js = std::isnan(js) ? f : std::max(js, f);
            if (s.fig8_r[a] >= 0.9) jw = std::isnan(jw) ? f : std::max(jw, f);
        }
        strong.push_back(js);
        weak.push_back(jw);
        diff.push_back(js - jw);
    }
    res.scalar("cn_jump_strong_mean", mean_sd(strong).mean, "1", "seed mean of the largest C/N jump factor over the Fig. 8 runs with r <= 0.6");
    res.scalar("cn_jump_weak_mean", mean_sd(weak).mean, "1", "seed mean of the largest C/N jump factor over the Fig. 8 runs with r >= 0.9");
    res.scalar("cn_jump_strong_minus_weak_z", mean_sd(diff).mean / mean_sd(diff).sem, "1",
               "seed mean of (strong - weak) jump factor over its standard error (paired by seed)");
    res.scalar("cn_jump_strong_over_weak", mean_sd(strong).mean / mean_sd(weak).mean, "1", "cn_jump_strong_mean / cn_jump_weak_mean");
    Table& t = res.table("cn_jumps", "largest jump of the normalised collision rate (dC/N/dt)/sqrt(K/K0) over its 16 neighbours, per point (seed mean)");
    t.add({{"r", "1", pr}, {"t_c", "s", ptc}, {"jump_factor", "1", mean}, {"jump_factor_sem", "1", sem}});
}

// Figs. 8 and 9 as a protocol (harness/protocol.hpp): sweep point i is (point i / seeds, seed
// i % seeds) with random stream i.
struct ParameterStudy {
    static constexpr const char* name = "parameter-study";
    using Spec = ParameterStudySpec;
    using Outcome = Trace;
    using Shared = Sweep;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Sweep prepare(const Spec& s, const RunContext&) { return make_sweep(s); }
    static std::vector<long> points(const Spec& s, const Sweep& sw) {
        std::vector<long> order(sw.points.size() * std::size_t(s.seeds));
        std::iota(order.begin(), order.end(), 0L);
        return order;
    }
    static Trace compute(const Spec& s, const Sweep& sw, long i, const PointContext& ctx) {
        return run_point(s, sw.points[std::size_t(i / s.seeds)], ctx.seed, std::uint64_t(i));
    }
    static Result report(const Spec& s, const Sweep& shared, const Swept<Trace>& swept, const RunContext&) {
        Sweep sw = shared;
        sw.traces.assign(sw.points.size(), std::vector<Trace>(std::size_t(s.seeds)));
        for (std::size_t i = 0; i < swept.outcomes.size(); ++i)
            sw.traces[i / std::size_t(s.seeds)][i % std::size_t(s.seeds)] = swept.outcomes[i];
        sw.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - sw.start).count();
        sw.resumed = swept.resumed;
        Result res;
        report_totals(res, s, sw);
        const std::vector<double> cn_grid = log_space(0.1, s.cn_end, int(std::round(40 * std::log10(s.cn_end / 0.1))) + 1);
        report_points(res, sw, cn_grid);
        report_fig8_summary(res, report_fig8_rows(res, s, sw));
        const Fig9 f9 = report_fig9_rows(res, s, sw, cn_grid);
        report_fig9_summary(res, f9);
        report_tc_late(res, f9);
        report_tc_spread(res, s, f9);
        report_cn_jumps(res, s, sw);
        return res;
    }
};

} // namespace

Experiment parameter_study() { return protocol_experiment<ParameterStudy>(); }

} // namespace granrepro::experiments
