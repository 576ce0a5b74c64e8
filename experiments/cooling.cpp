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
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <gsl/gsl_fit.h>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/rng_stream.hpp"
#include "engines/dsmc/dsmc_engine.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/dsmc_state_file.hpp"
#include "io/ed_state_file.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "observables/log_time_sampler.hpp"
#include "observables/pair_correlation.hpp"
#include "observables/structure_factor.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro::experiments {

namespace {

void validate(const ParameterSet& p) {
    {
        // Collisions of the ED and DSMC runs, bounded above at the initial Enskog rate (cooling
        // only slows it); vbar = 1e308 got as far as "all velocities are equal".
        const double n = double(p.integer("n_side")) * double(p.integer("n_side")), rho = p.real("rho");
        const double omega = theory::enskog_collision_rate_vbar(rho, p.real("d"), p.real("vbar"), theory::henderson_contact_value(rho));
        const double runs = double(p.integer("seeds")) * (double(p.flag("run_ed")) + double(p.flag("run_dsmc")));
        p.limit_work({"t_end", "n_side", "seeds", "vbar", "rho", "d", "equilibration"},
                     runs * n / 2 * (omega * p.real("t_end") + p.real("equilibration")), kMaxCollisions, "collisions");
    }
    const auto& w = p.reals("bd_windows");
    for (std::size_t i = 1; i < w.size(); ++i)
        if (!(w[i] > w[i - 1])) p.reject("bd_windows", "edges must increase");
    if (w.size() < 2) p.reject("bd_windows", "needs at least two edges");
    const double L = p.real("d") * std::sqrt(double(p.integer("n_side") * p.integer("n_side")) * M_PI / 4 / p.real("rho"));
    if (L / double(p.integer("n_side")) < p.real("d") * 1.0000001)
        p.reject("rho", "too dense for a square-lattice start (lattice spacing below d)");
    const auto& a2w = p.reals("a2_window");
    if (a2w.size() != 2 || !(a2w[1] > a2w[0]) || !(a2w[0] > 0)) p.reject("a2_window", "two increasing positive times in units of t0");
    const auto& snaps = p.reals("snapshot_times");
    if (snaps.empty() || snaps.front() != 0.0) p.reject("snapshot_times", "must start with 0 (the equilibrated state)");
    for (std::size_t i = 1; i < snaps.size(); ++i)
        if (!(snaps[i] > snaps[i - 1])) p.reject("snapshot_times", "must increase");
}

// What one method (ED or DSMC) produced from one initial state.
struct Trace {
    std::vector<double> t, kx, ky, krot, cn, elastic_cn, a2, a2_err;
    std::vector<std::vector<double>> g, g_err, S; // per snapshot
    std::vector<double> g_r, S_k;
    std::vector<ImpactParameterHistogram::Window> pbd;
    std::vector<double> pbd_centres;
    // While running: the seconds of the earlier parts of a resumed run; at the end, the total.
    double wall_seconds = 0;
};

struct Setup {
    std::vector<Vec2> pos, vel;
    std::vector<double> rad, mass;
    double L = 0, t0_abs = 0;         // box side [m], engine time at which t = 0 [s]
    double omega_measured = 0;        // elastic collision rate per particle during equilibration [1/s]
};

double kinetic_t0(const ParameterSet& p) {
    const double rho = p.real("rho");
    const double omega0 = theory::enskog_collision_rate_vbar(rho, p.real("d"), p.real("vbar"), theory::henderson_contact_value(rho));
    return theory::haff_t0(p.real("r"), omega0);
}

// Sample times: log-spaced K(t) samples, a2_samples evenly spaced in the a2 window, and the
// snapshot times, merged.
std::vector<double> sample_times(const ParameterSet& p) {
    const double t_end = p.real("t_end");
    LogTimeSampler log(t_end * 1e-4, t_end, int(p.integer("samples_per_decade")));
    std::vector<double> t = log.times();
    t.push_back(0.0);
    const double t0 = kinetic_t0(p);
    const auto& w = p.reals("a2_window");
    const long na = p.integer("a2_samples");
    for (long i = 0; i < na; ++i) {
        const double ti = t0 * (w[0] + (w[1] - w[0]) * (na > 1 ? double(i) / double(na - 1) : 0.0));
        if (ti <= t_end) t.push_back(ti);
    }
    for (double s : p.reals("snapshot_times"))
        if (s <= t_end) t.push_back(s);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), t.end());
    return t;
}

bool is_snapshot(const ParameterSet& p, double t) {
    for (double s : p.reals("snapshot_times"))
        if (std::abs(s - t) < 1e-12) return true;
    return false;
}

