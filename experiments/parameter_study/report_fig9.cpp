// parameter-study's report of Fig. 9: K against C/N and t for several t_c, its power laws and the spread over t_c.
#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "analysis/seed_stats.hpp"
#include "data/parameter_set.hpp"
#include "experiments/parameter_study/spec.hpp"

namespace granrepro::experiments::parameter_study_detail {

namespace {

PowerLawFit fit_zeta(const std::vector<double>& x, const std::vector<double>& log10k, double lo, double hi) {
    return fit_power_law(x, column(log10k, [](double l) { return std::pow(10.0, l); }), lo, hi);
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

// One fig9_t_c: exponents of K ∝ (C/N)^-zeta (seed mean and scatter of single seeds), K at the
// common end time, TC-elastic share at the end.
struct Fig9Row { double t_c = 0, z1 = NAN, z1e = NAN, z2 = NAN, z2e = NAN, z3 = NAN, k_late = NAN, k_late_e = NAN, el_frac = NAN; };
struct Fig9 {
    std::vector<Fig9Row> rows;
    std::vector<double> single_early, single_late; // single-run exponents, every t_c and seed
    std::vector<MeanCurve> mean_t;                 // seed means against t
    double t_common = INFINITY;                    // [s] the latest time every seed mean reaches
};
const ScalarOut out_fig9_common_end_time = outputs.scalar("fig9_common_end_time", "s",
    "latest time every Fig. 9 run reached");
// Per t_c of fig9_t_c; where the description ends in "t_c = " the run adds t_c and its unit.
const ScalarOut out_zeta_early = outputs.scalar("zeta_early_tc<n>", "1",
    "-d log K / d log(C/N) of the seed mean over zeta_fit_early, t_c = ");
const ScalarOut out_zeta_early_err = outputs.scalar("zeta_early_err_tc<n>", "1",
    "its uncertainty: standard error of the single-seed exponents");
const ScalarOut out_zeta_late = outputs.scalar("zeta_late_tc<n>", "1",
    "-d log K / d log(C/N) of the seed mean over zeta_fit_late, t_c = ");
const ScalarOut out_zeta_late_err = outputs.scalar("zeta_late_err_tc<n>", "1",
    "its uncertainty: standard error of the single-seed exponents");
const ScalarOut out_elastic_fraction = outputs.scalar("elastic_fraction_tc<n>", "1",
    "TC-elastic share of all collisions at the end (seed mean), t_c = ");

Fig9 report_fig9_rows(Result& res, const ParameterStudySpec& s, const Sweep& sw, const std::vector<double>& cn_grid) {
    Fig9 f;
    const auto &e1 = s.zeta_fit_early, &e2 = s.zeta_fit_late, &e3 = s.zeta_fit_tail;
    for (std::size_t k : sw.fig9_idx) f.mean_t.push_back(sw.mean_t[k]);
    for (const MeanCurve& m : f.mean_t) f.t_common = std::min(f.t_common, m.x.empty() ? 0.0 : m.x.back());
    res.put(out_fig9_common_end_time, f.t_common);
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
        const std::string tv = number_text(row.t_c) + " s";
        res.put(out_zeta_early, row.z1, {row.t_c}, tv);
        res.put(out_zeta_early_err, row.z1e, {row.t_c});
        res.put(out_zeta_late, row.z2, {row.t_c}, tv);
        res.put(out_zeta_late_err, row.z2e, {row.t_c});
        res.put(out_elastic_fraction, row.el_frac, {row.t_c}, tv);
    }
    return f;
}

const ScalarOut out_zeta_early_mean = outputs.scalar("zeta_early_mean", "1",
    "early exponent averaged over the t_c values of Fig. 9");
const ScalarOut out_zeta_early_sem = outputs.scalar("zeta_early_sem", "1",
    "its standard error from the scatter over t_c");
const ScalarOut out_zeta_late_mean = outputs.scalar("zeta_late_mean", "1",
    "late exponent averaged over the t_c values of Fig. 9");
const ScalarOut out_zeta_late_sem = outputs.scalar("zeta_late_sem", "1",
    "its standard error from the scatter over t_c");
const ScalarOut out_zeta_tail_mean = outputs.scalar("zeta_tail_mean", "1",
    "exponent of the seed-mean K over zeta_fit_tail, averaged over t_c");
const ScalarOut out_zeta_tail_sem = outputs.scalar("zeta_tail_sem", "1",
    "its standard error from the scatter over t_c");
const ScalarOut out_zeta_early_single_run_sd = outputs.scalar("zeta_early_single_run_sd", "1",
    "standard deviation of the early exponent of single runs (all seeds and t_c)");
const ScalarOut out_zeta_late_single_run_sd = outputs.scalar("zeta_late_single_run_sd", "1",
    "standard deviation of the late exponent of single runs (all seeds and t_c)");
const ScalarOut out_zeta_late_single_run_q10 = outputs.scalar("zeta_late_single_run_q10", "1",
    "10th percentile of the late exponent of single runs (all seeds and t_c)");
const ScalarOut out_zeta_late_single_run_q90 = outputs.scalar("zeta_late_single_run_q90", "1",
    "90th percentile of the late exponent of single runs (all seeds and t_c)");

void report_fig9_summary(Result& res, const Fig9& f) {
    Table& t = res.table(out_fig_summary, {9},
                         "per t_c at r = fig9_r: power-law exponents of the seed-mean K against C/N");
    t.add("t_c", "s").values = column(f.rows, &Fig9Row::t_c);
    const std::pair<const char*, double Fig9Row::*> columns[] = {
        {"zeta_early", &Fig9Row::z1}, {"zeta_early_err", &Fig9Row::z1e}, {"zeta_late", &Fig9Row::z2},
        {"zeta_late_err", &Fig9Row::z2e}, {"log10_K_over_K0_at_common_end", &Fig9Row::k_late},
        {"log10_K_over_K0_at_common_end_sem", &Fig9Row::k_late_e}, {"elastic_fraction_end", &Fig9Row::el_frac}};
    for (const auto& [name, field] : columns) t.add(name, "1").values = column(f.rows, field);
    const MeanSd z1 = mean_sd(column(f.rows, &Fig9Row::z1)), z2 = mean_sd(column(f.rows, &Fig9Row::z2)),
                 z3 = mean_sd(column(f.rows, &Fig9Row::z3));
    res.put(out_zeta_early_mean, z1.mean);
    res.put(out_zeta_early_sem, z1.sem);
    res.put(out_zeta_late_mean, z2.mean);
    res.put(out_zeta_late_sem, z2.sem);
    res.put(out_zeta_tail_mean, z3.mean);
    res.put(out_zeta_tail_sem, z3.sem);
    // Single-run scatter of the exponents (the paper's numbers come from single runs).
    res.put(out_zeta_early_single_run_sd, mean_sd(f.single_early).sem * std::sqrt(double(f.single_early.size())));
    res.put(out_zeta_late_single_run_sd, mean_sd(f.single_late).sem * std::sqrt(double(f.single_late.size())));
    // Its 10th and 90th percentiles: the range of what one run, as the paper shows, gives over the
    // same fit window (expected/README.md, rule 'single run').
    res.put(out_zeta_late_single_run_q10, quantile(f.single_late, 0.1));
    res.put(out_zeta_late_single_run_q90, quantile(f.single_late, 0.9));
}

const ScalarOut out_tc_late_slope = outputs.scalar("tc_late_slope", "1",
    "d log10 K / d log10 t_c at the common end time (> 0: larger t_c loses less energy)");
const ScalarOut out_tc_late_slope_err = outputs.scalar("tc_late_slope_err", "1",
    "its standard error (weights from the seed standard errors)");
const ScalarOut out_tc_late_slope_z = outputs.scalar("tc_late_slope_z", "1", "slope over its standard error");
const ScalarOut out_tc_late_log10K_gain = outputs.scalar("tc_late_log10K_gain", "1",
    "log10 K(largest t_c) - log10 K(smallest t_c) at the common end time (> 0: larger t_c lost less)");
const ScalarOut out_tc_late_log10K_gain_z = outputs.scalar("tc_late_log10K_gain_z", "1",
    "that difference over its standard error");

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
    res.put(out_tc_late_slope, c1);
    res.put(out_tc_late_slope_err, std::sqrt(v11));
    res.put(out_tc_late_slope_z, c1 / std::sqrt(v11));
    auto by_tc = [](const Fig9Row& a, const Fig9Row& b) { return a.t_c < b.t_c; };
    const Fig9Row& hi = *std::max_element(f.rows.begin(), f.rows.end(), by_tc);
    const Fig9Row& lo = *std::min_element(f.rows.begin(), f.rows.end(), by_tc);
    res.put(out_tc_late_log10K_gain, hi.k_late - lo.k_late);
    res.put(out_tc_late_log10K_gain_z, (hi.k_late - lo.k_late) / std::hypot(hi.k_late_e, lo.k_late_e));
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

const ScalarOut out_tc_spread_log10K_early = outputs.scalar("tc_spread_log10K_early", "1",
    "largest spread of the seed-mean log10(K/K0) among the t_c runs for t <= tc_compare_time");
const ScalarOut out_tc_spread_time = outputs.scalar("tc_spread_time", "s", "time of that largest spread");
const ScalarOut out_tc_spread_z_early = outputs.scalar("tc_spread_z_early", "1", "that spread over its standard error");
const ScalarOut out_tc_small_spread_z_all = outputs.scalar("tc_small_spread_z_all", "1",
    "largest spread of the seed-mean log10(K/K0) among the runs with t_c <= tc_small_max over the whole run, in combined standard errors");
const ScalarOut out_tc_small_spread_log10K_all = outputs.scalar("tc_small_spread_log10K_all", "1",
    "that spread in decades");
const ScalarOut out_tc_small_spread_time = outputs.scalar("tc_small_spread_time", "s", "time of that spread");
const ScalarOut out_tc_small_elastic_fraction_max = outputs.scalar("tc_small_elastic_fraction_max", "1",
    "largest TC-elastic share of all collisions at the end among the runs with t_c <= tc_small_max");

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
    res.put(out_tc_spread_log10K_early, e.decades);
    res.put(out_tc_spread_time, e.t);
    res.put(out_tc_spread_z_early, e.z);
    // Sec. 6: TCED "does not affect the system's behaviour as long as t_c is small enough".
    double el_max = 0;
    for (const Fig9Row& row : f.rows)
        if (row.t_c <= s.tc_small_max) el_max = std::max(el_max, row.el_frac);
    res.put(out_tc_small_spread_z_all, w.z);
    res.put(out_tc_small_spread_log10K_all, w.decades);
    res.put(out_tc_small_spread_time, w.t);
    res.put(out_tc_small_elastic_fraction_max, el_max);
}

} // namespace

void report_fig9(Result& res, const ParameterStudySpec& s, const Sweep& sw, const std::vector<double>& cn_grid) {
    const Fig9 f9 = report_fig9_rows(res, s, sw, cn_grid);
    report_fig9_summary(res, f9);
    report_tc_late(res, f9);
    report_tc_spread(res, s, f9);
}

} // namespace granrepro::experiments::parameter_study_detail
