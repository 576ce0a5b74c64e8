// bistable-pipe (Fig. 6): the report: per k_N tables of the steady states, branches, v_crit
// crossings, the near-wall area fraction, the estimates below Eq. (9) and the time series.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "analysis/seed_stats.hpp"
#include "data/parameter_set.hpp"
#include "experiments/bistable_pipe/spec.hpp"

namespace granrepro::experiments::bistable_pipe_detail {

const RunResult* find_run(const std::vector<RunResult>& results, int role, double k, double e, bool fast) {
    for (const RunResult& rr : results)
        if (rr.role == role && rr.k_N == k && rr.e_N == e && rr.fast == fast) return &rr;
    return nullptr;
}

const RunResult& run_at(const std::vector<RunResult>& results, int role, double k, double e, bool fast) {
    if (const RunResult* rr = find_run(results, role, k, e, fast)) return *rr;
    throw std::runtime_error("bistable-pipe: no run of role " + std::to_string(role) + " at k_N = " + number_text(k) +
                             ", e_N = " + number_text(e) + (fast ? ", fast start" : ", slow start") +
                             " among the outcomes (stored before outcomes named their run?)");
}

namespace {

// The columns of one k_N's table of Fig. 6, per start (0 slow, 1 fast) over e_N, and the
// construction's link for the slow start at the largest e_N.
enum SteadyColumn { kV, kVLast, kOutcome, kTEnd, kBalance, kSigmaVx, kNdot, kDvy, kVConstruction, kImpactSlope,
                    kContacts, kVyImpact, kVConstructionVxin, kReach, kBuildsPerStep, kXiSteady, kPhiWall, kStepsPerWall,
                    kColumns };
struct KColumns { std::vector<double> col[2][kColumns]; double link_top = NAN; };
// Over all runs: the worst Eq. (9) balance, the smallest impact-curve slope, steady states.
struct Totals { double worst_balance = 0, min_slope = INFINITY; int steady = 0; };

const TableOut out_steady = outputs.table("steady_k<n>", "steady-state mean velocity against e_N (NaN: no steady state)");
const ScalarOut out_fast_branch_fraction_eq5 = outputs.scalar("fast_branch_fraction_eq5_k<n>", "1",
    "fraction of e_N values whose fast start at Eq. (5)'s step (t_col / steps_per_contact throughout) reached a "
    "steady state above v_crit (NaN under time_step = eq5: the fast column itself is at that step)");

// One k_N of Fig. 6: both starts against e_N, with outcomes, Eq. (9) and the construction.
KColumns table_k(Result& r, const BistablePipeSpec& b, const PipeSpec& base, std::size_t ki,
                 const std::vector<RunResult>& results, Totals& tot) {
    const auto& es = b.eN_list;
    KColumns c;
    for (std::size_t ei = 0; ei < es.size(); ++ei)
        for (int f = 0; f < 2; ++f) {
            const RunResult& rr = run_at(results, kFig6, b.kN_list[ki], es[ei], f == 1);
            const bool ok = rr.outcome == kSteady;
            const double bal = ok ? rr.ndot * rr.dvy / base.geo.gravity : NAN;
            const Construction& cons = rr.construction;
            if (f == 0 && ei + 1 == es.size()) c.link_top = cons.link;
            const double row[kColumns] = {ok ? -rr.v_mean : NAN, -rr.v_final, double(rr.outcome),
                                          ok ? rr.t_steady : rr.t_final, bal, ok ? rr.sigma_vx : NAN,
                                          ok ? rr.ndot : NAN, ok ? rr.dvy : NAN, cons.v, cons.slope, cons.contacts,
                                          ok ? rr.vy_in : NAN, cons.v_vxin, cons.reach,
                                          double(rr.list_builds) / double(std::max(1L, rr.steps)), ok ? rr.xi_steady : NAN,
                                          ok ? rr.phi_wall : NAN,
                                          // steps while the plug passes one wall grain at its last speed
                                          base.geo.wall_spacing / (std::abs(rr.v_final) * rr.dt_final)};
            for (int j = 0; j < kColumns; ++j) c.col[f][j].push_back(row[j]);
            if (ok) {
                ++tot.steady;
                tot.worst_balance = std::max(tot.worst_balance, std::abs(bal - 1));
                if (std::isfinite(cons.slope)) tot.min_slope = std::min(tot.min_slope, cons.slope);
            }
        }
    Table& t = r.table(out_steady, {b.kN_list[ki]});
    t.add("e_N", "1").values = es;
    const char* names[kColumns] = {"v", "v_last", "outcome", "t_end", "eq9_balance", "sigma_vx", "ndot", "dvy",
                                   "v_construction", "impact_slope", "impact_contacts", "vy_impact",
                                   "v_construction_vxin", "construction_reach", "list_builds_per_step", "xi_max_steady",
                                   "phi_wall", "steps_per_wall"};
    const char* units[kColumns] = {"m/s", "m/s", "1", "s", "1", "m/s", "1/s", "m/s", "m/s", "s", "1", "m/s", "m/s", "1", "1", "1", "1", "1"};
    for (int f = 0; f < 2; ++f)
        for (int j = 0; j < kColumns; ++j) t.add(std::string(names[j]) + (f ? "_fast" : "_slow"), units[j]).values = c.col[f][j];
    // The fast starts at Eq. (5)'s step, drawn beside the resolved ones (time_step = "wall"): their
    // own runs where the wall rule can take over below v_abort, else the fast run itself when the
    // rule never changed its step (then the two runs are one).
    std::vector<double> ev, el, eo, es5, ex;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        const RunResult* own = find_run(results, kEq5, b.kN_list[ki], es[ei], true);
        const RunResult& fast = run_at(results, kFig6, b.kN_list[ki], es[ei], true);
        const double dt5 = pipe_time_step(base, pipe_law(b.kN_list[ki], es[ei], base.m_mean));
        // Under time_step = eq5 the fast run is itself at Eq. (5)'s step: nothing to draw beside it.
        const RunResult* rr = b.time_step == "eq5"             ? nullptr
                              : own                           ? own
                              : fast.dt_min >= dt5 ? &fast : nullptr;
        const bool ok = rr && rr->outcome == kSteady;
        ev.push_back(ok ? -rr->v_mean : NAN);
        el.push_back(rr ? -rr->v_final : NAN);
        eo.push_back(rr ? double(rr->outcome) : NAN);
        es5.push_back(rr ? base.geo.wall_spacing / (std::abs(rr->v_final) * rr->dt_final) : NAN);
        ex.push_back(ok ? rr->sigma_vx : NAN);
    }
    t.add({{"v_fast_eq5", "m/s", ev}, {"v_last_fast_eq5", "m/s", el}, {"outcome_fast_eq5", "1", eo},
           {"steps_per_wall_fast_eq5", "1", es5}, {"sigma_vx_fast_eq5", "m/s", ex}});
    int eq5_states = 0;
    for (std::size_t ei = 0; ei < es.size(); ++ei) eq5_states += ev[ei] >= v_crit(b, b.kN_list[ki]); // NaN: false
    // Under time_step = eq5 no comparison run exists (the fast column is itself at Eq. (5)'s step):
    // NaN, not a fraction of zero.
    r.put(out_fast_branch_fraction_eq5, b.time_step == "eq5" ? NAN : double(eq5_states) / double(es.size()), {b.kN_list[ki]});
    return c;
}

const ScalarOut out_impact_link_top = outputs.scalar("impact_link_top_k<n>", "1",
    "slow start at the largest e_N: Δv_y of the wall's impact curve at the measured mean impact velocities "
    "over the measured Δv_y per wall impact");
const ScalarOut out_slow_branch_lowest_eN = outputs.scalar("slow_branch_lowest_eN_k<n>", "1",
    "smallest e_N whose slow start reached a steady state in the normal regime (below v_crit)");
const ScalarOut out_fast_branch_fraction = outputs.scalar("fast_branch_fraction_k<n>", "1",
    "fraction of e_N values whose fast start reached a steady state above v_crit (the fast branch)");
const ScalarOut out_v_slow_top = outputs.scalar("v_slow_top_k<n>", "m/s", "steady speed of the slow start at the largest e_N");
const ScalarOut out_v_fast_top = outputs.scalar("v_fast_top_k<n>", "m/s", "steady speed of the fast start at the largest e_N");
const ScalarOut out_bistable_fraction = outputs.scalar("bistable_fraction_k<n>", "1",
    "fraction of the e_N > 0.85 of the grid where a slow (below v_crit) and a fast (above) steady state coexist");
const ScalarOut out_bistable_sigma_vx_ratio = outputs.scalar("bistable_sigma_vx_ratio_k<n>", "1",
    "σ_vx of the fast over the slow state at the largest bistable e_N");
const ScalarOut out_normal_branch_top = outputs.scalar("normal_branch_top_k<n>", "1",
    "1 if the slow start at the largest e_N reaches a steady state below v_crit = v_crit_2000 sqrt(k_N/2000 N/m)");
const ScalarOut out_bistable_eN_count = outputs.scalar("bistable_eN_count_k<n>", "1",
    "e_N > 0.85 of the grid at which a slow (below v_crit) and a fast (above) steady state coexist");

// The steady states of one k_N against v_crit(k_N): the slow branch (normal regime, below v_crit),
// the fast one, and where both coexist (bistability).
void report_states_k(Result& r, const std::vector<double>& es, double k, const KColumns& c, double v_crit) {
    const auto &slow = c.col[0], &fast = c.col[1];
    // A slow start that settles above v_crit has joined the fast branch and does not count.
    double e_lowest_slow = NAN;
    int fast_steady = 0;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        if (slow[kV][ei] < v_crit) e_lowest_slow = std::isnan(e_lowest_slow) ? es[ei] : std::min(e_lowest_slow, es[ei]);
        // A fast start that falls back to the slow branch is not a state of the fast branch.
        fast_steady += fast[kOutcome][ei] == double(kSteady) && fast[kV][ei] >= v_crit;
    }
    r.put(out_impact_link_top, c.link_top, {k});
    r.put(out_slow_branch_lowest_eN, e_lowest_slow, {k});
    r.put(out_fast_branch_fraction, double(fast_steady) / double(es.size()), {k});
    r.put(out_v_slow_top, slow[kV].back(), {k});
    r.put(out_v_fast_top, fast[kV].back(), {k});
    // Bistability: at the e_N > 0.85 of the grid, the slow start reaches a steady state in the
    // normal regime (below v_crit) and the fast start one above it: two coexisting steady states.
    int bistable = 0, above_085 = 0;
    double sx_ratio = NAN;
    for (std::size_t ei = 0; ei < es.size(); ++ei) {
        if (!(es[ei] > 0.85)) continue;
        ++above_085;
        if (!(slow[kV][ei] < v_crit && fast[kV][ei] >= v_crit)) continue; // NaN compares false
        ++bistable;
        sx_ratio = fast[kSigmaVx][ei] / slow[kSigmaVx][ei];
    }
    r.put(out_bistable_fraction, above_085 ? double(bistable) / above_085 : NAN, {k});
    r.put(out_bistable_sigma_vx_ratio, sx_ratio, {k});
    r.put(out_normal_branch_top, slow[kV].back() < v_crit ? 1.0 : 0.0, {k});
    r.put(out_bistable_eN_count, bistable, {k});
}

