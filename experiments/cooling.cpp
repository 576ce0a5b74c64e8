// cooling: Luding (1998) Section 3. N disks at rho = 0.25 are equilibrated elastically by ED
// (Sec. 3: about 10 collisions per particle); at t = 0 dissipation r = 0.8 is switched on and the
// same state is evolved by ED and by DSMC. Measured: K(t) against Eq. (18) (Fig. 2), the Sonine
// coefficient a2 of the velocity distribution, P(b/d) in time windows (Fig. 3), g(r/d) (Fig. 6)
// and S(k) (Fig. 7) at snapshot times. With seeds > 1 the whole comparison (equilibration, ED,
// DSMC) is repeated from independent initial states; the figures show the first seed, the S(k)
// claims use all of them (mean and seed scatter).
//
// t0 of Eq. (18): Eq. (19) as printed has sqrt(pi); the Enskog collision rate of hard disks,
// omega_0 = 2 n d g(d) sqrt(pi T/m) with T = m v̄^2/2 and Henderson's g(d) = 1/s_*(rho), and the
// 2D cooling law dT/dt = -(1 - r^2) omega T / 2 give t0 = 4 / ((1 - r^2) omega_0)
// = sqrt(2 pi) d s_* / (2 (1 - r^2) rho v̄), i.e. sqrt(2 pi). The paper's number 23.24 1/s is
// the sqrt(2 pi) value; Fig. 2 is normalised by it (src/theory/kinetic_theory.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "analysis/curve_analysis.hpp"
#include "analysis/seed_stats.hpp"
#include "core/rng_stream.hpp"
#include "data/spec.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include "engines/dsmc/dsmc_rules.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "harness/sampled_run.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "observables/log_time_sampler.hpp"
#include "observables/pair_correlation.hpp"
#include "observables/structure_factor.hpp"
#include "observables/velocity_correlation.hpp"
#include "scenarios/ed_gas.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro { // text choices of cooling.toml (read_spec finds them by argument-dependent lookup)
static void parse_choice(const std::string& s, DsmcFreeVolume& v) {
    v = s == "cell" ? DsmcFreeVolume::cell : s == "mean" ? DsmcFreeVolume::mean : DsmcFreeVolume::off;
}
static void parse_choice(const std::string& s, DsmcPartner& v) { v = s == "nearest" ? DsmcPartner::nearest : DsmcPartner::uniform; }
} // namespace granrepro

namespace granrepro::experiments {

namespace {

enum class InitialVelocities { uniform, maxwellian };
void parse_choice(const std::string& s, InitialVelocities& v) {
    v = s == "maxwellian" ? InitialVelocities::maxwellian : InitialVelocities::uniform;
}

struct CoolingSpec {
    long n_side = 0; // N = n_side^2
    double rho = 0, r = 0, d = 0, mass = 0, vbar = 0; // area fraction, restitution, [m], [kg], [m/s]
    InitialVelocities initial_velocities = InitialVelocities::uniform;
    long seeds = 0;
    double mu = 0, t_c = 0, dsmc_t_c = 0; // ED friction; TC thresholds [s]
    double equilibration = 0;             // collisions per particle at r = 1 before t = 0
    double t_end = 0;                     // [s]
    std::vector<double> snapshot_times, bd_windows; // [s]
    double sk_k_max = 0;
    std::vector<double> a2_window; // [t0]
    long a2_samples = 0, samples_per_decade = 0;
    double departure_level = 0;
    bool run_ed = true, run_dsmc = true;
    double dsmc_cell_diameters = 0, dsmc_mft_fraction = 0, dsmc_step_factor = 0;
    DsmcFreeVolume dsmc_free_volume = DsmcFreeVolume::off; DsmcPartner dsmc_partner = DsmcPartner::uniform;
    long dsmc_free_volume_block = 0;
    bool dsmc_no_repeat = false, dsmc_displacement = false;
    bool velocity_correlation = false; // pair velocity correlations at the snapshots (a study's observable)
    template <class V>
    void fields(V&& v) {
        v("n_side", n_side), v("rho", rho), v("r", r), v("d", d), v("mass", mass), v("vbar", vbar);
        v("initial_velocities", initial_velocities), v("seeds", seeds), v("mu", mu), v("t_c", t_c);
        v("dsmc_t_c", dsmc_t_c), v("equilibration", equilibration), v("t_end", t_end);
        v("snapshot_times", snapshot_times), v("bd_windows", bd_windows), v("sk_k_max", sk_k_max);
        v("a2_window", a2_window), v("a2_samples", a2_samples), v("samples_per_decade", samples_per_decade);
        v("departure_level", departure_level), v("run_ed", run_ed), v("run_dsmc", run_dsmc);
        v("dsmc_cell_diameters", dsmc_cell_diameters), v("dsmc_mft_fraction", dsmc_mft_fraction);
        v("dsmc_step_factor", dsmc_step_factor), v("dsmc_free_volume", dsmc_free_volume);
        v("dsmc_partner", dsmc_partner), v("dsmc_free_volume_block", dsmc_free_volume_block);
        v("dsmc_no_repeat", dsmc_no_repeat), v("dsmc_displacement", dsmc_displacement);
        v("velocity_correlation", velocity_correlation);
    }