std::vector<double> snapshot_times(const ParameterSet& p) {
    std::vector<double> snaps;
    for (double t : p.reals("snapshot_times"))
        if (t <= p.real("t_end")) snaps.push_back(t);
    return snaps;
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
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

// Mid-run checkpoint of one method: the engine state, the histogram counts and the trace up to a
// sample time. prepare() is deterministic, so a resumed run redoes the equilibration instead of
// storing the t = 0 state. P(b/d) enters the trace only at the end, so it lives in the counts.
constexpr const char* kCoolingRunSchema = "granrepro-cooling-run";
constexpr long kCoolingRunSchemaVersion = 2;

void write_engine(const H5Object& g, const EdEngine& eng) {
    write_ed_state(g, eng.save_state());
}
void write_engine(const H5Object& g, const DsmcEngine& eng) {
    write_dsmc_state(g, eng.save_state());
}
void read_engine(const H5Object& g, EdState& state) {
    state = read_ed_state(g);
}
void read_engine(const H5Object& g, DsmcState& state) {
    state = read_dsmc_state(g);
}

void write_trace(const H5Object& g, const Trace& tr) {
    g.array("t", tr.t);
    g.array("kx", tr.kx);
    g.array("ky", tr.ky);
    g.array("krot", tr.krot);
    g.array("cn", tr.cn);
    g.array("elastic_cn", tr.elastic_cn);
    g.array("a2", tr.a2);
    g.array("a2_err", tr.a2_err);
    g.array("g_r", tr.g_r);
    g.array("S_k", tr.S_k);
    g.attr("snapshots", long(tr.g.size()));
    for (std::size_t i = 0; i < tr.g.size(); ++i) {
        g.array("g_" + std::to_string(i), tr.g[i]);
        g.array("g_err_" + std::to_string(i), tr.g_err[i]);
        g.array("S_" + std::to_string(i), tr.S[i]);
    }
}

Trace read_trace(const H5Object& g) {
    Trace tr;
    tr.t = g.read_array<double>("t");
    tr.kx = g.read_array<double>("kx");
    tr.ky = g.read_array<double>("ky");
    tr.krot = g.read_array<double>("krot");
    tr.cn = g.read_array<double>("cn");
    tr.elastic_cn = g.read_array<double>("elastic_cn");
    tr.a2 = g.read_array<double>("a2");
    tr.a2_err = g.read_array<double>("a2_err");
    tr.g_r = g.read_array<double>("g_r");
    tr.S_k = g.read_array<double>("S_k");
    const long snapshots = g.read_long_attr("snapshots");
    for (long i = 0; i < snapshots; ++i) {
        tr.g.push_back(g.read_array<double>("g_" + std::to_string(i)));
        tr.g_err.push_back(g.read_array<double>("g_err_" + std::to_string(i)));
        tr.S.push_back(g.read_array<double>("S_" + std::to_string(i)));
    }
    return tr;
}

// Runs eng through the sample times, continuing from the checkpoint if there is one. start is
// when this process began the run (for the wall time stored in checkpoints).
template <class Engine, class Sample>
void observe(const ParameterSet& p, const Setup& s, Engine& eng, Trace& tr,
             RunCheckpoint& checkpoint, Clock::time_point start, Sample&& kinetic) {
    const double d = p.real("d");
    ImpactParameterHistogram hist(20, [&] {
        std::vector<double> e;
        for (double w : p.reals("bd_windows")) e.push_back(w + s.t0_abs);
        return e;
    }());
    const std::vector<double> times = sample_times(p);
    std::size_t next = 0; // index of the next sample time
    {
        // Read into temporaries: a file that fails half-way must leave the fresh start intact.
        decltype(eng.save_state()) state;
        std::vector<std::vector<std::uint64_t>> counts;
        Trace saved;
        long saved_next = 0;
        const bool resumed = checkpoint.load([&](const H5Object& root) {
            root.require_schema(kCoolingRunSchema, kCoolingRunSchemaVersion);
            saved_next = root.read_long_attr("next_sample");
            if (saved_next < 0 || std::size_t(saved_next) > times.size())
                throw std::runtime_error("next_sample out of range");
            read_engine(root.open_group("engine"), state);
            const H5Object h = root.open_group("impact_parameter");
            for (std::size_t w = 0; w < hist.windows(); ++w)
                counts.push_back(h.read_array<std::uint64_t>("window_" + std::to_string(w)));
            saved = read_trace(root.open_group("trace"));
            saved.wall_seconds = root.read_double_attr("wall_seconds");
        });
        if (resumed) {
            eng.restore_state(state);
            hist.set_counts(std::move(counts));
            tr = std::move(saved);
            next = std::size_t(saved_next);
        }
    }
    auto obs = [&hist](const CollisionRecord& c) { hist.add(c); };
    for (std::size_t i = next; i < times.size(); ++i) {
        const double t = times[i];
        eng.run_until(s.t0_abs + t, obs);
        report_engine_time(t, times.back());
        const auto k = kinetic(eng);
        const auto a2 = sonine_a2(eng.velocities());
        tr.t.push_back(t);
        tr.kx.push_back(k[0]);
        tr.ky.push_back(k[1]);
        tr.krot.push_back(k[2]);
        tr.cn.push_back(k[3]);
        tr.elastic_cn.push_back(k[4]);
        tr.a2.push_back(a2[0]);
        tr.a2_err.push_back(a2[1]);
        if (is_snapshot(p, t)) {
            const std::vector<Vec2> pos = eng.positions();
            PairCorrelation gr(s.L, s.L, 5 * d, 250);
            gr.accumulate(pos);
            StructureFactor sk(s.L, d);
            sk.accumulate(pos);
            const auto shell = sk.radial_average();
            tr.g.push_back(gr.g());
            tr.g_err.push_back(gr.g_error());
            tr.S.push_back(shell.S);
            if (tr.g_r.empty()) {
                for (double c : gr.centres()) tr.g_r.push_back(c / d);
                tr.S_k = shell.k;
            }
        }
        if (checkpoint.due())
            checkpoint.save([&](const H5Object& root) {
                root.stamp_schema(kCoolingRunSchema, kCoolingRunSchemaVersion);
                root.attr("next_sample", long(i + 1));
                root.attr("wall_seconds", tr.wall_seconds + seconds_since(start));
                write_engine(root.group("engine"), eng);
                const H5Object h = root.group("impact_parameter");
                for (std::size_t w = 0; w < hist.windows(); ++w)
                    h.array("window_" + std::to_string(w), hist.counts()[w]);
                write_trace(root.group("trace"), tr);
            });
    }
    tr.pbd_centres = hist.centres();
    for (std::size_t w = 0; w < hist.windows(); ++w) tr.pbd.push_back(hist.window(w));
}

// The random streams of seed index k: 2k for the initial state, 2k + 1 for DSMC (k = 0 keeps the
// streams of single-seed runs).
std::uint64_t setup_stream(long k) { return std::uint64_t(2 * k); }
std::uint64_t dsmc_stream(long k) { return std::uint64_t(2 * k + 1); }

Setup prepare(const RunContext& ctx, long seed_index) {
    const ParameterSet& p = ctx.params;
    Setup s;
    const long ns = p.integer("n_side");
    const std::size_t n = std::size_t(ns * ns);
    const double d = p.real("d");
    s.L = d * std::sqrt(double(n) * M_PI / 4 / p.real("rho"));
    s.rad.assign(n, 0.5 * d);
    s.mass.assign(n, p.real("mass"));
    RngStream rng(ctx.seed, setup_stream(seed_index));
    std::vector<Vec2> pos = square_lattice_positions(n, s.L, s.L);
    std::vector<Vec2> vel = p.text("initial_velocities") == "maxwellian" ? maxwellian_velocities(s.mass, p.real("vbar"), rng)
                                                                         : uniform_velocities(n, p.real("vbar"), rng);
    zero_momentum_and_scale(vel, s.mass, p.real("vbar"));
    EdConfig cfg;
    cfg.lx = cfg.ly = s.L;
    cfg.law.r = 1.0;
    EdEngine eng(cfg, pos, vel, s.rad, s.mass);
    // The first collisions after a lattice start are rarer than in equilibrium, so the
    // equilibrium collision rate is measured over the second half of the equilibration only
    // (the same total number of collisions, hence the same state at t = 0).
    const double eq = p.real("equilibration");
    equilibrate(eng, 0.5 * eq);
    const double t_half = eng.time();
    const auto c_half = eng.total_collisions();
    equilibrate(eng, 0.5 * eq);
    const double dt = eng.time() - t_half;
    s.omega_measured = dt > 0 ? 2.0 * double(eng.total_collisions() - c_half) / double(n) / dt : NAN;
    s.pos = eng.positions();
    s.vel = eng.velocities();
    // Elastic equilibration conserves energy; rescale anyway so that v̄ at t = 0 is exactly the
    // paper's (round-off only).
    zero_momentum_and_scale(s.vel, s.mass, p.real("vbar"));
    s.t0_abs = 0.0;
    return s;
}

// Checkpoint names: "ed" and "dsmc" for the first seed (as single-seed runs), "ed_<k>" after.
std::string run_name(const char* method, long seed_index) {
    return seed_index == 0 ? std::string(method) : std::string(method) + "_" + std::to_string(seed_index);
}

Trace run_ed(const RunContext& ctx, const Setup& s, long seed_index, Clock::time_point start) {
    const ParameterSet& p = ctx.params;
    EdConfig cfg;
    cfg.lx = cfg.ly = s.L;
    cfg.law.r = p.real("r");
    cfg.law.mu = p.real("mu");
    cfg.law.beta0 = p.real("mu") > 0 ? 0.0 : -1.0;
    cfg.t_c = p.real("t_c");
    EdEngine eng(cfg, s.pos, s.vel, s.rad, s.mass);
    Trace tr;
    RunCheckpoint checkpoint(ctx, run_name("ed", seed_index));
    const double n = double(s.pos.size());
    observe(p, s, eng, tr, checkpoint, start, [n](const EdEngine& e) {
        const EdKineticEnergy k = e.kinetic_energy();
        return std::array<double, 5>{k.kx, k.ky, k.krot, 2.0 * double(e.total_collisions()) / n,
                                     2.0 * double(e.elastic_collisions()) / n};
    });
    return tr;
}

DsmcConfig dsmc_config(const ParameterSet& p, double L) {
    DsmcConfig cfg;
    cfg.lx = cfg.ly = L;
    cfg.r = p.real("r");
    cfg.t_c = p.real("dsmc_t_c");
    cfg.min_cell_diameters = p.real("dsmc_cell_diameters");
    cfg.step_factor = p.real("dsmc_step_factor");
    const std::string fv = p.text("dsmc_free_volume");
    cfg.free_volume = fv == "cell" ? DsmcFreeVolume::cell : fv == "mean" ? DsmcFreeVolume::mean : DsmcFreeVolume::off;
    cfg.free_volume_block = std::uint32_t(p.integer("dsmc_free_volume_block"));
    cfg.displacement = p.flag("dsmc_displacement");
    cfg.partner = p.text("dsmc_partner") == "nearest" ? DsmcPartner::nearest : DsmcPartner::uniform;
    cfg.no_repeat_partner = p.flag("dsmc_no_repeat");
    cfg.mft_fraction = p.real("dsmc_mft_fraction");
    return cfg;
}

Trace run_dsmc(const RunContext& ctx, const Setup& s, long seed_index, Clock::time_point start) {
    const ParameterSet& p = ctx.params;
    DsmcConfig cfg = dsmc_config(p, s.L);
    cfg.seed = ctx.seed;
    cfg.stream = dsmc_stream(seed_index);
    DsmcEngine eng(cfg, s.pos, s.vel, s.rad, s.mass);
    Trace tr;
    RunCheckpoint checkpoint(ctx, run_name("dsmc", seed_index));
    const double n = double(s.pos.size());
    observe(p, s, eng, tr, checkpoint, start, [n](const DsmcEngine& e) {
        double kx = 0, ky = 0;
        for (std::size_t i = 0; i < e.size(); ++i) {
            kx += 0.5 * e.masses()[i] * e.velocities()[i].x * e.velocities()[i].x;
            ky += 0.5 * e.masses()[i] * e.velocities()[i].y * e.velocities()[i].y;
        }
        return std::array<double, 5>{kx, ky, 0.0, 2.0 * double(e.total_collisions()) / n,
                                     2.0 * double(e.elastic_collisions()) / n};
    });
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

// First time at which |y(t)| exceeds level, interpolated linearly in ln t between the samples
// around the crossing; NaN if it never does.
double first_exceeding(const std::vector<double>& t, const std::vector<double>& y, double level) {
    for (std::size_t i = 1; i < t.size(); ++i)
        if (std::abs(y[i]) > level && std::abs(y[i - 1]) <= level && t[i - 1] > 0) {
            const double f = (level - std::abs(y[i - 1])) / (std::abs(y[i]) - std::abs(y[i - 1]));
            return std::exp(std::log(t[i - 1]) + f * std::log(t[i] / t[i - 1]));
        }
    return NAN;
}

// Mean, maximum and minimum of a curve v(x) over lo <= x <= hi.
double mean_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    double s = 0;
    int n = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (x[i] >= lo && x[i] <= hi) {
            s += v[i];
            ++n;
        }
    return n ? s / n : NAN;
}
double max_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    double m = -INFINITY;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (x[i] >= lo && x[i] <= hi) m = std::max(m, v[i]);
    return m;
}
double min_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi) {
    double m = INFINITY;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (x[i] >= lo && x[i] <= hi) m = std::min(m, v[i]);
    return m;
}

