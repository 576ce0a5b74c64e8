// cluster-growth: an instant's P(N_c) and the fits of Eqs. (20)-(22), and Fig. 12 with its claims.
#include <algorithm>
#include <cmath>
#include <functional>
#include <gsl/gsl_statistics_double.h>
#include <optional>
#include <string>
#include <tuple>

#include "analysis/seed_stats.hpp"
#include "data/parameter_set.hpp"
#include "experiments/cluster_growth/spec.hpp"

namespace granrepro::experiments::cluster_growth_detail {

namespace {

RateHistogram histogram(const std::vector<double>& rate, double window, const ClusterSpec& s) {
    const double mean = mean_sd(rate).mean;
    if (mean * window <= 30) {
        const double mx = *std::max_element(rate.begin(), rate.end());
        return RateHistogram::per_count(rate, window, int(std::ceil(mx * window)));
    }
    std::vector<double> sorted = rate;
    std::sort(sorted.begin(), sorted.end());
    const double hi = gsl_stats_quantile_from_sorted_data(sorted.data(), 1, sorted.size(), s.hist_quantile);
    return RateHistogram::make(rate, window, RateHistogram::Binning::Linear, s.hist_bins, 0.0, std::max(hi, 2.0 / window));
}

// A fit over N_c >= lo; NaN where the fit fails.
CollisionRateFit fit(const RateHistogram& h, CollisionRateFit::Model m, double lo = -INFINITY) {
    try {
        return CollisionRateFit::fit(h, m, lo, INFINITY);
    } catch (const std::exception&) {
        CollisionRateFit f;
        f.model = m;
        f.value = f.error = f.chi2_reduced = NAN;
        return f;
    }
}

// Index of the instant whose C/N is nearest to cn in log; -1 if none.
int nearest(const std::vector<Instant>& in, double cn) {
    int best = -1;
    double bd = INFINITY;
    for (std::size_t k = 0; k < in.size(); ++k)
        if (in[k].cn > 0 && std::abs(std::log(in[k].cn / cn)) < bd) {
            bd = std::abs(std::log(in[k].cn / cn));
            best = int(k);
        }
    return best;
}

const TableOut out_pnc = outputs.table("pnc_<n>", "P(N_c) and the fitted Eqs. (20)-(22) at t = ");

// P(N_c) at one instant with the fitted Eqs. (20)-(22), as Fig. 12 shows it.
void fig12_histogram_table(Result& res, const Instant& in, std::size_t panel) {
    Table& h = res.table(out_pnc, {std::to_string(panel)}, number_text(in.t) + " s");
    std::vector<double> pp, pe, pw, pwt, pet;
    for (std::size_t b = 0; b < in.hist.centres.size(); ++b) {
        const double w = in.hist.edges[b + 1] - std::max(0.0, in.hist.edges[b]);
        auto model = [&](const CollisionRateFit& f) {
            return std::isfinite(f.value) ? CollisionRateFit::bin_probability(in.hist, b, f.model, f.value) / w : NAN;
        };
        pp.push_back(model(in.poisson));
        pe.push_back(model(in.expo));
        pw.push_back(model(in.power));
        // The tail fits only over the bins they were fitted to.
        const bool tail = in.hist.edges[b] >= in.tail_lo;
        pwt.push_back(tail ? model(in.power_tail) : NAN);
        pet.push_back(tail ? model(in.expo_tail) : NAN);
    }
    h.add({{"N_c", "1/s", in.hist.centres}, {"P", "s", in.hist.density}, {"P_err", "s", in.hist.error},
           {"poisson_eq20", "s", pp}, {"exponential_eq21", "s", pe}, {"powerlaw_eq22", "s", pw},
           {"powerlaw_eq22_tail", "s", pwt}, {"exponential_eq21_tail", "s", pet}});
}

// A panel's scalars come twice: at the instant nearest to one of the paper's C/N ("chi_cn8") and
// at the last instant ("chi_last").
struct PanelOut {
    ScalarOut near_cn, last;
};
PanelOut panel(const std::string& what, const char* unit, const char* description) {
    return {outputs.scalar(what + "_cn<n>", unit, description), outputs.scalar(what + "_last", unit, description)};
}
const PanelOut out_cn_nearest = panel("cn_nearest", "1", "our C/N at the instant nearest to the paper's");
const PanelOut out_t_nearest = panel("t_nearest", "s", "its time");
const PanelOut out_chi = panel("chi", "1", "Poisson Eq. (20) chi (mean count in Δt = t/2)");
const PanelOut out_chi_err = panel("chi_err", "1", "its standard error (Cramer-Rao)");
const PanelOut out_chi_since_start = panel("chi_since_start", "1", "Eq. (20) chi for the counts over (0, t] (window t, not t/2)");
const PanelOut out_chi_since_start_err = panel("chi_since_start_err", "1", "its standard error");
const PanelOut out_chi_rate = panel("chi_rate", "1/s", "chi / Δt, the Poisson mean rate");
const PanelOut out_chi2red_poisson = panel("chi2red_poisson", "1", "Pearson chi^2/dof of the Poisson fit");
const PanelOut out_A = panel("A", "1/s", "exponential Eq. (21) A");
const PanelOut out_A_err = panel("A_err", "1/s", "its standard error");
const PanelOut out_chi2red_exponential = panel("chi2red_exponential", "1", "Pearson chi^2/dof of the exponential fit");
const PanelOut out_B = panel("B", "1/s", "power law Eq. (22) B");
const PanelOut out_B_tail = panel("B_tail", "1/s", "Eq. (22) B fitted to the tail N_c >= tail_fit_from x mean N_c");
const PanelOut out_B_tail_err = panel("B_tail_err", "1/s", "its standard error");
const PanelOut out_powerlaw_over_exponential_chi2_tail = panel("powerlaw_over_exponential_chi2_tail", "1",
    "chi^2/dof of Eq. (22) over that of Eq. (21), both fitted to the tail only (< 1: power law better there)");
const PanelOut out_B_err = panel("B_err", "1/s", "its standard error");
const PanelOut out_chi2red_powerlaw = panel("chi2red_powerlaw", "1", "Pearson chi^2/dof of the power-law fit");
const PanelOut out_mean_Nc = panel("mean_Nc", "1/s", "mean N_c");
const PanelOut out_tail_fraction = panel("tail_fraction", "1", "fraction of particles with N_c > tail_rate");
const PanelOut out_poisson_over_best_other_chi2 = panel("poisson_over_best_other_chi2", "1",
    "chi^2/dof of Eq. (20) over the better of Eqs. (21), (22) (< 1: Poisson fits best)");
const PanelOut out_powerlaw_over_exponential_chi2 = panel("powerlaw_over_exponential_chi2", "1",
    "chi^2/dof of Eq. (22) over that of Eq. (21) (< 1: the power law fits better)");

// paper: the paper's C/N the instant is nearest to; none for the last instant.
void fig12_panel_scalars(Result& res, const Instant& in, std::optional<double> paper) {
    auto put = [&](const PanelOut& h, double value) {
        if (paper) res.put(h.near_cn, value, {*paper});
        else res.put(h.last, value);
    };
    put(out_cn_nearest, in.cn);
    put(out_t_nearest, in.t);
    put(out_chi, in.poisson.value);
    put(out_chi_err, in.poisson.error);
    put(out_chi_since_start, in.poisson_full.value);
    put(out_chi_since_start_err, in.poisson_full.error);
    put(out_chi_rate, in.poisson.value / in.window);
    put(out_chi2red_poisson, in.poisson.chi2_reduced);
    put(out_A, in.expo.value);
    put(out_A_err, in.expo.error);
    put(out_chi2red_exponential, in.expo.chi2_reduced);
    put(out_B, in.power.value);
    put(out_B_tail, in.power_tail.value);
    put(out_B_tail_err, in.power_tail.error);
    put(out_powerlaw_over_exponential_chi2_tail, in.power_tail.chi2_reduced / in.expo_tail.chi2_reduced);
    put(out_B_err, in.power.error);
    put(out_chi2red_powerlaw, in.power.chi2_reduced);
    put(out_mean_Nc, in.mean_rate);
    put(out_tail_fraction, in.tail_fraction);
    put(out_poisson_over_best_other_chi2, in.poisson.chi2_reduced / std::min(in.expo.chi2_reduced, in.power.chi2_reduced));
    put(out_powerlaw_over_exponential_chi2, in.power.chi2_reduced / in.expo.chi2_reduced);
}

// The fitted parameters at exactly the paper's C/N: linear interpolation of ln(parameter) in
// ln(C/N) between the two instants around it (consecutive instants differ by a factor 2 in t and
// by 1.1-2 in C/N, so the nearest instant alone can be far from the paper's C/N).
template <class Get>
double at_cn(const std::vector<Instant>& instants, double cn, Get get) {
    for (std::size_t k = 1; k < instants.size(); ++k)
        if (instants[k - 1].cn <= cn && instants[k].cn >= cn) {
            const double f = std::log(cn / instants[k - 1].cn) / std::log(instants[k].cn / instants[k - 1].cn);
            return std::exp(std::log(get(instants[k - 1])) * (1 - f) + std::log(get(instants[k])) * f);
        }
    return double(NAN);
}

} // namespace

// The per-particle rates and counts of an instant fix everything else in it, so a resumed run
// recomputes it identically.
Instant make_instant(InstantRecord rec, const ClusterSpec& s) {
    Instant in;
    static_cast<InstantRecord&>(in) = std::move(rec);
    const std::size_t n = in.rate.size();
    in.window = in.t / 2;
    std::size_t tail = 0;
    for (double r : in.rate)
        if (r > s.tail_rate) ++tail;
    const MeanSd rate = mean_sd(in.rate);
    in.mean_rate = rate.mean;
    in.sd_rate = rate.sd;
    in.tail_fraction = double(tail) / double(n);
    in.hist = histogram(in.rate, in.window, s);
    in.poisson = fit(in.hist, CollisionRateFit::Model::Poisson);
    in.expo = fit(in.hist, CollisionRateFit::Model::Exponential);
    in.power = fit(in.hist, CollisionRateFit::Model::PowerLaw);
    // The tail alone, as the paper reads Fig. 12(b,c): "the probability for large collision
    // frequencies ... can now be approximated by a power law". Still normalised over all N_c (no
    // free amplitude), so B is fixed by the tail's height and curvature.
    in.tail_lo = s.tail_fit_from * in.mean_rate;
    in.power_tail = fit(in.hist, CollisionRateFit::Model::PowerLaw, in.tail_lo);
    in.expo_tail = fit(in.hist, CollisionRateFit::Model::Exponential, in.tail_lo);
    // The same Poisson fit with the counts since t = 0 (window t instead of t/2): the paper's
    // chi = 6.5 at C/N = 8 is compared with both readings.
    std::vector<double> full(n);
    for (std::size_t i = 0; i < n; ++i) full[i] = double(in.counts[i]) / in.t;
    in.poisson_full = fit(histogram(full, in.t, s), CollisionRateFit::Model::Poisson);
    return in;
}

const TableOut out_instants = outputs.table("instants",
    "per instant t = t_base 2^k: C/N, N_c statistics and the fits of Eqs. (20)-(22)");

// Fig. 12, every instant: C/N, N_c statistics and the fits of Eqs. (20)-(22).
void fig12_instants_table(Result& res, const std::vector<Instant>& instants) {
    Table& t = res.table(out_instants);
    using I = Instant;
    auto col = [&](const char* name, const char* unit, auto get) { t.add(name, unit).values = column(instants, get); };
    const std::vector<std::tuple<const char*, const char*, double I::*>> plain = {
        {"t", "s", &I::t}, {"window", "s", &I::window}, {"C_over_N", "1", &I::cn},
        {"elastic_C_over_N", "1", &I::elastic_cn}, {"mean_Nc", "1/s", &I::mean_rate}, {"sd_Nc", "1/s", &I::sd_rate},
        {"fast_particles", "1", &I::fast_fraction}, {"tail_fraction", "1", &I::tail_fraction}};
    for (const auto& [name, unit, f] : plain) col(name, unit, f);
    // A fit's value, its error (err: that column's name, if any) and its reduced chi^2.
    auto fit = [&](const char* name, const char* err, const char* chi2, CollisionRateFit I::*f, const char* unit) {
        col(name, unit, [f](const Instant& in) { return (in.*f).value; });
        if (err) col(err, unit, [f](const Instant& in) { return (in.*f).error; });
        col(chi2, "1", [f](const Instant& in) { return (in.*f).chi2_reduced; });
    };
    fit("chi", "chi_err", "chi2red_poisson", &I::poisson, "1");
    fit("A", "A_err", "chi2red_exponential", &I::expo, "1/s");
    fit("B", "B_err", "chi2red_powerlaw", &I::power, "1/s");
    col("tail_from", "1/s", &I::tail_lo);
    fit("B_tail", "B_tail_err", "chi2red_powerlaw_tail", &I::power_tail, "1/s");
    fit("A_tail", nullptr, "chi2red_exponential_tail", &I::expo_tail, "1/s");
    col("bins", "1", [](const Instant& in) { return double(in.hist.centres.size()); });
}

const ScalarOut out_poisson_mean_width_falling_share = outputs.scalar("poisson_mean_width_falling_share", "1",
    "share of consecutive instants with C/N <= poisson_until_cn where mean and standard deviation of N_c both fall");
const ScalarOut out_poisson_mean_width_pairs = outputs.scalar("poisson_mean_width_pairs", "1",
    "number of such pairs of instants");

// Sec. 4.3: "a Poisson distribution whose mean and width chi/Dt continuously decrease with time
// for C/N <= 39": the share of the consecutive instants with C/N <= 39 over which both the mean
// and the standard deviation of N_c fall.
void report_poisson_falling(Result& res, const std::vector<Instant>& instants, double until_cn) {
    int pairs = 0, falling = 0;
    for (std::size_t k = 1; k < instants.size(); ++k)
        if (instants[k].cn <= until_cn) {
            ++pairs;
            if (instants[k].mean_rate < instants[k - 1].mean_rate && instants[k].sd_rate < instants[k - 1].sd_rate) ++falling;
        }
    res.put(out_poisson_mean_width_falling_share, pairs ? double(falling) / pairs : NAN);
    res.put(out_poisson_mean_width_pairs, double(pairs));
}

// The instants nearest to the paper's C/N values, and the last: histogram tables and scalars for the claims.
void fig12_panels(Result& res, const std::vector<Instant>& instants, const std::vector<double>& pcn) {
    std::vector<int> sel;
    for (double c : pcn) sel.push_back(nearest(instants, c));
    sel.push_back(instants.empty() ? -1 : int(instants.size()) - 1); // the last, beyond 2567
    std::vector<double> mp, mc, mt, mw;
    for (std::size_t s = 0; s < sel.size(); ++s) {
        const double paper = s < pcn.size() ? pcn[s] : NAN;
        mp.push_back(paper);
        if (sel[s] < 0) {
            mc.push_back(NAN); mt.push_back(NAN); mw.push_back(NAN);
            continue;
        }
        const Instant& in = instants[std::size_t(sel[s])];
        mc.push_back(in.cn);
        mt.push_back(in.t);
        mw.push_back(in.window);
        fig12_histogram_table(res, in, s);
        fig12_panel_scalars(res, in, s < pcn.size() ? std::optional(paper) : std::nullopt);
    }
    // Created last: res.table() may move the tables created before.
    Table& meta = res.table(out_fig_selection, {12}, "instants shown in Fig. 12: the paper's C/N and ours");
    meta.add({{"paper_C_over_N", "1", mp}, {"C_over_N", "1", mc}, {"t", "s", mt}, {"window", "s", mw}});
}

const ScalarOut out_chi_at_cn = outputs.scalar("chi_at_cn<n>", "1", "Eq. (20) chi interpolated to the paper's C/N");
const ScalarOut out_A_at_cn = outputs.scalar("A_at_cn<n>", "1/s", "Eq. (21) A interpolated to the paper's C/N");
const ScalarOut out_B_at_cn = outputs.scalar("B_at_cn<n>", "1/s", "Eq. (22) B interpolated to the paper's C/N");
const ScalarOut out_t_at_cn = outputs.scalar("t_at_cn<n>", "s", "time at which C/N reached the paper's value (interpolated)");

void report_at_paper_cn(Result& res, const std::vector<Instant>& instants, const std::vector<double>& paper_cn) {
    for (double c : paper_cn) {
        res.put(out_chi_at_cn, at_cn(instants, c, [](const Instant& in) { return in.poisson.value; }), {c});
        res.put(out_A_at_cn, at_cn(instants, c, [](const Instant& in) { return in.expo.value; }), {c});
        res.put(out_B_at_cn, at_cn(instants, c, [](const Instant& in) { return in.power.value; }), {c});
        res.put(out_t_at_cn, at_cn(instants, c, [](const Instant& in) { return in.t; }), {c});
    }
}

const ScalarOut out_B_geomean_70_1404 = outputs.scalar("B_geomean_70_1404", "1/s",
    "geometric mean of B over the instants with 70 <= C/N <= 1404");
const ScalarOut out_B_min_70_1404 = outputs.scalar("B_min_70_1404", "1/s", "smallest B there");
const ScalarOut out_B_tail_geomean_70_1404 = outputs.scalar("B_tail_geomean_70_1404", "1/s",
    "geometric mean of the tail-fitted B over the instants with 70 <= C/N <= 1404");
const ScalarOut out_powerlaw_better_tail_share_70_1404 = outputs.scalar("powerlaw_better_tail_share_70_1404", "1",
    "share of those instants where Eq. (22) fits the tail better than Eq. (21)");
const ScalarOut out_B_max_70_1404 = outputs.scalar("B_max_70_1404", "1/s", "largest B there");

// B over the clustered instants 70 <= C/N <= 1404 (the paper quotes one B for them).
void report_clustered_B(Result& res, const std::vector<Instant>& instants) {
    double lsum = 0, ls = 0, bmin = INFINITY, bmax = -INFINITY;
    int cnt = 0, c = 0, better = 0;
    for (const auto& in : instants) {
        if (!(in.cn >= 70 && in.cn <= 1404)) continue;
        if (std::isfinite(in.power.value)) {
            lsum += std::log(in.power.value);
            ++cnt;
            bmin = std::min(bmin, in.power.value);
            bmax = std::max(bmax, in.power.value);
        }
        if (std::isfinite(in.power_tail.value)) { // the tail fit
            ls += std::log(in.power_tail.value);
            ++c;
            if (in.power_tail.chi2_reduced < in.expo_tail.chi2_reduced) ++better;
        }
    }
    res.put(out_B_geomean_70_1404, cnt ? std::exp(lsum / cnt) : NAN);
    res.put(out_B_min_70_1404, cnt ? bmin : NAN);
    res.put(out_B_tail_geomean_70_1404, c ? std::exp(ls / c) : NAN);
    res.put(out_powerlaw_better_tail_share_70_1404, c ? double(better) / c : NAN);
    res.put(out_B_max_70_1404, cnt ? bmax : NAN);
}

const ScalarOut out_powerlaw_better_from_cn = outputs.scalar("powerlaw_better_from_cn", "1",
    "smallest C/N from which on Eq. (22) fits better than Eq. (21) at every instant");
const ScalarOut out_B_ratio_1404_over_183 = outputs.scalar("B_ratio_1404_over_183", "1",
    "B at the instant nearest C/N = 1404 over B nearest 183 (shape change), fits over the whole P(N_c)");
const ScalarOut out_B_tail_ratio_1404_over_183 = outputs.scalar("B_tail_ratio_1404_over_183", "1",
    "tail-fitted B at the instant nearest C/N = 1404 over that nearest 183 (shape change)");
const ScalarOut out_tail_ratio_2567_over_1404 = outputs.scalar("tail_ratio_2567_over_1404", "1",
    "P(N_c > tail_rate) nearest C/N = 2567 over that nearest 1404 (< 1: the tail drops again)");
const ScalarOut out_tail_ratio_last_over_1404 = outputs.scalar("tail_ratio_last_over_1404", "1",
    "P(N_c > tail_rate) at the last instant over that nearest C/N = 1404");
const ScalarOut out_powerlaw_better_share_after_70 = outputs.scalar("powerlaw_better_share_after_70", "1",
    "share of the instants with C/N > 70 where Eq. (22) fits better than Eq. (21)");

// Where the power law Eq. (22) takes over from the exponential Eq. (21), and how the shape
// changes after (Section 4.3).
void report_powerlaw_onset(Result& res, const std::vector<Instant>& instants) {
    // From which C/N on the power law fits better than the exponential at every later instant.
    double from = NAN;
    for (std::size_t k = instants.size(); k-- > 0;) {
        if (!(instants[k].power.chi2_reduced < instants[k].expo.chi2_reduced)) break;
        from = instants[k].cn;
    }
    res.put(out_powerlaw_better_from_cn, from);
    const int k1 = nearest(instants, 1404.0), k2 = nearest(instants, 2567.0), k0 = nearest(instants, 183.0);
    if (k0 >= 0 && k1 >= 0 && k2 >= 0) {
        res.put(out_B_ratio_1404_over_183, instants[std::size_t(k1)].power.value / instants[std::size_t(k0)].power.value);
        // The same with the tail estimator of powerlaw_B (N_c >= tail_fit_from x mean), so that the
        // shape claim and the B claim read Eq. (22) one way (issue 27 §4).
        res.put(out_B_tail_ratio_1404_over_183, instants[std::size_t(k1)].power_tail.value / instants[std::size_t(k0)].power_tail.value);
        res.put(out_tail_ratio_2567_over_1404, instants[std::size_t(k2)].tail_fraction / instants[std::size_t(k1)].tail_fraction);
        res.put(out_tail_ratio_last_over_1404, instants.back().tail_fraction / instants[std::size_t(k1)].tail_fraction);
    }
    // Which form fits best over the instants after C/N = 70 (Section 4.3: power law).
    double n_after = 0, pow_best = 0;
    for (const auto& in : instants)
        if (in.cn > 70 && std::isfinite(in.power.chi2_reduced) && std::isfinite(in.expo.chi2_reduced)) {
            ++n_after;
            if (in.power.chi2_reduced < in.expo.chi2_reduced) ++pow_best;
        }
    res.put(out_powerlaw_better_share_after_70, n_after > 0 ? pow_best / n_after : NAN);
}

} // namespace granrepro::experiments::cluster_growth_detail