const ScalarOut out_fast_branch_v_ln_eN = outputs.scalar("fast_branch_v_ln_eN_k<n>", "m/s",
    "mean of v |ln e_N| over the fast branch's states (constant if v ∝ 1/gamma_N)");
const ScalarOut out_fast_branch_v_ln_eN_cv = outputs.scalar("fast_branch_v_ln_eN_cv_k<n>", "1",
    "its coefficient of variation over the states");
// Per branch (<w>: slow or fast); the branch is named inside the description too, so that is
// written whole at run time.
const Words branches = {"slow", "fast"};
const ScalarOut out_branch_states = outputs.scalar("<w>_branch_states_k<n>", "1", "", branches);
const ScalarOut out_branch_contacts = outputs.scalar("<w>_branch_contacts_k<n>", "1",
    "mean wall grains touched per impact at the measured impact velocities, ", branches);
const ScalarOut out_branch_construction_ratio = outputs.scalar("<w>_branch_construction_ratio_k<n>", "1",
    "geometric mean of the construction's speed (v_x^i = σ_vx) over the measured one, ", branches);
const ScalarOut out_branch_construction_found = outputs.scalar("<w>_branch_construction_found_k<n>", "1", "", branches);
const ScalarOut out_branch_construction_ratio_vxin = outputs.scalar("<w>_branch_construction_ratio_vxin_k<n>", "1",
    "the same with v_x^i = the measured mean |v_x| of the wall impacts, ", branches);
