// cluster-growth (Figs. 10-12): the equilibrated gas and the TCED runs (the sweep's points), with
// their samples, instants and mid-run checkpoints.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "data/fields.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/cluster_growth/spec.hpp"
#include "harness/run_checkpoint.hpp"
#include "harness/run_log.hpp"
#include "harness/sampled_run.hpp"

namespace granrepro::experiments::cluster_growth_detail {

namespace {

// Everything the sampling loop carries from one sample to the next, besides the engine: the
// samples and the observer's bookkeeping (same fields, same order as schema version 3).
struct LoopState : Samples {
    std::vector<std::uint64_t> prev_counts; // at the previous instant t/2
    // Per-particle Eq. (7) bookkeeping from the collision records (observer state).
    std::vector<double> last_t, last_interval;  // [s]; -inf / +inf before the first
    std::vector<std::uint32_t> fast, prev_fast; // collisions within t_c of the previous one, and at t/2
    std::uint64_t fast_total = 0;               // their sum over particles
    GRANREPRO_FIELDS_BASE(Samples, prev_counts, last_t, last_interval, fast, prev_fast, fast_total)
};

constexpr const char* kRunSchema = "granrepro-cluster-growth-run";
constexpr long kRunSchemaVersion = 3; // 3: the carry written field by field (harness/sampled_run.hpp)

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

} // namespace

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

// A run's sweep point holds only what the analysis reads: of the other rule's run the samples
// (Fig. 10), of the main run's instants the positions only at the Fig. 11 snapshot times.
RunOutcome trimmed(RunOutcome r, const ClusterSpec& s, bool main_run) {
    if (!main_run) r.st.instants.clear();
    for (InstantRecord& in : r.st.instants)
        if (std::none_of(s.snapshot_times.begin(), s.snapshot_times.end(), [&](double tq) { return same_time(in.t, tq); }))
            in.pos.clear();
    return r;
}

} // namespace granrepro::experiments::cluster_growth_detail
