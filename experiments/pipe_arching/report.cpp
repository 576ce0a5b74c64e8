// pipe-arching's report over the seeds: relaxation, Fig. 14's fits, the seed table, arch and crack times, Sec. 5's statements, costs.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>

#include "analysis/seed_stats.hpp"
#include "experiments/pipe_arching/spec.hpp"

namespace granrepro::experiments::pipe_arching_detail {

namespace {

double fraction_below(const std::vector<double>& v, double x) {
    const auto k = std::ranges::count_if(v, [x](double y) { return !std::isnan(y) && y <= x + 1e-12; });
    return double(k) / double(v.size());
}
// Share of the finite values for which pred holds (NaN if none is finite).
template <class Pred> double share_finite(const std::vector<double>& v, Pred pred) {
    double k = 0, n = 0;
    for (double y : v)
        if (std::isfinite(y)) { n += 1; k += pred(y) ? 1 : 0; }
    return n > 0 ? k / n : NAN;
}

const ScalarOut out_vbar_t0 = outputs.scalar("vbar_t0", "m/s", "v̄ = sqrt(<v^2>) at t = 0, median over seeds");
const ScalarOut out_vbar_t0_run0 = outputs.scalar("vbar_t0_run0", "m/s", "v̄ at t = 0, run 0");
const ScalarOut out_vbar_relax_drift = outputs.scalar("vbar_relax_drift", "1",
    "v̄(0) over the mean v̄ of the last third of the relaxation, minus 1 (steadiness)");

// v̄ at t = 0 over seeds, after the elastic relaxation.
void report_relaxation(Result& res, const std::vector<SeedRun>& runs) {
    const std::vector<double> v0s = column(runs, &SeedRun::vbar0), vlate = column(runs, &SeedRun::vbar_relax_late);
    res.put(out_vbar_t0, median(v0s));
    res.put(out_vbar_t0_run0, runs.front().vbar0);
    res.put(out_vbar_relax_drift, median(v0s) / median(vlate) - 1);
}

const TableOut out_fits_per_time = outputs.table("fits_per_time",
    "Eq. (21) A (Fig. 14(a) times) or Eq. (22) B (Fig. 14(b) times) fitted at each time alone: run 0 with its standard error, and the median over seeds");
// Per time (<n>, three decimals) of A (Fig. 14(a)) or B (14(b)) (<w>); the description names the
// equation, so it is written at run time.
const ScalarOut out_fit_at = outputs.scalar("<w>_t<n>", "1/s", "", {"A", "B"});
const ScalarOut out_fit_err_at = outputs.scalar("<w>_err_t<n>", "1/s", "its standard error", {"A", "B"});
const ScalarOut out_fit_at_median_seeds = outputs.scalar("<w>_t<n>_median_seeds", "1/s", "", {"A", "B"});

// Fig. 14 per time: the fits at each time alone (run 0 with its error, median over seeds).
void report_fig14_times(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    const SeedRun& f0 = runs.front();
    const std::size_t n_before = s.dist_times_before.size();
    Table& pt = res.table(out_fits_per_time);
    std::vector<double> tt, v0, e0, med;
    for (std::size_t k = 0; k < f0.per_time.size(); ++k) {
        const double t = f0.per_time[k].t;
        tt.push_back(t);
        v0.push_back(f0.per_time[k].value);
        e0.push_back(f0.per_time[k].error);
        med.push_back(median(column(runs, [&](const SeedRun& r) { return r.per_time.at(k).value; })));
        const std::string what = k < n_before ? "A" : "B", eq = k < n_before ? "Eq. (21)" : "Eq. (22)";
        res.put(out_fit_at, v0.back(), {what, ttext(t)}, eq + " fit at this time alone, run 0");
        res.put(out_fit_err_at, e0.back(), {what, ttext(t)});
        res.put(out_fit_at_median_seeds, med.back(), {what, ttext(t)}, eq + " fit at this time alone, median over seeds");
    }
    pt.add({{"t", "s", tt}, {"run0", "1/s", v0}, {"run0_err", "1/s", e0}, {"median_seeds", "1/s", med}});
}

const ScalarOut out_A_fit = outputs.scalar("A_fit", "1/s", "Eq. (21), pooled over the Fig. 14(a) times, run 0");
const ScalarOut out_A_fit_err = outputs.scalar("A_fit_err", "1/s", "its standard error (Cramer-Rao)");
const ScalarOut out_A_fit_chi2_reduced = outputs.scalar("A_fit_chi2_reduced", "1", "Pearson chi^2/dof of that fit");
const ScalarOut out_B_fit = outputs.scalar("B_fit", "1/s", "Eq. (22), pooled over the Fig. 14(b) times, run 0");
const ScalarOut out_B_fit_err = outputs.scalar("B_fit_err", "1/s", "its standard error (Cramer-Rao)");
const ScalarOut out_B_fit_chi2_reduced = outputs.scalar("B_fit_chi2_reduced", "1", "Pearson chi^2/dof of that fit");
const ScalarOut out_A_fit_per_window = outputs.scalar("A_fit_per_window", "1", "A in collisions per dist_dt window");
const ScalarOut out_mean_Nc_before = outputs.scalar("mean_Nc_before", "1/s", "mean N_c at the Fig. 14(a) times, run 0");
const ScalarOut out_fig14_times_before_median = outputs.scalar("fig14_times_before_median", "1",
    "Fig. 14(a) times before the run's first arch, pooled into A, median over seeds");
const ScalarOut out_fig14_times_after_median = outputs.scalar("fig14_times_after_median", "1",
    "Fig. 14(b) times after the run's first arch, pooled into B, median over seeds");
const ScalarOut out_A_fit_median_seeds = outputs.scalar("A_fit_median_seeds", "1/s", "Eq. (21) A, median over seeds");
const ScalarOut out_B_fit_median_seeds = outputs.scalar("B_fit_median_seeds", "1/s", "Eq. (22) B, median over seeds");
const ScalarOut out_B_over_A_median_seeds = outputs.scalar("B_over_A_median_seeds", "1",
    "B/A per seed, median (unit-free)");
const ScalarOut out_B_over_A_fraction_below_paper = outputs.scalar("B_over_A_fraction_below_paper", "1",
    "fraction of seeds with B/A <= 14, the paper's value (its percentile in our distribution)");
const ScalarOut out_B_fraction_below_paper = outputs.scalar("B_fraction_below_paper", "1",
    "fraction of seeds with B <= 14e3 1/s (the paper's B in reading 1)");
const ScalarOut out_B_rel_median_seeds = outputs.scalar("B_rel_median_seeds", "1/s",
    "Eq. (22) B at the Fig. 14(b) times shifted by each seed's t_arch - t_arch_paper, median over seeds with an arch");
const ScalarOut out_B_rel_fraction_below_paper = outputs.scalar("B_rel_fraction_below_paper", "1",
    "fraction of those seeds with B_rel <= 14e3 1/s (the paper's B in reading 1)");
const ScalarOut out_B_rel_over_A_fraction_below_paper = outputs.scalar("B_rel_over_A_fraction_below_paper", "1",
    "fraction of seeds with B_rel / A <= 14, the paper's B/A");
const ScalarOut out_fig14_times_rel_median = outputs.scalar("fig14_times_rel_median", "1",
    "arch-relative Fig. 14(b) times within the fall, pooled into B_rel, median over seeds with an arch");
const ScalarOut out_A_fit_seed_sem = outputs.scalar("A_fit_seed_sem", "1/s",
    "standard error of the mean of A over seeds");
const ScalarOut out_B_fit_seed_sem = outputs.scalar("B_fit_seed_sem", "1/s",
    "standard error of the mean of B over seeds");
const ScalarOut out_B_over_A_seed_sem = outputs.scalar("B_over_A_seed_sem", "1",
    "standard error of the mean of B/A over seeds");
const ScalarOut out_B_over_A_seed_sd = outputs.scalar("B_over_A_seed_sd", "1", "standard deviation of B/A over seeds");
const ScalarOut out_A_in_1e3_per_s = outputs.scalar("A_in_1e3_per_s", "1",
    "A, median over seeds, in 1e3 1/s (reading 1: paper 1)");
const ScalarOut out_B_in_1e3_per_s = outputs.scalar("B_in_1e3_per_s", "1",
    "B, median over seeds, in 1e3 1/s (reading 1: paper 14)");
const ScalarOut out_A_per_window = outputs.scalar("A_per_window", "1",
    "A, median over seeds, in collisions per dist_dt (reading 2: paper 1)");
const ScalarOut out_B_per_window = outputs.scalar("B_per_window", "1",
    "B, median over seeds, in collisions per dist_dt (reading 2: paper 14)");
const TableOut out_fits = outputs.table("fits",
    "Eqs. (21), (22) pooled over each panel's four times, as drawn in Fig. 14 and checked: median over seeds, standard error of the mean over seeds, run 0 with its fit error");
const ScalarOut out_exp_over_pow_deviance_before = outputs.scalar("exp_over_pow_deviance_before", "1",
    "deviance of Eq. (21) over that of Eq. (22), Fig. 14(a) times, median over seeds (< 1: exponential fits better)");
const ScalarOut out_exp_over_pow_deviance_after = outputs.scalar("exp_over_pow_deviance_after", "1",
    "the same at the Fig. 14(b) times (> 1: power law fits better)");

// Fig. 14 pooled: Eqs. (21), (22) over each panel's four times, run 0 and over seeds (the
// claims' values), in both readings of the paper's units.
void report_fig14_fits(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    const SeedRun& f0 = runs.front();
    const double ddt = s.dist_dt;
    res.put(out_A_fit, f0.A);
    res.put(out_A_fit_err, f0.A_err);
    res.put(out_A_fit_chi2_reduced, f0.A_chi2);
    res.put(out_B_fit, f0.B);
    res.put(out_B_fit_err, f0.B_err);
    res.put(out_B_fit_chi2_reduced, f0.B_chi2);
    res.put(out_A_fit_per_window, f0.A * ddt);
    res.put(out_mean_Nc_before, f0.mean_rate_early);
    const std::vector<double> As = column(runs, &SeedRun::A), Bs = column(runs, &SeedRun::B);
    const auto BA = column(runs, [](const SeedRun& r) { return r.B / r.A; });
    // Deviance of the exponential over that of the power law: < 1 where Eq. (21) fits better.
    const auto ratio_early = column(runs, [](const SeedRun& r) { return r.dev_exp_early / r.dev_pow_early; });
    const auto ratio_late = column(runs, [](const SeedRun& r) { return r.dev_exp_late / r.dev_pow_late; });
    res.put(out_fig14_times_before_median, median(column(runs, &SeedRun::times_before)));
    res.put(out_fig14_times_after_median, median(column(runs, &SeedRun::times_after)));
    res.put(out_A_fit_median_seeds, median(As));
    res.put(out_B_fit_median_seeds, median(Bs));
    res.put(out_B_over_A_median_seeds, median(BA));
    // The paper's numbers come from one run: where they fall in our distribution over seeds.
    res.put(out_B_over_A_fraction_below_paper, share_finite(BA, [](double y) { return y <= 14.0; }));
    res.put(out_B_fraction_below_paper, share_finite(Bs, [](double y) { return y <= 14.0e3; }));
    const std::vector<double> Brel = column(runs, &SeedRun::B_rel);
    res.put(out_B_rel_median_seeds, median(Brel));
    res.put(out_B_rel_fraction_below_paper, share_finite(Brel, [](double y) { return y <= 14.0e3; }));
    res.put(out_B_rel_over_A_fraction_below_paper, share_finite(column(runs, [](const SeedRun& r) { return r.B_rel / r.A; }), [](double y) { return y <= 14.0; }));
    res.put(out_fig14_times_rel_median, median(column(runs, &SeedRun::times_rel)));
    const MeanSd a = mean_sd(As), b = mean_sd(Bs), ba = mean_sd(BA);
    res.put(out_A_fit_seed_sem, a.sem);
    res.put(out_B_fit_seed_sem, b.sem);
    res.put(out_B_over_A_seed_sem, ba.sem);
    res.put(out_B_over_A_seed_sd, ba.sd);
    // The two readings of the paper's 'A = 1, B = 14 s^-1' (Sec. 5): the axis in units of
    // 1e3 1/s, or in collisions per window dist_dt.
    res.put(out_A_in_1e3_per_s, median(As) / 1e3);
    res.put(out_B_in_1e3_per_s, median(Bs) / 1e3);
    res.put(out_A_per_window, median(As) * ddt);
    res.put(out_B_per_window, median(Bs) * ddt);
    Table& ft = res.table(out_fits);
    const std::vector<std::pair<const char*, double>> cols = {
        {"A", median(As)}, {"A_sem", a.sem}, {"A_run0", f0.A}, {"A_run0_err", f0.A_err},
        {"B", median(Bs)}, {"B_sem", b.sem}, {"B_run0", f0.B}, {"B_run0_err", f0.B_err}};
    for (const auto& [name, x] : cols) ft.add(name, "1/s").values = {x};
    ft.add({{"seeds", "1", {double(runs.size())}}, {"dist_dt", "s", {ddt}}});
    res.put(out_exp_over_pow_deviance_before, median(ratio_early));
    res.put(out_exp_over_pow_deviance_after, median(ratio_late));
}

const TableOut out_seeds = outputs.table("seeds",
    "per seed: first hot wall disk, first arch (time, lab and initial height), its precursor, first crack (NaN: none before t_end)");

void report_seed_table(Result& res, const std::vector<SeedRun>& runs) {
    Table& st = res.table(out_seeds);
    st.add("seed_index", "1").values = column(index_order(runs.size()), std::identity{});
    using S = SeedRun;
    const std::vector<std::tuple<const char*, const char*, std::function<double(const SeedRun&)>>> cols = {
        {"t_hot_wall", "s", &S::t_hot_wall}, {"t_precursor", "s", &S::t_precursor}, {"t_arch", "s", &S::t_arch},
        {"y_arch", "d", &S::y_arch}, {"y0_arch", "d", &S::y0_arch}, {"arch_size", "1", &S::arch_size},
        {"arch_foot_pressure_ratio", "1", [](const SeedRun& r) { return std::min(r.arch_pL, r.arch_pR); }},
        {"react_lag", "s", &S::react_lag}, {"arch_left_4ms", "1", &S::arch_left_4ms}, {"plug_wall_load", "1", &S::plug_wall_load},
        {"arch_brake", "m/s", &S::arch_brake}, {"opening_below", "d", &S::opening_below},
        {"wall_slowdown_arch", "m/s", &S::wall_slowdown_arch}, {"opening_max_after", "d", &S::opening_max_after},
        {"t_crack", "s", &S::t_crack}, {"y_crack", "d", &S::y_crack}, {"y0_crack", "d", &S::y0_crack},
        {"crack_opening", "d", &S::crack_opening}, {"opening_max_before", "d", &S::opening_max_before},
        {"opening_max_all", "d", &S::opening_max_all}, {"wave_steps", "1", &S::wave_steps},
        {"wave_steps_up", "1", &S::wave_steps_up}, {"wave_stronger", "1", &S::wave_stronger},
        {"friction_share", "1", &S::friction_share}, {"A", "1/s", &S::A},
        {"B", "1/s", &S::B}, {"wall_seconds", "s", &S::wall_seconds}};
    for (const auto& [name, unit, f] : cols) st.add(name, unit).values = column(runs, f);
}

const TableOut out_arch_time_cdf = outputs.table("arch_time_cdf", "fraction of seeds with an arch by time t");
const ScalarOut out_arch_fraction = outputs.scalar("arch_fraction", "1", "fraction of seeds with an arch before t_end");
const ScalarOut out_crack_fraction = outputs.scalar("crack_fraction", "1",
    "fraction of seeds with a crack before t_end");
const ScalarOut out_arch_time_fraction_by_paper = outputs.scalar("arch_time_fraction_by_paper", "1",
    "fraction of seeds whose first arch formed by the paper's 0.056 s (its percentile in our distribution)");
const ScalarOut out_precursor_time_fraction_by_paper = outputs.scalar("precursor_time_fraction_by_paper", "1",
    "fraction of seeds whose arch's first hot wall disk appeared by the paper's 0.048 s");
const ScalarOut out_crack_time_fraction_by_paper = outputs.scalar("crack_time_fraction_by_paper", "1",
    "fraction of seeds with a crack by the paper's 0.060 s");
const ScalarOut out_arch_by_0_05_fraction = outputs.scalar("arch_by_0.05_fraction", "1",
    "fraction of seeds whose first arch formed by 0.05 s, the last Fig. 14(a) time");
const ScalarOut out_arch_height_median = outputs.scalar("arch_height_median", "d",
    "lab height of the first arch above the removed floor, median");
const ScalarOut out_arch_initial_height_median = outputs.scalar("arch_initial_height_median", "d",
    "initial (t = 0) height of the first arch's disks, median");
const ScalarOut out_crack_initial_height_median = outputs.scalar("crack_initial_height_median", "d",
    "initial height of the disks bounding the first crack, median");
const ScalarOut out_precursor_lead_median = outputs.scalar("precursor_lead_median", "s",
    "first arch minus its first hot wall disk, median (paper: 0.008 s)");
const ScalarOut out_crack_after_arch_median = outputs.scalar("crack_after_arch_median", "s",
    "first crack minus first arch, median over seeds with both (paper: ~0.004 s)");
const ScalarOut out_crack_arch_height_offset_median = outputs.scalar("crack_arch_height_offset_median", "d",
    "|initial height of first crack - that of first arch|, median over seeds with both");
const ScalarOut out_t_arch_run0 = outputs.scalar("t_arch_run0", "s", "first arch, run 0");
const ScalarOut out_y_arch_run0 = outputs.scalar("y_arch_run0", "d", "its lab height above the removed floor, run 0");
const ScalarOut out_t_precursor_run0 = outputs.scalar("t_precursor_run0", "s", "its first hot wall disk, run 0");
const ScalarOut out_t_crack_run0 = outputs.scalar("t_crack_run0", "s", "first crack, run 0");
const ScalarOut out_y_crack_run0 = outputs.scalar("y_crack_run0", "d", "its lab height, run 0");
// The quartiles over seeds of each time (<w>), described at run time by what it is the time of.
const Words seed_times = {"t_arch", "t_precursor", "t_hot_wall", "t_crack"};
const ScalarOut out_time_q = outputs.scalar("<w>_q<n>", "s", "", seed_times);
const ScalarOut out_time_median = outputs.scalar("<w>_median", "s", "", seed_times);

// First arch, its first hot wall disk and first crack over seeds: when (censored at t_end),
// where, and where the paper's single run falls in that distribution.
void report_arch_times(Result& res, const std::vector<SeedRun>& runs) {
    const std::vector<double> ta = column(runs, &SeedRun::t_arch), tp = column(runs, &SeedRun::t_precursor);
    const std::vector<double> tw = column(runs, &SeedRun::t_hot_wall), tc = column(runs, &SeedRun::t_crack);
    const auto crack_after_arch = column(runs, [](const SeedRun& r) { return r.t_crack - r.t_arch; });
    const auto crack_near_arch = column(runs, [](const SeedRun& r) { return std::abs(r.y0_crack - r.y0_arch); });
    const auto precursor_lead = column(runs, [](const SeedRun& r) { return r.t_arch - r.t_precursor; });
    // Empirical distribution of the first-arch time over all seeds (those without an arch never count).
    std::vector<double> tt, fr;
    std::copy_if(ta.begin(), ta.end(), std::back_inserter(tt), [](double x) { return std::isfinite(x); });
    std::sort(tt.begin(), tt.end());
    for (std::size_t k = 0; k < tt.size(); ++k) fr.push_back(double(k + 1) / double(ta.size()));
    Table& cd = res.table(out_arch_time_cdf);
    cd.add({{"t_arch", "s", tt}, {"fraction", "1", fr}});
    auto quartiles = [&](const std::string& name, const std::vector<double>& v, const std::string& what) {
        res.put(out_time_q, quantile(v, 0.25, NonFinite::censored), {name, 25}, what + ", lower quartile over seeds (none = +inf)");
        res.put(out_time_median, quantile(v, 0.5, NonFinite::censored), {name}, what + ", median over seeds");
        res.put(out_time_q, quantile(v, 0.75, NonFinite::censored), {name, 75}, what + ", upper quartile over seeds");
    };
    quartiles("t_arch", ta, "first arch");
    quartiles("t_precursor", tp, "first hot wall disk of the first arch");
    quartiles("t_hot_wall", tw, "first hot disk at a wall (any)");
    quartiles("t_crack", tc, "first crack");
    auto happened = [](const std::vector<double>& v) {
        return 1 - double(std::count_if(v.begin(), v.end(), [](double x) { return std::isnan(x); })) / double(v.size());
    };
    res.put(out_arch_fraction, happened(ta));
    res.put(out_crack_fraction, happened(tc));
    res.put(out_arch_time_fraction_by_paper, fraction_below(ta, 0.056));
    res.put(out_precursor_time_fraction_by_paper, fraction_below(tp, 0.048));
    res.put(out_crack_time_fraction_by_paper, fraction_below(tc, 0.060));
    // Section 5 takes P(N_c) at 0.02-0.05 s as "before the first arch (or crack) occurs".
    res.put(out_arch_by_0_05_fraction, fraction_below(ta, 0.05));
    res.put(out_arch_height_median, median(column(runs, &SeedRun::y_arch)));
    res.put(out_arch_initial_height_median, median(column(runs, &SeedRun::y0_arch)));
    res.put(out_crack_initial_height_median, median(column(runs, &SeedRun::y0_crack)));
    res.put(out_precursor_lead_median, median(precursor_lead));
    res.put(out_crack_after_arch_median, median(crack_after_arch));
    res.put(out_crack_arch_height_offset_median, median(crack_near_arch));
    const SeedRun& f0 = runs.front();
    res.put(out_t_arch_run0, f0.t_arch);
    res.put(out_y_arch_run0, f0.y_arch);
    res.put(out_t_precursor_run0, f0.t_precursor);
    res.put(out_t_crack_run0, f0.t_crack);
    res.put(out_y_crack_run0, f0.y_crack);
}

const ScalarOut out_fluid_layers_median = outputs.scalar("fluid_layers_median", "1",
    "top rows at t = 0 in which at least half of the disks lost a lattice neighbour, median");
const ScalarOut out_lattice_broken_below_max = outputs.scalar("lattice_broken_below_max", "1",
    "share of the disks below those rows that lost a lattice neighbour, largest over seeds");
const ScalarOut out_react_lag_median = outputs.scalar("react_lag_median", "s",
    "first frame with half of the initiating disk's neighbours hot, minus its first hot frame, median (paper: 0.004 s)");
const ScalarOut out_arch_left_4ms_median = outputs.scalar("arch_left_4ms_median", "1",
    "share of the first arch's disks still hot 4 ms after it spanned the width, median");
const ScalarOut out_arch_above_later_fraction = outputs.scalar("arch_above_later_fraction", "1",
    "seeds with a later arch (after the first + 4 ms) more than arch_separation above the first");
const ScalarOut out_arch_below_later_fraction = outputs.scalar("arch_below_later_fraction", "1", "the same below");
const ScalarOut out_arch_above_and_below_fraction = outputs.scalar("arch_above_and_below_fraction", "1",
    "seeds with later arches both above and below");
const ScalarOut out_plug_wall_load_median = outputs.scalar("plug_wall_load_median", "1",
    "wall impulse on the arch's plug within 4 ms of the arch over the plug's weight times that time, median (1: the walls hold the plug)");
const ScalarOut out_plug_wall_load_over_mean_median = outputs.scalar("plug_wall_load_over_mean_median", "1",
    "plug_wall_load over the column's wall share over the whole fall, per seed, median (> 1: the walls hold the plug harder than the column)");
const ScalarOut out_arch_brake_median = outputs.scalar("arch_brake_median", "m/s",
    "largest gain of v_y(plug) - v_y(material below) within arch_window of the arch, median (> 0: the plug falls slower)");
const ScalarOut out_opening_below_median = outputs.scalar("opening_below_median", "d",
    "largest growth of the distance between plug and material below within arch_window of the arch, median");
const ScalarOut out_opening_below_fraction_visible = outputs.scalar("opening_below_fraction_visible", "1",
    "fraction of seeds whose plug and material below moved apart by at least crack_opening (opening_below)");
const ScalarOut out_opening_max_after_fraction_visible = outputs.scalar("opening_max_after_fraction_visible", "1",
    "fraction of seeds with a wall-to-wall gap of at least crack_opening within arch_window after the first arch");
const ScalarOut out_local_opening_after_median = outputs.scalar("local_opening_after_median", "d",
    "widest local opening at the initiating disk's wall over its own width within arch_window after the first arch, median over seeds with an arch");
const ScalarOut out_local_opening_after_fraction_visible = outputs.scalar("local_opening_after_fraction_visible", "1",
    "fraction of seeds whose local opening at the initiating disk reaches crack_opening within arch_window after the first arch");
const ScalarOut out_local_crack_lag_median = outputs.scalar("local_crack_lag_median", "s",
    "first time the local opening at the initiating disk reaches crack_opening, minus the first arch, median over seeds (none = +inf)");
const ScalarOut out_local_crack_fraction_by_paper = outputs.scalar("local_crack_fraction_by_paper", "1",
    "fraction of seeds whose local opening at the initiating disk reaches crack_opening by 0.060 s - t_arch_paper after their own arch (the paper's crack time)");
const ScalarOut out_opening_max_before_median = outputs.scalar("opening_max_before_median", "d",
    "widest wall-to-wall crack before the first arch, median over seeds (the falling column's own gaps)");
const ScalarOut out_opening_max_after_median = outputs.scalar("opening_max_after_median", "d",
    "widest wall-to-wall crack within arch_window after the first arch, median");
const ScalarOut out_opening_max_all_median = outputs.scalar("opening_max_all_median", "d",
    "widest wall-to-wall crack at any frame from t_detect_min on, median over seeds");
const ScalarOut out_wave_steps_total = outputs.scalar("wave_steps_total", "1",
    "steps between successive distinct arches, summed over seeds");
const ScalarOut out_wave_ascend_share = outputs.scalar("wave_ascend_share", "1",
    "share of those steps in which the new wave starts higher than the previous one");
const ScalarOut out_wave_ascend_z = outputs.scalar("wave_ascend_z", "1",
    "wave_ascend_share minus one half, in binomial standard errors sqrt(0.25 / wave_steps_total)");
const ScalarOut out_wave_stronger_fraction = outputs.scalar("wave_stronger_fraction", "1",
    "seeds in which a later wave (arch more than arch_separation from the first, after its first 4 ms) had more hot disks than the first arch, among seeds with an arch");
const ScalarOut out_crack_below_arch_median = outputs.scalar("crack_below_arch_median", "d",
    "initial height of the first arch minus that of the first crack, median (> 0: crack below)");
const ScalarOut out_crack_at_initiator_median = outputs.scalar("crack_at_initiator_median", "d",
    "crack course at the initiating disk's wall minus the disk's height, at the crack's first frame, median");
const ScalarOut out_wall_slowdown_arch_mean = outputs.scalar("wall_slowdown_arch_mean", "m/s",
    "v_y(wall disks) - v_y(inner disks) of the plug at the arch, mean over seeds (> 0: wall disks slower)");
const ScalarOut out_wall_slowdown_gain_mean = outputs.scalar("wall_slowdown_gain_mean", "m/s",
    "the same minus its value arch_window before the arch, mean over seeds");
const ScalarOut out_wall_slowdown_gain_z = outputs.scalar("wall_slowdown_gain_z", "1",
    "that mean over its standard error (seed scatter)");
const ScalarOut out_wall_load_peak_median = outputs.scalar("wall_load_peak_median", "1",
    "largest 5-frame mean of the walls' share of the weight, median over seeds");
// The distribution over seeds of the widest gap (<w>: over all frames, or after the arch).
const Words widest_gaps = {"opening_max_all", "opening_max_after"};
const ScalarOut out_opening_q = outputs.scalar("<w>_q<n>", "d", "its ", widest_gaps);
const ScalarOut out_opening_max = outputs.scalar("<w>_max", "d", "its largest value over seeds", widest_gaps);

// The section's other statements (Sec. 5), per seed, then over seeds.
void report_section(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    auto med = [&](double SeedRun::*f) { return median(column(runs, f)); };
    res.put(out_fluid_layers_median, med(&SeedRun::fluid_layers));
    double broken = 0;
    for (double x : column(runs, &SeedRun::lattice_broken_below)) broken = std::max(broken, x);
    res.put(out_lattice_broken_below_max, broken);
    res.put(out_react_lag_median, med(&SeedRun::react_lag));
    res.put(out_arch_left_4ms_median, med(&SeedRun::arch_left_4ms));
    // Later arches above and below are 0 or 1, and NaN together (no frame 4 ms after the first).
    const auto above = column(runs, &SeedRun::arch_above_later), below = column(runs, &SeedRun::arch_below_later);
    const auto both = column(runs, [](const SeedRun& r) { return r.arch_above_later * r.arch_below_later; });
    auto one = [](double y) { return y == 1.0; };
    res.put(out_arch_above_later_fraction, share_finite(above, one));
    res.put(out_arch_below_later_fraction, share_finite(below, one));
    res.put(out_arch_above_and_below_fraction, share_finite(both, one));
    res.put(out_plug_wall_load_median, med(&SeedRun::plug_wall_load));
    const auto rel = column(runs, [](const SeedRun& r) { return r.plug_wall_load / r.friction_share; });
    res.put(out_plug_wall_load_over_mean_median, median(rel));
    res.put(out_arch_brake_median, med(&SeedRun::arch_brake));
    res.put(out_opening_below_median, med(&SeedRun::opening_below));
    // Rule 'single run' (expected/README.md): a feature of the paper's one run must appear in at
    // least one seed in ten; over all seeds (a seed without an arch has neither).
    auto visible = [&](double SeedRun::*f) {
        return fraction_below(column(runs, [&](const SeedRun& r) { return -(r.*f); }), -s.crack_opening);
    };
    res.put(out_opening_below_fraction_visible, visible(&SeedRun::opening_below));
    res.put(out_opening_max_after_fraction_visible, visible(&SeedRun::opening_max_after));
    // Fig. 13's crack "at the position of the initiating particle" read as a local opening beside
    // that disk at its wall (local_crack, issue 43 §1): the paper's is visible from 0.060 s, 4 ms
    // after its arch at t_arch_paper = 0.056 s; ours is timed from each seed's own arch (as B_rel).
    res.put(out_local_opening_after_median, med(&SeedRun::local_opening_after));
    res.put(out_local_opening_after_fraction_visible, visible(&SeedRun::local_opening_after));
    const auto lag = column(runs, [](const SeedRun& r) { return r.t_local_crack - r.t_arch; });
    res.put(out_local_crack_lag_median, quantile(lag, 0.5, NonFinite::censored));
    res.put(out_local_crack_fraction_by_paper, fraction_below(lag, 0.060 - s.t_arch_paper));
    res.put(out_opening_max_before_median, med(&SeedRun::opening_max_before));
    res.put(out_opening_max_after_median, med(&SeedRun::opening_max_after));
    res.put(out_opening_max_all_median, med(&SeedRun::opening_max_all));
    // The distribution of the widest gap, not only crack yes/no (issue 27).
    for (const auto& [name, f] : {std::pair{"opening_max_all", &SeedRun::opening_max_all}, std::pair{"opening_max_after", &SeedRun::opening_max_after}}) {
        std::vector<double> v = column(runs, f);
        std::erase_if(v, [](double x) { return !std::isfinite(x); });
        res.put(out_opening_q, v.empty() ? NAN : quantile(v, 0.25, NonFinite::censored), {name, 25}, "lower quartile over seeds");
        res.put(out_opening_q, v.empty() ? NAN : quantile(v, 0.75, NonFinite::censored), {name, 75}, "upper quartile over seeds");
        res.put(out_opening_max, v.empty() ? NAN : *std::max_element(v.begin(), v.end()), {name});
    }
    // Successive waves (arch_aftermath): the share of steps that rise, pooled over seeds, and the
    // seeds in which a later wave is stronger than the first arch, among the seeds with an arch.
    double steps = 0, up = 0;
    for (const SeedRun& r : runs)
        if (std::isfinite(r.wave_steps)) { steps += r.wave_steps; up += r.wave_steps_up; }
    res.put(out_wave_steps_total, steps);
    res.put(out_wave_ascend_share, steps > 0 ? up / steps : NAN);
    // Rule 'sign' of expected/README.md: the share's distance from one half in binomial standard
    // errors sqrt(0.25 / n), so the claim's threshold (2) does not depend on the run's n.
    res.put(out_wave_ascend_z, steps > 0 ? (up / steps - 0.5) / std::sqrt(0.25 / steps) : NAN);
    res.put(out_wave_stronger_fraction, share_finite(column(runs, &SeedRun::wave_stronger), [](double y) { return y == 1.0; }));
    res.put(out_crack_below_arch_median, med(&SeedRun::crack_below_arch));
    res.put(out_crack_at_initiator_median, med(&SeedRun::crack_at_initiator));
    // Disks at the walls slow down (Sec. 5): v_y(wall) - v_y(inside) in the plug at the arch,
    // against the same at the window's start; the mean difference over seeds and its z-score.
    const MeanSd ws = mean_sd(column(runs, &SeedRun::wall_slowdown_arch));
    const MeanSd dd = mean_sd(column(runs, [](const SeedRun& r) { return r.wall_slowdown_arch - r.wall_slowdown_before; }));
    res.put(out_wall_slowdown_arch_mean, ws.mean);
    res.put(out_wall_slowdown_gain_mean, dd.mean);
    res.put(out_wall_slowdown_gain_z, dd.sem > 0 ? dd.mean / dd.sem : NAN);
    res.put(out_wall_load_peak_median, med(&SeedRun::wall_load_peak));
}

const ScalarOut out_momentum_balance_residual_max = outputs.scalar("momentum_balance_residual_max", "1",
    "max over seeds of |dP_y - (-M g t + J_wall)| / (M g t) over the fall");
const ScalarOut out_wall_friction_share = outputs.scalar("wall_friction_share", "1",
    "side-wall impulse over M g t_end, median (0: free fall)");
const ScalarOut out_seconds_per_seed_median = outputs.scalar("seconds_per_seed_median", "s",
    "wall time of one seed (relaxation + fall)");
const ScalarOut out_collisions_per_seed_median = outputs.scalar("collisions_per_seed_median", "1",
    "pair collisions during the fall, median");
const ScalarOut out_tc_elastic_share_median = outputs.scalar("tc_elastic_share_median", "1",
    "share of the fall's pair collisions made elastic by TC");

// Momentum balance and costs.
void report_costs(Result& res, const std::vector<SeedRun>& runs) {
    const auto resid = column(runs, [](const SeedRun& r) { return std::abs(r.momentum_residual); });
    res.put(out_momentum_balance_residual_max, *std::max_element(resid.begin(), resid.end()));
    res.put(out_wall_friction_share, median(column(runs, &SeedRun::friction_share)));
    res.put(out_seconds_per_seed_median, median(column(runs, &SeedRun::wall_seconds)));
    res.put(out_collisions_per_seed_median, median(column(runs, &SeedRun::collisions)));
    res.put(out_tc_elastic_share_median, median(column(runs, &SeedRun::elastic_share)));
}

} // namespace

void report_seeds(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    report_relaxation(res, runs);
    report_fig14_times(res, s, runs);
    report_fig14_fits(res, s, runs);
    report_seed_table(res, runs);
    report_arch_times(res, runs);
    report_section(res, s, runs);
    report_costs(res, runs);
}

} // namespace granrepro::experiments::pipe_arching_detail
