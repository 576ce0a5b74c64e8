// impact-parameter, Fig. 4: P(b/d) per r, in time windows, at r = 1 per density, and in 3D.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "experiments/impact_parameter/spec.hpp"

namespace granrepro::experiments::impact_parameter_detail {

namespace {

// P(b/d) from counts: density over [0, 1] with bin width 1/nb, Poisson error sqrt(n) per bin.
struct Histogram {
    std::vector<double> p, err;
    std::uint64_t total = 0;
};

Histogram normalise(const std::vector<std::uint64_t>& counts) {
    Histogram h;
    const std::size_t nb = counts.size();
    h.total = std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
    h.p.assign(nb, NAN);
    h.err.assign(nb, NAN);
    if (h.total == 0) return h;
    const double s = static_cast<double>(nb) / static_cast<double>(h.total);
    for (std::size_t k = 0; k < nb; ++k) {
        h.p[k] = s * static_cast<double>(counts[k]);
        h.err[k] = s * std::sqrt(static_cast<double>(counts[k]));
    }
    return h;
}

// chi^2 of the bins against P = 1, per degree of freedom. The normalisation fixes one
// combination of the bins, so dof = nb - 1; for molecular chaos the expectation is 1 with a
// standard deviation sqrt(2/(nb-1)). Poisson variance is taken from the expected count n/nb,
// which keeps empty or sparse bins from dominating.
double chi2_per_dof(const std::vector<std::uint64_t>& counts) {
    const double nb = static_cast<double>(counts.size());
    const double total = static_cast<double>(std::accumulate(counts.begin(), counts.end(), std::uint64_t{0}));
    if (total <= 0.0 || nb < 2) return NAN;
    const double expect = total / nb;
    double chi2 = 0.0;
    for (auto c : counts) chi2 += (static_cast<double>(c) - expect) * (static_cast<double>(c) - expect) / expect;
    return chi2 / (nb - 1.0);
}

// P(b/d > 0.8) / P(b/d < 0.2) from the counts in those ranges (bins must align with 0.2, 0.8)
// and its Poisson error: R = n_hi/n_lo, sigma_R = R sqrt(1/n_hi + 1/n_lo).
struct Ratio {
    double value = NAN, err = NAN, z = NAN;
};
Ratio grazing_ratio(const std::vector<std::uint64_t>& counts) {
    const std::size_t nb = counts.size();
    const std::size_t lo_end = static_cast<std::size_t>(std::lround(0.2 * static_cast<double>(nb)));
    const std::size_t hi_begin = nb - lo_end;
    double lo = 0, hi = 0;
    for (std::size_t k = 0; k < lo_end; ++k) lo += static_cast<double>(counts[k]);
    for (std::size_t k = hi_begin; k < nb; ++k) hi += static_cast<double>(counts[k]);
    Ratio r;
    if (lo <= 0 || hi <= 0) return r;
    r.value = hi / lo;
    r.err = r.value * std::sqrt(1.0 / hi + 1.0 / lo);
    r.z = (r.value - 1.0) / r.err;
    return r;
}

// b/d counts of run k in windows [w0, w1), added over the seeds [seed0, seed1).
std::vector<std::uint64_t> merged(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k, std::size_t w0,
                                  std::size_t w1, std::size_t seed0 = 0, std::size_t seed1 = SIZE_MAX) {
    std::vector<std::uint64_t> c(static_cast<std::size_t>(s.n_bins), 0);
    for (std::size_t seed = seed0; seed < std::min(seed1, s.n_seeds()); ++seed)
        for (std::size_t w = w0; w < w1; ++w)
            for (std::size_t b = 0; b < c.size(); ++b) c[b] += at(s, pts, seed, k).counts[w][b];
    return c;
}

// Seed-to-seed scatter of the grazing ratio of run k: checks the Poisson errors, which assume
// independent collisions (correlated re-collisions would make them too small).
double grazing_ratio_seed_sem(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k) {
    double s1 = 0, s2 = 0;
    for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) {
        const double rr = grazing_ratio(merged(s, pts, k, 0, s.n_windows(), seed, seed + 1)).value;
        s1 += rr;
        s2 += rr * rr;
    }
    const double ns = static_cast<double>(s.n_seeds()), mean = s1 / ns;
    return std::sqrt(std::max(0.0, s2 / ns - mean * mean) / (ns - 1.0));
}

} // namespace

const TableOut out_fig4_inelastic = outputs.table("fig4_inelastic",
    "P(b/d) at rho = 0.7495 per r: whole run 0 <= t < t_end and last window");

// Fig. 4, inelastic: whole run and the late window (the last of window_edges).
void fig4_inelastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    Table& t4 = res.table(out_fig4_inelastic);
    t4.add("b_over_d", "1").values = centres;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = r_label(s, k);
        for (const bool late : {false, true}) {
            const auto c = merged(s, pts, k, late ? s.n_windows() - 1 : 0, s.n_windows());
            const Histogram h = normalise(c);
            const Ratio ra = grazing_ratio(c);
            const std::string sfx = late ? "late_" : "", when = late ? "last window" : "whole run";
            t4.add({{"P_" + sfx + lb, "1", h.p}, {"err_" + sfx + lb, "1", h.err}});
            res.scalar("collisions_" + sfx + lb, static_cast<double>(h.total), "1",
                       late ? "pair collisions in the last window, all seeds" : "pair collisions 0 <= t < t_end, all seeds");
            res.scalar("chi2_dof_" + sfx + lb, chi2_per_dof(c), "1", "chi^2 per dof of P(b/d) against 1, " + when);
            res.scalar("grazing_ratio_" + sfx + lb, ra.value, "1", "P(b/d > 0.8) / P(b/d < 0.2), " + when);
            res.scalar("grazing_ratio_" + sfx + "err_" + lb, ra.err, "1", "its Poisson error");
            res.scalar("grazing_z_" + sfx + lb, ra.z, "1", "(ratio - 1) / error, " + when);
        }
        if (s.n_seeds() >= 2)
            res.scalar("grazing_ratio_seed_sem_" + lb, grazing_ratio_seed_sem(s, pts, k), "1",
                       "standard error of the mean of the per-seed ratios (compare grazing_ratio_err)");
        const std::uint64_t el = seed_sum(s, pts, k, &PointResult::elastic_by_tc);
        const std::uint64_t tot = seed_sum(s, pts, k, &PointResult::pair_collisions);
        res.scalar("tc_elastic_fraction_" + lb, tot ? static_cast<double>(el) / static_cast<double>(tot) : NAN, "1",
                   "fraction of collisions made elastic by the TC model (Eq. 7)");
    }
}