    // Enskog collision rate per particle at t = 0 with Henderson's g(d) [1/s], and Haff's t0 [s].
    double omega_enskog() const { return theory::enskog_collision_rate_vbar(rho, d, vbar, theory::henderson_contact_value(rho)); }
    double t0() const { return theory::haff_t0(r, omega_enskog()); }
    double box() const { return d * std::sqrt(double(n_side * n_side) * M_PI / 4 / rho); } // [m]
    // The snapshot times the run reaches [s].
    std::vector<double> snapshots() const {
        std::vector<double> s;
        for (double t : snapshot_times)
            if (t <= t_end) s.push_back(t);
        return s;
    }
};

DsmcConfig dsmc_config(const CoolingSpec& c, double L) {
    DsmcConfig cfg;
    cfg.lx = cfg.ly = L;
    cfg.r = c.r;
    cfg.t_c = c.dsmc_t_c;
    cfg.min_cell_diameters = c.dsmc_cell_diameters;
    cfg.step_factor = c.dsmc_step_factor;
    cfg.free_volume = c.dsmc_free_volume;
    cfg.free_volume_block = std::uint32_t(c.dsmc_free_volume_block);
    cfg.displacement = c.dsmc_displacement;
    cfg.partner = c.dsmc_partner;
    cfg.no_repeat_partner = c.dsmc_no_repeat;
    cfg.mft_fraction = c.dsmc_mft_fraction;
    return cfg;
}

void validate(const ParameterSet& p) {
    const auto c = read_spec<CoolingSpec>(p);
    // Collisions of the ED and DSMC runs, bounded above at the initial Enskog rate (cooling only
    // slows it); vbar = 1e308 got as far as "all velocities are equal".
    const double n = double(c.n_side) * double(c.n_side);
    if (!c.run_ed && !c.run_dsmc) p.reject(std::vector<std::string>{"run_ed", "run_dsmc"}, "at least one must be true");
    const double runs = double(c.seeds) * (double(c.run_ed) + double(c.run_dsmc));
    p.limit_work({"t_end", "n_side", "seeds", "vbar", "rho", "d", "equilibration"},
                 runs * n / 2 * (c.omega_enskog() * c.t_end + c.equilibration), kMaxCollisions, "collisions");
    const auto& w = c.bd_windows;
    for (std::size_t i = 1; i < w.size(); ++i)
        if (!(w[i] > w[i - 1])) p.reject("bd_windows", "edges must increase");
    if (w.size() < 2) p.reject("bd_windows", "needs at least two edges");
    if (c.box() / double(c.n_side) < c.d * 1.0000001)
        p.reject("rho", "too dense for a square-lattice start (lattice spacing below d)");
    // g(r) is measured up to 5 d, at most half the box (rho = 0.7 at n_side = 8 failed inside the run).
    if (c.box() < 10 * c.d) p.reject(std::vector<std::string>{"n_side", "rho"}, "the box must be at least 10 d wide for g(r) up to r = 5 d");
    // A step far below the mean free time multiplies the DSMC steps (1e-300 never ended).
    if (c.dsmc_mft_fraction > 0 && c.dsmc_mft_fraction < 1e-3)
        p.reject("dsmc_mft_fraction", "must be 0 (off) or at least 1e-3 of the mean free time");
    // The DSMC cell count as the engine's constructor computes it (same sums, same order): a
    // free-volume block wider than the cells per side was refused seconds into the run, naming
    // no parameter (dsmc_free_volume_block = 99).
    if (c.run_dsmc) {
        if (c.dsmc_free_volume_block % 2 == 0) p.reject("dsmc_free_volume_block", "must be odd (a block centred on its cell)");
        const DsmcConfig cfg = dsmc_config(c, c.box());
        const double r = 0.5 * c.d, box = cfg.lx * cfg.ly;
        double asum = 0, area = 0;
        for (double i = 0; i < n; ++i) { asum += r; area += std::numbers::pi * r * r; }
        const double chi = cfg.free_volume == DsmcFreeVolume::off
                               ? 1.0
                               : 1.0 / std::max(1.0 - area / box / cfg.rcp_fraction, cfg.free_volume_floor);
        const double lambda = dsmc_mean_free_path(n / box, 2.0 * asum / n, chi);
        const std::size_t cells = dsmc_cells_per_side(cfg.lx, lambda, cfg.min_cell_diameters * 2.0 * r);
        if (std::size_t(c.dsmc_free_volume_block) > cells)
            p.reject(std::vector<std::string>{"dsmc_free_volume_block", "n_side", "rho", "dsmc_cell_diameters"},
                     "the block is wider than the " + std::to_string(cells) + " DSMC cells per side");
    }
    const auto& a2w = c.a2_window;
    if (a2w.size() != 2 || !(a2w[1] > a2w[0]) || !(a2w[0] > 0)) p.reject("a2_window", "two increasing positive times in units of t0");
    const auto& snaps = c.snapshot_times;
    if (snaps.empty() || snaps.front() != 0.0) p.reject("snapshot_times", "must start with 0 (the equilibrated state)");
    for (std::size_t i = 1; i < snaps.size(); ++i)
        if (!(snaps[i] > snaps[i - 1])) p.reject("snapshot_times", "must increase");
}

// g(r/d) with its counting error, and S(k), at one snapshot time; with velocity_correlation the
// pair velocity correlations C_n, C_t (observables/velocity_correlation.hpp) and their errors.
struct Snapshot {
    std::vector<double> g, g_err, S;
    std::vector<double> vc_n, vc_n_err, vc_t, vc_t_err, vc_a, vc_a_err;
    template <class V> void fields(V&& v) {
        v("g", g), v("g_err", g_err), v("S", S);
        v("vc_n", vc_n), v("vc_n_err", vc_n_err), v("vc_t", vc_t), v("vc_t_err", vc_t_err);
        v("vc_a", vc_a), v("vc_a_err", vc_a_err);
    }
};

// The counts per b/d bin of one P(b/d) time window.
struct WindowCounts {
    std::vector<std::uint64_t> bins;
    template <class V> void fields(V&& v) { v("bins", bins); }
};

// What one method (ED or DSMC) produced from one initial state. fields() lists what a run carries
// between samples (and its checkpoints hold) and what its sweep point returns: the wall time is
// set at the end (a mid-run checkpoint keeps its own clock), P(b/d) is made from the counts when
// the point is read back.
struct Trace {
    std::vector<double> t, kx, ky, krot, cn, elastic_cn, a2, a2_err;
    std::vector<Snapshot> snaps;
    std::vector<double> g_r, S_k;
    std::vector<WindowCounts> pbd_counts; // the impact-parameter histogram's state
    std::vector<ImpactParameterHistogram::Window> pbd;
    std::vector<double> pbd_centres;
    double wall_seconds = 0; // this run's, resumed parts included
    template <class V>
    void fields(V&& v) {
        v("t", t), v("kx", kx), v("ky", ky), v("krot", krot), v("cn", cn), v("elastic_cn", elastic_cn);
        v("a2", a2), v("a2_err", a2_err), v("snapshots", snaps), v("g_r", g_r), v("S_k", S_k);
        v("impact_parameter", pbd_counts), v("wall_seconds", wall_seconds);
    }
};

// A seed's state at t = 0; its collision_rate is that of the second half of the equilibration.
struct Setup : EquilibratedGas {
    std::vector<double> rad, mass;
    double L = 0; // box side [m]
};

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

// Pair velocity correlations from contact (r = d) to 3 d in bins of 0.1 d.
VelocityCorrelation velocity_correlation(double L, double d) { return VelocityCorrelation(L, L, d, 3 * d, 20); }

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
// the velocity correlations.
constexpr const char* kCoolingRunSchema = "granrepro-cooling-run";
constexpr long kCoolingRunSchemaVersion = 5;

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

// The random streams of seed index k: 2k for the initial state, 2k + 1 for DSMC (k = 0 keeps the
// streams of single-seed runs).
std::uint64_t setup_stream(long k) { return std::uint64_t(2 * k); }
std::uint64_t dsmc_stream(long k) { return std::uint64_t(2 * k + 1); }

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

// The seeds' initial states, each equilibrated when first needed (by a sweep point or by the
// report) and then kept: a process equilibrates only the seeds it uses, so an MPI rank serving
// points does not redo every seed's equilibration (issue 28). prepare() is deterministic.
class Setups {
public:
    Setups(const CoolingSpec& c, std::uint64_t seed) : c_(&c), seed_(seed), n_(c.seeds), slots_(new Slot[std::size_t(c.seeds)]) {}
    long size() const { return n_; }
    const Setup& operator[](long k) const {
        Slot& slot = slots_[std::size_t(k)];
        std::call_once(slot.once, [&] { slot.value = prepare(*c_, seed_, k); });
        return slot.value;
    }

private:
    struct Slot {
        std::once_flag once;
        Setup value;
    };
    const CoolingSpec* c_;
    std::uint64_t seed_;
    long n_;
    std::unique_ptr<Slot[]> slots_;
};

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
    return observe(c, s, eng, run);
}

// A sweep point's trace as read back, with P(b/d) made from its counts.
Trace with_pbd(Trace tr, const CoolingSpec& c) {
    const ImpactParameterHistogram hist = pbd_histogram(c, tr);
    tr.pbd_centres = hist.centres();
    for (std::size_t w = 0; w < hist.windows(); ++w) tr.pbd.push_back(hist.window(w));
    return tr;
}

// K/K0 of a trace and Eq. (18) at its times.
std::vector<double> k_ratio(const Trace& tr) {
    const double k0 = tr.kx.front() + tr.ky.front() + tr.krot.front();
    std::vector<double> out;
    for (std::size_t i = 0; i < tr.t.size(); ++i) out.push_back((tr.kx[i] + tr.ky[i] + tr.krot[i]) / k0);
    return out;
}

double eq18(double t, double t0) { return theory::haff_energy_ratio(t, t0); }

// Largest |K/K_18 - 1| over t <= t_max, and K/K_18 interpolated (log-log) at t.
double max_dev(const Trace& tr, double t0, double t_max) {
    const auto k = k_ratio(tr);
    double worst = 0;
    for (std::size_t i = 0; i < tr.t.size(); ++i)
        if (tr.t[i] <= t_max) worst = std::max(worst, std::abs(k[i] / eq18(tr.t[i], t0) - 1));
    return worst;
}
double ratio_at(const Trace& tr, double t0, double t) {
    const auto k = k_ratio(tr);
    for (std::size_t i = 1; i < tr.t.size(); ++i)
        if (tr.t[i] >= t && tr.t[i - 1] > 0) {
            const double f = std::log(t / tr.t[i - 1]) / std::log(tr.t[i] / tr.t[i - 1]);
            const double a = std::log(k[i - 1] / eq18(tr.t[i - 1], t0)), b = std::log(k[i] / eq18(tr.t[i], t0));
            return std::exp(a + f * (b - a));
        }
    return NAN;
}

// Eq. (18) at the sample times of a trace.
std::vector<double> eq18_curve(const Trace& tr, double t0) {
    std::vector<double> out;
    for (double t : tr.t) out.push_back(eq18(t, t0));
    return out;
}

// First t/t0 at which |k/ref - 1| exceeds level, interpolated linearly in ln t between the
// samples around the crossing; NaN if it never does.
double first_departure(const std::vector<double>& t, const std::vector<double>& k, const std::vector<double>& ref,
                       double t0, double level) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < t.size() && i < k.size() && i < ref.size(); ++i) {
        x.push_back(t[i] / t0);
        y.push_back(std::abs(k[i] / ref[i] - 1));
    }
    for (std::size_t i = 1; i < x.size(); ++i)
        if (y[i] > level && y[i - 1] <= level && x[i - 1] > 0) {
            const double f = (level - y[i - 1]) / (y[i] - y[i - 1]);
            return std::exp(std::log(x[i - 1]) + f * std::log(x[i] / x[i - 1]));
        }
    return NAN;
}

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

