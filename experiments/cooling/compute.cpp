// cooling: one method's run (ED or DSMC) from a seed's equilibrated state through the sample
// times, with its samples and snapshots, and the seeds' initial states.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/rng_stream.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/cooling/spec.hpp"
#include "harness/sampled_run.hpp"
#include "observables/log_time_sampler.hpp"
#include "observables/pair_correlation.hpp"
#include "observables/structure_factor.hpp"
#include "observables/velocity_correlation.hpp"

namespace granrepro::experiments::cooling_detail {

// The DSMC engine's configuration from the spec, for a periodic box of side L [m].
DsmcConfig dsmc_config(const CoolingSpec& c, double L) {
    DsmcConfig cfg;
    cfg.lx = cfg.ly = L;
    cfg.r = c.r;
    cfg.t_c = c.dsmc_t_c;
    cfg.min_cell_diameters = c.dsmc_cell_diameters;
    cfg.step_factor = c.dsmc_step_factor;
    cfg.free_volume = c.dsmc_free_volume;
    cfg.free_volume_block = std::uint32_t(c.dsmc_free_volume_block);
    cfg.rcp_fraction = c.dsmc_rcp_fraction;
    cfg.displacement = c.dsmc_displacement;
    cfg.partner = c.dsmc_partner;
    cfg.no_repeat_partner = c.dsmc_no_repeat;
    cfg.mft_fraction = c.dsmc_mft_fraction;
    return cfg;
}

// a2 of the translational velocities (about their mean) and its standard error from the sample
// variance of v^4 (independent particles).
std::array<double, 2> sonine_a2(const std::vector<Vec2>& vel) {
    const double n = double(vel.size());
    Vec2 mean;
    for (const Vec2& v : vel) mean += v;
    mean = mean / n;
    double s2 = 0, s4 = 0, s8 = 0;
    for (const Vec2& v : vel) {
        const double c2 = norm2(v - mean);
        s2 += c2;
        s4 += c2 * c2;
        s8 += c2 * c2 * c2 * c2;
    }
    const double m2 = s2 / n, m4 = s4 / n, m8 = s8 / n;
    return {theory::sonine_a2_2d(m2, m4), std::sqrt(std::max(m8 - m4 * m4, 0.0) / n) / (2 * m2 * m2)};
}

// Pair velocity correlations from contact (r = d) to 3 d in bins of 0.1 d.
VelocityCorrelation velocity_correlation(double L, double d) { return VelocityCorrelation(L, L, d, 3 * d, 20); }

// The random streams of seed index k: 2k for the initial state, 2k + 1 for DSMC (k = 0 keeps the
// streams of single-seed runs).
std::uint64_t setup_stream(long k) { return std::uint64_t(2 * k); }
std::uint64_t dsmc_stream(long k) { return std::uint64_t(2 * k + 1); }

namespace {

// Sample times: log-spaced K(t) samples, a2_samples evenly spaced in the a2 window, and the
// snapshot times, merged.
std::vector<double> sample_times(const CoolingSpec& c) {
    LogTimeSampler log(c.t_end * 1e-4, c.t_end, int(c.samples_per_decade));
    std::vector<double> t = log.times();
    t.push_back(0.0);
    const double t0 = c.t0();
    const auto& w = c.a2_window;
    const long na = c.a2_samples;
    for (long i = 0; i < na; ++i) {
        const double ti = t0 * (w[0] + (w[1] - w[0]) * (na > 1 ? double(i) / double(na - 1) : 0.0));
        if (ti <= c.t_end) t.push_back(ti);
    }
    for (double s : c.snapshots()) t.push_back(s);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), t.end());
    return t;
}

// The kinetic energy split as Fig. 2 plots it; DSMC disks have no spin.
EdKineticEnergy kinetic_split(const EdEngine& e) { return e.kinetic_energy(); }
EdKineticEnergy kinetic_split(const DsmcEngine& e) {
    EdKineticEnergy k;
    for (std::size_t i = 0; i < e.size(); ++i) {
        k.kx += 0.5 * e.masses()[i] * e.velocities()[i].x * e.velocities()[i].x;
        k.ky += 0.5 * e.masses()[i] * e.velocities()[i].y * e.velocities()[i].y;
    }
    return k;
}

// One sample at time t: the kinetic energy, collisions per particle and a2.
template <class Engine>
void record_sample(Trace& tr, const Engine& eng, double t) {
    const double n = double(eng.size());
    const EdKineticEnergy k = kinetic_split(eng);
    const auto a2 = sonine_a2(eng.velocities());
    tr.t.push_back(t);
    tr.kx.push_back(k.kx);
    tr.ky.push_back(k.ky);
    tr.krot.push_back(k.krot);
    tr.cn.push_back(2.0 * double(eng.total_collisions()) / n);
    tr.elastic_cn.push_back(2.0 * double(eng.elastic_collisions()) / n);
    tr.a2.push_back(a2[0]);
    tr.a2_err.push_back(a2[1]);
}

// g(r/d) out to 5 d and S(k) of the positions at a snapshot time, and the velocity correlations
// if the spec asks for them.
void record_snapshot(Trace& tr, const CoolingSpec& c, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double L) {
    const double d = c.d;
    PairCorrelation gr(L, L, 5 * d, 250);
    gr.accumulate(pos);
    StructureFactor sk(L, d);
    sk.accumulate(pos);
    const auto shell = sk.radial_average();
    Snapshot& sn = tr.snaps.emplace_back();
    sn.g = gr.g(), sn.g_err = gr.g_error(), sn.S = shell.S;
    if (c.velocity_correlation) {
        VelocityCorrelation vc = velocity_correlation(L, d);
        vc.accumulate(pos, vel);
        sn.vc_n = vc.normal(), sn.vc_n_err = vc.normal_error(), sn.vc_t = vc.tangential(), sn.vc_t_err = vc.tangential_error();
        sn.vc_a = vc.approach(), sn.vc_a_err = vc.approach_error();
    }
    if (tr.g_r.empty()) {
        for (double c : gr.centres()) tr.g_r.push_back(c / d);
        tr.S_k = shell.k;
    }
}

