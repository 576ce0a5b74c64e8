// cooling: the report of a run (set-up, t0, the equilibrated a2, the figures of ED and DSMC), and
// the helpers its figure files share.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "analysis/seed_stats.hpp"
#include "core/rng_stream.hpp"
#include "experiments/cooling/spec.hpp"

namespace granrepro::experiments::cooling_detail {

// The values of a curve v(x) over lo <= x <= hi, and their mean, maximum and minimum.
std::vector<double> over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    std::vector<double> in;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (x[i] >= lo && x[i] <= hi) in.push_back(v[i]);
    return in;
}
double mean_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    const auto in = over(v, x, lo, hi);
    return in.empty() ? NAN : std::accumulate(in.begin(), in.end(), 0.0) / double(in.size());
}
double max_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    const auto in = over(v, x, lo, hi);
    return std::accumulate(in.begin(), in.end(), -HUGE_VAL, [](double a, double b) { return std::max(a, b); });
}
double min_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    const auto in = over(v, x, lo, hi);
    return std::accumulate(in.begin(), in.end(), HUGE_VAL, [](double a, double b) { return std::min(a, b); });
}

// The mean over seeds of v through `mean`, and its seed standard deviation through `sd`.
void add_mean_sd(Result& res, const ScalarOut& mean, const ScalarOut& sd, const std::vector<double>& v) {
    const MeanSd ms = mean_sd(v, NonFinite::censored);
    res.put(mean, ms.mean);
    res.put(sd, ms.sd);
}