// Mean over 1 <= k <= k_max of ln(S_a/S_b), or of |ln(S_a/S_b)| (shells where both are positive).
double mean_log_ratio(const std::vector<double>& sa, const std::vector<double>& sb, const std::vector<double>& k, double k_max,
                      bool absolute = false) {
    double sum = 0;
    int cnt = 0;
    for (std::size_t i = 0; i < k.size() && i < sa.size() && i < sb.size(); ++i)
        if (k[i] >= 1 && k[i] <= k_max && sa[i] > 0 && sb[i] > 0) {
            sum += absolute ? std::abs(std::log(sa[i] / sb[i])) : std::log(sa[i] / sb[i]);
            ++cnt;
        }
    return cnt ? sum / cnt : NAN;
}

// Mean and sample standard deviation.
std::array<double, 2> mean_sd(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m += x;
    m /= double(v.size());
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return {m, v.size() > 1 ? std::sqrt(s / double(v.size() - 1)) : NAN};
}

// The mean over seeds of v as `name`, and its seed standard deviation as name_sd.
void add_mean_sd(Result& res, const std::string& name, const std::vector<double>& v, const std::string& what) {
    const auto ms = mean_sd(v);
    res.scalar(name, ms[0], "1", what);
    res.scalar(name + "_sd", ms[1], "1", "its seed standard deviation");
}

// A bump of S(k) at shell kc (the DSMC cell lattice, box/cell, folded into the FFT range by the
// NGP aliasing of an M-point grid): mean S over kc +- 2 over the geometric mean of the mean S over
// the flanks 0.75 kc +- 2 and 1.25 kc +- 2 (a flank beyond M/2 is left out). A smooth S(k) gives
// about 1.
double bump_contrast(const std::vector<double>& S, const std::vector<double>& k, double kc) {
    const double kmax = k.empty() ? 0 : k.back();
    const double centre = mean_over(S, k, kc - 2, kc + 2);
    const double lo = mean_over(S, k, 0.75 * kc - 2, 0.75 * kc + 2);
    const double hi = 1.25 * kc + 2 <= kmax ? mean_over(S, k, 1.25 * kc - 2, 1.25 * kc + 2) : NAN;
    return std::isfinite(hi) ? centre / std::sqrt(lo * hi) : centre / lo;
}

// Early collision rate: C/N at the sample nearest t = 0.25 t0 over what Haff's law with the
// Enskog-Henderson rate omega promises there (the rate of the collision rule, before clustering).
double rate_over_enskog(const Trace& tr, double t0, double omega) {
    std::size_t best = 1;
    for (std::size_t i = 1; i < tr.t.size(); ++i)
        if (std::abs(std::log(tr.t[i] / (0.25 * t0))) < std::abs(std::log(tr.t[best] / (0.25 * t0)))) best = i;
    return tr.cn[best] / theory::haff_collisions_per_particle(tr.t[best], t0, omega);
}

// Grazing over central collisions: mean P(b/d) over b/d > 0.8 against b/d < 0.2.
double grazing_ratio(const ImpactParameterHistogram::Window& w, const std::vector<double>& centres) {
    return mean_over(w.p, centres, 0.8, 1.0) / mean_over(w.p, centres, 0.0, 0.2);
}

// Mean S(1 <= k <= k_max) of one snapshot of a trace.
double small_k_S(const Trace& tr, const Snapshot& at, double k_max) { return mean_over(at.S, tr.S_k, 1, k_max); }

// The snapshot at t = 20 s (S(k) stops changing after it; issue 3), if the run has one.
std::optional<std::size_t> snapshot_20s(const std::vector<double>& snaps) {
    std::optional<std::size_t> at;
    for (std::size_t i = 0; i < snaps.size(); ++i)
        if (std::abs(snaps[i] - 20.0) < 1e-9) at = i;
    return at;
}

// HCS Sonine coefficient before clustering (van Noije & Ernst 1998): samples in the a2 window
// (units of t0), weighted mean over samples and seeds taken as independent measurements (samples
// ~1 collision per particle apart).
void hcs_a2(Result& res, const std::vector<Trace>& trs, const CoolingSpec& c, const char* name) {
    const double t0 = c.t0();
    const double a2_vne = theory::van_noije_ernst_a2(c.r, 2);
    const auto& w = c.a2_window;
    double sw = 0, swa = 0;
    int cnt = 0;
    for (const Trace& tr : trs)
        for (std::size_t i = 0; i < tr.t.size(); ++i)
            if (tr.t[i] >= w[0] * t0 * (1 - 1e-9) && tr.t[i] <= w[1] * t0 * (1 + 1e-9)) {
                const double wi = 1 / (tr.a2_err[i] * tr.a2_err[i]);
                sw += wi;
                swa += wi * tr.a2[i];
                ++cnt;
            }
    const double a2 = swa / sw, err = 1 / std::sqrt(sw);
    res.scalar(std::string("a2_hcs_") + name, a2, "1", std::string("Sonine a2 in the a2 window, weighted mean over samples and seeds, ") + name);
    res.scalar(std::string("a2_hcs_err_") + name, err, "1", "its standard error (samples taken as independent)");
    res.scalar(std::string("a2_hcs_samples_") + name, double(cnt), "1", "samples in the window");
    res.scalar(std::string("a2_hcs_z_") + name, (a2 - a2_vne) / err, "1", "(a2 - van Noije-Ernst) in standard errors");
}

// What a DSMC variant does before clustering, against kinetic theory (first seed, a2 all seeds).
void add_dsmc_kinetics(Result& res, const std::vector<Trace>& dss, const CoolingSpec& c) {
    const double t0 = c.t0();
    const Trace& ds = dss.front();
    res.scalar("dsmc_rate_over_enskog_early", rate_over_enskog(ds, t0, c.omega_enskog()), "1", "C/N at t = 0.25 t0 over Haff's law with the Enskog rate, DSMC");
    res.scalar("t0_fit_over_kinetic_dsmc", fit_haff_inv_t0(ds.t, k_ratio(ds), t0) * t0, "1", "1/t0 fitted to the DSMC K(t) over t <= t0 (Eq. 18) over the kinetic-theory 1/t0");
    res.scalar("dsmc_over_eq18_2t0", ratio_at(ds, t0, 2 * t0), "1", "K/K_18 at t = 2 t0, DSMC");
    hcs_a2(res, dss, c, "dsmc");
}