const ScalarOut out_branch_construction_reach = outputs.scalar("<w>_branch_construction_reach_k<n>", "1",
    "geometric mean over the states of max Δv_y(v_y^i; v_x^i = σ_vx) / (g/ṅ): below 1 the paper's "
    "association gives no intersection, ", branches);

// One regime of a k_N: states faster than v_crit(k_N) (Fig. 3's maximum, scaled with sqrt(k_N) by
// Eq. 8) are the fast branch whichever start reached them. Fig. 5 says the fast branch is the
// emergency brake (>= 2 wall grains per impact), the slow one the normal regime. And the paper's
// construction against the measured speed.
void report_branch_k(Result& r, const std::vector<double>& es, double k, const KColumns& c, double v_crit,
                     bool fast_branch) {
    double contacts = 0, ratio = 0, ratio_in = 0, reach = 0;
    int nc = 0, nr = 0, nr_in = 0, nreach = 0;
    std::vector<double> v_ln_e; // fast branch: v |ln e_N| per state
    for (const auto& col : c.col)
        for (std::size_t ei = 0; ei < es.size(); ++ei) {
            const double v = col[kV][ei];
            if (std::isnan(v) || (v > v_crit) != fast_branch) continue;
            if (std::isfinite(col[kContacts][ei])) { contacts += col[kContacts][ei]; ++nc; }
            if (std::isfinite(col[kVConstruction][ei])) { ratio += std::log(col[kVConstruction][ei] / v); ++nr; }
            if (std::isfinite(col[kVConstructionVxin][ei])) { ratio_in += std::log(col[kVConstructionVxin][ei] / v); ++nr_in; }
            if (std::isfinite(col[kReach][ei])) { reach += std::log(col[kReach][ei]); ++nreach; }
            if (fast_branch) v_ln_e.push_back(v * std::abs(std::log(es[ei])));
        }
    const std::string name = fast_branch ? "fast" : "slow";
    if (fast_branch) {
        // The fast branch's speed against 1/|ln e_N| ∝ 1/gamma_N: how much of its braking is the
        // dashpot's speed-independent friction impulse (brake-failure's high_v_plateau).
        const MeanSd vl = mean_sd(v_ln_e);
        r.put(out_fast_branch_v_ln_eN, vl.mean, {k});
        r.put(out_fast_branch_v_ln_eN_cv, vl.sd / vl.mean, {k});
    }
    r.put(out_branch_states, nc, {name, k}, "steady states on the " + name + " branch (either start)");
    r.put(out_branch_contacts, nc ? contacts / nc : NAN, {name, k}, name + " branch");
    r.put(out_branch_construction_ratio, nr ? std::exp(ratio / nr) : NAN, {name, k},
          name + " branch; NaN if no state has a stable intersection");
    r.put(out_branch_construction_found, nc ? double(nr) / nc : NAN, {name, k},
          "fraction of the " + name + " branch's states for which the construction (v_x^i = σ_vx) finds a "
          "stable intersection within 0.1-3 times the measured speed");
    r.put(out_branch_construction_ratio_vxin, nr_in ? std::exp(ratio_in / nr_in) : NAN, {name, k}, name + " branch");
    r.put(out_branch_construction_reach, nreach ? std::exp(reach / nreach) : NAN, {name, k}, name + " branch");
}

