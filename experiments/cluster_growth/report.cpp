// cluster-growth: the run's scalars, Fig. 10 (K(t), C/N and the TC-elastic shares) and Fig. 11
// (positions coloured by N_c, where N_c is largest, how structures grow).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "data/parameter_set.hpp"
#include "experiments/cluster_growth/spec.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro::experiments::cluster_growth_detail {

namespace {

const TableOut out_energy = outputs.table("energy", "K/K0, C/N and TC-elastic collisions per particle against t");

// Fig. 10: K/K0, C/N and the TC-elastic collisions per particle against t; returns K/K0.
std::vector<double> fig10_table(Result& res, const Samples& st, double t0, double late_from) {
    const auto& ts = st.ts;
    Table& t = res.table(out_energy);
    std::vector<double> kk, an, e18, s2, s1, efrac;
    for (std::size_t i = 0; i < ts.size(); ++i) {
        kk.push_back(st.ks[i] / st.ks[0]);
        an.push_back((st.kxs[i] - st.kys[i]) / (st.kxs[i] + st.kys[i]));
        e18.push_back(theory::haff_energy_ratio(ts[i], t0));
        efrac.push_back(st.cns[i] > 0 ? st.ecns[i] / st.cns[i] : NAN);
    }
    t.add({{"t", "s", ts}, {"K_over_K0", "1", kk}, {"eq18", "1", e18}, {"anisotropy", "1", an},
           {"C_over_N", "1", st.cns}, {"elastic_C_over_N", "1", st.ecns}, {"elastic_fraction", "1", efrac},
           {"own_interval_share", "1", st.fast_share}, {"hot_particles", "1", st.hot}});
    // Guide lines of Fig. 10(a): slope -2, the t >> t0 asymptote of Eq. (18), (t/t0)^-2; slope -1
    // through the geometric mean of the samples from late_slope_from on.
    double lsum = 0;
    int lcount = 0;
    for (std::size_t i = 1; i < ts.size(); ++i)
        if (ts[i] >= late_from) {
            lsum += std::log(kk[i] * ts[i]);
            ++lcount;
        }
    for (std::size_t i = 0; i < ts.size(); ++i) {
        s2.push_back(ts[i] >= t0 ? (t0 / ts[i]) * (t0 / ts[i]) : NAN);
        s1.push_back(ts[i] >= 0.1 * late_from && lcount ? std::exp(lsum / lcount) / ts[i] : NAN);
    }
    t.add({{"slope_minus2", "1", s2}, {"slope_minus1", "1", s1}});
    return kk;
}

const ScalarOut out_t0_fit_over_kinetic = outputs.scalar("t0_fit_over_kinetic", "1",
    "1/t0 fitted to K(t) over t <= t0 (Eq. 18) over the kinetic-theory value");
const ScalarOut out_K_slope_steepest_early = outputs.scalar("K_slope_steepest_early", "1",
    "steepest slope of log K against log t over one octave, t <= late_slope_from");
const ScalarOut out_K_slope_late = outputs.scalar("K_slope_late", "1",
    "average slope of log K against log t from late_slope_from to the end (GSL fit)");
const ScalarOut out_K_slope_late_err = outputs.scalar("K_slope_late_err", "1",
    "its standard error (residual scatter of the 13-per-decade samples)");
const ScalarOut out_K_over_eq18_end = outputs.scalar("K_over_eq18_end", "1",
    "K over Eq. (18) at the end: how much slower than homogeneous cooling");

// How K(t) departs from homogeneous cooling: Eq. (18) early, the slopes later.
void fig10_slopes(Result& res, const std::vector<double>& ts, const std::vector<double>& kk, double t0, int m, double late_from) {
    // Early cooling: Eq. (18) fitted over t <= t0.
    res.put(out_t0_fit_over_kinetic, fit_haff_inv_t0(ts, kk, t0) * t0);
    // Steepest local slope d ln K / d ln t (over one octave) before late_slope_from: Eq. (18)
    // tends to -2 only for t >> t0, while clustering sets in at a few t0.
    double steepest = 0;
    for (std::size_t i = std::size_t(m) + 1; i < ts.size() && ts[i] <= late_from; ++i)
        steepest = std::min(steepest, std::log(kk[i] / kk[i - std::size_t(m)]) / std::log(2.0));
    res.put(out_K_slope_steepest_early, steepest);
    const PowerLawFit late = fit_power_law(ts, kk, late_from, ts.back());
    res.put(out_K_slope_late, late.exponent);
    res.put(out_K_slope_late_err, late.exponent_err);
    res.put(out_K_over_eq18_end, kk.back() / theory::haff_energy_ratio(ts.back(), t0));
}

// The TC-elastic shares of the main run carry no suffix, those of the run with the other pair
// rule its name: "_both", or "_either" when the main run uses tc_both = true (the TOML's list
// lacked these, so such a run stopped before it wrote its results).
const Words rule_words{"", "_both", "_either"};
const ScalarOut out_elastic_fraction_early_max = outputs.scalar("elastic_fraction_early_max<w>", "1",
    "largest TC-elastic share of all pair collisions, cumulative, for t <= elastic_until", rule_words);
const ScalarOut out_elastic_fraction_max = outputs.scalar("elastic_fraction_max<w>", "1",
    "largest TC-elastic share of all pair collisions over the run", rule_words);
const ScalarOut out_own_interval_share_early_max = outputs.scalar("own_interval_share_early_max<w>", "1",
    "largest cumulative share of particle-collisions within t_c of that particle's previous one, t <= elastic_until", rule_words);
const ScalarOut out_hot_particles_early_max = outputs.scalar("hot_particles_early_max<w>", "1",
    "largest fraction of particles whose latest collision came within t_c of the previous one, samples t <= elastic_until",
    rule_words);
const ScalarOut out_hot_particles_early_mean = outputs.scalar("hot_particles_early_mean<w>", "1",
    "its mean over those (log-spaced) samples", rule_words);
// At t = 0.04, 0.64 and 10.24 s, the time in the name as the literal in the code spells it.
const ScalarOut out_C_over_N_at = outputs.scalar("C_over_N_at_<n>s<w>", "1",
    "C/N = (sum of per-particle counts)/N = 2 pair collisions/N at t = ", rule_words);
const ScalarOut out_pairs_over_N_at = outputs.scalar("pairs_over_N_at_<n>s<w>", "1",
    "pair collisions/N (each collision counted once) at t = ", rule_words);

// The TC-elastic share three ways (see the top of cluster_growth.cpp), for t <= elastic_until and over
// the whole run, of one run with pair rule `rule`.
void report_elastic_shares(Result& res, const Samples& ls, const std::string& tag, const char* rule, double until) {
    double coll = 0, coll_all = 0, own = 0, hot_max = 0, hot_sum = 0;
    int hot_n = 0;
    for (std::size_t i = 1; i < ls.ts.size(); ++i) {
        if (!(ls.cns[i] > 0)) continue;
        coll_all = std::max(coll_all, ls.ecns[i] / ls.cns[i]);
        if (ls.ts[i] > until) continue;
        coll = std::max(coll, ls.ecns[i] / ls.cns[i]);
        own = std::max(own, ls.fast_share[i]);
        hot_max = std::max(hot_max, ls.hot[i]);
        hot_sum += ls.hot[i];
        ++hot_n;
    }
    const std::string r = std::string(" (") + rule + " rule)";
    res.put(out_elastic_fraction_early_max, coll, {tag}, r);
    res.put(out_elastic_fraction_max, coll_all, {tag}, r);
    res.put(out_own_interval_share_early_max, own, {tag}, r);
    res.put(out_hot_particles_early_max, hot_max, {tag}, r);
    res.put(out_hot_particles_early_mean, hot_n ? hot_sum / hot_n : NAN, {tag}, r);
    auto at = [&](double tq, const std::vector<double>& v) -> double {
        for (std::size_t i = 0; i < ls.ts.size(); ++i)
            if (same_time(ls.ts[i], tq)) return v[i];
        return NAN;
    };
    for (const char* when : {"0.04", "0.64", "10.24"}) {
        const double tq = std::stod(when);
        res.put(out_C_over_N_at, at(tq, ls.cns), {when, tag}, when + (" s" + r));
        res.put(out_pairs_over_N_at, 0.5 * at(tq, ls.cns), {when, tag}, when + (" s" + r));
    }
}

const ScalarOut out_elastic_share_before_until = outputs.scalar("elastic_share_before_until", "1",
    "TC-elastic share of the pair collisions up to the last sample t <= elastic_until");
const ScalarOut out_elastic_share_after_until = outputs.scalar("elastic_share_after_until", "1",
    "TC-elastic share of the pair collisions from that sample to the end");
const ScalarOut out_elastic_share_late_over_early = outputs.scalar("elastic_share_late_over_early", "1",
    "elastic_share_after_until / elastic_share_before_until: above 1 when elastic collisions increase for t > elastic_until");
const ScalarOut out_elastic_share_after_until_collisions = outputs.scalar("elastic_share_after_until_collisions", "1",
    "pair collisions after elastic_until (sets the counting error of elastic_share_after_until)");

// Fig. 10(b), "for larger times, the number of elastic collisions increases": the TC-elastic
// share of the pair collisions made after elastic_until (the last sample t <= elastic_until up to
// the end) over the share made up to it. Above 1: the squares of Fig. 10(b) rise faster than the
// circles. NaN if the run ends before elastic_until or has no elastic collision by then.
void report_elastic_increase(Result& res, const Samples& st, double until, double n) {
    std::size_t u = 0;
    for (std::size_t i = 1; i < st.ts.size(); ++i)
        if (st.ts[i] <= until) u = i;
    const std::size_t e = st.ts.size() - 1;
    double early = NAN, late = NAN;
    if (u > 0 && e > u && st.cns[u] > 0 && st.cns[e] > st.cns[u]) {
        early = st.ecns[u] / st.cns[u];
        late = (st.ecns[e] - st.ecns[u]) / (st.cns[e] - st.cns[u]);
    }
    res.put(out_elastic_share_before_until, early);
    res.put(out_elastic_share_after_until, late);
    res.put(out_elastic_share_late_over_early, early > 0 ? late / early : NAN);
    res.put(out_elastic_share_after_until_collisions, e > u ? 0.5 * (st.cns[e] - st.cns[u]) * n : NAN);
}

// The disks per cell of a grid of cells of `cell` (at least 3 x 3) over the periodic box of side L,
// row by row; cell(q) is the (column, row) of position q.
struct CellCounts {
    std::size_t m;
    double L;
    std::vector<double> count;
    CellCounts(const std::vector<Vec2>& pos, double L, double cell)
        : m(std::max<std::size_t>(3, std::size_t(L / cell))), L(L), count(m * m, 0.0) {
        for (const Vec2& q : pos) {
            const auto c = this->cell(q);
            count[c[1] * m + c[0]] += 1;
        }
    }
    std::array<std::size_t, 2> cell(const Vec2& q) const {
        return {std::min(m - 1, std::size_t(q.x / L * double(m))), std::min(m - 1, std::size_t(q.y / L * double(m)))};
    }
};

// Mean of the Fig. 11 colour (N_c) over particles ranked by the local area fraction around them
// (disks per cell of cluster_cell diameters, smoothed over the 3 x 3 block): the mean N_c in each
// of `groups` equal-size groups from the most dilute to the densest.
std::vector<double> rate_by_density(const Instant& in, double L, double cell, int groups) {
    const CellCounts cells(in.pos, L, cell);
    const std::size_t nc = cells.m;
    const std::vector<double>& occ = cells.count;
    std::vector<std::pair<double, double>> dens_rate;
    for (std::size_t i = 0; i < in.pos.size(); ++i) {
        const auto c = cells.cell(in.pos[i]);
        double s = 0;
        for (std::size_t dy = 0; dy < 3; ++dy)
            for (std::size_t dx = 0; dx < 3; ++dx) s += occ[((c[1] + nc + dy - 1) % nc) * nc + (c[0] + nc + dx - 1) % nc];
        dens_rate.push_back({s, in.rate[i]});
    }
    std::sort(dens_rate.begin(), dens_rate.end()); // ties broken by rate: deterministic
    std::vector<double> out(std::size_t(groups), 0.0);
    const std::size_t n = dens_rate.size();
    for (int g = 0; g < groups; ++g) {
        const std::size_t a = n * std::size_t(g) / std::size_t(groups), b = n * std::size_t(g + 1) / std::size_t(groups);
        double s = 0;
        for (std::size_t i = a; i < b; ++i) s += dens_rate[i].second;
        out[std::size_t(g)] = b > a ? s / double(b - a) : NAN;
    }
    return out;
}

const ScalarOut out_densest_tenth_rank_of_max_Nc = outputs.scalar("densest_tenth_rank_of_max_Nc", "1",
    "over the clustered snapshots (C/N >= 70): the lowest density rank (1-10) of the tenth of particles with the largest mean N_c");
const ScalarOut out_densest_tenth_Nc_over_mean_min = outputs.scalar("densest_tenth_Nc_over_mean_min", "1",
    "the smallest ratio of the densest tenth's mean N_c to the overall mean there");
const ScalarOut out_densest_tenth_Nc_over_mean_t = outputs.scalar("densest_tenth_Nc_over_mean_t<n>", "1",
    "mean N_c of the densest tenth over the overall mean at this snapshot");
const ScalarOut out_densest_tenth_rank_of_max_Nc_t = outputs.scalar("densest_tenth_rank_of_max_Nc_t<n>", "1",
    "density rank (1-10) of the tenth with the largest mean N_c");

// From the first clustered snapshot on (C/N >= 70, Sec. 4.3): the smallest rank of the tenth
// with the largest mean N_c (10 = the densest at every such snapshot).
void report_cluster_centres(Result& res, const std::vector<double>& mt, const std::vector<double>& mc,
                            const std::vector<double>& top, const std::vector<double>& ratio) {
    double worst = NAN, min_ratio = NAN;
    for (std::size_t k = 0; k < mt.size(); ++k)
        if (mc[k] >= 70) {
            worst = std::isnan(worst) ? top[k] : std::min(worst, top[k]);
            min_ratio = std::isnan(min_ratio) ? ratio[k] : std::min(min_ratio, ratio[k]);
        }
    res.put(out_densest_tenth_rank_of_max_Nc, worst);
    res.put(out_densest_tenth_Nc_over_mean_min, min_ratio);
    for (std::size_t k = 0; k < mt.size(); ++k) {
        res.put(out_densest_tenth_Nc_over_mean_t, ratio[k], {mt[k]});
        res.put(out_densest_tenth_rank_of_max_Nc_t, top[k], {mt[k]});
    }
}

const ScalarOut out_density_corr_length_growing_share = outputs.scalar("density_corr_length_growing_share", "1",
    "share of successive Fig. 11 snapshots whose density correlation length exceeds the previous one's");
const ScalarOut out_density_corr_length_pairs = outputs.scalar("density_corr_length_pairs", "1",
    "number of such snapshot pairs");
const ScalarOut out_density_corr_length_last_over_first = outputs.scalar("density_corr_length_last_over_first", "1",
    "density correlation length at the last snapshot over that at the first");
const ScalarOut out_density_corr_length_t = outputs.scalar("density_corr_length_t<n>", "1",
    "first zero of the density autocorrelation (cells of cluster_cell d), in d, at this snapshot");
const TableOut out_structure_growth = outputs.table("structure_growth",
    "density correlation length at the Fig. 11 snapshots");

// Fig. 11's "grow in size": the density correlation length at each snapshot, and the share of
// successive snapshots at which it is larger than at the one before.
void report_structure_growth(Result& res, const std::vector<double>& mt, const std::vector<double>& xi) {
    int pairs = 0, growing = 0;
    for (std::size_t k = 1; k < xi.size(); ++k) {
        if (!std::isfinite(xi[k]) || !std::isfinite(xi[k - 1])) continue;
        ++pairs;
        if (xi[k] > xi[k - 1]) ++growing;
    }
    res.put(out_density_corr_length_growing_share, pairs ? double(growing) / pairs : NAN);
    res.put(out_density_corr_length_pairs, double(pairs));
    res.put(out_density_corr_length_last_over_first, xi.size() > 1 ? xi.back() / xi.front() : NAN);
    for (std::size_t k = 0; k < mt.size(); ++k)
        res.put(out_density_corr_length_t, xi[k], {mt[k]});
    Table& t = res.table(out_structure_growth);
    t.add({{"t", "s", mt}, {"corr_length_over_d", "1", xi}});
}

// Fig. 11, "structures build up in the system and grow in size": the density correlation length,
// the first zero of the radially averaged autocorrelation C(r) of the disk count per cell of
// cluster_cell diameters (the cells of rate_by_density), linearly interpolated between cell
// distances; in diameters. C(r) over every periodic displacement (m^4 products, 1e8 at m = 100).
double density_correlation_length(const Instant& in, double L, double cell, double d) {
    CellCounts cells(in.pos, L, cell);
    const std::size_t m = cells.m;
    std::vector<double>& o = cells.count;
    const double mean = double(in.pos.size()) / double(m * m);
    for (double& v : o) v -= mean;
    const std::size_t rmax = m / 2 + 1;
    std::vector<double> acc(rmax + 1, 0.0), cnt(rmax + 1, 0.0);
    for (std::size_t dy = 0; dy < m; ++dy)
        for (std::size_t dx = 0; dx < m; ++dx) {
            const double sx = dx <= m / 2 ? double(dx) : double(dx) - double(m), sy = dy <= m / 2 ? double(dy) : double(dy) - double(m);
            const auto r = std::size_t(std::lround(std::hypot(sx, sy)));
            if (r > rmax) continue;
            double sum = 0;
            for (std::size_t y = 0; y < m; ++y) {
                const double* a = &o[y * m];
                const double* b = &o[((y + dy) % m) * m];
                for (std::size_t x = 0; x < m; ++x) sum += a[x] * b[(x + dx) % m];
            }
            acc[r] += sum;
            cnt[r] += 1;
        }
    if (!(acc[0] > 0)) return NAN;
    const double c0 = acc[0] / cnt[0];
    double prev = 1;
    for (std::size_t r = 1; r <= rmax; ++r) {
        if (cnt[r] == 0) continue;
        const double c = acc[r] / cnt[r] / c0;
        if (c <= 0) return (double(r) - 1 + prev / (prev - c)) * cell / d;
        prev = c;
    }
    return NAN;
}

} // namespace