// Per-seed S(k) at every snapshot and K/K0 of one method, for studies that compare runs made
// separately (scripts/studies/dsmc_variants.sh).
void add_seed_tables(Result& res, const std::vector<Trace>& trs, const std::vector<double>& snaps, const char* name) {
    for (std::size_t k = 0; k < trs.size(); ++k) {
        const Trace& tr = trs[k];
        {
            Table& t = res.table(std::string("sk_") + name + "_seed" + std::to_string(k), std::string("S(k) at the snapshot times, seed index ") + std::to_string(k) + ", " + name);
            t.add("k", "1").values = tr.S_k;
            for (std::size_t i = 0; i < tr.snaps.size(); ++i) t.add("S_t" + number_text(snaps[i]), "1").values = tr.snaps[i].S;
        }
        Table& e = res.table(std::string("energy_") + name + "_seed" + std::to_string(k), std::string("K/K0 against t, seed index ") + std::to_string(k) + ", " + name);
        e.add({{"t", "s", tr.t}, {"K_over_K0", "1", k_ratio(tr)}, {"C_over_N", "1", tr.cn}});
    }
}

// run_ed = false: DSMC alone (for variant studies; the claims that compare with ED are then missing).
Result report_dsmc_only(const CoolingSpec& c, const std::vector<Trace>& dss) {
    Result res;
    double wall = 0;
    for (const Trace& tr : dss) wall += tr.wall_seconds;
    res.scalar("seeds", double(c.seeds), "1", "independent initial states");
    res.scalar("wall_time_dsmc", wall, "s", "wall time of the DSMC runs, summed over seeds");
    add_seed_tables(res, dss, c.snapshots(), "dsmc");
    add_dsmc_kinetics(res, dss, c);
    return res;
}

// The run's size and cost, and t0 in its three readings: Eq. (19) as printed, kinetic theory, and
// the measured elastic collision rate.
void add_setup(Result& res, const CoolingSpec& c, const Setup& s, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const double r = c.r;
    // Eq. (19) as printed; theory::luding_eq19_t0_printed forms s_* otherwise and differs in the
    // last bit.
    const double s_star = 1 / theory::henderson_contact_value(c.rho);
    const double t0_printed = std::sqrt(M_PI) * c.d * s_star / (2 * (1 - r * r) * c.rho * c.vbar);
    const double t0_measured_rate = 4 / ((1 - r * r) * s.collision_rate);
    res.scalar("N", double(s.pos.size()), "1", "number of disks");
    res.scalar("seeds", double(c.seeds), "1", "independent initial states (equilibration, ED and DSMC each)");
    double wall_ed = 0, wall_ds = 0;
    for (const Trace& tr : eds) wall_ed += tr.wall_seconds;
    for (const Trace& tr : dss) wall_ds += tr.wall_seconds;
    res.scalar("wall_time_ed", wall_ed, "s", "wall time of the ED runs from t = 0 with their observables, summed over seeds and resumed parts");
    if (c.run_dsmc)
        res.scalar("wall_time_dsmc", wall_ds, "s", "wall time of the DSMC runs from t = 0 with their observables, summed over seeds and resumed parts");
    res.scalar("box", s.L, "m", "side of the periodic box");
    res.scalar("t0_inv_eq19_printed", 1 / t0_printed, "1/s", "1/t0 from Eq. (19) as printed (sqrt(pi))");
    res.scalar("t0_inv_kinetic_theory", 1 / c.t0(), "1/s", "1/t0 = (1-r^2) omega_E / 4 with Henderson's g(d): sqrt(2 pi)");
    res.scalar("omega_equilibration_over_enskog", s.collision_rate / c.omega_enskog(), "1",
               "elastic ED collision rate over the second half of the equilibration over the Enskog-Henderson rate");
    res.scalar("t0_inv_measured_rate", 1 / t0_measured_rate, "1/s", "1/t0 from the measured elastic collision rate");
}

// The equilibrated state is Maxwellian (Sec. 3: "so that a Maxwellian velocity distribution ...
// exists"): a2 pooled over the seeds, against 0 with its standard error.
void add_equilibrated_a2(Result& res, const CoolingSpec& c, std::uint64_t seed, const Setups& setups) {
    std::vector<Vec2> all;
    for (long k = 0; k < setups.size(); ++k) all.insert(all.end(), setups[k].vel.begin(), setups[k].vel.end());
    const auto a2 = sonine_a2(all);
    RngStream rng(seed, setup_stream(0));
    const auto v0 = initial_velocities(c, setups[0].mass, rng);
    res.scalar("a2_initial_velocities", sonine_a2(v0)[0], "1", "a2 of the velocities drawn before the equilibration (uniform components: -0.3)");
    res.scalar("a2_equilibrated", a2[0], "1", "Sonine a2 of the velocities at t = 0 (after the elastic equilibration), all seeds");
    res.scalar("a2_equilibrated_err", a2[1], "1", "its standard error (sample variance of v^4)");
    res.scalar("a2_equilibrated_z", a2[0] / a2[1], "1", "a2 at t = 0 in standard errors (Maxwellian: |z| ~ 1)");
}

// Fig. 2: K/K0, its parts, Eq. (18), C/N and a2 against t/t0 of one method.
void add_energy_table(Result& res, const Trace& tr, double t0, const char* name) {
    Table& t = res.table(std::string("energy_") + name, std::string("K/K0 and a2 against t/t0, ") + name);
    const double k0 = tr.kx.front() + tr.ky.front() + tr.krot.front();
    const auto over_by = [](const std::vector<double>& v, double by) {
        std::vector<double> out;
        for (double x : v) out.push_back(x / by);
        return out;
    };
    t.add({{"t", "s", tr.t}, {"t_over_t0", "1", over_by(tr.t, t0)}, {"K_over_K0", "1", k_ratio(tr)},
           {"Kx_over_K0", "1", over_by(tr.kx, k0)}, {"Ky_over_K0", "1", over_by(tr.ky, k0)},
           {"Krot_over_K0", "1", over_by(tr.krot, k0)}, {"eq18", "1", eq18_curve(tr, t0)}, {"C_over_N", "1", tr.cn},
           {"elastic_C_over_N", "1", tr.elastic_cn}, {"a2", "1", tr.a2}, {"a2_err", "1", tr.a2_err}});
}

