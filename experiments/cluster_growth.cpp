// cluster-growth: Luding (1998) Sections 4.2 and 4.3, Figs. 10-12. N = 79524 disks in a periodic
// box of side L = 500 d (rho = 0.25) are equilibrated elastically; at t = 0 the TCED model
// (Eq. 7) with r = 0.8 and t_c = 1e-5 s takes over and the gas cools, clusters and the clusters
// grow. Measured: K(t), C/N(t) and the TC-elastic collisions per particle (Fig. 10); at
// t = t_base 2^k the per-particle collision frequency N_c over the last Δt = t/2 (Figs. 11, 12),
// its distribution P(N_c) and the fits of Eqs. (20)-(22).
//
// C/N = sum of per-particle collision counts / N = 2 (pair collisions) / N. Why this reading:
// Eq. (18) with the Enskog rate omega0 (experiments/cooling.cpp) gives
// C/N = omega0 t0 ln(1 + t/t0) = 4/(1-r^2) ln(1 + t/t0) = 7.3 at t = 0.04 s, the paper's
// "C/N = 8, i.e. t = 0.04 s"; counting a pair collision once would give 3.7.
//
// TC-elastic share, three ways (Sec. 4.2 speaks of "the fraction of particles that have collisions
// with a collision frequency larger than 1/t_c"): (1) the engine's share of pair collisions made
// elastic by Eq. (7) under the pair rule in force ("either" or "both" partners); (2) per particle,
// Eq. (7) literally: the share of particle-collisions (each pair collision counts for both
// partners) that came within t_c of that particle's previous one; (3) the fraction of particles
// whose latest collision came within t_c of the one before (current collision frequency > 1/t_c).
// With tc_compare_until > 0 the other pair rule runs beside the main one from the same state.
//
// Why t = t_base 2^k: the paper's instants 0.04, 0.64 and 10.24 s are 0.01 s times powers of two,
// and with Δt = t/2 the window of one instant starts exactly at the previous instant, so storing
// the per-particle counts at every instant gives N_c = (count(t) - count(t/2)) / (t/2) with no
// per-collision bookkeeping (1e8 collisions at paper scale).
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <gsl/gsl_statistics_double.h>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>

#include "analysis/curve_analysis.hpp"
#include "core/rng_stream.hpp"
#include "data/spec.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "harness/progress.hpp"
#include "harness/run_checkpoint.hpp"
#include "harness/run_log.hpp"
#include "harness/sampled_run.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/rate_histogram.hpp"
#include "scenarios/ed_gas.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro::experiments {

namespace {

enum class Start { lattice, random };
void parse_choice(const std::string& s, Start& x) { x = s == "lattice" ? Start::lattice : Start::random; }

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
    template <class V>
    void fields(V&& v) {
        v("n_side", n_side), v("box_over_d", box_over_d), v("d", d), v("mass", mass), v("vbar", vbar);
        v("mu", mu), v("r", r), v("t_c", t_c), v("tc_both", tc_both), v("tc_compare_until", tc_compare_until);
        v("initial_positions", initial_positions), v("equilibration", equilibration), v("t_base", t_base);
        v("samples_per_octave", samples_per_octave), v("cn_end", cn_end), v("t_max", t_max);
        v("paper_cn", paper_cn), v("snapshot_times", snapshot_times), v("cluster_cell", cluster_cell);
        v("poisson_until_cn", poisson_until_cn), v("tail_fit_from", tail_fit_from), v("hist_bins", hist_bins);
        v("hist_quantile", hist_quantile), v("tail_rate", tail_rate), v("late_slope_from", late_slope_from);
        v("elastic_until", elastic_until);
    }
    std::size_t n() const { return std::size_t(n_side * n_side); }
    double L() const { return box_over_d * d; } // [m]
    std::vector<double> radii() const { return std::vector<double>(n(), 0.5 * d); }
    std::vector<double> masses() const { return std::vector<double>(n(), mass); }
};

void validate(const ParameterSet& p) {
    const auto s = read_spec<ClusterSpec>(p);
    if (s.box_over_d / double(s.n_side) < 1.0000001)
        p.reject(std::vector<std::string>{"box_over_d", "n_side"},
                 "box_over_d too small for a square-lattice start of n_side^2 disks (lattice spacing below d)");
    // The linked-cell grid of the ED engine has ~(box_over_d)^2 cells of one diameter.
    p.limit_work({"box_over_d"}, s.box_over_d * s.box_over_d, 1e8, "cells of the linked-cell grid");
    if (s.box_over_d < 3.0) p.reject("box_over_d", "must be at least 3 (three cells for the minimum image)");
    if (s.t_max <= s.t_base) p.reject("t_max", "must exceed t_base");
    if (s.paper_cn.empty()) p.reject("paper_cn", "needs at least one value");
    // The main run to C/N = cn_end (or t_max), the other pair rule beside it, the
    // equilibration: bounded by 2 (cn_end + equilibration) collisions per particle.
    const double n = double(s.n_side) * double(s.n_side);
    p.limit_work({"cn_end", "n_side", "equilibration"}, 2 * n / 2 * (s.cn_end + s.equilibration), kMaxCollisions, "collisions");
    // Samples at t_base 2^(j/m) up to t_max, each holding the N positions.
    const double samples = std::log2(s.t_max / s.t_base) * double(s.samples_per_octave);
    p.limit_work({"t_max", "t_base", "samples_per_octave"}, samples, 1e5, "samples");
}

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