const ScalarOut out_vcrit_crossings = outputs.scalar("vcrit_crossings_k<n>", "1",
    "runs that started below v_crit and whose mean speed exceeded it at some sample");
const ScalarOut out_vcrit_crossings_end_fast = outputs.scalar("vcrit_crossings_end_fast_k<n>", "1",
    "fraction of those runs that ended above v_crit (fast steady state, or faster than v_crit at the end)");
const ScalarOut out_vcrit_crossings_settled_fast = outputs.scalar("vcrit_crossings_settled_fast_k<n>", "1",
    "fraction of those runs that ended in a steady state above v_crit (the emergency brake of the Summary)");

// Fig. 6 over every k_N, and what the paper says across them.
// "If the flow ... becomes higher than v_crit, the system will accelerate to the emergency-brake
// steady state" (Summary): of the runs of one k_N whose mean speed ever exceeded v_crit, the
// fraction that ended above it (a fast steady state, or still faster than v_crit at the end).
void report_vcrit_crossings_k(Result& r, double k, const std::vector<const RunResult*>& runs, double v_crit) {
    int crossed = 0, ended_fast = 0, settled_fast = 0;
    for (const RunResult* run : runs) {
        const RunResult& rr = *run;
        // "Becomes faster": starts below v_crit (a fast start begins above it and may only fall back).
        if (rr.v.empty() || -rr.v.front() > v_crit || -*std::min_element(rr.v.begin(), rr.v.end()) <= v_crit) continue;
        ++crossed;
        ended_fast += (rr.outcome == kSteady ? -rr.v_mean : -rr.v_final) > v_crit;
        settled_fast += rr.outcome == kSteady && -rr.v_mean > v_crit;
    }
    r.put(out_vcrit_crossings, crossed, {k});
    r.put(out_vcrit_crossings_end_fast, crossed ? double(ended_fast) / crossed : NAN, {k});
    r.put(out_vcrit_crossings_settled_fast, crossed ? double(settled_fast) / crossed : NAN, {k});
}