// Fig. 2, ED against kinetic theory: early cooling (Eq. 18, the Enskog rate), where K(t) departs
// from Eq. (18), and the HCS a2.
void add_ed_cooling(Result& res, const CoolingSpec& c, const std::vector<Trace>& eds) {
    const Trace& ed = eds.front();
    const double t0 = c.t0();
    const double inv_t0_fit = fit_haff_inv_t0(ed.t, k_ratio(ed), t0);
    res.scalar("t0_inv_fit_ed", inv_t0_fit, "1/s", "1/t0 fitted to the ED K(t) over t <= t0 (Eq. 18)");
    res.scalar("t0_fit_over_kinetic_ed", inv_t0_fit * t0, "1", "fitted over kinetic-theory 1/t0, ED");
    res.scalar("ed_rate_over_enskog_early", rate_over_enskog(ed, t0, c.omega_enskog()), "1", "C/N at t = 0.25 t0 over Haff's law with the Enskog rate, ED");
    res.scalar("ed_eq18_max_dev_2t0", max_dev(ed, t0, 2 * t0), "1", "max |K/K_18 - 1| for t <= 2 t0, ED");
    res.scalar("ed_over_eq18_10t0", ratio_at(ed, t0, 10 * t0), "1", "K/K_18 at t = 10 t0, ED");
    res.scalar("ed_over_eq18_end", ratio_at(ed, t0, ed.t.back()), "1", "K/K_18 at t_end, ED");
    res.scalar("ed_C_over_N_end", ed.cn.back(), "1", "collisions per particle at t_end, ED");
    res.scalar("ed_elastic_fraction_end", ed.elastic_cn.back() / ed.cn.back(), "1", "TC-elastic share of collisions, ED");
    // Departure from homogeneous cooling (Sec. 3.1: "at t/t0 ≈ 2 substantial deviations"): the
    // first t/t0 where the ED K(t) leaves Eq. (18) by more than departure_level, per seed.
    std::vector<double> dep;
    for (const Trace& tr : eds)
        dep.push_back(first_departure(tr.t, k_ratio(tr), eq18_curve(tr, t0), t0, c.departure_level));
    add_mean_sd(res, "ed_departure_t_over_t0", dep, "first t/t0 with |K_ED/K_18 - 1| > departure_level, mean over seeds");
    res.scalar("a2_van_noije_ernst", theory::van_noije_ernst_a2(c.r, 2), "1", "van Noije-Ernst a2 of the 2D HCS at this r (first Sonine approximation)");
    hcs_a2(res, eds, c, "ed");
}

// Sec. 3.2, "more and more grazing collisions occur with increasing simulation time": the grazing
// ratio of every window with its counting error (Poisson: the relative error of a ratio of two
// bin-group counts is sqrt(1/C_hi + 1/C_lo); the window total cancels), and the share of
// successive window pairs in which it does not fall by more than 3 combined standard errors.
void add_grazing_trend(Result& res, const Trace& ed) {
    std::vector<double> ratio, err;
    for (const auto& w : ed.pbd) {
        double hi = 0, lo = 0, nhi = 0, nlo = 0;
        for (std::size_t b = 0; b < w.counts.size() && b < ed.pbd_centres.size(); ++b) {
            const double x = ed.pbd_centres[b];
            if (x >= 0.8 && x <= 1.0) { hi += double(w.counts[b]); ++nhi; }
            if (x >= 0.0 && x <= 0.2) { lo += double(w.counts[b]); ++nlo; }
        }
        const double r = (hi > 0 && lo > 0) ? (hi / nhi) / (lo / nlo) : NAN;
        ratio.push_back(r);
        err.push_back(r * std::sqrt(1 / hi + 1 / lo));
    }
    Table& t = res.table("impact_parameter_grazing", "grazing ratio P(b/d>0.8)/P(b/d<0.2) of the ED run per window, with its counting error");
    std::vector<double> b;
    for (const auto& w : ed.pbd) b.push_back(w.t_begin);
    t.add({{"t_begin", "s", b}, {"grazing_ratio", "1", ratio}, {"grazing_ratio_err", "1", err}});
    int pairs = 0, rising = 0;
    double min_z = NAN;
    for (std::size_t k = 1; k < ratio.size(); ++k) {
        if (!std::isfinite(ratio[k]) || !std::isfinite(ratio[k - 1])) continue;
        const double z = (ratio[k] - ratio[k - 1]) / std::hypot(err[k], err[k - 1]);
        ++pairs;
        if (z >= -3) ++rising;
        min_z = std::isnan(min_z) ? z : std::min(min_z, z);
    }
    res.scalar("pbd_grazing_rising_share", pairs ? double(rising) / pairs : NAN, "1",
               "share of successive P(b/d) windows whose grazing ratio does not fall by more than 3 combined standard errors");
    res.scalar("pbd_grazing_rising_pairs", double(pairs), "1", "number of successive window pairs judged");
    res.scalar("pbd_grazing_step_min_z", min_z, "1", "smallest change of the grazing ratio between successive windows, in combined standard errors");
    res.scalar("pbd_grazing_ratio_last_over_first", ratio.empty() ? NAN : ratio.back() / ratio.front(), "1",
               "grazing ratio of the last window over the first (from the counts)");
}

// Fig. 3: P(b/d) of the ED run per time window, and grazing over central collisions in the first
// and last window.
void add_impact_parameter(Result& res, const Trace& ed) {
    {
        Table& t = res.table("impact_parameter_ed", "P(b/d) of the ED run per time window (columns by window start)");
        t.add("b_over_d", "1").values = ed.pbd_centres;
        for (const auto& w : ed.pbd)
            t.add({{"P_t" + number_text(w.t_begin), "1", w.p}, {"err_t" + number_text(w.t_begin), "1", w.error}});
    }
    Table& wt = res.table("impact_parameter_windows", "time windows of P(b/d): [t_begin, t_end)");
    std::vector<double> b, e;
    for (const auto& w : ed.pbd) {
        b.push_back(w.t_begin);
        e.push_back(w.t_end);
    }
    wt.add({{"t_begin", "s", b}, {"t_end", "s", e}});
    res.scalar("pbd_grazing_ratio_first", grazing_ratio(ed.pbd.front(), ed.pbd_centres), "1", "P(b/d>0.8)/P(b/d<0.2), first window, ED");
    res.scalar("pbd_grazing_ratio_last", grazing_ratio(ed.pbd.back(), ed.pbd_centres), "1", "P(b/d>0.8)/P(b/d<0.2), last window, ED");
    res.scalar("pbd_collisions_first", double(ed.pbd.front().total), "1", "collisions in the first window");
    add_grazing_trend(res, ed);
}

// Figs. 6 and 7: g(r/d) and S(k) of one method at the snapshot times.
void add_structure_tables(Result& res, const Trace& tr, const std::vector<double>& snaps, double rho, const char* name) {
    {
        Table& g = res.table(std::string("gr_") + name, std::string("g(r/d) at the snapshot times, ") + name);
        g.add("r_over_d", "1").values = tr.g_r;
        for (std::size_t i = 0; i < tr.snaps.size(); ++i) g.add("g_t" + number_text(snaps[i]), "1").values = tr.snaps[i].g;
    }
    Table& sk = res.table(std::string("sk_") + name, std::string("S(k), k = l/lambda, at the snapshot times, ") + name);
    sk.add("k", "1").values = tr.S_k;
    for (std::size_t i = 0; i < tr.snaps.size(); ++i) sk.add("S_t" + number_text(snaps[i]), "1").values = tr.snaps[i].S;
    sk.add("S_equilibrium", "1").values = std::vector<double>(tr.S_k.size(), theory::hard_disk_structure_factor_zero(rho));
}