RateHistogram histogram(const std::vector<double>& rate, double window, const ClusterSpec& s) {
    const double mean = gsl_stats_mean(rate.data(), 1, rate.size());
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
    in.mean_rate = gsl_stats_mean(in.rate.data(), 1, n);
    in.sd_rate = gsl_stats_sd(in.rate.data(), 1, n);
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

// Everything the sampling loop carries from one sample to the next, besides the engine: the
// samples and the observer's bookkeeping (same fields, same order as schema version 3).
struct LoopState : Samples {
    std::vector<std::uint64_t> prev_counts; // at the previous instant t/2
    // Per-particle Eq. (7) bookkeeping from the collision records (observer state).
    std::vector<double> last_t, last_interval;  // [s]; -inf / +inf before the first
    std::vector<std::uint32_t> fast, prev_fast; // collisions within t_c of the previous one, and at t/2
    std::uint64_t fast_total = 0;               // their sum over particles
    template <class V>
    void fields(V&& v) {
        Samples::fields(v);
        v("prev_counts", prev_counts), v("last_t", last_t), v("last_interval", last_interval), v("fast", fast), v("prev_fast", prev_fast);
        v("fast_total", fast_total);
    }
};

constexpr const char* kRunSchema = "granrepro-cluster-growth-run";
constexpr long kRunSchemaVersion = 3; // 3: the carry written field by field (harness/sampled_run.hpp)

// The initial state: disks on a square lattice (Sec. 4.1) or placed at random, Maxwellian
// velocities, equilibrated elastically. The collision rate is that of the equilibration's second
// half (as in cooling): the first collisions after a lattice start are rarer than in equilibrium,
// which put the whole-run rate 3.6 % below Enskog's (issue 27 §4).
EquilibratedGas initial_gas(const ClusterSpec& s, std::uint64_t seed) {
    const double L = s.L();
    const std::vector<double> rad = s.radii(), mass = s.masses();
    RngStream rng(seed, 0);
    if (s.initial_positions == Start::lattice)
        return equilibrated_lattice_gas(L, maxwellian_velocities(mass, s.vbar, rng), rad, mass, s.vbar, s.equilibration, true);
    std::vector<Vec2> pos = random_positions(rad, L, L, true, true, rng);
    return equilibrated_gas(L, pos, maxwellian_velocities(mass, s.vbar, rng), rad, mass, s.vbar, s.equilibration, true);
}

// The TCED gas at t = 0: Eq. (7) with pair rule tc_both.
EdEngine tced_engine(const ClusterSpec& s, const EquilibratedGas& gas, bool tc_both) {
    EdConfig cfg = rough_disk_box(s.L(), s.r, s.mu, s.t_c);
    cfg.tc_both = tc_both;
    return EdEngine(cfg, gas.pos, gas.vel, s.radii(), s.masses());
}

// Eq. (7) per particle, from the records: was this collision within t_c of the particle's
// previous one?
void observe(LoopState& st, const CollisionRecord& c, double t_c) {
    for (const int q : {c.i, c.j}) {
        const auto k = std::size_t(q);
        const double dt = c.t - st.last_t[k];
        st.last_interval[k] = dt;
        if (dt <= t_c) {
            ++st.fast[k];
            ++st.fast_total;
        }
        st.last_t[k] = c.t;
    }
}

// Every sample: K, C/N and the TC-elastic shares (Fig. 10).
void record_sample(LoopState& st, const EdEngine& eng, double t, double t_c) {
    const std::size_t n = st.last_interval.size();
    const EdKineticEnergy k = eng.kinetic_energy();
    st.ts.push_back(t);
    st.ks.push_back(k.total());
    st.kxs.push_back(k.kx);
    st.kys.push_back(k.ky);
    st.cns.push_back(2.0 * double(eng.total_collisions()) / double(n));
    st.ecns.push_back(2.0 * double(eng.elastic_collisions()) / double(n));
    st.fast_share.push_back(eng.total_collisions() ? double(st.fast_total) / (2.0 * double(eng.total_collisions())) : 0.0);
    std::size_t hot = 0;
    for (double iv : st.last_interval)
        if (iv <= t_c) ++hot;
    st.hot.push_back(double(hot) / double(n));
}

// The samples at t = 0 and the observer's state before the first collision.
LoopState fresh_loop(const EdEngine& eng, std::size_t n, double t_c) {
    LoopState st;
    st.last_t.assign(n, -INFINITY);
    st.last_interval.assign(n, INFINITY);
    st.fast.assign(n, 0);
    record_sample(st, eng, 0.0, t_c);
    return st;
}

// At t = t_base 2^k: N_c over (t/2, t] from the counts now and at the previous instant t/2.
void record_instant(LoopState& st, const EdEngine& eng, double t) {
    std::vector<std::uint64_t> counts = eng.collision_counts();
    if (!st.prev_counts.empty()) {
        const std::size_t n = counts.size();
        InstantRecord in{t, st.cns.back(), st.ecns.back(), 0.0, std::vector<double>(n), counts, eng.positions()};
        std::size_t fast_particles = 0;
        for (std::size_t i = 0; i < n; ++i) {
            in.rate[i] = double(counts[i] - st.prev_counts[i]) / (t / 2);
            if (st.fast[i] > st.prev_fast[i]) ++fast_particles;
        }
        in.fast_fraction = double(fast_particles) / double(n);
        st.instants.push_back(std::move(in));
    }
    st.prev_counts = std::move(counts);
    st.prev_fast = st.fast;
}

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

// One TCED run from the equilibrated state: samples at t_base 2^(j/m), j from -3m, until
// C/N >= cn_end or t >= t_max at an instant, or t > t_stop; resumes from its checkpoint `name`
// if there is one.
RunOutcome run_tced(const RunContext& ctx, const ClusterSpec& s, const EquilibratedGas& gas, bool tc_both, double cn_end,
                    double t_stop, const std::string& name, Progress* progress) {
    const int m = s.samples_per_octave;
    RunCheckpoint checkpoint(ctx, name);
    SampledRun<LoopState> run(checkpoint, kRunSchema, kRunSchemaVersion);
    LoopState st;
    RunOutcome out;
    EdState saved;
    const bool resumed = run.resume(saved, st);
    EdEngine eng = resumed ? EdEngine(saved) : tced_engine(s, gas, tc_both);
    if (!resumed) st = fresh_loop(eng, s.n(), s.t_c);
    const ProgressSlot slot(progress, -1); // the engine time is shown, the instants are ticked
    if (progress) progress->tick((run.next_sample() + m - 1) / m);
    bool advancing = false; // from a sample time's trigger to its sample: a runtime_error is the engine's
    const auto trigger = [&](long i) -> std::optional<double> {
        const double t = s.t_base * std::exp2(double(i - 3 * m) / m);
        if (t > t_stop * (1 + 1e-12)) return std::nullopt;
        advancing = true;
        return t;
    };
    const auto sample = [&](long i, double t) {
        advancing = false;
        record_sample(st, eng, t, s.t_c);
        if ((i - 3 * m) % m != 0) return false;
        if (progress) progress->tick();
        record_instant(st, eng, t);
        return st.cns.back() >= cn_end || t >= s.t_max;
    };
    try {
        run.run(eng, st, trigger, [&](const CollisionRecord& c) { observe(st, c, s.t_c); }, sample, t_stop);
    } catch (const std::runtime_error& e) {
        if (!advancing) throw; // a checkpoint that failed or an interrupt, not the engine
        out.error = e.what();  // the collapse guard; keep what was measured
        warn("cluster-growth: " + out.error);
    }
    out.st = std::move(st); // the samples; the bookkeeping stays in the checkpoint
    out.omega_eq = gas.collision_rate;
    out.wall = run.wall_seconds();
    out.events = double(eng.events_processed());
    out.collisions = double(eng.total_collisions());
    return out;
}

// Mean of the Fig. 11 colour (N_c) over particles ranked by the local area fraction around them
// (disks per cell of cluster_cell diameters, smoothed over the 3 x 3 block): the mean N_c in each
// of `groups` equal-size groups from the most dilute to the densest.
std::vector<double> rate_by_density(const Instant& in, double L, double cell, int groups) {
    const auto nc = std::max<std::size_t>(3, std::size_t(L / cell));
    std::vector<double> occ(nc * nc, 0.0);
    auto index = [&](const Vec2& q) {
        const auto ix = std::min(nc - 1, std::size_t(q.x / L * double(nc)));
        const auto iy = std::min(nc - 1, std::size_t(q.y / L * double(nc)));
        return std::array<std::size_t, 2>{ix, iy};
    };
    for (const Vec2& q : in.pos) {
        const auto c = index(q);
        occ[c[1] * nc + c[0]] += 1;
    }
    std::vector<std::pair<double, double>> dens_rate;
    for (std::size_t i = 0; i < in.pos.size(); ++i) {
        const auto c = index(in.pos[i]);
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

// The homogeneous gas at t = 0: Enskog's collision rate and t0 of Eq. (18) (sqrt(2 pi) in
// Eq. 19; see theory/kinetic_theory.hpp).
struct KineticTheory {
    double rho = 0, omega_enskog = 0, t0 = 0; // omega [1/s], t0 [s]
};

KineticTheory kinetic_theory(const ClusterSpec& s) {
    const double rho = M_PI / 4 * double(s.n()) / (s.box_over_d * s.box_over_d);
    const double s_star = (1 - rho) * (1 - rho) / (1 - 7 * rho / 16);
    const double omega = 8 * rho * s.vbar / (s_star * s.d * std::sqrt(2 * M_PI));
    return {rho, omega, theory::haff_t0(s.r, omega)};
}

void report_run(Result& res, const ClusterSpec& s, const KineticTheory& kin, const RunOutcome& main_run,
                const RunOutcome* other_run) {
    res.scalar("N", double(s.n()), "1", "number of disks");
    res.scalar("rho", kin.rho, "1", "area fraction (pi/4) N / L^2");
    res.scalar("t0_kinetic", kin.t0, "s", "t0 of Eq. (18) from kinetic theory (sqrt(2 pi) in Eq. 19; see cooling.cpp)");
    res.scalar("omega_equilibration_over_enskog", main_run.omega_eq / kin.omega_enskog, "1", "elastic collision rate per particle during equilibration over Enskog's");
    res.scalar("wall_seconds_run", main_run.wall, "s", "wall time of the cooling run (after equilibration)");
    res.scalar("events_per_second", main_run.events / main_run.wall, "1/s", "ED events (collisions, cell crossings, stale) per second");
    res.scalar("collisions_per_second", main_run.collisions / main_run.wall, "1/s", "pair collisions per second");
    res.scalar("events", main_run.events, "1", "ED events of the cooling run");
    res.scalar("tc_both", s.tc_both ? 1.0 : 0.0, "1", "pair rule of the main run: 1 = both partners within t_c, 0 = either");
    if (other_run) res.scalar("wall_seconds_other_rule", other_run->wall, "s", "wall time of the run with the other pair rule");
    res.scalar("t_end", main_run.st.ts.back(), "s", "end of the run");
    res.scalar("C_over_N_end", main_run.st.cns.back(), "1", "collisions per particle at the end");
    res.scalar("stopped_by_engine", main_run.error.empty() ? 0.0 : 1.0, "1", "1 if the collapse guard stopped the run");
}

// Fig. 10: K/K0, C/N and the TC-elastic collisions per particle against t; returns K/K0.
std::vector<double> fig10_table(Result& res, const Samples& st, double t0, double late_from) {
    const auto& ts = st.ts;
    Table& t = res.table("energy", "K/K0, C/N and TC-elastic collisions per particle against t");
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

// How K(t) departs from homogeneous cooling: Eq. (18) early, the slopes later.
void fig10_slopes(Result& res, const std::vector<double>& ts, const std::vector<double>& kk, double t0, int m, double late_from) {
    // Early cooling: Eq. (18) fitted over t <= t0.
    res.scalar("t0_fit_over_kinetic", fit_haff_inv_t0(ts, kk, t0) * t0, "1", "1/t0 fitted to K(t) over t <= t0 (Eq. 18) over the kinetic-theory value");
    // Steepest local slope d ln K / d ln t (over one octave) before late_slope_from: Eq. (18)
    // tends to -2 only for t >> t0, while clustering sets in at a few t0.
    double steepest = 0;
    for (std::size_t i = std::size_t(m) + 1; i < ts.size() && ts[i] <= late_from; ++i)
        steepest = std::min(steepest, std::log(kk[i] / kk[i - std::size_t(m)]) / std::log(2.0));
    res.scalar("K_slope_steepest_early", steepest, "1", "steepest slope of log K against log t over one octave, t <= late_slope_from");
    const PowerLawFit late = fit_power_law(ts, kk, late_from, ts.back());
    res.scalar("K_slope_late", late.exponent, "1", "average slope of log K against log t from late_slope_from to the end (GSL fit)");
    res.scalar("K_slope_late_err", late.exponent_err, "1", "its standard error (residual scatter of the 13-per-decade samples)");
    res.scalar("K_over_eq18_end", kk.back() / theory::haff_energy_ratio(ts.back(), t0), "1", "K over Eq. (18) at the end: how much slower than homogeneous cooling");
}

// The TC-elastic share three ways (see the top of this file), for t <= elastic_until and over
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
    res.scalar("elastic_fraction_early_max" + tag, coll, "1", "largest TC-elastic share of all pair collisions, cumulative, for t <= elastic_until" + r);
    res.scalar("elastic_fraction_max" + tag, coll_all, "1", "largest TC-elastic share of all pair collisions over the run" + r);
    res.scalar("own_interval_share_early_max" + tag, own, "1",
               "largest cumulative share of particle-collisions within t_c of that particle's previous one, t <= elastic_until" + r);
    res.scalar("hot_particles_early_max" + tag, hot_max, "1",
               "largest fraction of particles whose latest collision came within t_c of the previous one, samples t <= elastic_until" + r);
    res.scalar("hot_particles_early_mean" + tag, hot_n ? hot_sum / hot_n : NAN, "1", "its mean over those (log-spaced) samples" + r);
    auto at = [&](double tq, const std::vector<double>& v) -> double {
        for (std::size_t i = 0; i < ls.ts.size(); ++i)
            if (std::abs(ls.ts[i] / tq - 1) < 1e-9) return v[i];
        return NAN;
    };
    for (const char* when : {"0.04", "0.64", "10.24"}) {
        const double tq = std::stod(when);
        res.scalar(std::string("C_over_N_at_") + when + "s" + tag, at(tq, ls.cns), "1",
                   std::string("C/N = (sum of per-particle counts)/N = 2 pair collisions/N at t = ") + when + " s" + r);
        res.scalar(std::string("pairs_over_N_at_") + when + "s" + tag, 0.5 * at(tq, ls.cns), "1",
                   std::string("pair collisions/N (each collision counted once) at t = ") + when + " s" + r);
    }
}

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
    res.scalar("elastic_share_before_until", early, "1", "TC-elastic share of the pair collisions up to the last sample t <= elastic_until");
    res.scalar("elastic_share_after_until", late, "1", "TC-elastic share of the pair collisions from that sample to the end");
    res.scalar("elastic_share_late_over_early", early > 0 ? late / early : NAN, "1",
               "elastic_share_after_until / elastic_share_before_until: above 1 when elastic collisions increase for t > elastic_until");
    res.scalar("elastic_share_after_until_collisions", e > u ? 0.5 * (st.cns[e] - st.cns[u]) * n : NAN, "1",
               "pair collisions after elastic_until (sets the counting error of elastic_share_after_until)");
}

void fig10(Result& res, const ClusterSpec& s, double t0, const Samples& st, const Samples* other) {
    const std::vector<double> kk = fig10_table(res, st, t0, s.late_slope_from);
    fig10_slopes(res, st.ts, kk, t0, s.samples_per_octave, s.late_slope_from);
    // The main pair rule and, with tc_compare_until, the other one.
    report_elastic_shares(res, st, "", s.tc_both ? "both" : "either", s.elastic_until);
    if (other) report_elastic_shares(res, *other, s.tc_both ? "_either" : "_both", s.tc_both ? "either" : "both", s.elastic_until);
    res.scalar("elastic_per_particle_end", st.ecns.back(), "1", "TC-elastic collisions per particle at the end");
    report_elastic_increase(res, st, s.elastic_until, double(s.n()));
    res.scalar("C_over_N_eq18_at_0.64s", 4 / (1 - s.r * s.r) * std::log(1 + 0.64 / t0), "1",
               "C/N at 0.64 s if the gas stayed homogeneous: 4/(1-r^2) ln(1 + t/t0)");
}

// Fig. 12, every instant: C/N, N_c statistics and the fits of Eqs. (20)-(22).
void fig12_instants_table(Result& res, const std::vector<Instant>& instants) {
    Table& t = res.table("instants", "per instant t = t_base 2^k: C/N, N_c statistics and the fits of Eqs. (20)-(22)");
    using I = Instant;
    auto col = [&](const char* name, const char* unit, auto get) {
        auto& c = t.add(name, unit);
        for (const auto& in : instants) c.values.push_back(std::invoke(get, in));
    };
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
    res.scalar("poisson_mean_width_falling_share", pairs ? double(falling) / pairs : NAN, "1",
               "share of consecutive instants with C/N <= poisson_until_cn where mean and standard deviation of N_c both fall");
    res.scalar("poisson_mean_width_pairs", double(pairs), "1", "number of such pairs of instants");
}

// P(N_c) at one instant with the fitted Eqs. (20)-(22), as Fig. 12 shows it.
void fig12_histogram_table(Result& res, const Instant& in, std::size_t panel) {
    Table& h = res.table("pnc_" + std::to_string(panel), "P(N_c) and the fitted Eqs. (20)-(22) at t = " + number_text(in.t) + " s");
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

void fig12_panel_scalars(Result& res, const Instant& in, const std::string& tag) {
    res.scalar("cn_nearest" + tag, in.cn, "1", "our C/N at the instant nearest to the paper's");
    res.scalar("t_nearest" + tag, in.t, "s", "its time");
    res.scalar("chi" + tag, in.poisson.value, "1", "Poisson Eq. (20) chi (mean count in Δt = t/2)");
    res.scalar("chi_err" + tag, in.poisson.error, "1", "its standard error (Cramer-Rao)");
    res.scalar("chi_since_start" + tag, in.poisson_full.value, "1", "Eq. (20) chi for the counts over (0, t] (window t, not t/2)");
    res.scalar("chi_since_start_err" + tag, in.poisson_full.error, "1", "its standard error");
    res.scalar("chi_rate" + tag, in.poisson.value / in.window, "1/s", "chi / Δt, the Poisson mean rate");
    res.scalar("chi2red_poisson" + tag, in.poisson.chi2_reduced, "1", "Pearson chi^2/dof of the Poisson fit");
    res.scalar("A" + tag, in.expo.value, "1/s", "exponential Eq. (21) A");
    res.scalar("A_err" + tag, in.expo.error, "1/s", "its standard error");
    res.scalar("chi2red_exponential" + tag, in.expo.chi2_reduced, "1", "Pearson chi^2/dof of the exponential fit");
    res.scalar("B" + tag, in.power.value, "1/s", "power law Eq. (22) B");
    res.scalar("B_tail" + tag, in.power_tail.value, "1/s", "Eq. (22) B fitted to the tail N_c >= tail_fit_from x mean N_c");
    res.scalar("B_tail_err" + tag, in.power_tail.error, "1/s", "its standard error");
    res.scalar("powerlaw_over_exponential_chi2_tail" + tag, in.power_tail.chi2_reduced / in.expo_tail.chi2_reduced, "1",
               "chi^2/dof of Eq. (22) over that of Eq. (21), both fitted to the tail only (< 1: power law better there)");
    res.scalar("B_err" + tag, in.power.error, "1/s", "its standard error");
    res.scalar("chi2red_powerlaw" + tag, in.power.chi2_reduced, "1", "Pearson chi^2/dof of the power-law fit");
    res.scalar("mean_Nc" + tag, in.mean_rate, "1/s", "mean N_c");
    res.scalar("tail_fraction" + tag, in.tail_fraction, "1", "fraction of particles with N_c > tail_rate");
    res.scalar("poisson_over_best_other_chi2" + tag, in.poisson.chi2_reduced / std::min(in.expo.chi2_reduced, in.power.chi2_reduced), "1",
               "chi^2/dof of Eq. (20) over the better of Eqs. (21), (22) (< 1: Poisson fits best)");
    res.scalar("powerlaw_over_exponential_chi2" + tag, in.power.chi2_reduced / in.expo.chi2_reduced, "1",
               "chi^2/dof of Eq. (22) over that of Eq. (21) (< 1: the power law fits better)");
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
        fig12_panel_scalars(res, in, s < pcn.size() ? "_cn" + number_text(paper) : std::string("_last"));
    }
    // Created last: res.table() may move the tables created before.
    Table& meta = res.table("fig12_selection", "instants shown in Fig. 12: the paper's C/N and ours");
    meta.add({{"paper_C_over_N", "1", mp}, {"C_over_N", "1", mc}, {"t", "s", mt}, {"window", "s", mw}});
}

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
    res.scalar("densest_tenth_rank_of_max_Nc", worst, "1",
               "over the clustered snapshots (C/N >= 70): the lowest density rank (1-10) of the tenth of particles with the largest mean N_c");
    res.scalar("densest_tenth_Nc_over_mean_min", min_ratio, "1", "the smallest ratio of the densest tenth's mean N_c to the overall mean there");
    for (std::size_t k = 0; k < mt.size(); ++k) {
        res.scalar("densest_tenth_Nc_over_mean_t" + number_text(mt[k]), ratio[k], "1", "mean N_c of the densest tenth over the overall mean at this snapshot");
        res.scalar("densest_tenth_rank_of_max_Nc_t" + number_text(mt[k]), top[k], "1", "density rank (1-10) of the tenth with the largest mean N_c");
    }
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

void report_at_paper_cn(Result& res, const std::vector<Instant>& instants, const std::vector<double>& paper_cn) {
    for (double c : paper_cn) {
        const std::string tag = "_at_cn" + number_text(c);
        res.scalar("chi" + tag, at_cn(instants, c, [](const Instant& in) { return in.poisson.value; }), "1", "Eq. (20) chi interpolated to the paper's C/N");
        res.scalar("A" + tag, at_cn(instants, c, [](const Instant& in) { return in.expo.value; }), "1/s", "Eq. (21) A interpolated to the paper's C/N");
        res.scalar("B" + tag, at_cn(instants, c, [](const Instant& in) { return in.power.value; }), "1/s", "Eq. (22) B interpolated to the paper's C/N");
        res.scalar("t" + tag, at_cn(instants, c, [](const Instant& in) { return in.t; }), "s", "time at which C/N reached the paper's value (interpolated)");
    }
}

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
    res.scalar("B_geomean_70_1404", cnt ? std::exp(lsum / cnt) : NAN, "1/s", "geometric mean of B over the instants with 70 <= C/N <= 1404");
    res.scalar("B_min_70_1404", cnt ? bmin : NAN, "1/s", "smallest B there");
    res.scalar("B_tail_geomean_70_1404", c ? std::exp(ls / c) : NAN, "1/s",
               "geometric mean of the tail-fitted B over the instants with 70 <= C/N <= 1404");
    res.scalar("powerlaw_better_tail_share_70_1404", c ? double(better) / c : NAN, "1",
               "share of those instants where Eq. (22) fits the tail better than Eq. (21)");
    res.scalar("B_max_70_1404", cnt ? bmax : NAN, "1/s", "largest B there");
}

// Where the power law Eq. (22) takes over from the exponential Eq. (21), and how the shape
// changes after (Section 4.3).
void report_powerlaw_onset(Result& res, const std::vector<Instant>& instants) {
    // From which C/N on the power law fits better than the exponential at every later instant.
    double from = NAN;
    for (std::size_t k = instants.size(); k-- > 0;) {
        if (!(instants[k].power.chi2_reduced < instants[k].expo.chi2_reduced)) break;
        from = instants[k].cn;
    }
    res.scalar("powerlaw_better_from_cn", from, "1", "smallest C/N from which on Eq. (22) fits better than Eq. (21) at every instant");
    const int k1 = nearest(instants, 1404.0), k2 = nearest(instants, 2567.0), k0 = nearest(instants, 183.0);
    if (k0 >= 0 && k1 >= 0 && k2 >= 0) {
        res.scalar("B_ratio_1404_over_183", instants[std::size_t(k1)].power.value / instants[std::size_t(k0)].power.value, "1",
                   "B at the instant nearest C/N = 1404 over B nearest 183 (shape change), fits over the whole P(N_c)");
        // The same with the tail estimator of powerlaw_B (N_c >= tail_fit_from x mean), so that the
        // shape claim and the B claim read Eq. (22) one way (issue 27 §4).
        res.scalar("B_tail_ratio_1404_over_183",
                   instants[std::size_t(k1)].power_tail.value / instants[std::size_t(k0)].power_tail.value, "1",
                   "tail-fitted B at the instant nearest C/N = 1404 over that nearest 183 (shape change)");
        res.scalar("tail_ratio_2567_over_1404", instants[std::size_t(k2)].tail_fraction / instants[std::size_t(k1)].tail_fraction, "1",
                   "P(N_c > tail_rate) nearest C/N = 2567 over that nearest 1404 (< 1: the tail drops again)");
        res.scalar("tail_ratio_last_over_1404", instants.back().tail_fraction / instants[std::size_t(k1)].tail_fraction, "1",
                   "P(N_c > tail_rate) at the last instant over that nearest C/N = 1404");
    }
    // Which form fits best over the instants after C/N = 70 (Section 4.3: power law).
    double n_after = 0, pow_best = 0;
    for (const auto& in : instants)
        if (in.cn > 70 && std::isfinite(in.power.chi2_reduced) && std::isfinite(in.expo.chi2_reduced)) {
            ++n_after;
            if (in.power.chi2_reduced < in.expo.chi2_reduced) ++pow_best;
        }
    res.scalar("powerlaw_better_share_after_70", n_after > 0 ? pow_best / n_after : NAN, "1",
               "share of the instants with C/N > 70 where Eq. (22) fits better than Eq. (21)");
}

// Fig. 11's "grow in size": the density correlation length at each snapshot, and the share of
// successive snapshots at which it is larger than at the one before.
void report_structure_growth(Result& res, const std::vector<double>& mt, const std::vector<double>& xi) {
    int pairs = 0, growing = 0;
    for (std::size_t k = 1; k < xi.size(); ++k) {
        if (!std::isfinite(xi[k]) || !std::isfinite(xi[k - 1])) continue;
        ++pairs;
        if (xi[k] > xi[k - 1]) ++growing;
    }
    res.scalar("density_corr_length_growing_share", pairs ? double(growing) / pairs : NAN, "1",
               "share of successive Fig. 11 snapshots whose density correlation length exceeds the previous one's");
    res.scalar("density_corr_length_pairs", double(pairs), "1", "number of such snapshot pairs");
    res.scalar("density_corr_length_last_over_first", xi.size() > 1 ? xi.back() / xi.front() : NAN, "1",
               "density correlation length at the last snapshot over that at the first");
    for (std::size_t k = 0; k < mt.size(); ++k)
        res.scalar("density_corr_length_t" + number_text(mt[k]), xi[k], "1",
                   "first zero of the density autocorrelation (cells of cluster_cell d), in d, at this snapshot");
    Table& t = res.table("structure_growth", "density correlation length at the Fig. 11 snapshots");
    t.add({{"t", "s", mt}, {"corr_length_over_d", "1", xi}});
}

// Is the instant at t the Fig. 11 snapshot time tq?
bool snapshot_at(double t, double tq) { return std::abs(t / tq - 1) < 1e-9; }

// Fig. 11, "structures build up in the system and grow in size": the density correlation length,
// the first zero of the radially averaged autocorrelation C(r) of the disk count per cell of
// cluster_cell diameters (the cells of rate_by_density), linearly interpolated between cell
// distances; in diameters. C(r) over every periodic displacement (m^4 products, 1e8 at m = 100).
double density_correlation_length(const Instant& in, double L, double cell, double d) {
    const auto m = std::max<std::size_t>(3, std::size_t(L / cell));
    std::vector<double> o(m * m, 0.0);
    for (const Vec2& q : in.pos) {
        const auto ix = std::min(m - 1, std::size_t(q.x / L * double(m)));
        const auto iy = std::min(m - 1, std::size_t(q.y / L * double(m)));
        o[iy * m + ix] += 1;
    }
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

// Fig. 11: positions coloured by N_c at the paper's times, one colour range for all panels.
// Sec. 4.2: "in the bright regions in the centers of the clusters the collision frequency is
// largest". Particles ranked by the number of disks around them (cells of cluster_cell
// diameters, 3 x 3 block); mean N_c per tenth, densest tenth last. The claim looks at which
// tenth has the largest mean N_c.
void fig11(Result& res, const std::vector<Instant>& instants, const ClusterSpec& s) {
    std::vector<const Instant*> shown;
    for (double tq : s.snapshot_times)
        for (const auto& in : instants)
            if (snapshot_at(in.t, tq)) shown.push_back(&in);
    double lo = INFINITY, hi = 0; // from the smallest positive N_c to the largest
    for (const Instant* in : shown)
        for (double v : in->rate)
            if (v > 0) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
    std::vector<double> mt, mc, top, ratio, xi;
    for (const Instant* in : shown) {
        mt.push_back(in->t);
        mc.push_back(in->cn);
        Table& sn = res.table("snapshot_" + std::to_string(mt.size() - 1),
                              "positions and N_c over the last t/2 at t = " + number_text(in->t) + " s");
        std::vector<double> x, y;
        for (const Vec2& q : in->pos) {
            x.push_back(q.x / s.d);
            y.push_back(q.y / s.d);
        }
        sn.add({{"x_over_d", "1", x}, {"y_over_d", "1", y}, {"N_c", "1/s", in->rate}});
        const auto g = rate_by_density(*in, s.L(), s.cluster_cell * s.d, 10);
        top.push_back(double(std::max_element(g.begin(), g.end()) - g.begin() + 1));
        xi.push_back(density_correlation_length(*in, s.L(), s.cluster_cell * s.d, s.d));
        ratio.push_back(g.back() / in->mean_rate);
    }
    Table& meta = res.table("fig11_selection", "instants of the snapshots, the common colour range, and N_c in the densest tenth");
    meta.add({{"t", "s", mt}, {"C_over_N", "1", mc}, {"Nc_colour_lo", "1/s", std::vector<double>(mt.size(), lo)},
              {"Nc_colour_hi", "1/s", std::vector<double>(mt.size(), hi)}, {"densest_tenth_with_max_Nc", "1", top},
              {"densest_tenth_Nc_over_mean", "1", ratio}});
    report_cluster_centres(res, mt, mc, top, ratio);
    report_structure_growth(res, mt, xi);
}

// A run's sweep point holds only what the analysis reads: of the other rule's run the samples
// (Fig. 10), of the main run's instants the positions only at the Fig. 11 snapshot times.
RunOutcome trimmed(RunOutcome r, const ClusterSpec& s, bool main_run) {
    if (!main_run) r.st.instants.clear();
    for (InstantRecord& in : r.st.instants)
        if (std::none_of(s.snapshot_times.begin(), s.snapshot_times.end(), [&](double tq) { return snapshot_at(in.t, tq); }))
            in.pos.clear();
    return r;
}

// Figs. 10-12 as a protocol (harness/protocol.hpp). The main run (pair rule tc_both) to cn_end
// and, with tc_compare_until > 0, the other pair rule beside it up to that time, both from one
// equilibrated state: the sweep's points 0 and 1, the main run first (the longer one: 1.8 against
// 0.44 CPU s at quick scale).
struct ClusterGrowth {
    static constexpr const char* name = "cluster-growth";
    using Spec = ClusterSpec;
    using Outcome = RunOutcome;
    // The state both runs start from, made once, by the first point that needs it (not at all
    // where every point is resumed or gathered), and the main run's progress line.
    struct Shared {
        struct State {
            std::once_flag made;
            EquilibratedGas gas;
            std::optional<Progress> progress;
        };
        std::unique_ptr<State> state = std::make_unique<State>();
        const EquilibratedGas& gas(const ClusterSpec& s, std::uint64_t seed) const {
            std::call_once(state->made, [&] { state->gas = initial_gas(s, seed); });
            return state->gas;
        }
    };
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Shared prepare(const Spec& s, const RunContext& ctx) {
        Shared sh;
        sh.state->progress.emplace("cluster-growth", long(std::ceil(std::log2(s.t_max / s.t_base))) + 4, ctx.quiet);
        return sh;
    }
    static std::vector<long> points(const Spec& s, const Shared&) {
        return s.tc_compare_until > 0 ? std::vector<long>{0, 1} : std::vector<long>{0};
    }
    static RunOutcome compute(const Spec& s, const Shared& sh, long k, const PointContext& ctx) {
        const EquilibratedGas& gas = sh.gas(s, ctx.seed);
        if (k == 0) return trimmed(run_tced(ctx, s, gas, s.tc_both, s.cn_end, s.t_max, "ed", &*sh.state->progress), s, true);
        return trimmed(run_tced(ctx, s, gas, !s.tc_both, INFINITY, s.tc_compare_until, "ed_other_rule", nullptr), s, false);
    }
    static Result report(const Spec& s, const Shared&, const Swept<RunOutcome>& swept, const RunContext&) {
        std::vector<RunOutcome> runs = swept.outcomes;
        const RunOutcome& main_run = runs.front();
        const RunOutcome* other_run = runs.size() > 1 ? &runs[1] : nullptr;
        std::vector<Instant> instants;
        for (InstantRecord& rec : runs.front().st.instants) instants.push_back(make_instant(std::move(rec), s));

        Result res;
        res.scalar("resumed_points", double(swept.resumed), "1", "sweep points loaded from a checkpoint");
        const KineticTheory kin = kinetic_theory(s);
        report_run(res, s, kin, main_run, other_run);
        fig10(res, s, kin.t0, main_run.st, other_run ? &other_run->st : nullptr);
        fig12_instants_table(res, instants);
        report_poisson_falling(res, instants, s.poisson_until_cn);
        fig12_panels(res, instants, s.paper_cn);
        report_at_paper_cn(res, instants, s.paper_cn);
        report_clustered_B(res, instants);
        report_powerlaw_onset(res, instants);
        fig11(res, instants, s);
        return res;
    }
};

} // namespace

Experiment cluster_growth() { return protocol_experiment<ClusterGrowth>(); }

} // namespace granrepro::experiments
