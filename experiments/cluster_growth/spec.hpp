// cluster-growth (Figs. 10-12): the spec, what a run and an instant hold, and what the files share.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "core/vec2.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"
#include "harness/experiment.hpp"
#include "harness/progress.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/rate_histogram.hpp"
#include "scenarios/ed_gas.hpp"

namespace granrepro::experiments::cluster_growth_detail {

// The catalog every output handle of cluster-growth registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"cluster-growth"};
// The instants Figs. 11 and 12 show (report.cpp, report_fig12.cpp): one family, as the TOML
// declared it, each figure's own description passed where it is written.
inline const TableOut out_fig_selection = outputs.table("fig<n>_selection", "");

enum class Start { lattice, random };
inline void parse_choice(const std::string& s, Start& x) { x = s == "lattice" ? Start::lattice : Start::random; }

struct ClusterSpec {
    long n_side = 0;                         // N = n_side^2
    double box_over_d = 0, cluster_cell = 0; // in diameters
    double d = 0, mass = 0, vbar = 0;        // [m], [kg], [m/s]
    double r = 0, mu = 0;
    double t_c = 0, t_base = 0, t_max = 0, late_slope_from = 0, elastic_until = 0; // [s]
    double tc_compare_until = 0; // [s]; 0: no run with the other pair rule
    bool tc_both = false;
    Start initial_positions = Start::lattice;
    double equilibration = 0; // collisions per particle at r = 1
    double cn_end = 0, poisson_until_cn = 0, tail_fit_from = 0, hist_quantile = 0;
    double tail_rate = 0; // [1/s]
    int samples_per_octave = 0, hist_bins = 0;
    std::vector<double> paper_cn, snapshot_times; // snapshot_times [s]
    GRANREPRO_FIELDS(n_side, box_over_d, d, mass, vbar, mu, r, t_c, tc_both, tc_compare_until, initial_positions,
                     equilibration, t_base, samples_per_octave, cn_end, t_max, paper_cn, snapshot_times, cluster_cell,
                     poisson_until_cn, tail_fit_from, hist_bins, hist_quantile, tail_rate, late_slope_from,
                     elastic_until)
    std::size_t n() const { return std::size_t(n_side * n_side); }
    double L() const { return box_over_d * d; } // [m]
    std::vector<double> radii() const { return std::vector<double>(n(), 0.5 * d); }
    std::vector<double> masses() const { return std::vector<double>(n(), mass); }
};

// What an instant t = t_base 2^k is rebuilt from (make_instant); the checkpoint holds only this.
struct InstantRecord {
    double t = 0, cn = 0, elastic_cn = 0; // t [s]; C/N and TC-elastic C/N at t
    double fast_fraction = 0; // particles with a collision within t_c of their previous one in (t/2, t]
    std::vector<double> rate;          // N_c per particle over (t/2, t] [1/s]
    std::vector<std::uint64_t> counts; // collisions per particle over (0, t]
    std::vector<Vec2> pos;             // positions at t [m]; in a point's JSON only at snapshot_times
    template <class V>
    void fields(V&& v) {
        v("t", t), v("cn", cn), v("elastic_cn", elastic_cn), v("fast_fraction", fast_fraction);
        v("rate", rate), v("counts", counts), v("position", pos);
    }
};

// One instant and what was measured there.
struct Instant : InstantRecord {
    double window = 0;
    RateHistogram hist;
    CollisionRateFit poisson, expo, power;
    CollisionRateFit poisson_full; // Eq. (20) for the counts over (0, t]
    CollisionRateFit power_tail, expo_tail; // Eqs. (22), (21) over N_c >= tail_fit_from x mean N_c
    double tail_lo = 0;                    // that lower end [1/s]
    double mean_rate = 0, sd_rate = 0, tail_fraction = 0;
};

// What a run measured, sample by sample and at the instants: all the analysis reads of it.
struct Samples {
    std::vector<double> ts, ks, kxs, kys, cns, ecns; // per sample: t [s], K, K_x, K_y [J], C/N, TC-elastic C/N
    std::vector<double> fast_share; // per sample: cumulative share of particle-collisions within t_c of the particle's previous one
    std::vector<double> hot;        // per sample: fraction of particles whose latest interval was <= t_c
    std::vector<InstantRecord> instants;
    template <class V>
    void fields(V&& v) {
        v("t", ts), v("K", ks), v("Kx", kxs), v("Ky", kys), v("C_over_N", cns), v("elastic_C_over_N", ecns);
        v("fast_share", fast_share), v("hot", hot), v("instants", instants);
    }
};

// A run's sweep point: what the analysis reads of it, through its JSON (harness/protocol.hpp), so
// that threads, ranks, shards and gather give the same bits. No ±inf in it (JSON would return NaN;
// omega_eq is NaN without equilibration, and stays NaN): the carry's per-particle bookkeeping,
// -inf / +inf before a particle's first collision, stays in the mid-run checkpoint.
struct RunOutcome {
    Samples st;
    std::string error; // the collapse guard's message, if it stopped the run
    double wall = 0;   // [s]
    double events = 0, collisions = 0;
    double omega_eq = 0; // collision rate per particle of the elastic equilibration [1/s]
    template <class V>
    void fields(V&& v) {
        v("samples", st), v("error", error), v("wall_seconds", wall), v("events", events), v("collisions", collisions);
        v("omega_equilibration", omega_eq);
    }
};

// Is t the time tq (e.g. the instant at t the Fig. 11 snapshot time tq)? Times are t_base 2^(j/m),
// computed, so equal only to 1e-9.
inline bool same_time(double t, double tq) { return std::abs(t / tq - 1) < 1e-9; }

// compute.cpp: the equilibrated initial state, one TCED run from it, and what of a run is kept.
EquilibratedGas initial_gas(const ClusterSpec& s, std::uint64_t seed);
RunOutcome run_tced(const RunContext& ctx, const ClusterSpec& s, const EquilibratedGas& gas, bool tc_both, double cn_end,
                    double t_stop, const std::string& name, Progress* progress);
RunOutcome trimmed(RunOutcome r, const ClusterSpec& s, bool main_run);

// The homogeneous gas at t = 0: Enskog's collision rate and t0 of Eq. (18) (sqrt(2 pi) in
// Eq. 19; see theory/kinetic_theory.hpp).
struct KineticTheory {
    double rho = 0, omega_enskog = 0, t0 = 0; // omega [1/s], t0 [s]
};
KineticTheory kinetic_theory(const ClusterSpec& s);

// report.cpp: the run's scalars, Fig. 10 and Fig. 11 (the snapshots, cluster centres, growth).
void report_run(Result& res, const ClusterSpec& s, const KineticTheory& kin, const RunOutcome& main_run,
                const RunOutcome* other_run);
void fig10(Result& res, const ClusterSpec& s, double t0, const Samples& st, const Samples* other);
void fig11(Result& res, const std::vector<Instant>& instants, const ClusterSpec& s);

// report_fig12.cpp: an instant's N_c histogram and fits, and Fig. 12 with the claims about it.
Instant make_instant(InstantRecord rec, const ClusterSpec& s);
void fig12_instants_table(Result& res, const std::vector<Instant>& instants);
void report_poisson_falling(Result& res, const std::vector<Instant>& instants, double until_cn);
void fig12_panels(Result& res, const std::vector<Instant>& instants, const std::vector<double>& pcn);
void report_at_paper_cn(Result& res, const std::vector<Instant>& instants, const std::vector<double>& paper_cn);
void report_clustered_B(Result& res, const std::vector<Instant>& instants);
void report_powerlaw_onset(Result& res, const std::vector<Instant>& instants);

} // namespace granrepro::experiments::cluster_growth_detail