// Time-resolved P(b/d) (as Fig. 3 does for the large system): one table per r.
void fig4_windows(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    const auto& edges = s.window_edges;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = r_label(s, k);
        Table& tw = res.table("windows_" + lb, "P(b/d) per time window (window_edges), all seeds");
        tw.add("b_over_d", "1").values = centres;
        for (std::size_t w = 0; w < s.n_windows(); ++w) {
            const auto c = merged(s, pts, k, w, w + 1);
            const Histogram h = normalise(c);
            const std::string wl = label("t", edges[w], "%g") + label("-", edges[w + 1], "%g");
            tw.add({{"P_" + wl, "1", h.p}, {"err_" + wl, "1", h.err}});
            res.scalar("grazing_ratio_" + lb + "_" + wl, grazing_ratio(c).value, "1",
                       "P(b/d > 0.8) / P(b/d < 0.2) in that window");
        }
    }
}

const TableOut out_fig4_elastic = outputs.table("fig4_elastic", "P(b/d) at r = 1 for N = 240 and several densities");
const ScalarOut out_elastic_chi2_dof_worst = outputs.scalar("elastic_chi2_dof_worst", "1",
    "largest chi^2 per dof over the elastic densities");

// Fig. 4, elastic check (Sec. 3.2, "P(b/d) is not sensitive to the density").
void fig4_elastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    Table& te = res.table(out_fig4_elastic);
    te.add("b_over_d", "1").values = centres;
    double worst_chi2 = 0.0;
    for (std::size_t j = 0; j < s.elastic_densities.size(); ++j) {
        const std::string lb = label("rho", s.elastic_densities[j], "%g");
        const auto c = merged(s, pts, s.n_r() + j, 0, 1);
        const Histogram h = normalise(c);
        te.add({{"P_" + lb, "1", h.p}, {"err_" + lb, "1", h.err}});
        const double chi = chi2_per_dof(c);
        worst_chi2 = std::max(worst_chi2, chi);
        res.scalar("elastic_chi2_dof_" + lb, chi, "1", "chi^2 per dof of P(b/d) against 1 at r = 1");
        const Ratio ra = grazing_ratio(c);
        res.scalar("elastic_grazing_z_" + lb, ra.z, "1", "(P(b/d > 0.8)/P(b/d < 0.2) - 1) / error at r = 1");
        res.scalar("elastic_collisions_" + lb, static_cast<double>(h.total), "1", "pair collisions counted, all seeds");
    }
    res.put(out_elastic_chi2_dof_worst, worst_chi2);
}

const TableOut out_fig4_elastic_3d = outputs.table("fig4_elastic_3d",
    "P(b/d) of elastic smooth hard spheres in 3D (periodic cube), per packing fraction, and 2 b/d");

// The 3D check per packing fraction: chi^2 of the bins against 2 b/d (and, to show the test's
// power, against 1).
void fig4_elastic_3d(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    const int nb = s.n_bins;
    Table& t3 = res.table(out_fig4_elastic_3d);
    t3.add("b_over_d", "1").values = centres;
    t3.add("P_2bd", "1").values = column(centres, [](double x) { return 2 * x; });
    for (std::size_t k = 0; k < s.elastic3d_packing.size(); ++k) {
        const std::string lb = label("eta", s.elastic3d_packing[k], "%g");
        const auto& c3 = pts[s.n_2d() + k].counts[0];
        const Histogram h = normalise(c3);
        t3.add({{"P_" + lb, "1", h.p}, {"err_" + lb, "1", h.err}});
        // chi^2 against a density f on [0, 1] with exact bin integrals; dof = bins - 1.
        auto chi2 = [&](auto cdf) {
            const double tot = static_cast<double>(h.total);
            double x2 = 0;
            for (int b = 0; b < nb; ++b) {
                const double e = tot * (cdf((b + 1.0) / nb) - cdf(static_cast<double>(b) / nb));
                const double o = static_cast<double>(c3[static_cast<std::size_t>(b)]);
                x2 += (o - e) * (o - e) / e;
            }
            return x2 / (nb - 1.0);
        };
        res.scalar("elastic3d_chi2_dof_" + lb, chi2([](double x) { return x * x; }), "1",
                   "chi^2 per dof of the 3D P(b/d) against 2 b/d (molecular chaos in 3D)");
        res.scalar("elastic3d_chi2_dof_flat_" + lb, chi2([](double x) { return x; }), "1",
                   "chi^2 per dof of the 3D P(b/d) against the 2D form 1 (the test's power)");
        res.scalar("elastic3d_collisions_" + lb, static_cast<double>(h.total), "1", "collisions counted");
    }
}

} // namespace granrepro::experiments::impact_parameter_detail
