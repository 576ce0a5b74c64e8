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

// Each measure of fig4_inelastic twice, indexed by late: over the whole run and in the last window.
const ScalarOut out_collisions[2] = {
    outputs.scalar("collisions_r<n>", "1", "pair collisions 0 <= t < t_end, all seeds"),
    outputs.scalar("collisions_late_r<n>", "1", "pair collisions in the last window, all seeds")};
const ScalarOut out_chi2_dof[2] = {
    outputs.scalar("chi2_dof_r<n>", "1", "chi^2 per dof of P(b/d) against 1, whole run"),
    outputs.scalar("chi2_dof_late_r<n>", "1", "chi^2 per dof of P(b/d) against 1, last window")};
const ScalarOut out_grazing_ratio[2] = {
    outputs.scalar("grazing_ratio_r<n>", "1", "P(b/d > 0.8) / P(b/d < 0.2), whole run"),
    outputs.scalar("grazing_ratio_late_r<n>", "1", "P(b/d > 0.8) / P(b/d < 0.2), last window")};
const ScalarOut out_grazing_ratio_err[2] = {outputs.scalar("grazing_ratio_err_r<n>", "1", "its Poisson error"),
                                            outputs.scalar("grazing_ratio_late_err_r<n>", "1", "its Poisson error")};
const ScalarOut out_grazing_z[2] = {outputs.scalar("grazing_z_r<n>", "1", "(ratio - 1) / error, whole run"),
                                    outputs.scalar("grazing_z_late_r<n>", "1", "(ratio - 1) / error, last window")};
const ScalarOut out_grazing_ratio_seed_sem = outputs.scalar("grazing_ratio_seed_sem_r<n>", "1",
    "standard error of the mean of the per-seed ratios (compare grazing_ratio_err)");
const ScalarOut out_tc_elastic_fraction = outputs.scalar("tc_elastic_fraction_r<n>", "1",
    "fraction of collisions made elastic by the TC model (Eq. 7)");

// Fig. 4, inelastic: whole run and the late window (the last of window_edges).
void fig4_inelastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    Table& t4 = res.table(out_fig4_inelastic);
    t4.add("b_over_d", "1").values = centres;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = r_label(s, k), r = r_text(s, k);
        for (const bool late : {false, true}) {
            const auto c = merged(s, pts, k, late ? s.n_windows() - 1 : 0, s.n_windows());
            const Histogram h = normalise(c);
            const Ratio ra = grazing_ratio(c);
            const std::string sfx = late ? "late_" : "";
            t4.add({{"P_" + sfx + lb, "1", h.p}, {"err_" + sfx + lb, "1", h.err}});
            res.put(out_collisions[late], static_cast<double>(h.total), {r});
            res.put(out_chi2_dof[late], chi2_per_dof(c), {r});
            res.put(out_grazing_ratio[late], ra.value, {r});
            res.put(out_grazing_ratio_err[late], ra.err, {r});
            res.put(out_grazing_z[late], ra.z, {r});
        }
        if (s.n_seeds() >= 2) res.put(out_grazing_ratio_seed_sem, grazing_ratio_seed_sem(s, pts, k), {r});
        const std::uint64_t el = seed_sum(s, pts, k, &PointResult::elastic_by_tc);
        const std::uint64_t tot = seed_sum(s, pts, k, &PointResult::pair_collisions);
        res.put(out_tc_elastic_fraction, tot ? static_cast<double>(el) / static_cast<double>(tot) : NAN, {r});
    }
}

const TableOut out_windows = outputs.table("windows_r<n>", "P(b/d) per time window (window_edges), all seeds");
// <n> after t is the window's range as "%g-%g" of its edges ("0.5-1"), which <n>'s characters
// admit: the names stay those claims and plots already use.
const ScalarOut out_grazing_ratio_window = outputs.scalar("grazing_ratio_r<n>_t<n>", "1",
    "P(b/d > 0.8) / P(b/d < 0.2) in that window");

// Time-resolved P(b/d) (as Fig. 3 does for the large system): one table per r.
void fig4_windows(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    const auto& edges = s.window_edges;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        Table& tw = res.table(out_windows, {r_text(s, k)});
        tw.add("b_over_d", "1").values = centres;
        for (std::size_t w = 0; w < s.n_windows(); ++w) {
            const auto c = merged(s, pts, k, w, w + 1);
            const Histogram h = normalise(c);
            const std::string range = label("", edges[w], "%g") + label("-", edges[w + 1], "%g"), wl = "t" + range;
            tw.add({{"P_" + wl, "1", h.p}, {"err_" + wl, "1", h.err}});
            res.put(out_grazing_ratio_window, grazing_ratio(c).value, {r_text(s, k), range});
        }
    }
}

const TableOut out_fig4_elastic = outputs.table("fig4_elastic", "P(b/d) at r = 1 for N = 240 and several densities");
// Per elastic density (number_text writes it as the "%g" of the labels).
const ScalarOut out_elastic_chi2_dof = outputs.scalar("elastic_chi2_dof_rho<n>", "1", "chi^2 per dof of P(b/d) against 1 at r = 1");
const ScalarOut out_elastic_grazing_z = outputs.scalar("elastic_grazing_z_rho<n>", "1",
    "(P(b/d > 0.8)/P(b/d < 0.2) - 1) / error at r = 1");
const ScalarOut out_elastic_collisions = outputs.scalar("elastic_collisions_rho<n>", "1", "pair collisions counted, all seeds");
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
        res.put(out_elastic_chi2_dof, chi, {s.elastic_densities[j]});
        const Ratio ra = grazing_ratio(c);
        res.put(out_elastic_grazing_z, ra.z, {s.elastic_densities[j]});
        res.put(out_elastic_collisions, static_cast<double>(h.total), {s.elastic_densities[j]});
    }
    res.put(out_elastic_chi2_dof_worst, worst_chi2);
}

const TableOut out_fig4_elastic_3d = outputs.table("fig4_elastic_3d",
    "P(b/d) of elastic smooth hard spheres in 3D (periodic cube), per packing fraction, and 2 b/d");

// Per packing fraction (as number_text writes it, like the "%g" of the labels).
const ScalarOut out_elastic3d_chi2_dof = outputs.scalar("elastic3d_chi2_dof_eta<n>", "1",
    "chi^2 per dof of the 3D P(b/d) against 2 b/d (molecular chaos in 3D)");
const ScalarOut out_elastic3d_chi2_dof_flat = outputs.scalar("elastic3d_chi2_dof_flat_eta<n>", "1",
    "chi^2 per dof of the 3D P(b/d) against the 2D form 1 (the test's power)");
const ScalarOut out_elastic3d_collisions = outputs.scalar("elastic3d_collisions_eta<n>", "1", "collisions counted");

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
        res.put(out_elastic3d_chi2_dof, chi2([](double x) { return x * x; }), {s.elastic3d_packing[k]});
        res.put(out_elastic3d_chi2_dof_flat, chi2([](double x) { return x; }), {s.elastic3d_packing[k]});
        res.put(out_elastic3d_collisions, static_cast<double>(h.total), {s.elastic3d_packing[k]});
    }
}

} // namespace granrepro::experiments::impact_parameter_detail