const ScalarOut out_near_wall_phi_mean = outputs.scalar("near_wall_phi_mean", "1",
    "mean area fraction of the layer one diameter inside the wall crests, steady states");
const ScalarOut out_near_wall_phi_spread = outputs.scalar("near_wall_phi_spread", "1",
    "(largest - smallest) / mean of that near-wall area fraction over the steady states");

// Eq. (9)'s argument: the volume fraction near the wall is "essentially a constant for fixed global
// volume fraction". Over every steady state of Fig. 6 (all k_N, both starts, one global phi): its spread.
void report_near_wall_phi(Result& r, const std::vector<RunResult>& results) {
    std::vector<double> pw;
    for (const RunResult& rr : results)
        if (rr.role == kFig6 && rr.outcome == kSteady && std::isfinite(rr.phi_wall)) pw.push_back(rr.phi_wall);
    const auto [lo, hi] = std::minmax_element(pw.begin(), pw.end());
    const double mean = mean_sd(pw).mean;
    r.put(out_near_wall_phi_mean, mean);
    r.put(out_near_wall_phi_spread, pw.size() >= 2 ? (*hi - *lo) / mean : NAN);
}

} // namespace


const ScalarOut out_dt_check_change = outputs.scalar("dt_check_change", "1",
    "the fast start at dt_check_eN (k_N = kN_list[1]) with every step halved against its Fig. 6 run: relative change of the steady speed if both settled, else of the speed at the end of the shorter run");
const ScalarOut out_dt_check_same_outcome = outputs.scalar("dt_check_same_outcome", "1",
    "1 if that run and its Fig. 6 run end alike (steady, free fall or unsettled)");

// The fast start run again with every step halved (dt_check_eN) against its Fig. 6 run: the
// relative change of the steady speed if both settled, else of the speed at the end of the
// shorter run (both accelerating, or one settled: a change of outcome shows as a large change).
void report_dt_check(Result& r, const std::vector<RunResult>& results) {
    const auto chk = std::find_if(results.begin(), results.end(), [](const RunResult& rr) { return rr.role == kDtCheck; });
    if (chk == results.end()) return;
    const RunResult &h = *chk, &a = run_at(results, kFig6, h.k_N, h.e_N, true);
    double change;
    if (a.outcome == kSteady && h.outcome == kSteady) {
        change = std::abs(h.v_mean - a.v_mean) / std::abs(a.v_mean);
    } else {
        const std::size_t n = std::min(a.v.size(), h.v.size()); // samples at the same times
        change = n ? std::abs(h.v[n - 1] - a.v[n - 1]) / std::abs(a.v[n - 1]) : NAN;
    }
    r.put(out_dt_check_change, change);
    r.put(out_dt_check_same_outcome, a.outcome == h.outcome ? 1.0 : 0.0);
}