KineticTheory kinetic_theory(const ClusterSpec& s) {
    const double rho = M_PI / 4 * double(s.n()) / (s.box_over_d * s.box_over_d);
    const double omega = theory::enskog_collision_rate_vbar(rho, s.d, s.vbar, theory::henderson_contact_value(rho));
    return {rho, omega, theory::haff_t0(s.r, omega)};
}

const ScalarOut out_N = outputs.scalar("N", "1", "number of disks");
const ScalarOut out_rho = outputs.scalar("rho", "1", "area fraction (pi/4) N / L^2");
const ScalarOut out_t0_kinetic = outputs.scalar("t0_kinetic", "s",
    "t0 of Eq. (18) from kinetic theory (sqrt(2 pi) in Eq. 19; see cooling.cpp)");
const ScalarOut out_omega_equilibration_over_enskog = outputs.scalar("omega_equilibration_over_enskog", "1",
    "elastic collision rate per particle during equilibration over Enskog's");
const ScalarOut out_wall_seconds_run = outputs.scalar("wall_seconds_run", "s",
    "wall time of the cooling run (after equilibration)");
const ScalarOut out_events_per_second = outputs.scalar("events_per_second", "1/s",
    "ED events (collisions, cell crossings, stale) per second");
const ScalarOut out_collisions_per_second = outputs.scalar("collisions_per_second", "1/s",
    "pair collisions per second");