// The pair velocity correlations of one method at the snapshot times, seed means (issue 27 §3:
// does the gas keep molecular chaos at t = 0, and how fast do correlations build up?): a table over
// r/d, and at contact (d <= r < 1.1 d) per snapshot the mean over seeds and its standard error
// over seeds (NaN with one seed: the pairs of one snapshot share particles, so their own spread
// would understate it).
void add_velocity_correlation(Result& res, const CoolingSpec& c, const std::vector<Trace>& trs, const char* name) {
    const std::vector<double> snaps = c.snapshots();
    const VelocityCorrelation grid = velocity_correlation(c.box(), c.d);
    Table& t = res.table(std::string("vcorr_") + name,
                         std::string("pair velocity correlations C_n, C_t (mean over seeds) at the snapshot times, ") + name);
    std::vector<double> r;
    for (double x : grid.centres()) r.push_back(x / c.d);
    t.add("r_over_d", "1").values = r;
    for (std::size_t i = 0; i < snaps.size(); ++i)
        for (const auto& [col, member] :
             {std::pair{"Cn_t", &Snapshot::vc_n}, std::pair{"Ct_t", &Snapshot::vc_t}, std::pair{"A_t", &Snapshot::vc_a}}) {
            std::vector<double> mean(r.size(), 0.0);
            for (const Trace& tr : trs)
                for (std::size_t b = 0; b < r.size(); ++b) mean[b] += (tr.snaps[i].*member)[b] / double(trs.size());
            t.add(col + number_text(snaps[i]), "1").values = mean;
        }
    for (std::size_t i = 0; i < snaps.size(); ++i) {
        std::vector<double> cn, ct, ca;
        for (const Trace& tr : trs)
            cn.push_back(tr.snaps[i].vc_n.front()), ct.push_back(tr.snaps[i].vc_t.front()), ca.push_back(tr.snaps[i].vc_a.front());
        const MeanSd mn = granrepro::mean_sd(cn), mt = granrepro::mean_sd(ct), ma = granrepro::mean_sd(ca);
        const std::string at = "_t" + number_text(snaps[i]);
        res.scalar(std::string(name) + "_vcorr_n_contact" + at, mn.mean, "1",
                   "C_n of pairs at d <= r < 1.1 d, mean over seeds (molecular chaos: 0)");
        res.scalar(std::string(name) + "_vcorr_n_contact_err" + at, mn.sem, "1", "its standard error over seeds");
        res.scalar(std::string(name) + "_vcorr_t_contact" + at, mt.mean, "1", "C_t of pairs at d <= r < 1.1 d, mean over seeds");
        res.scalar(std::string(name) + "_vcorr_t_contact_err" + at, mt.sem, "1", "its standard error over seeds");
        res.scalar(std::string(name) + "_vcorr_approach_contact" + at, ma.mean, "1",
                   "<g_n^2 | approaching> / (2 T1) of pairs at d <= r < 1.1 d, mean over seeds (molecular chaos: 1)");
        res.scalar(std::string(name) + "_vcorr_approach_contact_err" + at, ma.sem, "1", "its standard error over seeds");
    }
}

// chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 over r/d >= r_lo, with
// the counting errors of both, and the number of bins.
std::array<double, 2> early_g_chi2(const Trace& ed, double r_lo) {
    const Snapshot &a = ed.snaps[0], &b = ed.snaps[1];
    double chi2 = 0;
    int bins = 0;
    for (std::size_t i = 0; i < ed.g_r.size(); ++i)
        if (ed.g_r[i] >= r_lo) {
            const double var = a.g_err[i] * a.g_err[i] + b.g_err[i] * b.g_err[i];
            if (var > 0) {
                chi2 += (b.g[i] - a.g[i]) * (b.g[i] - a.g[i]) / var;
                ++bins;
            }
        }
    return {bins ? chi2 / bins : NAN, double(bins)};
}

// Fig. 6, ED: the clustered g at the last snapshot (exclusion hole, the peaks of packed disks at
// sqrt(3), 2 and 3 d, contact value), and early g as elastic.
void add_ed_g(Result& res, const Trace& ed, const std::vector<double>& snaps, double t0) {
    const auto& g_last = ed.snaps.back().g;
    res.scalar("ed_g_inside_contact_max", max_over(g_last, ed.g_r, 0.0, 0.98), "1", "largest g(r/d) for r/d < 0.98, last snapshot, ED");
    res.scalar("ed_g_peak_sqrt3_contrast", max_over(g_last, ed.g_r, 1.68, 1.78) / min_over(g_last, ed.g_r, 1.4, 1.6), "1",
               "max g near sqrt(3) over min g in [1.4, 1.6], last snapshot, ED");
    res.scalar("ed_g_peak_2_contrast", max_over(g_last, ed.g_r, 1.95, 2.05) / min_over(g_last, ed.g_r, 1.8, 1.9), "1",
               "max g near 2 over min g in [1.8, 1.9], last snapshot, ED");
    res.scalar("ed_g_peak_3_contrast", max_over(g_last, ed.g_r, 2.95, 3.05) / min_over(g_last, ed.g_r, 2.75, 2.9), "1",
               "max g near 3 over min g in [2.75, 2.9], last snapshot, ED");
    res.scalar("ed_g_contact", max_over(g_last, ed.g_r, 1.0, 1.04), "1", "g at contact, last snapshot, ED");
    // Early g equals the elastic one (Sec. 3.3: "for short times one observes g as for an elastic
    // hard sphere gas"): the first snapshot after t = 0 against t = 0 (the end of the elastic
    // equilibration), over 0.98 <= r/d <= 5.
    if (ed.snaps.size() < 2) return;
    const auto all = early_g_chi2(ed, 0.98), beyond = early_g_chi2(ed, 1.1);
    res.scalar("ed_g_early_vs_elastic_chi2", all[0], "1",
               "chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 (elastic), 0.98 <= r/d <= 5, ED");
    res.scalar("ed_g_early_vs_elastic_chi2_beyond_contact", beyond[0], "1", "the same over 1.1 <= r/d <= 5");
    res.scalar("ed_g_early_vs_elastic_bins_beyond_contact", beyond[1], "1", "bins in that range");
    res.scalar("ed_g_early_time_over_t0", snaps[1] / t0, "1", "time of that snapshot in t0");
    res.scalar("ed_g_contact_early_over_elastic", max_over(ed.snaps[1].g, ed.g_r, 1.0, 1.04) / max_over(ed.snaps[0].g, ed.g_r, 1.0, 1.04), "1",
               "contact value of g at the first snapshot after t = 0 over that at t = 0, ED");
}

// Fig. 7, ED: growth of S(k) at small k, measured from equilibrium: against the elastic hard-disk
// S(0) (Henderson's equation of state; what an equilibrated elastic gas has at k <= 25), not
// against the t = 0 snapshot, whose long waves still carry the lattice start.
void add_ed_sk(Result& res, const std::vector<Trace>& eds, const std::vector<double>& snaps, double k_small, double s_eq) {
    res.scalar("Sk_equilibrium_hard_disks", s_eq, "1", "S(k -> 0) of the elastic hard-disk gas at rho (Henderson's equation of state)");
    const auto i20 = snapshot_20s(snaps);
    std::vector<double> growth, lattice, change, lns;
    for (const Trace& tr : eds) {
        growth.push_back(small_k_S(tr, tr.snaps.back(), k_small) / s_eq);
        lattice.push_back(small_k_S(tr, tr.snaps.front(), k_small) / s_eq);
        const double s20 = i20 ? small_k_S(tr, tr.snaps[*i20], k_small) : NAN;
        change.push_back(small_k_S(tr, tr.snaps.back(), k_small) / s20 - 1);
        lns.push_back(std::log(growth.back()));
    }
    const Trace& ed = eds.front();
    res.scalar("ed_Sk_growth_over_equilibrium", mean_sd(growth)[0], "1",
               "mean S(1 <= k <= sk_k_max) at the last snapshot over the equilibrium S(0), ED, mean over seeds");
    res.scalar("ed_Sk_t0_over_equilibrium", mean_sd(lattice)[0], "1",
               "the same at t = 0: below 1 where the long waves have not forgotten the lattice start");
    res.scalar("ed_Sk_small_k_growth", small_k_S(ed, ed.snaps.back(), k_small) / small_k_S(ed, ed.snaps.front(), k_small), "1",
               "mean S(k <= sk_k_max) at the last snapshot over that at t = 0 (lattice leftover), ED, first seed");
    add_mean_sd(res, "ed_Sk_change_after_20s", change,
                "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, ED, mean over seeds");
    res.scalar("ed_Sk_log_seed_sd", mean_sd(lns)[1], "1",
               "seed standard deviation of ln(mean S_ED(k <= sk_k_max)) at the last snapshot: the run-to-run scatter of one run");
}