namespace {

// Wall time of a method's runs, summed over seeds [s].
double wall_seconds(const std::vector<Trace>& trs) {
    const std::vector<double> wall = column(trs, &Trace::wall_seconds);
    return std::accumulate(wall.begin(), wall.end(), 0.0);
}

// <w>: the method, ed or dsmc; <n>: the seed index, as std::to_string writes it.
const TableOut out_sk_seed = outputs.table("sk_<w>_seed<n>", "S(k) at the snapshot times, seed index ", {"ed", "dsmc"});
const TableOut out_energy_seed = outputs.table("energy_<w>_seed<n>", "K/K0 against t, seed index ", {"ed", "dsmc"});

// Per-seed S(k) at every snapshot and K/K0 of one method, for studies that compare runs made
// separately (scripts/studies/dsmc_variants.sh).
void add_seed_tables(Result& res, const std::vector<Trace>& trs, const std::vector<double>& snaps, const char* name) {
    for (std::size_t k = 0; k < trs.size(); ++k) {
        const Trace& tr = trs[k];
        {
            Table& t = res.table(out_sk_seed, {name, std::to_string(k)}, std::to_string(k) + ", " + name);
            t.add("k", "1").values = tr.S_k;
            for (std::size_t i = 0; i < tr.snaps.size(); ++i) t.add("S_t" + number_text(snaps[i]), "1").values = tr.snaps[i].S;
        }
        Table& e = res.table(out_energy_seed, {name, std::to_string(k)}, std::to_string(k) + ", " + name);
        e.add({{"t", "s", tr.t}, {"K_over_K0", "1", k_ratio(tr)}, {"C_over_N", "1", tr.cn}});
    }
}

const ScalarOut out_N = outputs.scalar("N", "1", "number of disks");
// seeds and wall_time_dsmc are written by report_dsmc_only too, which describes them its own way:
// each writer appends the rest of the description.
const ScalarOut out_seeds = outputs.scalar("seeds", "1", "independent initial states");
const ScalarOut out_wall_time_ed = outputs.scalar("wall_time_ed", "s",
    "wall time of the ED runs from t = 0 with their observables, summed over seeds and resumed parts");
const ScalarOut out_wall_time_dsmc = outputs.scalar("wall_time_dsmc", "s", "wall time of the DSMC runs");
const ScalarOut out_box = outputs.scalar("box", "m", "side of the periodic box");
const ScalarOut out_t0_inv_eq19_printed = outputs.scalar("t0_inv_eq19_printed", "1/s",
    "1/t0 from Eq. (19) as printed (sqrt(pi))");
const ScalarOut out_t0_inv_kinetic_theory = outputs.scalar("t0_inv_kinetic_theory", "1/s",
    "1/t0 = (1-r^2) omega_E / 4 with Henderson's g(d): sqrt(2 pi)");
const ScalarOut out_omega_equilibration_over_enskog = outputs.scalar("omega_equilibration_over_enskog", "1",
    "elastic ED collision rate over the second half of the equilibration over the Enskog-Henderson rate");
const ScalarOut out_t0_inv_measured_rate = outputs.scalar("t0_inv_measured_rate", "1/s",
    "1/t0 from the measured elastic collision rate");

// The run's size and cost, and t0 in its three readings: Eq. (19) as printed, kinetic theory, and
// the measured elastic collision rate.
void add_setup(Result& res, const CoolingSpec& c, const Setup& s, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const double r = c.r;
    // Eq. (19) as printed; theory::luding_eq19_t0_printed forms s_* otherwise and differs in the
    // last bit.
    const double s_star = 1 / theory::henderson_contact_value(c.rho);
    const double t0_printed = std::sqrt(M_PI) * c.d * s_star / (2 * (1 - r * r) * c.rho * c.vbar);
    const double t0_measured_rate = 4 / ((1 - r * r) * s.collision_rate);
    res.put(out_N, double(s.pos.size()));
    res.put(out_seeds, double(c.seeds), {}, " (equilibration, ED and DSMC each)");
    res.put(out_wall_time_ed, wall_seconds(eds));
    if (c.run_dsmc)
        res.put(out_wall_time_dsmc, wall_seconds(dss), {}, " from t = 0 with their observables, summed over seeds and resumed parts");
    res.put(out_box, s.L);
    res.put(out_t0_inv_eq19_printed, 1 / t0_printed);
    res.put(out_t0_inv_kinetic_theory, 1 / c.t0());
    res.put(out_omega_equilibration_over_enskog, s.collision_rate / c.omega_enskog());
    res.put(out_t0_inv_measured_rate, 1 / t0_measured_rate);
}

const ScalarOut out_a2_initial_velocities = outputs.scalar("a2_initial_velocities", "1",
    "a2 of the velocities drawn before the equilibration (uniform components: -0.3)");
const ScalarOut out_a2_equilibrated = outputs.scalar("a2_equilibrated", "1",
    "Sonine a2 of the velocities at t = 0 (after the elastic equilibration), all seeds");
const ScalarOut out_a2_equilibrated_err = outputs.scalar("a2_equilibrated_err", "1",
    "its standard error (sample variance of v^4)");
const ScalarOut out_a2_equilibrated_z = outputs.scalar("a2_equilibrated_z", "1",
    "a2 at t = 0 in standard errors (Maxwellian: |z| ~ 1)");

// The equilibrated state is Maxwellian (Sec. 3: "so that a Maxwellian velocity distribution ...
// exists"): a2 pooled over the seeds, against 0 with its standard error.
void add_equilibrated_a2(Result& res, const CoolingSpec& c, std::uint64_t seed, const Setups& setups) {
    std::vector<Vec2> all;
    for (long k = 0; k < setups.size(); ++k) all.insert(all.end(), setups[k].vel.begin(), setups[k].vel.end());
    const auto a2 = sonine_a2(all);
    RngStream rng(seed, setup_stream(0));
    const auto v0 = initial_velocities(c, setups[0].mass, rng);
    res.put(out_a2_initial_velocities, sonine_a2(v0)[0]);
    res.put(out_a2_equilibrated, a2[0]);
    res.put(out_a2_equilibrated_err, a2[1]);
    res.put(out_a2_equilibrated_z, a2[0] / a2[1]);
}

const ScalarOut out_dsmc_eq18_max_dev_2t0 = outputs.scalar("dsmc_eq18_max_dev_2t0", "1",
    "max |K/K_18 - 1| for t <= 2 t0, DSMC");
const ScalarOut out_dsmc_g_inside_contact_mean = outputs.scalar("dsmc_g_inside_contact_mean", "1",
    "mean g(r/d < 0.9), last snapshot, DSMC (no exclusion hole: about 1)");
const ScalarOut out_dsmc_g_contact_peak = outputs.scalar("dsmc_g_contact_peak", "1",
    "g near contact over g at 2.5-5 d, last snapshot, DSMC");
const ScalarOut out_dsmc_Sk_small_k_growth = outputs.scalar("dsmc_Sk_small_k_growth", "1",
    "mean S(k <= sk_k_max) at the last snapshot over that at t = 0, DSMC, first seed");
const ScalarOut out_dsmc_Sk_growth_over_equilibrium = outputs.scalar("dsmc_Sk_growth_over_equilibrium", "1",
    "mean S(k <= sk_k_max) at the last snapshot over the hard-disk equilibrium S(0), DSMC, first seed");
const ScalarOut out_dsmc_C_over_N_end = outputs.scalar("dsmc_C_over_N_end", "1",
    "collisions per particle at t_end, DSMC");
const ScalarOut out_dsmc_pbd_grazing_ratio_last = outputs.scalar("dsmc_pbd_grazing_ratio_last", "1",
    "P(b/d>0.8)/P(b/d<0.2), last window, DSMC (molecular chaos: 1)");

// Figs. 2, 6 and 7 of DSMC, and DSMC against ED.
void add_dsmc(Result& res, const CoolingSpec& c, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const Trace& ds = dss.front();
    const double t0 = c.t0(), k_small = c.sk_k_max;
    const std::vector<double> snaps = c.snapshots();
    add_energy_table(res, ds, t0, "dsmc");
    add_structure_tables(res, ds, snaps, c.rho, "dsmc");
    res.put(out_dsmc_eq18_max_dev_2t0, max_dev(ds, t0, 2 * t0));
    add_dsmc_kinetics(res, dss, c);
    add_ed_dsmc_energy(res, eds, dss, t0, c.departure_level);
    add_loss_per_collision(res, c, eds, dss);
    const auto& g_last = ds.snaps.back().g;
    res.put(out_dsmc_g_inside_contact_mean, mean_over(g_last, ds.g_r, 0.0, 0.9));
    res.put(out_dsmc_g_contact_peak, max_over(g_last, ds.g_r, 0.9, 1.1) / mean_over(g_last, ds.g_r, 2.5, 5.0));
    add_sk_agreement(res, eds, dss, snaps, k_small);
    add_cell_imprint(res, eds, dss);
    res.put(out_dsmc_Sk_small_k_growth, small_k_S(ds, ds.snaps.back(), k_small) / small_k_S(ds, ds.snaps.front(), k_small));
    res.put(out_dsmc_Sk_growth_over_equilibrium, small_k_S(ds, ds.snaps.back(), k_small) / theory::hard_disk_structure_factor_zero(c.rho));
    res.put(out_dsmc_C_over_N_end, ds.cn.back());
    add_seed_tables(res, dss, snaps, "dsmc");
    if (c.velocity_correlation) add_velocity_correlation(res, c, dss, "dsmc");
    res.put(out_dsmc_pbd_grazing_ratio_last, grazing_ratio(ds.pbd.back(), ds.pbd_centres));
}

} // namespace