const ScalarOut out_events = outputs.scalar("events", "1", "ED events of the cooling run");
const ScalarOut out_tc_both = outputs.scalar("tc_both", "1",
    "pair rule of the main run: 1 = both partners within t_c, 0 = either");
const ScalarOut out_wall_seconds_other_rule = outputs.scalar("wall_seconds_other_rule", "s",
    "wall time of the run with the other pair rule");
const ScalarOut out_t_end = outputs.scalar("t_end", "s", "end of the run");
const ScalarOut out_C_over_N_end = outputs.scalar("C_over_N_end", "1", "collisions per particle at the end");
const ScalarOut out_stopped_by_engine = outputs.scalar("stopped_by_engine", "1",
    "1 if the collapse guard stopped the run");

void report_run(Result& res, const ClusterSpec& s, const KineticTheory& kin, const RunOutcome& main_run,
                const RunOutcome* other_run) {
    res.put(out_N, double(s.n()));
    res.put(out_rho, kin.rho);
    res.put(out_t0_kinetic, kin.t0);
    res.put(out_omega_equilibration_over_enskog, main_run.omega_eq / kin.omega_enskog);
    res.put(out_wall_seconds_run, main_run.wall);
    res.put(out_events_per_second, main_run.events / main_run.wall);
    res.put(out_collisions_per_second, main_run.collisions / main_run.wall);
    res.put(out_events, main_run.events);
    res.put(out_tc_both, s.tc_both ? 1.0 : 0.0);
    if (other_run) res.put(out_wall_seconds_other_rule, other_run->wall);
    res.put(out_t_end, main_run.st.ts.back());
    res.put(out_C_over_N_end, main_run.st.cns.back());
    res.put(out_stopped_by_engine, main_run.error.empty() ? 0.0 : 1.0);
}