const ScalarOut out_steady_runs = outputs.scalar("steady_runs", "1", "runs that reached a steady state");
const ScalarOut out_fast_branch_k200_over_k2000 = outputs.scalar("fast_branch_k200_over_k2000", "1",
    "geometric mean of v_fast(k_N = 200) / v_fast(k_N = 2000) over the e_N where both settled on the fast branch");
const ScalarOut out_eq9_worst_deviation = outputs.scalar("eq9_worst_deviation", "1",
    "largest |ṅ Δv_y / g - 1| over steady runs (Eq. 9)");
const ScalarOut out_impact_slope_min = outputs.scalar("impact_slope_min", "s",
    "smallest slope dΔv_y/dv of the impact curve at a steady state's speed (Eq. 9 argument: > 0)");
const ScalarOut out_length_check_ratio = outputs.scalar("length_check_ratio", "1",
    "steady speed at length_check over that at length (same k_N, e_N, slow start)");
const ScalarOut out_xi_max_over_d = outputs.scalar("xi_max_over_d_k<n>", "1",
    "largest overlap of any contact over all runs at this k_N, over the smaller diameter (Eq. 4's xi_max)");
const ScalarOut out_xi_max_steady_over_d = outputs.scalar("xi_max_steady_over_d_k<n>", "1",
    "the same over the steady states only (NaN: none)");

void report_fig6(Result& r, const BistablePipeSpec& b, const PipeSpec& base, const std::vector<RunResult>& results) {
    const auto &ks = b.kN_list, &es = b.eN_list;
    Totals tot;
    for (std::size_t ki = 0; ki < ks.size(); ++ki) { // one row of the figure
        const double k = ks[ki]; // fills the <n> of the per-k_N names ("steady_k2000")
        const KColumns c = table_k(r, b, base, ki, results, tot);
        const double vc = v_crit(b, k);
        report_states_k(r, es, k, c, vc);
        for (bool fast : {false, true}) report_branch_k(r, es, k, c, vc, fast);
        std::vector<const RunResult*> runs; // Fig. 6's runs at this k_N, by e_N, slow start first
        for (double e : es)
            for (bool fast : {false, true}) runs.push_back(&run_at(results, kFig6, ks[ki], e, fast));
        report_vcrit_crossings_k(r, k, runs, vc);
        double xi = 0;
        for (const RunResult* rr : runs) xi = std::max(xi, rr->xi_max);
        r.put(out_xi_max_over_d, xi, {k});
        double xs = NAN;
        for (const RunResult* rr : runs)
            if (const double x = rr->xi_steady; std::isfinite(x)) xs = std::isnan(xs) ? x : std::max(xs, x);
        r.put(out_xi_max_steady_over_d, xs, {k});
    }
    report_near_wall_phi(r, results);
    report_dt_check(r, results);
    r.put(out_steady_runs, tot.steady);
    // Softer grains brake earlier: the k_N = 200 fast branch against the k_N = 2000 one at the same
    // e_N (geometric mean of the speed ratio over the e_N where both fast starts settled above v_crit).
    const auto k_lo = std::find(ks.begin(), ks.end(), 200.0), k_mid = std::find(ks.begin(), ks.end(), 2000.0);
    if (k_lo != ks.end() && k_mid != ks.end()) {
        double lr = 0;
        int nr = 0;
        for (double e : es) {
            const RunResult &lo = run_at(results, kFig6, *k_lo, e, true), &mid = run_at(results, kFig6, *k_mid, e, true);
            // Fast-branch states only: a fast start that fell back to the slow branch is not one.
            if (lo.outcome != kSteady || mid.outcome != kSteady || -lo.v_mean < v_crit(b, 200.0) ||
                -mid.v_mean < v_crit(b, 2000.0))
                continue;
            lr += std::log(lo.v_mean / mid.v_mean);
            ++nr;
        }
        r.put(out_fast_branch_k200_over_k2000, nr ? std::exp(lr / nr) : NAN);
    }
    r.put(out_eq9_worst_deviation, tot.steady ? tot.worst_balance : NAN);
    r.put(out_impact_slope_min, std::isfinite(tot.min_slope) ? tot.min_slope : NAN);
    if (b.length_check > 0) {
        const double k_check = ks[ks.size() > 1 ? 1 : 0]; // make_tasks' choice
        const RunResult& at_length = run_at(results, kFig6, k_check, es.back(), false);
        const RunResult& at_check = run_at(results, kLengthCheck, k_check, es.back(), false);
        r.put(out_length_check_ratio, (at_length.outcome == kSteady && at_check.outcome == kSteady) ? at_check.v_mean / at_length.v_mean : NAN);
    }
}

