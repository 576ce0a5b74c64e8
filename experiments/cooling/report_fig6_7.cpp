// cooling, Figs. 6 and 7: g(r/d) and S(k) at the snapshot times (ED, DSMC against ED, the DSMC
// cell lattice's imprint), and the pair velocity correlations.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "analysis/seed_stats.hpp"
#include "experiments/cooling/spec.hpp"
#include "observables/velocity_correlation.hpp"

namespace granrepro::experiments::cooling_detail {

namespace {

// Mean over 1 <= k <= k_max of ln(S_a/S_b), or of |ln(S_a/S_b)| (shells where both are positive).
double mean_log_ratio(const std::vector<double>& sa, const std::vector<double>& sb, const std::vector<double>& k, double k_max,
                      bool absolute = false) {
    double sum = 0;
    int cnt = 0;
    for (std::size_t i = 0; i < k.size() && i < sa.size() && i < sb.size(); ++i)
        if (k[i] >= 1 && k[i] <= k_max && sa[i] > 0 && sb[i] > 0) {
            sum += absolute ? std::abs(std::log(sa[i] / sb[i])) : std::log(sa[i] / sb[i]);
            ++cnt;
        }
    return cnt ? sum / cnt : NAN;
}

// A bump of S(k) at shell kc (the DSMC cell lattice, box/cell, folded into the FFT range by the
// NGP aliasing of an M-point grid): mean S over kc +- 2 over the geometric mean of the mean S over
// the flanks 0.75 kc +- 2 and 1.25 kc +- 2 (a flank beyond M/2 is left out). A smooth S(k) gives
// about 1.
double bump_contrast(const std::vector<double>& S, const std::vector<double>& k, double kc) {
    const double kmax = k.empty() ? 0 : k.back();
    const double centre = mean_over(S, k, kc - 2, kc + 2);
    const double lo = mean_over(S, k, 0.75 * kc - 2, 0.75 * kc + 2);
    const double hi = 1.25 * kc + 2 <= kmax ? mean_over(S, k, 1.25 * kc - 2, 1.25 * kc + 2) : NAN;
    return std::isfinite(hi) ? centre / std::sqrt(lo * hi) : centre / lo;
}

// The snapshot at t = 20 s (S(k) stops changing after it; issue 3), if the run has one.
std::optional<std::size_t> snapshot_20s(const std::vector<double>& snaps) {
    std::optional<std::size_t> at;
    for (std::size_t i = 0; i < snaps.size(); ++i)
        if (std::abs(snaps[i] - 20.0) < 1e-9) at = i;
    return at;
}

// chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 over r/d >= r_lo, with
// the counting errors of both, and the number of bins.
std::array<double, 2> early_g_chi2(const Trace& ed, double r_lo) {
    const Snapshot &a = ed.snaps[0], &b = ed.snaps[1];
    double chi2 = 0;
    int bins = 0;
    for (std::size_t i = 0; i < ed.g_r.size(); ++i)
        if (ed.g_r[i] >= r_lo) {
            const double var = a.g_err[i] * a.g_err[i] + b.g_err[i] * b.g_err[i];
            if (var > 0) {
                chi2 += (b.g[i] - a.g[i]) * (b.g[i] - a.g[i]) / var;
                ++bins;
            }
        }
    return {bins ? chi2 / bins : NAN, double(bins)};
}

} // namespace

// Mean S(1 <= k <= k_max) of one snapshot of a trace.
double small_k_S(const Trace& tr, const Snapshot& at, double k_max) { return mean_over(at.S, tr.S_k, 1, k_max); }

// <w>: the method, ed or dsmc.
const TableOut out_gr = outputs.table("gr_<w>", "g(r/d) at the snapshot times, ", {"ed", "dsmc"});
const TableOut out_sk = outputs.table("sk_<w>", "S(k), k = l/lambda, at the snapshot times, ", {"ed", "dsmc"});

// Figs. 6 and 7: g(r/d) and S(k) of one method at the snapshot times.
void add_structure_tables(Result& res, const Trace& tr, const std::vector<double>& snaps, double rho, const char* name) {
    {
        Table& g = res.table(out_gr, {name}, name);
        g.add("r_over_d", "1").values = tr.g_r;
        for (std::size_t i = 0; i < tr.snaps.size(); ++i) g.add("g_t" + number_text(snaps[i]), "1").values = tr.snaps[i].g;
    }
    Table& sk = res.table(out_sk, {name}, name);
    sk.add("k", "1").values = tr.S_k;
    for (std::size_t i = 0; i < tr.snaps.size(); ++i) sk.add("S_t" + number_text(snaps[i]), "1").values = tr.snaps[i].S;
    sk.add("S_equilibrium", "1").values = std::vector<double>(tr.S_k.size(), theory::hard_disk_structure_factor_zero(rho));
}

// <w>: the method, ed or dsmc; <n>: the snapshot time.
const TableOut out_vcorr = outputs.table("vcorr_<w>",
    "pair velocity correlations C_n, C_t (mean over seeds) at the snapshot times, ", {"ed", "dsmc"});
const ScalarOut out_vcorr_n_contact = outputs.scalar("<w>_vcorr_n_contact_t<n>", "1",
    "C_n of pairs at d <= r < 1.1 d, mean over seeds (molecular chaos: 0)", {"ed", "dsmc"});
const ScalarOut out_vcorr_n_contact_err = outputs.scalar("<w>_vcorr_n_contact_err_t<n>", "1",
    "its standard error over seeds", {"ed", "dsmc"});
const ScalarOut out_vcorr_t_contact = outputs.scalar("<w>_vcorr_t_contact_t<n>", "1",
    "C_t of pairs at d <= r < 1.1 d, mean over seeds", {"ed", "dsmc"});
const ScalarOut out_vcorr_t_contact_err = outputs.scalar("<w>_vcorr_t_contact_err_t<n>", "1",
    "its standard error over seeds", {"ed", "dsmc"});
const ScalarOut out_vcorr_approach_contact = outputs.scalar("<w>_vcorr_approach_contact_t<n>", "1",
    "<g_n^2 | approaching> / (2 T1) of pairs at d <= r < 1.1 d, mean over seeds (molecular chaos: 1)", {"ed", "dsmc"});
const ScalarOut out_vcorr_approach_contact_err = outputs.scalar("<w>_vcorr_approach_contact_err_t<n>", "1",
    "its standard error over seeds", {"ed", "dsmc"});

// The pair velocity correlations of one method at the snapshot times, seed means (issue 27 §3:
// does the gas keep molecular chaos at t = 0, and how fast do correlations build up?): a table over
// r/d, and at contact (d <= r < 1.1 d) per snapshot the mean over seeds and its standard error
// over seeds (NaN with one seed: the pairs of one snapshot share particles, so their own spread
// would understate it).
void add_velocity_correlation(Result& res, const CoolingSpec& c, const std::vector<Trace>& trs, const char* name) {
    const std::vector<double> snaps = c.snapshots();
    const VelocityCorrelation grid = velocity_correlation(c.box(), c.d);
    Table& t = res.table(out_vcorr, {name}, name);
    const std::vector<double> r = column(grid.centres(), [&](double x) { return x / c.d; });
    t.add("r_over_d", "1").values = r;
    for (std::size_t i = 0; i < snaps.size(); ++i)
        for (const auto& [col, member] :
             {std::pair{"Cn_t", &Snapshot::vc_n}, std::pair{"Ct_t", &Snapshot::vc_t}, std::pair{"A_t", &Snapshot::vc_a}}) {
            std::vector<double> mean(r.size(), 0.0);
            for (const Trace& tr : trs)
                for (std::size_t b = 0; b < r.size(); ++b) mean[b] += (tr.snaps[i].*member)[b] / double(trs.size());
            t.add(col + number_text(snaps[i]), "1").values = mean;
        }
    for (std::size_t i = 0; i < snaps.size(); ++i)
        for (const auto& [mean, sem, member] :
             {std::tuple{&out_vcorr_n_contact, &out_vcorr_n_contact_err, &Snapshot::vc_n},
              std::tuple{&out_vcorr_t_contact, &out_vcorr_t_contact_err, &Snapshot::vc_t},
              std::tuple{&out_vcorr_approach_contact, &out_vcorr_approach_contact_err, &Snapshot::vc_a}}) {
            const MeanSd m = mean_sd(column(trs, [&](const Trace& tr) { return (tr.snaps[i].*member).front(); }));
            res.put(*mean, m.mean, {name, snaps[i]});
            res.put(*sem, m.sem, {name, snaps[i]});
        }
}

const ScalarOut out_ed_g_inside_contact_max = outputs.scalar("ed_g_inside_contact_max", "1",
    "largest g(r/d) for r/d < 0.98, last snapshot, ED");
const ScalarOut out_ed_g_peak_sqrt3_contrast = outputs.scalar("ed_g_peak_sqrt3_contrast", "1",
    "max g near sqrt(3) over min g in [1.4, 1.6], last snapshot, ED");
// The peaks at 2 and 3 d (<n>); each write completes the description with its own ranges.
const ScalarOut out_ed_g_peak_contrast = outputs.scalar("ed_g_peak_<n>_contrast", "1", "max g near ");
const ScalarOut out_ed_g_contact = outputs.scalar("ed_g_contact", "1", "g at contact, last snapshot, ED");
const ScalarOut out_ed_g_early_vs_elastic_chi2 = outputs.scalar("ed_g_early_vs_elastic_chi2", "1",
    "chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 (elastic), 0.98 <= r/d <= 5, ED");
const ScalarOut out_ed_g_early_vs_elastic_chi2_beyond_contact = outputs.scalar("ed_g_early_vs_elastic_chi2_beyond_contact", "1",
    "the same over 1.1 <= r/d <= 5");
const ScalarOut out_ed_g_early_vs_elastic_bins_beyond_contact = outputs.scalar("ed_g_early_vs_elastic_bins_beyond_contact", "1",
    "bins in that range");
const ScalarOut out_ed_g_early_time_over_t0 = outputs.scalar("ed_g_early_time_over_t0", "1",
    "time of that snapshot in t0");
const ScalarOut out_ed_g_contact_early_over_elastic = outputs.scalar("ed_g_contact_early_over_elastic", "1",
    "contact value of g at the first snapshot after t = 0 over that at t = 0, ED");
const ScalarOut out_ed_g_early_vs_elastic_chi2_beyond_contact_mean = outputs.scalar("ed_g_early_vs_elastic_chi2_beyond_contact_mean", "1",
    "chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 over 1.1 <= r/d <= 5, ED, mean over seeds");
const ScalarOut out_ed_g_early_vs_elastic_chi2_beyond_contact_mean_sd = outputs.scalar("ed_g_early_vs_elastic_chi2_beyond_contact_mean_sd", "1", "its seed standard deviation");

// Fig. 6, ED: the clustered g at the last snapshot (exclusion hole, the peaks of packed disks at
// sqrt(3), 2 and 3 d, contact value), and early g as elastic.
void add_ed_g(Result& res, const std::vector<Trace>& eds, const std::vector<double>& snaps, double t0) {
    const Trace& ed = eds.front();
    const auto& g_last = ed.snaps.back().g;
    res.put(out_ed_g_inside_contact_max, max_over(g_last, ed.g_r, 0.0, 0.98));
    res.put(out_ed_g_peak_sqrt3_contrast, max_over(g_last, ed.g_r, 1.68, 1.78) / min_over(g_last, ed.g_r, 1.4, 1.6));
    res.put(out_ed_g_peak_contrast, max_over(g_last, ed.g_r, 1.95, 2.05) / min_over(g_last, ed.g_r, 1.8, 1.9), {2},
            "2 over min g in [1.8, 1.9], last snapshot, ED");
    res.put(out_ed_g_peak_contrast, max_over(g_last, ed.g_r, 2.95, 3.05) / min_over(g_last, ed.g_r, 2.75, 2.9), {3},
            "3 over min g in [2.75, 2.9], last snapshot, ED");
    res.put(out_ed_g_contact, max_over(g_last, ed.g_r, 1.0, 1.04));
    // Early g equals the elastic one (Sec. 3.3: "for short times one observes g as for an elastic
    // hard sphere gas"): the first snapshot after t = 0 against t = 0 (the end of the elastic
    // equilibration), over 0.98 <= r/d <= 5.
    if (ed.snaps.size() < 2) return;
    const auto all = early_g_chi2(ed, 0.98), beyond = early_g_chi2(ed, 1.1);
    res.put(out_ed_g_early_vs_elastic_chi2, all[0]);
    res.put(out_ed_g_early_vs_elastic_chi2_beyond_contact, beyond[0]);
    res.put(out_ed_g_early_vs_elastic_bins_beyond_contact, beyond[1]);
    // Every seed's chi^2 beyond contact (issue 43 §3: two first-seed runs gave 1.19 and 1.58,
    // further apart than the counting spread sqrt(2/195) = 0.10 of one), its seed mean and spread.
    std::vector<double> per_seed;
    for (const Trace& tr : eds)
        if (tr.snaps.size() >= 2) per_seed.push_back(early_g_chi2(tr, 1.1)[0]);
    add_mean_sd(res, out_ed_g_early_vs_elastic_chi2_beyond_contact_mean, out_ed_g_early_vs_elastic_chi2_beyond_contact_mean_sd, per_seed);
    res.put(out_ed_g_early_time_over_t0, snaps[1] / t0);
    res.put(out_ed_g_contact_early_over_elastic, max_over(ed.snaps[1].g, ed.g_r, 1.0, 1.04) / max_over(ed.snaps[0].g, ed.g_r, 1.0, 1.04));
}

const ScalarOut out_Sk_equilibrium_hard_disks = outputs.scalar("Sk_equilibrium_hard_disks", "1",
    "S(k -> 0) of the elastic hard-disk gas at rho (Henderson's equation of state)");
const ScalarOut out_ed_Sk_growth_over_equilibrium = outputs.scalar("ed_Sk_growth_over_equilibrium", "1",
    "mean S(1 <= k <= sk_k_max) at the last snapshot over the equilibrium S(0), ED, mean over seeds");
const ScalarOut out_ed_Sk_t0_over_equilibrium = outputs.scalar("ed_Sk_t0_over_equilibrium", "1",
    "the same at t = 0: below 1 where the long waves have not forgotten the lattice start");
const ScalarOut out_ed_Sk_small_k_growth = outputs.scalar("ed_Sk_small_k_growth", "1",
    "mean S(k <= sk_k_max) at the last snapshot over that at t = 0 (lattice leftover), ED, first seed");
const ScalarOut out_ed_Sk_log_seed_sd = outputs.scalar("ed_Sk_log_seed_sd", "1",
    "seed standard deviation of ln(mean S_ED(k <= sk_k_max)) at the last snapshot: the run-to-run scatter of one run");
const ScalarOut out_ed_Sk_change_after_20s = outputs.scalar("ed_Sk_change_after_20s", "1",
    "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, ED, mean over seeds");
const ScalarOut out_ed_Sk_change_after_20s_sd = outputs.scalar("ed_Sk_change_after_20s_sd", "1", "its seed standard deviation");

// Fig. 7, ED: growth of S(k) at small k, measured from equilibrium: against the elastic hard-disk
// S(0) (Henderson's equation of state; what an equilibrated elastic gas has at k <= 25), not
// against the t = 0 snapshot, whose long waves still carry the lattice start.
void add_ed_sk(Result& res, const std::vector<Trace>& eds, const std::vector<double>& snaps, double k_small, double s_eq) {
    res.put(out_Sk_equilibrium_hard_disks, s_eq);
    const auto i20 = snapshot_20s(snaps);
    std::vector<double> growth, lattice, change, lns;
    for (const Trace& tr : eds) {
        growth.push_back(small_k_S(tr, tr.snaps.back(), k_small) / s_eq);
        lattice.push_back(small_k_S(tr, tr.snaps.front(), k_small) / s_eq);
        const double s20 = i20 ? small_k_S(tr, tr.snaps[*i20], k_small) : NAN;
        change.push_back(small_k_S(tr, tr.snaps.back(), k_small) / s20 - 1);
        lns.push_back(std::log(growth.back()));
    }
    const Trace& ed = eds.front();
    res.put(out_ed_Sk_growth_over_equilibrium, mean_sd(growth, NonFinite::censored).mean);
    res.put(out_ed_Sk_t0_over_equilibrium, mean_sd(lattice, NonFinite::censored).mean);
    res.put(out_ed_Sk_small_k_growth, small_k_S(ed, ed.snaps.back(), k_small) / small_k_S(ed, ed.snaps.front(), k_small));
    add_mean_sd(res, out_ed_Sk_change_after_20s, out_ed_Sk_change_after_20s_sd, change);
    res.put(out_ed_Sk_log_seed_sd, mean_sd(lns, NonFinite::censored).sd);
}

const TableOut out_sk_change_intervals = outputs.table("sk_change_intervals",
    "relative change of mean S(1 <= k <= sk_k_max) between successive snapshots from 20 s on: seed mean of the per-seed change (judged convention) with its seed sd, and the change of the seed-mean S");

// Fig. 7, "the structure factor ceases to change for t >= 20 s" (Sec. 3.3), interval by interval:
// for each pair of successive snapshots from 20 s on (runs to 80 s: 20-40, 40-60, 60-80 s) the
// relative change of mean S(1 <= k <= k_small), per seed and then averaged over seeds with its seed
// standard deviation (the one convention of the claims, expected/README.md rule 'average'), and
// beside it the change of the seed-mean S (the other convention, for comparison only). dss may be
// empty (run_dsmc = false).
void add_sk_change_intervals(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss,
                             const std::vector<double>& snaps, double k_small) {
    const auto i20 = snapshot_20s(snaps);
    if (!i20) return;
    Table& t = res.table(out_sk_change_intervals);
    std::vector<double> lo, hi;
    for (std::size_t i = *i20; i + 1 < snaps.size(); ++i) lo.push_back(snaps[i]), hi.push_back(snaps[i + 1]);
    t.add({{"t_begin", "s", lo}, {"t_end", "s", hi}});
    for (const auto& [trs, name] : {std::pair{&eds, "ed"}, std::pair{&dss, "dsmc"}}) {
        if (trs->empty()) continue;
        std::vector<double> mean, sd, of_mean;
        for (std::size_t i = *i20; i + 1 < snaps.size(); ++i) {
            std::vector<double> change;
            double sa = 0, sb = 0;
            for (const Trace& tr : *trs) {
                const double a = small_k_S(tr, tr.snaps[i], k_small), b = small_k_S(tr, tr.snaps[i + 1], k_small);
                change.push_back(b / a - 1);
                sa += a, sb += b;
            }
            const MeanSd ms = mean_sd(change, NonFinite::censored);
            mean.push_back(ms.mean), sd.push_back(ms.sd), of_mean.push_back(sb / sa - 1);
        }
        const std::string n = name;
        t.add({{n + "_change", "1", mean}, {n + "_change_sd", "1", sd}, {n + "_change_of_seed_mean", "1", of_mean}});
    }
}

const TableOut out_sk_seeds = outputs.table("sk_seeds",
    "per seed: mean S(1 <= k <= sk_k_max) of ED and DSMC at 20 s and at the last snapshot, and the mean ln ratio");
const ScalarOut out_Sk_dsmc_over_ed_factor = outputs.scalar("Sk_dsmc_over_ed_factor", "1",
    "exp of Sk_dsmc_over_ed_log: DSMC's S(k <= sk_k_max) in units of ED's");
const ScalarOut out_Sk_ed_dsmc_mean_abs_log_ratio = outputs.scalar("Sk_ed_dsmc_mean_abs_log_ratio", "1",
    "mean |ln(S_ED/S_DSMC)| over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
const ScalarOut out_Sk_dsmc_over_ed_log = outputs.scalar("Sk_dsmc_over_ed_log", "1",
    "ln(S_DSMC/S_ED) averaged over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
const ScalarOut out_Sk_dsmc_over_ed_log_sd = outputs.scalar("Sk_dsmc_over_ed_log_sd", "1", "its seed standard deviation");
const ScalarOut out_Sk_dsmc_over_ed_log_20s = outputs.scalar("Sk_dsmc_over_ed_log_20s", "1",
    "the same at t = 20 s");
const ScalarOut out_Sk_dsmc_over_ed_log_20s_sd = outputs.scalar("Sk_dsmc_over_ed_log_20s_sd", "1", "its seed standard deviation");
const ScalarOut out_dsmc_Sk_change_after_20s = outputs.scalar("dsmc_Sk_change_after_20s", "1",
    "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, DSMC, mean over seeds");
const ScalarOut out_dsmc_Sk_change_after_20s_sd = outputs.scalar("dsmc_Sk_change_after_20s_sd", "1", "its seed standard deviation");

// Fig. 7, DSMC against ED: agreement of S(k) at small k. Per seed: m = mean over
// 1 <= k <= sk_k_max of ln(S_DSMC/S_ED) at the last snapshot (and at 20 s); then mean and
// scatter over seeds, and a table of the seeds.
void add_sk_agreement(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, const std::vector<double>& snaps, double k_small) {
    const auto i20 = snapshot_20s(snaps);
    std::vector<double> idx, e20, elast, d20, dlast, m_last, m_20, abs_last, d_change;
    for (std::size_t k = 0; k < eds.size(); ++k) {
        const Trace &a = eds[k], &b = dss[k];
        idx.push_back(double(k));
        e20.push_back(i20 ? small_k_S(a, a.snaps[*i20], k_small) : NAN);
        d20.push_back(i20 ? small_k_S(b, b.snaps[*i20], k_small) : NAN);
        elast.push_back(small_k_S(a, a.snaps.back(), k_small));
        dlast.push_back(small_k_S(b, b.snaps.back(), k_small));
        d_change.push_back(dlast.back() / d20.back() - 1);
        m_last.push_back(mean_log_ratio(b.snaps.back().S, a.snaps.back().S, a.S_k, k_small));
        abs_last.push_back(mean_log_ratio(a.snaps.back().S, b.snaps.back().S, a.S_k, k_small, true));
        if (i20) m_20.push_back(mean_log_ratio(b.snaps[*i20].S, a.snaps[*i20].S, a.S_k, k_small));
    }
    Table& t = res.table(out_sk_seeds);
    t.add({{"seed_index", "1", idx}, {"S_ed_20s", "1", e20}, {"S_ed_last", "1", elast}, {"S_dsmc_20s", "1", d20},
           {"S_dsmc_last", "1", dlast}, {"mean_ln_ratio_last", "1", m_last}});
    add_mean_sd(res, out_Sk_dsmc_over_ed_log, out_Sk_dsmc_over_ed_log_sd, m_last);
    res.put(out_Sk_dsmc_over_ed_factor, std::exp(mean_sd(m_last, NonFinite::censored).mean));
    if (!m_20.empty()) add_mean_sd(res, out_Sk_dsmc_over_ed_log_20s, out_Sk_dsmc_over_ed_log_20s_sd, m_20);
    res.put(out_Sk_ed_dsmc_mean_abs_log_ratio, mean_sd(abs_last, NonFinite::censored).mean);
    add_mean_sd(res, out_dsmc_Sk_change_after_20s, out_dsmc_Sk_change_after_20s_sd, d_change);
}

const ScalarOut out_dsmc_cells_per_side = outputs.scalar("dsmc_cells_per_side", "1", "DSMC cells per box side");
const ScalarOut out_dsmc_cell_shell = outputs.scalar("dsmc_cell_shell", "1",
    "the S(k) shell of the cell lattice (box/cell, aliased into 1..M/2)");
const ScalarOut out_dsmc_Sk_cell_imprint = outputs.scalar("dsmc_Sk_cell_imprint", "1",
    "S at the cell shell over the geometric mean of the flanks at 0.75 and 1.25 of it, last snapshot, DSMC, mean over seeds");
const ScalarOut out_ed_Sk_cell_imprint_control = outputs.scalar("ed_Sk_cell_imprint_control", "1",
    "the same measure on ED's S(k) (no cells)");
const ScalarOut out_dsmc_Sk_cell_imprint_over_ed = outputs.scalar("dsmc_Sk_cell_imprint_over_ed", "1",
    "DSMC's contrast at the cell shell over ED's there (1: no imprint)");

// Fig. 7, the DSMC cell lattice's imprint on S(k): the bump of S at the cell shell, DSMC against
// ED (no cells), last snapshot, mean over seeds. The cells per side are the first seed's DSMC run's.
void add_cell_imprint(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const double cells = double(dss.front().dsmc_cells_per_side);
    const double M = 2 * (eds.front().S_k.empty() ? 1 : eds.front().S_k.back());
    // NGP on an M grid aliases mode n to n - M round(n/M).
    const double kc = std::abs(cells - M * std::round(cells / M));
    std::vector<double> imprint, imprint_ed;
    for (std::size_t k = 0; k < eds.size(); ++k) {
        imprint.push_back(bump_contrast(dss[k].snaps.back().S, dss[k].S_k, kc));
        imprint_ed.push_back(bump_contrast(eds[k].snaps.back().S, eds[k].S_k, kc));
    }
    res.put(out_dsmc_cells_per_side, cells);
    res.put(out_dsmc_cell_shell, kc);
    res.put(out_dsmc_Sk_cell_imprint, mean_sd(imprint, NonFinite::censored).mean);
    res.put(out_ed_Sk_cell_imprint_control, mean_sd(imprint_ed, NonFinite::censored).mean);
    res.put(out_dsmc_Sk_cell_imprint_over_ed, mean_sd(imprint, NonFinite::censored).mean / mean_sd(imprint_ed, NonFinite::censored).mean);
}
} // namespace granrepro::experiments::cooling_detail