const ScalarOut out_elastic_per_particle_end = outputs.scalar("elastic_per_particle_end", "1",
    "TC-elastic collisions per particle at the end");
const ScalarOut out_C_over_N_eq18_at_0_64s = outputs.scalar("C_over_N_eq18_at_0.64s", "1",
    "C/N at 0.64 s if the gas stayed homogeneous: 4/(1-r^2) ln(1 + t/t0)");

void fig10(Result& res, const ClusterSpec& s, double t0, const Samples& st, const Samples* other) {
    const std::vector<double> kk = fig10_table(res, st, t0, s.late_slope_from);
    fig10_slopes(res, st.ts, kk, t0, s.samples_per_octave, s.late_slope_from);
    // The main pair rule and, with tc_compare_until, the other one.
    report_elastic_shares(res, st, "", s.tc_both ? "both" : "either", s.elastic_until);
    if (other) report_elastic_shares(res, *other, s.tc_both ? "_either" : "_both", s.tc_both ? "either" : "both", s.elastic_until);
    res.put(out_elastic_per_particle_end, st.ecns.back());
    report_elastic_increase(res, st, s.elastic_until, double(s.n()));
    res.put(out_C_over_N_eq18_at_0_64s, 4 / (1 - s.r * s.r) * std::log(1 + 0.64 / t0));
}