const TableOut out_eq9_windows = outputs.table("eq9_windows",
    "ṅ, Δv_y, σ_vx and speed over windows of eq9_window, every run");
const ScalarOut out_ndot_vs_sigma_vx_exponent = outputs.scalar("ndot_vs_sigma_vx_exponent", "1",
    "exponent of ṅ ∝ σ_vx^a over all windows");
const ScalarOut out_ndot_dvy_vs_dvy_exponent = outputs.scalar("ndot_dvy_vs_dvy_exponent", "1",
    "exponent of ṅ Δv_y ∝ Δv_y^b over all windows");
const ScalarOut out_sigma_vx_vs_dvy_exponent = outputs.scalar("sigma_vx_vs_dvy_exponent", "1",
    "exponent of σ_vx ∝ Δv_y^c over all windows");
// A scalar named like the table above (out_eq9_windows): the count of windows in the fits.
const ScalarOut out_eq9_windows_count = outputs.scalar("eq9_windows", "1", "windows in those fits");

// The crude estimates below Eq. (9), over windows of every run: ṅ ∝ σ_vx, and ṅ Δv_y grows
// about quadratically with Δv_y.
void report_eq9_windows(Result& r, const std::vector<RunResult>& results) {
    std::vector<double> wk, wn, wd, ws, wv, lx, ly, ld, lnd; // every window; those for the power-law fits
    for (std::size_t i = 0; i < results.size(); ++i)
        for (std::size_t j = 0; j < results[i].w_ndot.size(); ++j) {
            if (results[i].role != kFig6 && results[i].role != kLengthCheck) break; // the model's runs only
            const double n = results[i].w_ndot[j], d = results[i].w_dvy[j], sx = results[i].w_sx[j];
            wk.push_back(results[i].k_N);
            wn.push_back(n);
            wd.push_back(d);
            ws.push_back(sx);
            wv.push_back(results[i].w_v[j]);
            if (n > 0 && sx > 0 && d > 0) {
                lx.push_back(sx);
                ly.push_back(n);
                ld.push_back(d);
                lnd.push_back(n * d);
            }
        }
    Table& tw = r.table(out_eq9_windows);
    tw.add({{"k_N", "N/m", wk}, {"ndot", "1/s", wn}, {"dvy", "m/s", wd}, {"sigma_vx", "m/s", ws}, {"v", "m/s", wv}});
    const auto a = lx.size() >= 10 ? fit_power_law(lx, ly, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    const auto c = ld.size() >= 10 ? fit_power_law(ld, lnd, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    const auto sd = ld.size() >= 10 ? fit_power_law(ld, lx, 0, INFINITY) : PowerLawFit{NAN, NAN, 0};
    r.put(out_ndot_vs_sigma_vx_exponent, a.exponent);
    r.put(out_ndot_dvy_vs_dvy_exponent, c.exponent);
    r.put(out_sigma_vx_vs_dvy_exponent, sd.exponent);
    r.put(out_eq9_windows_count, double(lx.size()));
}

// One table per run: series_k<k_N>_e<e_N>_<start and role> (series_word).
const TableOut out_series = outputs.table("series_k<n>_e<n>_<w>", "mean velocity and rms v_x against time",
                                          {"slow", "fast", "slow_length_check", "fast_eq5", "fast_dt_check"});

void report_series(Result& r, const std::vector<RunResult>& results) {
    for (const RunResult& rr : results) {
        Table& ts = r.table(out_series, {rr.k_N, rr.e_N, series_word(rr.fast, rr.role)});
        ts.add("t", "s").values = rr.t;
        ts.add({{"v_down", "m/s", column(rr.v, std::negate<>())}, {"sigma_vx", "m/s", rr.sx}});
    }
}
} // namespace granrepro::experiments::bistable_pipe_detail