// Mean over 1 <= k <= k_max of ln(S_a/S_b) (shells where both are positive).
double mean_log_ratio(const std::vector<double>& sa, const std::vector<double>& sb, const std::vector<double>& k, double k_max) {
    double sum = 0;
    int cnt = 0;
    for (std::size_t i = 0; i < k.size() && i < sa.size() && i < sb.size(); ++i)
        if (k[i] >= 1 && k[i] <= k_max && sa[i] > 0 && sb[i] > 0) {
            sum += std::log(sa[i] / sb[i]);
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

std::string time_label(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t%g", t);
    return buf;
}

// Early collision rate: C/N at the sample nearest t = 0.25 t0 over what Haff's law with the
// Enskog-Henderson rate omega promises there (the rate of the collision rule, before clustering).
double rate_over_enskog(const Trace& tr, double t0, double omega) {
    std::size_t best = 1;
    for (std::size_t i = 1; i < tr.t.size(); ++i)
        if (std::abs(std::log(tr.t[i] / (0.25 * t0))) < std::abs(std::log(tr.t[best] / (0.25 * t0)))) best = i;
    return tr.cn[best] / theory::haff_collisions_per_particle(tr.t[best], t0, omega);
}

// Eq. (18) fitted over t <= t0 (1/sqrt(K/K0) - 1 = t/t0, a line through 0): fitted 1/t0 in units
// of the kinetic-theory one.
double fit_t0(const Trace& tr, double t0) {
    const auto k = k_ratio(tr);
    std::vector<double> x, y;
    for (std::size_t i = 0; i < tr.t.size(); ++i)
        if (tr.t[i] > 0 && tr.t[i] <= t0) {
            x.push_back(tr.t[i]);
            y.push_back(1 / std::sqrt(k[i]) - 1);
        }
    double c1 = NAN, cov = 0, ss = 0;
    if (x.size() >= 2) gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
    return c1 * t0;
}

// HCS Sonine coefficient before clustering (van Noije & Ernst 1998): samples in the a2 window
// (units of t0), weighted mean over samples and seeds taken as independent measurements (samples
// ~1 collision per particle apart).
void hcs_a2(Result& res, const std::vector<Trace>& trs, const ParameterSet& p, const char* name) {
    const double t0 = kinetic_t0(p);
    const double a2_vne = theory::van_noije_ernst_a2(p.real("r"), 2);
    const auto& w = p.reals("a2_window");
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
void add_dsmc_kinetics(Result& res, const std::vector<Trace>& dss, const ParameterSet& p) {
    const double rho = p.real("rho"), t0 = kinetic_t0(p);
    const double omega = theory::enskog_collision_rate_vbar(rho, p.real("d"), p.real("vbar"), theory::henderson_contact_value(rho));
    const Trace& ds = dss.front();
    res.scalar("dsmc_rate_over_enskog_early", rate_over_enskog(ds, t0, omega), "1", "C/N at t = 0.25 t0 over Haff's law with the Enskog rate, DSMC");
    res.scalar("t0_fit_over_kinetic_dsmc", fit_t0(ds, t0), "1", "1/t0 fitted to the DSMC K(t) over t <= t0 (Eq. 18) over the kinetic-theory 1/t0");
    res.scalar("dsmc_over_eq18_2t0", ratio_at(ds, t0, 2 * t0), "1", "K/K_18 at t = 2 t0, DSMC");
    hcs_a2(res, dss, p, "dsmc");
}

// Per-seed S(k) at every snapshot and K/K0 of one method, for studies that compare runs made
// separately (scripts/studies/dsmc_variants.sh).
void add_seed_tables(Result& res, const std::vector<Trace>& trs, const std::vector<double>& snaps, const char* name) {
    for (std::size_t k = 0; k < trs.size(); ++k) {
        const Trace& tr = trs[k];
        {
            Table& t = res.table(std::string("sk_") + name + "_seed" + std::to_string(k), std::string("S(k) at the snapshot times, seed index ") + std::to_string(k) + ", " + name);
            t.add("k", "1").values = tr.S_k;
            for (std::size_t i = 0; i < tr.S.size(); ++i) t.add("S_" + time_label(snaps[i]), "1").values = tr.S[i];
        }
        Table& e = res.table(std::string("energy_") + name + "_seed" + std::to_string(k), std::string("K/K0 against t, seed index ") + std::to_string(k) + ", " + name);
        e.add("t", "s").values = tr.t;
        e.add("K_over_K0", "1").values = k_ratio(tr);
        e.add("C_over_N", "1").values = tr.cn;
    }
}

// run_ed = false: DSMC alone from the same initial states (for variant studies; the claims that
// compare with ED are then missing).
Result run_dsmc_only(const RunContext& ctx, const std::vector<Setup>& setups) {
    const ParameterSet& p = ctx.params;
    const long seeds = long(setups.size());
    std::vector<Trace> dss(setups.size());
    Progress progress("cooling", seeds, ctx.quiet);
    parallel_sweep(seeds, ctx.threads, &progress, [&](long k) {
        const auto start = Clock::now();
        dss[std::size_t(k)] = run_dsmc(ctx, setups[std::size_t(k)], k, start);
        dss[std::size_t(k)].wall_seconds += seconds_since(start);
    });
    Result res;
    double wall = 0;
    for (const Trace& tr : dss) wall += tr.wall_seconds;
    res.scalar("seeds", double(seeds), "1", "independent initial states");
    res.scalar("wall_time_dsmc", wall, "s", "wall time of the DSMC runs, summed over seeds");
    add_seed_tables(res, dss, snapshot_times(p), "dsmc");
    add_dsmc_kinetics(res, dss, p);
    return res;
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const long seeds = p.integer("seeds");
    const double r = p.real("r"), rho = p.real("rho"), d = p.real("d"), vbar = p.real("vbar");
    const double s_star = 1 / theory::henderson_contact_value(rho);
    const double t0_printed = std::sqrt(M_PI) * d * s_star / (2 * (1 - r * r) * rho * vbar);
    const double t0_kinetic = kinetic_t0(p);
    const double omega_enskog = theory::enskog_collision_rate_vbar(rho, d, vbar, theory::henderson_contact_value(rho));

    std::vector<Setup> setups;
    for (long k = 0; k < seeds; ++k) setups.push_back(prepare(ctx, k));
    const Setup& s = setups.front();
    const double t0_measured_rate = 4 / ((1 - r * r) * s.omega_measured);

    const bool dsmc = p.flag("run_dsmc");
    if (!p.flag("run_ed")) return run_dsmc_only(ctx, setups);
    const long methods = dsmc ? 2 : 1;
    std::vector<Trace> eds(static_cast<std::size_t>(seeds)), dss(static_cast<std::size_t>(seeds));
    Progress progress("cooling", methods * seeds, ctx.quiet);
    parallel_sweep(methods * seeds, ctx.threads, &progress, [&](long job) {
        const auto start = Clock::now();
        const long k = job / methods;
        const bool is_ed = job % methods == 0;
        Trace& tr = is_ed ? eds[std::size_t(k)] : dss[std::size_t(k)];
        tr = is_ed ? run_ed(ctx, setups[std::size_t(k)], k, start) : run_dsmc(ctx, setups[std::size_t(k)], k, start);
        tr.wall_seconds += seconds_since(start);
    });
    const Trace& ed = eds.front();
    const Trace& ds = dss.front();

    Result res;
    res.scalar("N", double(s.pos.size()), "1", "number of disks");
    res.scalar("seeds", double(seeds), "1", "independent initial states (equilibration, ED and DSMC each)");
    double wall_ed = 0, wall_ds = 0;
    for (long k = 0; k < seeds; ++k) {
        wall_ed += eds[std::size_t(k)].wall_seconds;
        if (dsmc) wall_ds += dss[std::size_t(k)].wall_seconds;
    }
    res.scalar("wall_time_ed", wall_ed, "s", "wall time of the ED runs from t = 0 with their observables, summed over seeds and resumed parts");
    if (dsmc)
        res.scalar("wall_time_dsmc", wall_ds, "s", "wall time of the DSMC runs from t = 0 with their observables, summed over seeds and resumed parts");
    res.scalar("box", s.L, "m", "side of the periodic box");
    res.scalar("t0_inv_eq19_printed", 1 / t0_printed, "1/s", "1/t0 from Eq. (19) as printed (sqrt(pi))");
    res.scalar("t0_inv_kinetic_theory", 1 / t0_kinetic, "1/s", "1/t0 = (1-r^2) omega_E / 4 with Henderson's g(d): sqrt(2 pi)");
    res.scalar("omega_equilibration_over_enskog", s.omega_measured / omega_enskog, "1",
               "elastic ED collision rate over the second half of the equilibration over the Enskog-Henderson rate");
    res.scalar("t0_inv_measured_rate", 1 / t0_measured_rate, "1/s", "1/t0 from the measured elastic collision rate");

    // The equilibrated state is Maxwellian (Sec. 3: "so that a Maxwellian velocity distribution
    // ... exists"): a2 pooled over the seeds, against 0 with its standard error.
    {
        std::vector<Vec2> all;
        for (const Setup& st : setups) all.insert(all.end(), st.vel.begin(), st.vel.end());
        const auto a2 = sonine_a2(all);
        std::vector<Vec2> start_vel;
        RngStream rng(ctx.seed, setup_stream(0));
        const auto v0 = p.text("initial_velocities") == "maxwellian" ? maxwellian_velocities(s.mass, vbar, rng)
                                                                     : uniform_velocities(s.mass.size(), vbar, rng);
        res.scalar("a2_initial_velocities", sonine_a2(v0)[0], "1", "a2 of the velocities drawn before the equilibration (uniform components: -0.3)");
        res.scalar("a2_equilibrated", a2[0], "1", "Sonine a2 of the velocities at t = 0 (after the elastic equilibration), all seeds");
        res.scalar("a2_equilibrated_err", a2[1], "1", "its standard error (sample variance of v^4)");
        res.scalar("a2_equilibrated_z", a2[0] / a2[1], "1", "a2 at t = 0 in standard errors (Maxwellian: |z| ~ 1)");
    }

    auto add_energy = [&](const Trace& tr, const char* name) {
        Table& t = res.table(std::string("energy_") + name, std::string("K/K0 and a2 against t/t0, ") + name);
        const auto k = k_ratio(tr);
        const double k0 = tr.kx.front() + tr.ky.front() + tr.krot.front();
        std::vector<double> tt0, e18, kx, ky, kr;
        for (std::size_t i = 0; i < tr.t.size(); ++i) {
            tt0.push_back(tr.t[i] / t0_kinetic);
            e18.push_back(eq18(tr.t[i], t0_kinetic));
            kx.push_back(tr.kx[i] / k0);
            ky.push_back(tr.ky[i] / k0);
            kr.push_back(tr.krot[i] / k0);
        }
        t.add("t", "s").values = tr.t;
        t.add("t_over_t0", "1").values = tt0;
        t.add("K_over_K0", "1").values = k;
        t.add("Kx_over_K0", "1").values = kx;
        t.add("Ky_over_K0", "1").values = ky;
        t.add("Krot_over_K0", "1").values = kr;
        t.add("eq18", "1").values = e18;
        t.add("C_over_N", "1").values = tr.cn;
        t.add("elastic_C_over_N", "1").values = tr.elastic_cn;
        t.add("a2", "1").values = tr.a2;
        t.add("a2_err", "1").values = tr.a2_err;
    };
    add_energy(ed, "ed");
    // Early cooling fitted to Eq. (18) over t <= t0: 1/sqrt(K/K0) - 1 = t/t0, a line through 0.
    {
        const auto k = k_ratio(ed);
        std::vector<double> x, y;
        for (std::size_t i = 0; i < ed.t.size(); ++i)
            if (ed.t[i] > 0 && ed.t[i] <= t0_kinetic) {
                x.push_back(ed.t[i]);
                y.push_back(1 / std::sqrt(k[i]) - 1);
            }
        double c1 = NAN, cov = 0, ss = 0;
        if (x.size() >= 2) gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
        res.scalar("t0_inv_fit_ed", c1, "1/s", "1/t0 fitted to the ED K(t) over t <= t0 (Eq. 18)");
        res.scalar("t0_fit_over_kinetic_ed", c1 * t0_kinetic, "1", "fitted over kinetic-theory 1/t0, ED");
    }
    res.scalar("ed_rate_over_enskog_early", rate_over_enskog(ed, t0_kinetic, omega_enskog), "1", "C/N at t = 0.25 t0 over Haff's law with the Enskog rate, ED");
    res.scalar("ed_eq18_max_dev_2t0", max_dev(ed, t0_kinetic, 2 * t0_kinetic), "1", "max |K/K_18 - 1| for t <= 2 t0, ED");
    res.scalar("ed_over_eq18_10t0", ratio_at(ed, t0_kinetic, 10 * t0_kinetic), "1", "K/K_18 at t = 10 t0, ED");
    res.scalar("ed_over_eq18_end", ratio_at(ed, t0_kinetic, ed.t.back()), "1", "K/K_18 at t_end, ED");
    res.scalar("ed_C_over_N_end", ed.cn.back(), "1", "collisions per particle at t_end, ED");
    res.scalar("ed_elastic_fraction_end", ed.elastic_cn.back() / ed.cn.back(), "1", "TC-elastic share of collisions, ED");

    // Departure from homogeneous cooling (Sec. 3.1: "at t/t0 ≈ 2 substantial deviations"): the
    // first t/t0 where the ED K(t) leaves Eq. (18) by more than departure_level, per seed.
    const double level = p.real("departure_level");
    {
        std::vector<double> dep;
        for (const Trace& tr : eds) {
            const auto k = k_ratio(tr);
            std::vector<double> x, y;
            for (std::size_t i = 0; i < tr.t.size(); ++i) {
                x.push_back(tr.t[i] / t0_kinetic);
                y.push_back(k[i] / eq18(tr.t[i], t0_kinetic) - 1);
            }
            dep.push_back(first_exceeding(x, y, level));
        }
        const auto ms = mean_sd(dep);
        res.scalar("ed_departure_t_over_t0", ms[0], "1", "first t/t0 with |K_ED/K_18 - 1| > departure_level, mean over seeds");
        res.scalar("ed_departure_t_over_t0_sd", ms[1], "1", "its seed standard deviation");
    }

    // HCS Sonine coefficient before clustering (van Noije & Ernst 1998): samples in the a2 window
    // (units of t0), pooled over seeds as independent measurements (samples ~1 collision per
    // particle apart).
    const double a2_vne = theory::van_noije_ernst_a2(r, 2);
    res.scalar("a2_van_noije_ernst", a2_vne, "1", "van Noije-Ernst a2 of the 2D HCS at this r (first Sonine approximation)");
    hcs_a2(res, eds, p, "ed");

    // P(b/d), Fig. 3.
    {
        Table& t = res.table("impact_parameter_ed", "P(b/d) of the ED run per time window (columns by window start)");
        t.add("b_over_d", "1").values = ed.pbd_centres;
        for (const auto& w : ed.pbd) {
            t.add("P_" + time_label(w.t_begin - s.t0_abs), "1").values = w.p;
            t.add("err_" + time_label(w.t_begin - s.t0_abs), "1").values = w.error;
        }
        // Grazing over central: mean P over b/d > 0.8 against b/d < 0.2, first and last window.
        auto ratio = [&](const ImpactParameterHistogram::Window& w) {
            return mean_over(w.p, ed.pbd_centres, 0.8, 1.0) / mean_over(w.p, ed.pbd_centres, 0.0, 0.2);
        };
        {
            Table& wt = res.table("impact_parameter_windows", "time windows of P(b/d): [t_begin, t_end)");
            std::vector<double> b, e;
            for (const auto& w : ed.pbd) {
                b.push_back(w.t_begin - s.t0_abs);
                e.push_back(w.t_end - s.t0_abs);
            }
            wt.add("t_begin", "s").values = b;
            wt.add("t_end", "s").values = e;
        }
        res.scalar("pbd_grazing_ratio_first", ratio(ed.pbd.front()), "1", "P(b/d>0.8)/P(b/d<0.2), first window, ED");
        res.scalar("pbd_grazing_ratio_last", ratio(ed.pbd.back()), "1", "P(b/d>0.8)/P(b/d<0.2), last window, ED");
        res.scalar("pbd_collisions_first", double(ed.pbd.front().total), "1", "collisions in the first window");
    }

    // g(r/d) and S(k), Figs. 6 and 7.
    const std::vector<double> snaps = snapshot_times(p);
    auto add_structure = [&](const Trace& tr, const char* name) {
        {
            Table& g = res.table(std::string("gr_") + name, std::string("g(r/d) at the snapshot times, ") + name);
            g.add("r_over_d", "1").values = tr.g_r;
            for (std::size_t i = 0; i < tr.g.size(); ++i) g.add("g_" + time_label(snaps[i]), "1").values = tr.g[i];
        }
        Table& sk = res.table(std::string("sk_") + name, std::string("S(k), k = l/lambda, at the snapshot times, ") + name);
        sk.add("k", "1").values = tr.S_k;
        for (std::size_t i = 0; i < tr.S.size(); ++i) sk.add("S_" + time_label(snaps[i]), "1").values = tr.S[i];
        sk.add("S_equilibrium", "1").values = std::vector<double>(tr.S_k.size(), theory::hard_disk_structure_factor_zero(rho));
    };
    add_structure(ed, "ed");
    add_seed_tables(res, eds, snaps, "ed");
    const auto& g_last = ed.g.back();
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
    // equilibration), chi^2 per bin over 0.98 <= r/d <= 5 with the counting errors of both.
    if (ed.g.size() >= 2) {
        auto chi2_per_bin = [&](double r_lo) {
            double chi2 = 0;
            int bins = 0;
            for (std::size_t b = 0; b < ed.g_r.size(); ++b)
                if (ed.g_r[b] >= r_lo) {
                    const double var = ed.g_err[0][b] * ed.g_err[0][b] + ed.g_err[1][b] * ed.g_err[1][b];
                    if (var > 0) {
                        chi2 += (ed.g[1][b] - ed.g[0][b]) * (ed.g[1][b] - ed.g[0][b]) / var;
                        ++bins;
                    }
                }
            return std::array<double, 2>{bins ? chi2 / bins : NAN, double(bins)};
        };
        const auto all = chi2_per_bin(0.98), beyond = chi2_per_bin(1.1);
        res.scalar("ed_g_early_vs_elastic_chi2", all[0], "1",
                   "chi^2 per bin of g(r/d) at the first snapshot after t = 0 against t = 0 (elastic), 0.98 <= r/d <= 5, ED");
        res.scalar("ed_g_early_vs_elastic_chi2_beyond_contact", beyond[0], "1", "the same over 1.1 <= r/d <= 5");
        res.scalar("ed_g_early_vs_elastic_bins_beyond_contact", beyond[1], "1", "bins in that range");
        res.scalar("ed_g_early_time_over_t0", snaps[1] / t0_kinetic, "1", "time of that snapshot in t0");
        res.scalar("ed_g_contact_early_over_elastic", max_over(ed.g[1], ed.g_r, 1.0, 1.04) / max_over(ed.g[0], ed.g_r, 1.0, 1.04), "1",
                   "contact value of g at the first snapshot after t = 0 over that at t = 0, ED");
    }
    // Growth of S(k) at small k, measured from equilibrium: against the elastic hard-disk S(0)
    // (Henderson's equation of state; what an equilibrated elastic gas has at k <= 25), not
    // against the t = 0 snapshot, whose long waves still carry the lattice start.
    const double k_small = p.real("sk_k_max");
    const double s_eq = theory::hard_disk_structure_factor_zero(rho);
    res.scalar("Sk_equilibrium_hard_disks", s_eq, "1", "S(k -> 0) of the elastic hard-disk gas at rho (Henderson's equation of state)");
    {
        std::vector<double> growth, lattice, change;
        for (const Trace& tr : eds) {
            growth.push_back(mean_over(tr.S.back(), tr.S_k, 1, k_small) / s_eq);
            lattice.push_back(mean_over(tr.S.front(), tr.S_k, 1, k_small) / s_eq);
            double s20 = NAN;
            for (std::size_t i = 0; i < snaps.size(); ++i)
                if (std::abs(snaps[i] - 20.0) < 1e-9) s20 = mean_over(tr.S[i], tr.S_k, 1, k_small);
            change.push_back(mean_over(tr.S.back(), tr.S_k, 1, k_small) / s20 - 1);
        }
        res.scalar("ed_Sk_growth_over_equilibrium", mean_sd(growth)[0], "1",
                   "mean S(1 <= k <= sk_k_max) at the last snapshot over the equilibrium S(0), ED, mean over seeds");
        res.scalar("ed_Sk_t0_over_equilibrium", mean_sd(lattice)[0], "1",
                   "the same at t = 0: below 1 where the long waves have not forgotten the lattice start");
        res.scalar("ed_Sk_small_k_growth", mean_over(ed.S.back(), ed.S_k, 1, k_small) / mean_over(ed.S.front(), ed.S_k, 1, k_small), "1",
                   "mean S(k <= sk_k_max) at the last snapshot over that at t = 0 (lattice leftover), ED, first seed");
        const auto ms = mean_sd(change);
        res.scalar("ed_Sk_change_after_20s", ms[0], "1", "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, ED, mean over seeds");
        res.scalar("ed_Sk_change_after_20s_sd", ms[1], "1", "its seed standard deviation");
        std::vector<double> lns;
        for (double g : growth) lns.push_back(std::log(g));
        res.scalar("ed_Sk_log_seed_sd", mean_sd(lns)[1], "1",
                   "seed standard deviation of ln(mean S_ED(k <= sk_k_max)) at the last snapshot: the run-to-run scatter of one run");
    }

    if (dsmc) {
        add_energy(ds, "dsmc");
        add_structure(ds, "dsmc");
        res.scalar("dsmc_eq18_max_dev_2t0", max_dev(ds, t0_kinetic, 2 * t0_kinetic), "1", "max |K/K_18 - 1| for t <= 2 t0, DSMC");
        add_dsmc_kinetics(res, dss, p);
        // ED against DSMC.
        const auto ke = k_ratio(ed), kd = k_ratio(ds);
        double early = 0, late_max = 0;
        for (std::size_t i = 0; i < ke.size() && i < kd.size(); ++i) {
            if (ed.t[i] <= 5 * t0_kinetic) early = std::max(early, std::abs(kd[i] / ke[i] - 1));
            if (ed.t[i] >= 30 * t0_kinetic) late_max = std::max(late_max, kd[i] / ke[i]);
        }
        res.scalar("dsmc_vs_ed_max_dev_5t0", early, "1", "max |K_DSMC/K_ED - 1| for t <= 5 t0");
        res.scalar("dsmc_over_ed_max_late", late_max > 0 ? late_max : NAN, "1", "largest K_DSMC/K_ED for t >= 30 t0");
        res.scalar("dsmc_over_ed_end", kd.back() / ke.back(), "1", "K_DSMC/K_ED at t_end");
        res.scalar("dsmc_over_ed_t0", ratio_at(ds, t0_kinetic, t0_kinetic) / ratio_at(ed, t0_kinetic, t0_kinetic), "1", "K_DSMC/K_ED at t = t0");
        res.scalar("dsmc_over_ed_5t0", ratio_at(ds, t0_kinetic, 5 * t0_kinetic) / ratio_at(ed, t0_kinetic, 5 * t0_kinetic), "1", "K_DSMC/K_ED at t = 5 t0");
        // Where ED and DSMC split (Sec. 3.1: "only at t/t0 ≈ 10 a difference"): first t/t0 with
        // |K_DSMC/K_ED - 1| > departure_level, per seed.
        {
            std::vector<double> split;
            for (long k = 0; k < seeds; ++k) {
                const Trace& a = eds[std::size_t(k)];
                const Trace& b = dss[std::size_t(k)];
                const auto ka = k_ratio(a), kb = k_ratio(b);
                std::vector<double> x, y;
                for (std::size_t i = 0; i < a.t.size() && i < b.t.size(); ++i) {
                    x.push_back(a.t[i] / t0_kinetic);
                    y.push_back(kb[i] / ka[i] - 1);
                }
                split.push_back(first_exceeding(x, y, level));
            }
            const auto ms = mean_sd(split);
            res.scalar("dsmc_ed_split_t_over_t0", ms[0], "1", "first t/t0 with |K_DSMC/K_ED - 1| > departure_level, mean over seeds");
            res.scalar("dsmc_ed_split_t_over_t0_sd", ms[1], "1", "its seed standard deviation");
        }
        res.scalar("dsmc_g_inside_contact_mean", mean_over(ds.g.back(), ds.g_r, 0.0, 0.9), "1",
                   "mean g(r/d < 0.9), last snapshot, DSMC (no exclusion hole: about 1)");
        res.scalar("dsmc_g_contact_peak", max_over(ds.g.back(), ds.g_r, 0.9, 1.1) / mean_over(ds.g.back(), ds.g_r, 2.5, 5.0), "1",
                   "g near contact over g at 2.5-5 d, last snapshot, DSMC");
        // Agreement of S(k) at small k. Per seed: m = mean over 1 <= k <= sk_k_max of
        // ln(S_DSMC/S_ED) at the last snapshot (and at 20 s); then mean and scatter over seeds.
        {
            std::vector<double> m_last, m_20, abs_last, d_change, imprint, imprint_ed;
            const DsmcConfig probe = dsmc_config(p, s.L);
            DsmcEngine sizing(probe, s.pos, s.vel, s.rad, s.mass);
            const double cells = double(sizing.cells_x());
            const double M = 2 * (ed.S_k.empty() ? 1 : ed.S_k.back());
            // NGP on an M grid aliases mode n to n - M round(n/M).
            const double kc = std::abs(cells - M * std::round(cells / M));
            for (long k = 0; k < seeds; ++k) {
                const Trace& a = eds[std::size_t(k)];
                const Trace& b = dss[std::size_t(k)];
                m_last.push_back(mean_log_ratio(b.S.back(), a.S.back(), a.S_k, k_small));
                double s20 = NAN;
                for (std::size_t i = 0; i < snaps.size(); ++i)
                    if (std::abs(snaps[i] - 20.0) < 1e-9) {
                        m_20.push_back(mean_log_ratio(b.S[i], a.S[i], a.S_k, k_small));
                        s20 = mean_over(b.S[i], b.S_k, 1, k_small);
                    }
                d_change.push_back(mean_over(b.S.back(), b.S_k, 1, k_small) / s20 - 1);
                double sabs = 0;
                int cnt = 0;
                for (std::size_t i = 0; i < a.S_k.size(); ++i)
                    if (a.S_k[i] >= 1 && a.S_k[i] <= k_small && a.S.back()[i] > 0 && b.S.back()[i] > 0) {
                        sabs += std::abs(std::log(a.S.back()[i] / b.S.back()[i]));
                        ++cnt;
                    }
                abs_last.push_back(cnt ? sabs / cnt : NAN);
                imprint.push_back(bump_contrast(b.S.back(), b.S_k, kc));
                imprint_ed.push_back(bump_contrast(a.S.back(), a.S_k, kc));
            }
            const auto ml = mean_sd(m_last);
            res.scalar("Sk_dsmc_over_ed_log", ml[0], "1",
                       "ln(S_DSMC/S_ED) averaged over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
            res.scalar("Sk_dsmc_over_ed_log_sd", ml[1], "1", "its seed standard deviation");
            res.scalar("Sk_dsmc_over_ed_factor", std::exp(ml[0]), "1", "exp of Sk_dsmc_over_ed_log: DSMC's S(k <= sk_k_max) in units of ED's");
            if (!m_20.empty()) {
                const auto m2 = mean_sd(m_20);
                res.scalar("Sk_dsmc_over_ed_log_20s", m2[0], "1", "the same at t = 20 s");
                res.scalar("Sk_dsmc_over_ed_log_20s_sd", m2[1], "1", "its seed standard deviation");
            }
            res.scalar("Sk_ed_dsmc_mean_abs_log_ratio", mean_sd(abs_last)[0], "1",
                       "mean |ln(S_ED/S_DSMC)| over 1 <= k <= sk_k_max at the last snapshot, mean over seeds");
            const auto dc = mean_sd(d_change);
            res.scalar("dsmc_Sk_change_after_20s", dc[0], "1",
                       "relative change of mean S(k <= sk_k_max) from t = 20 s to the last snapshot, DSMC, mean over seeds");
            res.scalar("dsmc_Sk_change_after_20s_sd", dc[1], "1", "its seed standard deviation");
            res.scalar("dsmc_cells_per_side", cells, "1", "DSMC cells per box side");
            res.scalar("dsmc_cell_shell", kc, "1", "the S(k) shell of the cell lattice (box/cell, aliased into 1..M/2)");
            res.scalar("dsmc_Sk_cell_imprint", mean_sd(imprint)[0], "1",
                       "S at the cell shell over the geometric mean of the flanks at 0.75 and 1.25 of it, last snapshot, DSMC, mean over seeds");
            res.scalar("ed_Sk_cell_imprint_control", mean_sd(imprint_ed)[0], "1", "the same measure on ED's S(k) (no cells)");
            res.scalar("dsmc_Sk_cell_imprint_over_ed", mean_sd(imprint)[0] / mean_sd(imprint_ed)[0], "1",
                       "DSMC's contrast at the cell shell over ED's there (1: no imprint)");
            {
                Table& t = res.table("sk_seeds", "per seed: mean S(1 <= k <= sk_k_max) of ED and DSMC at 20 s and at the last snapshot, and the mean ln ratio");
                std::vector<double> idx, e20, elast, d20, dlast;
                for (long k = 0; k < seeds; ++k) {
                    const Trace& a = eds[std::size_t(k)];
                    const Trace& b = dss[std::size_t(k)];
                    idx.push_back(double(k));
                    double ae = NAN, be = NAN;
                    for (std::size_t i = 0; i < snaps.size(); ++i)
                        if (std::abs(snaps[i] - 20.0) < 1e-9) {
                            ae = mean_over(a.S[i], a.S_k, 1, k_small);
                            be = mean_over(b.S[i], b.S_k, 1, k_small);
                        }
                    e20.push_back(ae);
                    d20.push_back(be);
                    elast.push_back(mean_over(a.S.back(), a.S_k, 1, k_small));
                    dlast.push_back(mean_over(b.S.back(), b.S_k, 1, k_small));
                }
                t.add("seed_index", "1").values = idx;
                t.add("S_ed_20s", "1").values = e20;
                t.add("S_ed_last", "1").values = elast;
                t.add("S_dsmc_20s", "1").values = d20;
                t.add("S_dsmc_last", "1").values = dlast;
                t.add("mean_ln_ratio_last", "1").values = m_last;
            }
        }
        res.scalar("dsmc_Sk_small_k_growth", mean_over(ds.S.back(), ds.S_k, 1, k_small) / mean_over(ds.S.front(), ds.S_k, 1, k_small), "1",
                   "mean S(k <= sk_k_max) at the last snapshot over that at t = 0, DSMC, first seed");
        res.scalar("dsmc_Sk_growth_over_equilibrium", mean_over(ds.S.back(), ds.S_k, 1, k_small) / s_eq, "1",
                   "mean S(k <= sk_k_max) at the last snapshot over the hard-disk equilibrium S(0), DSMC, first seed");
        res.scalar("dsmc_C_over_N_end", ds.cn.back(), "1", "collisions per particle at t_end, DSMC");
        add_seed_tables(res, dss, snaps, "dsmc");
        const auto& pw = ds.pbd.back();
        res.scalar("dsmc_pbd_grazing_ratio_last", mean_over(pw.p, ds.pbd_centres, 0.8, 1.0) / mean_over(pw.p, ds.pbd_centres, 0.0, 0.2), "1",
                   "P(b/d>0.8)/P(b/d<0.2), last window, DSMC (molecular chaos: 1)");
    }
    return res;
}

} // namespace

Experiment cooling() { return {"cooling", &validate, &run}; }

} // namespace granrepro::experiments