const TableOut out_snapshot = outputs.table("snapshot_<n>", "positions and N_c over the last t/2 at t = ");

// Fig. 11: positions coloured by N_c at the paper's times, one colour range for all panels.
// Sec. 4.2: "in the bright regions in the centers of the clusters the collision frequency is
// largest". Particles ranked by the number of disks around them (cells of cluster_cell
// diameters, 3 x 3 block); mean N_c per tenth, densest tenth last. The claim looks at which
// tenth has the largest mean N_c.
void fig11(Result& res, const std::vector<Instant>& instants, const ClusterSpec& s) {
    std::vector<const Instant*> shown;
    for (double tq : s.snapshot_times)
        for (const auto& in : instants)
            if (same_time(in.t, tq)) shown.push_back(&in);
    double lo = INFINITY, hi = 0; // from the smallest positive N_c to the largest
    for (const Instant* in : shown)
        for (double v : in->rate)
            if (v > 0) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
    const std::vector<double> mt = column(shown, &Instant::t), mc = column(shown, &Instant::cn);
    std::vector<double> top, ratio, xi;
    for (const Instant* in : shown) {
        Table& sn = res.table(out_snapshot, {std::to_string(top.size())}, number_text(in->t) + " s");
        const auto x = column(in->pos, [&](const Vec2& q) { return q.x / s.d; });
        const auto y = column(in->pos, [&](const Vec2& q) { return q.y / s.d; });
        sn.add({{"x_over_d", "1", x}, {"y_over_d", "1", y}, {"N_c", "1/s", in->rate}});
        const auto g = rate_by_density(*in, s.L(), s.cluster_cell * s.d, 10);
        top.push_back(double(std::max_element(g.begin(), g.end()) - g.begin() + 1));
        xi.push_back(density_correlation_length(*in, s.L(), s.cluster_cell * s.d, s.d));
        ratio.push_back(g.back() / in->mean_rate);
    }
    Table& meta = res.table(out_fig_selection, {11},
                            "instants of the snapshots, the common colour range, and N_c in the densest tenth");
    meta.add({{"t", "s", mt}, {"C_over_N", "1", mc}, {"Nc_colour_lo", "1/s", std::vector<double>(mt.size(), lo)},
              {"Nc_colour_hi", "1/s", std::vector<double>(mt.size(), hi)}, {"densest_tenth_with_max_Nc", "1", top},
              {"densest_tenth_Nc_over_mean", "1", ratio}});
    report_cluster_centres(res, mt, mc, top, ratio);
    report_structure_growth(res, mt, xi);
}

} // namespace granrepro::experiments::cluster_growth_detail