// run_ed = false: DSMC alone (for variant studies; the claims that compare with ED are then missing).
Result report_dsmc_only(const CoolingSpec& c, const std::vector<Trace>& dss) {
    Result res;
    res.put(out_seeds, double(c.seeds));
    res.put(out_wall_time_dsmc, wall_seconds(dss), {}, ", summed over seeds");
    add_seed_tables(res, dss, c.snapshots(), "dsmc");
    add_dsmc_kinetics(res, dss, c);
    return res;
}

// Figs. 2, 3, 6 and 7 of ED, and DSMC against ED if it ran.
Result report_all(const CoolingSpec& c, std::uint64_t seed, const Setups& setups, const std::vector<Trace>& eds,
              const std::vector<Trace>& dss) {
    const Trace& ed = eds.front();
    const std::vector<double> snaps = c.snapshots();
    Result res;
    add_setup(res, c, setups[0], eds, dss);
    add_equilibrated_a2(res, c, seed, setups);
    add_energy_table(res, ed, c.t0(), "ed");
    add_ed_cooling(res, c, eds);
    add_impact_parameter(res, ed);
    add_structure_tables(res, ed, snaps, c.rho, "ed");
    add_seed_tables(res, eds, snaps, "ed");
    add_ed_g(res, eds, snaps, c.t0());
    add_ed_sk(res, eds, snaps, c.sk_k_max, theory::hard_disk_structure_factor_zero(c.rho));
    add_sk_change_intervals(res, eds, dss, snaps, c.sk_k_max);
    if (c.velocity_correlation) add_velocity_correlation(res, c, eds, "ed");
    if (c.run_dsmc) add_dsmc(res, c, eds, dss);
    return res;
}

} // namespace granrepro::experiments::cooling_detail