// Fig. 2, DSMC against ED: where their K(t) agree, and where they split (Sec. 3.1: "only at
// t/t0 ≈ 10 a difference"): the first t/t0 with |K_DSMC/K_ED - 1| > level, per seed.
void add_ed_dsmc_energy(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, double t0, double level) {
    const Trace &ed = eds.front(), &ds = dss.front();
    const auto ke = k_ratio(ed), kd = k_ratio(ds);
    double early = 0, late_max = 0;
    for (std::size_t i = 0; i < ke.size() && i < kd.size(); ++i) {
        if (ed.t[i] <= 5 * t0) early = std::max(early, std::abs(kd[i] / ke[i] - 1));
        if (ed.t[i] >= 30 * t0) late_max = std::max(late_max, kd[i] / ke[i]);
    }
    res.scalar("dsmc_vs_ed_max_dev_5t0", early, "1", "max |K_DSMC/K_ED - 1| for t <= 5 t0");
    res.scalar("dsmc_over_ed_max_late", late_max > 0 ? late_max : NAN, "1", "largest K_DSMC/K_ED for t >= 30 t0");
    res.scalar("dsmc_over_ed_end", kd.back() / ke.back(), "1", "K_DSMC/K_ED at t_end");
    res.scalar("dsmc_over_ed_t0", ratio_at(ds, t0, t0) / ratio_at(ed, t0, t0), "1", "K_DSMC/K_ED at t = t0");
    res.scalar("dsmc_over_ed_5t0", ratio_at(ds, t0, 5 * t0) / ratio_at(ed, t0, 5 * t0), "1", "K_DSMC/K_ED at t = 5 t0");
    std::vector<double> split;
    for (std::size_t k = 0; k < eds.size(); ++k)
        split.push_back(first_departure(eds[k].t, k_ratio(dss[k]), k_ratio(eds[k]), t0, level));
    add_mean_sd(res, "dsmc_ed_split_t_over_t0", split, "first t/t0 with |K_DSMC/K_ED - 1| > departure_level, mean over seeds");
}