// Mid-run checkpoints of one method hold the engine state and the trace up to a sample time (with
// the P(b/d) counts). prepare() is deterministic, so a resumed run redoes the equilibration
// instead of storing the t = 0 state. Version 4: the trace carries its wall time; 5: its snapshots
// the velocity correlations; 6: the DSMC cells per side.
constexpr const char* kCoolingRunSchema = "granrepro-cooling-run";
constexpr long kCoolingRunSchemaVersion = 6;

// The P(b/d) histogram holding the trace's counts (none yet: empty).
ImpactParameterHistogram pbd_histogram(const CoolingSpec& c, const Trace& tr) {
    ImpactParameterHistogram hist(20, c.bd_windows);
    if (tr.pbd_counts.empty()) return hist;
    std::vector<std::vector<std::uint64_t>> counts;
    for (const WindowCounts& w : tr.pbd_counts) counts.push_back(w.bins);
    hist.set_counts(std::move(counts));
    return hist;
}

// Runs eng (started at t = 0) through the sample times, continuing from run's checkpoint if
// there is one; the one loop of ED and DSMC.
template <class Engine>
Trace observe(const CoolingSpec& c, const Setup& s, Engine& eng, SampledRun<Trace>& run) {
    Trace tr;
    decltype(eng.save_state()) saved;
    if (run.resume(saved, tr)) eng.restore_state(saved);
    ImpactParameterHistogram hist = pbd_histogram(c, tr);
    const std::vector<double> times = sample_times(c);
    const auto trigger = [&](long i) {
        return std::size_t(i) < times.size() ? std::optional<double>(times[std::size_t(i)]) : std::nullopt;
    };
    run.run(eng, tr, trigger, [&hist](const CollisionRecord& col) { hist.add(col); },
            [&](long, double t) {
                record_sample(tr, eng, t);
                const auto now = [t](double snap) { return std::abs(snap - t) < 1e-12; };
                if (std::any_of(c.snapshot_times.begin(), c.snapshot_times.end(), now))
                    record_snapshot(tr, c, eng.positions(), eng.velocities(), s.L);
                tr.pbd_counts.clear();
                for (const auto& w : hist.counts()) tr.pbd_counts.push_back({w});
                return false;
            },
            times.back());
    tr.wall_seconds = run.wall_seconds();
    return tr;
}

} // namespace

// The velocities drawn before the equilibration.
std::vector<Vec2> initial_velocities(const CoolingSpec& c, const std::vector<double>& mass, RngStream& rng) {
    return c.initial_velocities == InitialVelocities::maxwellian ? maxwellian_velocities(mass, c.vbar, rng)
                                                                 : uniform_velocities(mass.size(), c.vbar, rng);
}

Setup prepare(const CoolingSpec& c, std::uint64_t seed, long seed_index) {
    Setup s;
    const std::size_t n = std::size_t(c.n_side * c.n_side);
    s.L = c.box();
    s.rad.assign(n, 0.5 * c.d);
    s.mass.assign(n, c.mass);
    RngStream rng(seed, setup_stream(seed_index));
    // The first collisions after a lattice start are rarer than in equilibrium, so the
    // equilibrium collision rate is measured over the second half of the equilibration only.
    static_cast<EquilibratedGas&>(s) =
        equilibrated_lattice_gas(s.L, initial_velocities(c, s.mass, rng), s.rad, s.mass, c.vbar, c.equilibration, true);
    return s;
}

// One method's run from seed index k's initial state. Checkpoint names: "ed" and "dsmc" for the
// first seed (as single-seed runs), "ed_<k>" after.
Trace run_method(const RunContext& ctx, const CoolingSpec& c, const Setup& s, long k, bool is_ed) {
    const std::string method = is_ed ? "ed" : "dsmc";
    RunCheckpoint checkpoint(ctx, k == 0 ? method : method + "_" + std::to_string(k));
    SampledRun<Trace> run(checkpoint, kCoolingRunSchema, kCoolingRunSchemaVersion);
    if (is_ed) {
        EdEngine eng(rough_disk_box(s.L, c.r, c.mu, c.t_c), s.pos, s.vel, s.rad, s.mass);
        return observe(c, s, eng, run);
    }
    DsmcConfig cfg = dsmc_config(c, s.L);
    cfg.seed = ctx.seed;
    cfg.stream = dsmc_stream(k);
    DsmcEngine eng(cfg, s.pos, s.vel, s.rad, s.mass);
    Trace tr = observe(c, s, eng, run);
    tr.dsmc_cells_per_side = long(eng.cells_x());
    return tr;
}

// A sweep point's trace as read back, with P(b/d) made from its counts.
Trace with_pbd(Trace tr, const CoolingSpec& c) {
    const ImpactParameterHistogram hist = pbd_histogram(c, tr);
    tr.pbd_centres = hist.centres();
    for (std::size_t w = 0; w < hist.windows(); ++w) tr.pbd.push_back(hist.window(w));
    return tr;
}
} // namespace granrepro::experiments::cooling_detail
