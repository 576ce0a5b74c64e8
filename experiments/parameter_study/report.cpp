// parameter-study's report common to both figures: totals, every point's seed 0 and seed means, C/N jumps.
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "analysis/seed_stats.hpp"
#include "data/parameter_set.hpp"
#include "experiments/parameter_study/spec.hpp"
#include "harness/run_log.hpp"

namespace granrepro::experiments::parameter_study_detail {

namespace {

// ln(K/K0) at x on the samples xs (tr.cn or tr.t) of a trace, linearly interpolated in x, or in
// log x (log_x); NaN outside the run.
double ln_k_at(const Trace& tr, const std::vector<double>& xs, double x, bool log_x) {
    for (std::size_t i = 1; i < xs.size(); ++i)
        if (xs[i] >= x && (log_x ? xs[i - 1] > 0 : xs[i] > xs[i - 1])) {
            const double f = log_x ? std::log(x / xs[i - 1]) / std::log(xs[i] / xs[i - 1]) : (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
            return std::log(tr.k(i - 1) / tr.k(0)) * (1 - f) + std::log(tr.k(i) / tr.k(0)) * f;
        }
    return NAN;
}

// ln(K/K0) at time t (linear interpolation in log t); NaN outside the run.
double ln_k_at_t(const Trace& tr, double t) { return ln_k_at(tr, tr.t, t, true); }

const TableOut out_run = outputs.table("run_r<n>_tc<n>", "seed 0: K/K0, anisotropy, C/N against t for r = ");

// Seed 0 of one point as it ran (the paper shows single runs), with Eq. (18)'s line.
void report_seed0(Result& res, const Trace& tr, const Point& pt) {
    Table& t = res.table(out_run, {pt.r, pt.t_c}, number_text(pt.r) + ", t_c = " + number_text(pt.t_c) + " s");
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

} // namespace

// ln(K/K0) at C/N = x, linearly interpolated; NaN outside the run.
double ln_k_at_cn(const Trace& tr, double x) { return ln_k_at(tr, tr.cn, x, false); }

MeanCurve mean_curve(const std::vector<Trace>& seeds, const std::vector<double>& grid, double (*lnk)(const Trace&, double)) {
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

const ScalarOut out_N = outputs.scalar("N", "1", "number of disks");
const ScalarOut out_rho = outputs.scalar("rho", "1", "area fraction (pi/4) N / L^2");
const ScalarOut out_sweep_wall_seconds = outputs.scalar("sweep_wall_seconds", "s",
    "wall time of the sweep (all points, --threads as given)");
const ScalarOut out_events_per_second = outputs.scalar("events_per_second", "1/s",
    "ED events (collisions, cell crossings, stale) per second of one thread");
const ScalarOut out_runs_stopped_by_engine = outputs.scalar("runs_stopped_by_engine", "1",
    "runs the collapse guard stopped before cn_end");

void report_totals(Result& res, const ParameterStudySpec& s, const Sweep& sw) {
    const double n = double(s.n_side * s.n_side), L = s.box_over_d;
    res.put(out_N, n);
    res.put(out_rho, M_PI / 4 * n / (L * L));
    res.put(out_sweep_wall_seconds, sw.wall);
    double events = 0, cpu = 0, failed = 0;
    for (const auto& pt : sw.traces)
        for (const auto& tr : pt) {
            events += tr.events;
            cpu += tr.wall_seconds;
            failed += tr.error.empty() ? 0 : 1;
            if (!tr.error.empty()) warn("parameter-study: " + tr.error);
        }
    res.put(out_events_per_second, events / cpu);
    res.put(out_runs_stopped_by_engine, failed);
}

const TableOut out_mean_cn = outputs.table("mean_cn_r<n>_tc<n>", "log10(K/K0) against C/N, mean and standard error over the seeds");
const TableOut out_mean_t = outputs.table("mean_t_r<n>_tc<n>", "log10(K/K0) against t, mean and standard error over the seeds");

// Every point's seed 0 and its seed means against C/N (on cn_grid) and against t.
void report_points(Result& res, Sweep& sw, const std::vector<double>& cn_grid) {
    auto mean_table = [&](const TableOut& h, const Point& pt, const char* x, const char* unit, const MeanCurve& m) {
        Table& t = res.table(h, {pt.r, pt.t_c});
        t.add(x, unit).values = m.x;
        t.add({{"log10_K_over_K0", "1", m.mean}, {"log10_K_over_K0_sem", "1", m.sem}});
    };
    for (std::size_t k = 0; k < sw.points.size(); ++k) {
        const Point& pt = sw.points[k];
        report_seed0(res, sw.traces[k][0], pt);
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
        mean_table(out_mean_cn, pt, "C_over_N", "1", sw.mean_cn[k]);
        mean_table(out_mean_t, pt, "t", "s", sw.mean_t[k]);
    }
}

const ScalarOut out_cn_jump_strong_mean = outputs.scalar("cn_jump_strong_mean", "1",
    "seed mean of the largest C/N jump factor over the Fig. 8 runs with r <= 0.6");
const ScalarOut out_cn_jump_weak_mean = outputs.scalar("cn_jump_weak_mean", "1",
    "seed mean of the largest C/N jump factor over the Fig. 8 runs with r >= 0.9");
const ScalarOut out_cn_jump_strong_minus_weak_z = outputs.scalar("cn_jump_strong_minus_weak_z", "1",
    "seed mean of (strong - weak) jump factor over its standard error (paired by seed)");
const ScalarOut out_cn_jump_strong_over_weak = outputs.scalar("cn_jump_strong_over_weak", "1",
    "cn_jump_strong_mean / cn_jump_weak_mean");
const TableOut out_cn_jumps = outputs.table("cn_jumps",
    "largest jump of the normalised collision rate (dC/N/dt)/sqrt(K/K0) over its 16 neighbours, per point (seed mean)");

// Jump factors of every run of Figs. 8 and 9 (seed mean), and per seed the largest over the
// strong-dissipation runs of Fig. 8 (r <= 0.6) against the largest over the weak ones (r >= 0.9,
// Sec. 3.2's "weak dissipation"): their paired difference over its standard error.
void report_cn_jumps(Result& res, const ParameterStudySpec& s, const Sweep& sw) {
    std::vector<double> pr, ptc, mean, sem;
    for (std::size_t p = 0; p < sw.points.size(); ++p) {
        const std::vector<double> f = column(sw.traces[p], cn_jump_factor);
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
    res.put(out_cn_jump_strong_mean, mean_sd(strong).mean);
    res.put(out_cn_jump_weak_mean, mean_sd(weak).mean);
    res.put(out_cn_jump_strong_minus_weak_z, mean_sd(diff).mean / mean_sd(diff).sem);
    res.put(out_cn_jump_strong_over_weak, mean_sd(strong).mean / mean_sd(weak).mean);
    Table& t = res.table(out_cn_jumps);
    t.add({{"r", "1", pr}, {"t_c", "s", ptc}, {"jump_factor", "1", mean}, {"jump_factor_sem", "1", sem}});
}

} // namespace granrepro::experiments::parameter_study_detail