// Fig. 7, DSMC against ED: agreement of S(k) at small k. Per seed: m = mean over
// 1 <= k <= sk_k_max of ln(S_DSMC/S_ED) at the last snapshot (and at 20 s); then mean and
// scatter over seeds, and a table of the seeds.
void add_sk_agreement(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, const std::vector<double>& snaps, double k_small) {
    const auto i20 = snapshot_20s(snaps);
    std::vector<double> idx, e20, elast, d20, dlast, m_last, m_20, abs_last, d_change;
    for (std::size_t k = 0; k < eds.size(); ++k) {
        const Trace &a = eds[k], &b = dss[k];
        idx.push_back(double(k));
        e20.push_back(i20 ? small_k_S(a, a.snaps[*i20], k_small) : NAN);
        d20.push_back(i20 ? small_k_S(b, b.snaps[*i20], k_small) : NAN);
        elast.push_back(small_k_S(a, a.snaps.back(), k_small));
        dlast.push_back(small_k_S(b, b.snaps.back(), k_small));
        d_change.push_back(dlast.back() / d20.back() - 1);
        m_last.push_back(mean_log_ratio(b.snaps.back().S, a.snaps.back().S, a.S_k, k_small));
        abs_last.push_back(mean_log_ratio(a.snaps.back().S, b.snaps.back().S, a.S_k, k_small, true));
        if (i20) m_20.push_back(mean_log_ratio(b.snaps[*i20].S, a.snaps[*i20].S, a.S_k, k_small));
    }
    Table& t = res.table("sk_seeds", "per seed: mean S(1 <= k <= sk_k_max) of ED and DSMC at 20 s and at the last snapshot, and the mean ln ratio");
    t.add({{"seed_index", "1", idx}, {"S_ed_20s", "1", e20}, {"S_ed_last", "1", elast}, {"S_dsmc_20s", "1", d20},
           {"S_dsmc_last", "1", dlast}, {"mean_ln_ratio_last", "1", m_last}});
    add_mean_sd(res, "Sk_dsmc_over_ed_log", m_last, "ln(S_DSMC/S_ED) averaged over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
    res.scalar("Sk_dsmc_over_ed_factor", std::exp(mean_sd(m_last)[0]), "1", "exp of Sk_dsmc_over_ed_log: DSMC's S(k <= sk_k_max) in units of ED's");
    if (!m_20.empty()) add_mean_sd(res, "Sk_dsmc_over_ed_log_20s", m_20, "the same at t = 20 s");
    res.scalar("Sk_ed_dsmc_mean_abs_log_ratio", mean_sd(abs_last)[0], "1",
               "mean |ln(S_ED/S_DSMC)| over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
    add_mean_sd(res, "dsmc_Sk_change_after_20s", d_change,
                "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, DSMC, mean over seeds");
}

// Fig. 7, the DSMC cell lattice's imprint on S(k): the bump of S at the cell shell, DSMC against
// ED (no cells), last snapshot, mean over seeds.
void add_cell_imprint(Result& res, const CoolingSpec& c, const Setup& s, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const DsmcEngine sizing(dsmc_config(c, s.L), s.pos, s.vel, s.rad, s.mass);
    const double cells = double(sizing.cells_x());
    const double M = 2 * (eds.front().S_k.empty() ? 1 : eds.front().S_k.back());
    // NGP on an M grid aliases mode n to n - M round(n/M).
    const double kc = std::abs(cells - M * std::round(cells / M));
    std::vector<double> imprint, imprint_ed;
    for (std::size_t k = 0; k < eds.size(); ++k) {
        imprint.push_back(bump_contrast(dss[k].snaps.back().S, dss[k].S_k, kc));
        imprint_ed.push_back(bump_contrast(eds[k].snaps.back().S, eds[k].S_k, kc));
    }
    res.scalar("dsmc_cells_per_side", cells, "1", "DSMC cells per box side");
    res.scalar("dsmc_cell_shell", kc, "1", "the S(k) shell of the cell lattice (box/cell, aliased into 1..M/2)");
    res.scalar("dsmc_Sk_cell_imprint", mean_sd(imprint)[0], "1",
               "S at the cell shell over the geometric mean of the flanks at 0.75 and 1.25 of it, last snapshot, DSMC, mean over seeds");
    res.scalar("ed_Sk_cell_imprint_control", mean_sd(imprint_ed)[0], "1", "the same measure on ED's S(k) (no cells)");
    res.scalar("dsmc_Sk_cell_imprint_over_ed", mean_sd(imprint)[0] / mean_sd(imprint_ed)[0], "1", "DSMC's contrast at the cell shell over ED's there (1: no imprint)");
}

// Sec. 3.1, "DSMC dissipates more energy than ED as soon as the number of central collisions is
// overestimated": the energy lost per collision, -ln(K(b)/K(a)) / ((1 - r^2)/2 (C/N(b) - C/N(a)))
// (1: a Maxwellian gas under molecular chaos at the global temperature), DSMC over ED, per seed in
// windows of t/t0 (K and C/N interpolated linearly in t), then the seed mean of each window
// (scripts/studies/cooling_loss_per_collision.md). From 2 t0 on, where ED's P(b/d) tilts towards
// grazing collisions (Fig. 3), the smallest of those window ratios and the share of successive
// windows in which it rises.
void add_loss_per_collision(Result& res, const CoolingSpec& c, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const double t0 = c.t0(), f = (1 - c.r * c.r) / 2;
    const auto at = [](const std::vector<double>& t, const std::vector<double>& v, double x) {
        for (std::size_t i = 1; i < t.size(); ++i)
            if (t[i] >= x) return v[i - 1] + (v[i] - v[i - 1]) * (x - t[i - 1]) / (t[i] - t[i - 1]);
        return double(NAN);
    };
    const auto loss = [&](const Trace& tr, double a, double b) {
        const auto k = k_ratio(tr);
        return -std::log(at(tr.t, k, b * t0) / at(tr.t, k, a * t0)) / (f * (at(tr.t, tr.cn, b * t0) - at(tr.t, tr.cn, a * t0)));
    };
    const std::vector<double> edges = {0.1, 0.5, 1, 2, 5, 10, 20, 50};
    std::vector<double> lo, hi, ratio, sd;
    for (std::size_t w = 0; w + 1 < edges.size(); ++w) {
        std::vector<double> per_seed;
        for (std::size_t k = 0; k < eds.size() && k < dss.size(); ++k) {
            const double q = loss(dss[k], edges[w], edges[w + 1]) / loss(eds[k], edges[w], edges[w + 1]);
            if (std::isfinite(q)) per_seed.push_back(q);
        }
        if (per_seed.empty()) continue;
        const auto ms = mean_sd(per_seed);
        lo.push_back(edges[w]);
        hi.push_back(edges[w + 1]);
        ratio.push_back(ms[0]);
        sd.push_back(ms[1]);
    }
    Table& t = res.table("loss_per_collision", "energy lost per collision, DSMC over ED, windows of t/t0 (mean over seeds)");
    t.add({{"t_over_t0_begin", "1", lo}, {"t_over_t0_end", "1", hi}, {"dsmc_over_ed", "1", ratio}, {"dsmc_over_ed_sd", "1", sd}});
    double min_ratio = NAN, min_sd = NAN;
    int pairs = 0, rising = 0;
    for (std::size_t w = 0; w < ratio.size(); ++w) {
        if (lo[w] < 2) continue;
        if (std::isnan(min_ratio) || ratio[w] < min_ratio) {
            min_ratio = ratio[w];
            min_sd = sd[w];
        }
        if (w > 0 && lo[w - 1] >= 2) {
            ++pairs;
            if (ratio[w] > ratio[w - 1]) ++rising;
        }
    }
    res.scalar("loss_per_collision_dsmc_over_ed_min_after_2t0", min_ratio, "1",
               "smallest DSMC/ED energy loss per collision over the windows 2-5, 5-10, 10-20, 20-50 t0 (those inside the run), seed mean");
    res.scalar("loss_per_collision_dsmc_over_ed_min_after_2t0_sd", min_sd, "1", "its seed standard deviation (NaN for one seed)");
    res.scalar("loss_per_collision_dsmc_over_ed_2_5t0", ratio.size() > 3 && lo[3] == 2 ? ratio[3] : NAN, "1",
               "DSMC/ED energy loss per collision over 2-5 t0, seed mean");
    res.scalar("loss_per_collision_ratio_rising_share", pairs ? double(rising) / pairs : NAN, "1",
               "share of successive windows from 2 t0 on in which DSMC/ED energy loss per collision rises");
    res.scalar("loss_per_collision_ratio_rising_pairs", double(pairs), "1", "number of such window pairs");
}

// Figs. 2, 6 and 7 of DSMC, and DSMC against ED.
void add_dsmc(Result& res, const CoolingSpec& c, const Setup& s, const std::vector<Trace>& eds, const std::vector<Trace>& dss) {
    const Trace& ds = dss.front();
    const double t0 = c.t0(), k_small = c.sk_k_max;
    const std::vector<double> snaps = c.snapshots();
    add_energy_table(res, ds, t0, "dsmc");
    add_structure_tables(res, ds, snaps, c.rho, "dsmc");
    res.scalar("dsmc_eq18_max_dev_2t0", max_dev(ds, t0, 2 * t0), "1", "max |K/K_18 - 1| for t <= 2 t0, DSMC");
    add_dsmc_kinetics(res, dss, c);
    add_ed_dsmc_energy(res, eds, dss, t0, c.departure_level);
    add_loss_per_collision(res, c, eds, dss);
    const auto& g_last = ds.snaps.back().g;
    res.scalar("dsmc_g_inside_contact_mean", mean_over(g_last, ds.g_r, 0.0, 0.9), "1", "mean g(r/d < 0.9), last snapshot, DSMC (no exclusion hole: about 1)");
    res.scalar("dsmc_g_contact_peak", max_over(g_last, ds.g_r, 0.9, 1.1) / mean_over(g_last, ds.g_r, 2.5, 5.0), "1",
               "g near contact over g at 2.5-5 d, last snapshot, DSMC");
    add_sk_agreement(res, eds, dss, snaps, k_small);
    add_cell_imprint(res, c, s, eds, dss);
    res.scalar("dsmc_Sk_small_k_growth", small_k_S(ds, ds.snaps.back(), k_small) / small_k_S(ds, ds.snaps.front(), k_small), "1",
               "mean S(k <= sk_k_max) at the last snapshot over that at t = 0, DSMC, first seed");
    res.scalar("dsmc_Sk_growth_over_equilibrium", small_k_S(ds, ds.snaps.back(), k_small) / theory::hard_disk_structure_factor_zero(c.rho), "1",
               "mean S(k <= sk_k_max) at the last snapshot over the hard-disk equilibrium S(0), DSMC, first seed");
    res.scalar("dsmc_C_over_N_end", ds.cn.back(), "1", "collisions per particle at t_end, DSMC");
    add_seed_tables(res, dss, snaps, "dsmc");
    if (c.velocity_correlation) add_velocity_correlation(res, c, dss, "dsmc");
    res.scalar("dsmc_pbd_grazing_ratio_last", grazing_ratio(ds.pbd.back(), ds.pbd_centres), "1", "P(b/d>0.8)/P(b/d<0.2), last window, DSMC (molecular chaos: 1)");
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
    add_ed_g(res, ed, snaps, c.t0());
    add_ed_sk(res, eds, snaps, c.sk_k_max, theory::hard_disk_structure_factor_zero(c.rho));
    if (c.velocity_correlation) add_velocity_correlation(res, c, eds, "ed");
    if (c.run_dsmc) add_dsmc(res, c, setups[0], eds, dss);
    return res;
}

// Figs. 2, 3, 6 and 7 as a protocol (harness/protocol.hpp): ED and DSMC (run_ed = false: DSMC
// alone, for variant studies) from every seed's initial state, one sweep point per seed and
// method: points 0 .. n_ed-1 are ED of seed i, the rest DSMC of seed i - n_ed. Index order is cost
// order, ED first (quick scale: ED 0.46, DSMC 0.12 CPU s a seed). A point's random streams are its
// seed index's, whichever thread, rank or shard computes it.
struct Cooling {
    static constexpr const char* name = "cooling";
    using Spec = CoolingSpec;
    using Outcome = Trace;
    using Shared = Setups;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Setups prepare(const Spec& c, const RunContext& ctx) { return Setups(c, ctx.seed); }
    static long n_ed(const Spec& c) { return c.run_ed ? c.seeds : 0; }
    static std::vector<long> points(const Spec& c, const Setups&) {
        std::vector<long> order(std::size_t(n_ed(c) + (c.run_dsmc ? c.seeds : 0)));
        std::iota(order.begin(), order.end(), 0L);
        return order;
    }
    static Trace compute(const Spec& c, const Setups& setups, long i, const PointContext& ctx) {
        const long k = i < n_ed(c) ? i : i - n_ed(c);
        return run_method(ctx, c, setups[k], k, i < n_ed(c));
    }
    static Result report(const Spec& c, const Setups& setups, const Swept<Trace>& swept, const RunContext& ctx) {
        std::vector<Trace> eds, dss;
        for (std::size_t i = 0; i < swept.outcomes.size(); ++i)
            (long(i) < n_ed(c) ? eds : dss).push_back(with_pbd(swept.outcomes[i], c));
        Result res = c.run_ed ? report_all(c, ctx.seed, setups, eds, dss) : report_dsmc_only(c, dss);
        res.scalar("resumed_points", double(swept.resumed), "1", "sweep points loaded from a checkpoint");
        return res;
    }
};

} // namespace

Experiment cooling() { return protocol_experiment<Cooling>(); }

} // namespace granrepro::experiments
