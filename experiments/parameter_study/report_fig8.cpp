// parameter-study's report of Fig. 8: K against C/N for several r, its exponential fit and the shear mode.
#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <string>

#include "analysis/seed_stats.hpp"
#include "data/parameter_set.hpp"
#include "experiments/parameter_study/spec.hpp"

namespace granrepro::experiments::parameter_study_detail {

namespace {

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

// Per r of fig8_r ("c_fit_r0.3"); where the description ends in "r = " the run adds r.
const ScalarOut out_c_fit = outputs.scalar("c_fit_r<n>", "1",
    "fitted c of K/K0 = exp(-c C/N) over the first exp_fit_efolds, seed mean, r = ");
const ScalarOut out_c_fit_err = outputs.scalar("c_fit_err_r<n>", "1", "its standard error over the seeds");
const ScalarOut out_c_over_theory = outputs.scalar("c_over_theory_r<n>", "1", "fitted c over (1 - r^2)/2 from Eq. (18), r = ");
const ScalarOut out_line_departure = outputs.scalar("line_departure_r<n>", "1",
    "ln(K/K_line) where the fitted line has decayed by line_check_efolds, seed mean, r = ");
const ScalarOut out_line_departure_err = outputs.scalar("line_departure_err_r<n>", "1", "its standard error over the seeds");
const ScalarOut out_aniso_onset_cn = outputs.scalar("aniso_onset_cn_r<n>", "1",
    "median over seeds of the first C/N with |K_x - K_y|/K > aniso_threshold (NaN: most never), r = ");
const ScalarOut out_aniso_max = outputs.scalar("aniso_max_r<n>", "1", "seed mean of the largest |K_x - K_y|/K of a run, r = ");
const ScalarOut out_aniso_early_mean = outputs.scalar("aniso_early_mean_r<n>", "1", "mean |K_x - K_y|/K over C/N <= 10, r = ");

// One fig8_r: statistics over the seeds.
struct Fig8Row { double r, c_fit, c_err, c_th, dev, dev_err, onset, max_aniso, early_aniso, onset_q25, onset_q75; };
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
                                                     mean_sd(column(runs, &Fig8Run::early_aniso)).mean,
                                                     // quartiles of the onset over seeds: its scatter, to
                                                     // judge an ordering of medians (never = +inf, NaN)
                                                     quantile(column(runs, &Fig8Run::onset), 0.25, NonFinite::censored),
                                                     quantile(column(runs, &Fig8Run::onset), 0.75, NonFinite::censored)});
        const std::string rv = number_text(r);
        res.put(out_c_fit, f.c_fit, {r}, rv);
        res.put(out_c_fit_err, f.c_err, {r});
        res.put(out_c_over_theory, f.c_fit / cth, {r}, rv);
        res.put(out_line_departure, f.dev, {r}, rv);
        res.put(out_line_departure_err, f.dev_err, {r});
        res.put(out_aniso_onset_cn, f.onset, {r}, rv);
        res.put(out_aniso_max, f.max_aniso, {r}, rv);
        res.put(out_aniso_early_mean, f.early_aniso, {r}, rv);
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

const ScalarOut out_aniso_early_mean_max = outputs.scalar("aniso_early_mean_max", "1",
    "largest (over r) mean |K_x - K_y|/K for C/N <= 10");
const ScalarOut out_line_departure_min_r_le_095 = outputs.scalar("line_departure_min_r_le_095", "1",
    "smallest ln(K/K_line) among r <= 0.95");
const ScalarOut out_line_departure_max_r_gt_095 = outputs.scalar("line_departure_max_r_gt_095", "1",
    "largest ln(K/K_line) among r > 0.95");
const ScalarOut out_c_fit_order_violations = outputs.scalar("c_fit_order_violations", "1",
    "pairs r_a > r_b whose fitted initial decay rate c is not smaller for the larger r");
const ScalarOut out_aniso_max_best = outputs.scalar("aniso_max_best", "1",
    "largest (over r) seed-mean largest |K_x-K_y|/K: how close the shear mode comes to 1");
const ScalarOut out_aniso_onset_order_violations = outputs.scalar("aniso_onset_order_violations", "1",
    "pairs r_a > r_b whose smaller r reaches |K_x-K_y|/K > aniso_threshold later (medians over seeds)");
const ScalarOut out_aniso_onset_order_fraction = outputs.scalar("aniso_onset_order_fraction", "1",
    "share of the r pairs ordered as the paper says (earlier for smaller r)");
const ScalarOut out_aniso_onset_order_fraction_r_ge_06 = outputs.scalar("aniso_onset_order_fraction_r_ge_06", "1",
    "as aniso_onset_order_fraction, among r >= 0.6 only");
const ScalarOut out_aniso_max_min_r_le_06 = outputs.scalar("aniso_max_min_r_le_06", "1",
    "smallest (over r <= 0.6) seed-mean largest |K_x-K_y|/K");

// The table of Fig. 8's rows and the orderings the figure shows across r: departure from the
// line, initial slope, shear-mode onset.
void report_fig8_summary(Result& res, const std::vector<Fig8Row>& rows) {
    Table& t = res.table(out_fig_summary, {8},
                         "per r at t_c = fig8_t_c (seed statistics): exponential fit, departure, anisotropy");
    const std::pair<const char*, double Fig8Row::*> columns[] = {
        {"r", &Fig8Row::r}, {"c_fit", &Fig8Row::c_fit}, {"c_fit_err", &Fig8Row::c_err}, {"c_theory", &Fig8Row::c_th},
        {"line_departure", &Fig8Row::dev}, {"line_departure_err", &Fig8Row::dev_err},
        {"aniso_onset_cn_median", &Fig8Row::onset}, {"aniso_max_mean", &Fig8Row::max_aniso},
        {"aniso_early_mean", &Fig8Row::early_aniso}, {"aniso_onset_cn_q25", &Fig8Row::onset_q25},
        {"aniso_onset_cn_q75", &Fig8Row::onset_q75}};
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
    res.put(out_aniso_early_mean_max, worst_early);
    res.put(out_line_departure_min_r_le_095, smallest_dev_strong);
    res.put(out_line_departure_max_r_gt_095, largest_dev_weak);
    res.put(out_c_fit_order_violations, c_viol);
    res.put(out_aniso_max_best, *std::max_element(max_aniso.begin(), max_aniso.end()));
    const OnsetOrder all = onset_order(rows, -INFINITY);
    res.put(out_aniso_onset_order_violations, all.violations);
    res.put(out_aniso_onset_order_fraction, all.fraction());
    res.put(out_aniso_onset_order_fraction_r_ge_06, onset_order(rows, 0.6 - 1e-12).fraction());
    res.put(out_aniso_max_min_r_le_06, max_strong);
}

} // namespace

void report_fig8(Result& res, const ParameterStudySpec& s, const Sweep& sw) { report_fig8_summary(res, report_fig8_rows(res, s, sw)); }

} // namespace granrepro::experiments::parameter_study_detail
