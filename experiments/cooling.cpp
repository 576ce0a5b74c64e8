// cooling: Luding (1998) Section 3. N disks at rho = 0.25 are equilibrated elastically by ED
// (Sec. 3: about 10 collisions per particle); at t = 0 dissipation r = 0.8 is switched on and the
// same state is evolved by ED and by DSMC. Measured: K(t) against Eq. (18) (Fig. 2), P(b/d) in
// time windows (Fig. 3), g(r/d) (Fig. 6) and S(k) (Fig. 7) at snapshot times.
//
// t0 of Eq. (18): Eq. (19) as printed has sqrt(pi); the Enskog collision rate of hard disks,
// omega_0 = 2 n d g(d) sqrt(pi T/m) with T = m v̄^2/2 and Henderson's g(d) = 1/s_*(rho), and the
// 2D cooling law dT/dt = -(1 - r^2) omega T / 2 give t0 = 4 / ((1 - r^2) omega_0)
// = sqrt(2 pi) d s_* / (2 (1 - r^2) rho v̄), i.e. sqrt(2 pi). The paper's number 23.24 1/s is
// the sqrt(2 pi) value; Fig. 2 is normalised by it.
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
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/dsmc_state_file.hpp"
#include "io/ed_state_file.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "observables/log_time_sampler.hpp"
#include "observables/pair_correlation.hpp"
#include "observables/structure_factor.hpp"

namespace granrepro::experiments {

namespace {

void validate(const ParameterSet& p) {
    const auto& w = p.reals("bd_windows");
    for (std::size_t i = 1; i < w.size(); ++i)
        if (!(w[i] > w[i - 1])) p.reject("bd_windows", "edges must increase");
    if (w.size() < 2) p.reject("bd_windows", "needs at least two edges");
    const double L = p.real("d") * std::sqrt(double(p.integer("n_side") * p.integer("n_side")) * M_PI / 4 / p.real("rho"));
    if (L / double(p.integer("n_side")) < p.real("d") * 1.0000001)
        p.reject("rho", "too dense for a square-lattice start (lattice spacing below d)");
}

// What one method (ED or DSMC) produced.
struct Trace {
    std::vector<double> t, kx, ky, krot, cn, elastic_cn;
    std::vector<std::vector<double>> g, S; // per snapshot
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

// Sample times: log-spaced K(t) samples and the snapshot times, merged.
std::vector<double> sample_times(const ParameterSet& p) {
    const double t_end = p.real("t_end");
    LogTimeSampler log(t_end * 1e-4, t_end, int(p.integer("samples_per_decade")));
    std::vector<double> t = log.times();
    t.push_back(0.0);
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

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Mid-run checkpoint of one method: the engine state, the histogram counts and the trace up to a
// sample time. prepare() is deterministic, so a resumed run redoes the equilibration instead of
// storing the t = 0 state. P(b/d) enters the trace only at the end, so it lives in the counts.
constexpr const char* kCoolingRunSchema = "granrepro-cooling-run";
constexpr long kCoolingRunSchemaVersion = 1;

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
    g.array("g_r", tr.g_r);
    g.array("S_k", tr.S_k);
    g.attr("snapshots", long(tr.g.size()));
    for (std::size_t i = 0; i < tr.g.size(); ++i) {
        g.array("g_" + std::to_string(i), tr.g[i]);
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
    tr.g_r = g.read_array<double>("g_r");
    tr.S_k = g.read_array<double>("S_k");
    const long snapshots = g.read_long_attr("snapshots");
    for (long i = 0; i < snapshots; ++i) {
        tr.g.push_back(g.read_array<double>("g_" + std::to_string(i)));
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
        const auto k = kinetic(eng);
        tr.t.push_back(t);
        tr.kx.push_back(k[0]);
        tr.ky.push_back(k[1]);
        tr.krot.push_back(k[2]);
        tr.cn.push_back(k[3]);
        tr.elastic_cn.push_back(k[4]);
        if (is_snapshot(p, t)) {
            const std::vector<Vec2> pos = eng.positions();
            PairCorrelation gr(s.L, s.L, 5 * d, 250);
            gr.accumulate(pos);
            StructureFactor sk(s.L, d);
            sk.accumulate(pos);
            const auto shell = sk.radial_average();
            tr.g.push_back(gr.g());
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

Setup prepare(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    Setup s;
    const long ns = p.integer("n_side");
    const std::size_t n = std::size_t(ns * ns);
    const double d = p.real("d");
    s.L = d * std::sqrt(double(n) * M_PI / 4 / p.real("rho"));
    s.rad.assign(n, 0.5 * d);
    s.mass.assign(n, p.real("mass"));
    RngStream rng(ctx.seed, 0);
    std::vector<Vec2> pos = square_lattice_positions(n, s.L, s.L);
    std::vector<Vec2> vel = maxwellian_velocities(s.mass, p.real("vbar"), rng);
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

Trace run_ed(const RunContext& ctx, const Setup& s, Clock::time_point start) {
    const ParameterSet& p = ctx.params;
    EdConfig cfg;
    cfg.lx = cfg.ly = s.L;
    cfg.law.r = p.real("r");
    cfg.law.mu = p.real("mu");
    cfg.law.beta0 = p.real("mu") > 0 ? 0.0 : -1.0;
    cfg.t_c = p.real("t_c");
    EdEngine eng(cfg, s.pos, s.vel, s.rad, s.mass);
    Trace tr;
    RunCheckpoint checkpoint(ctx, "ed");
    const double n = double(s.pos.size());
    observe(p, s, eng, tr, checkpoint, start, [n](const EdEngine& e) {
        const EdKineticEnergy k = e.kinetic_energy();
        return std::array<double, 5>{k.kx, k.ky, k.krot, 2.0 * double(e.total_collisions()) / n,
                                     2.0 * double(e.elastic_collisions()) / n};
    });
    return tr;
}

Trace run_dsmc(const RunContext& ctx, const Setup& s, Clock::time_point start) {
    const ParameterSet& p = ctx.params;
    DsmcConfig cfg;
    cfg.lx = cfg.ly = s.L;
    cfg.r = p.real("r");
    cfg.t_c = p.real("dsmc_t_c");
    cfg.min_cell_diameters = p.real("dsmc_cell_diameters");
    cfg.step_factor = p.real("dsmc_step_factor");
    const std::string fv = p.text("dsmc_free_volume");
    cfg.free_volume = fv == "cell" ? DsmcFreeVolume::cell : fv == "mean" ? DsmcFreeVolume::mean : DsmcFreeVolume::off;
    cfg.displacement = p.flag("dsmc_displacement");
    cfg.seed = ctx.seed;
    cfg.stream = 1;
    DsmcEngine eng(cfg, s.pos, s.vel, s.rad, s.mass);
    Trace tr;
    RunCheckpoint checkpoint(ctx, "dsmc");
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

double eq18(double t, double t0) { return 1.0 / ((1 + t / t0) * (1 + t / t0)); }

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

std::string time_label(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t%g", t);
    return buf;
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const Setup s = prepare(ctx);
    const double r = p.real("r"), rho = p.real("rho"), d = p.real("d"), vbar = p.real("vbar");
    const double s_star = (1 - rho) * (1 - rho) / (1 - 7 * rho / 16);
    const double t0_printed = std::sqrt(M_PI) * d * s_star / (2 * (1 - r * r) * rho * vbar);
    const double t0_kinetic = std::sqrt(2 * M_PI) * d * s_star / (2 * (1 - r * r) * rho * vbar);
    const double omega_enskog = 8 * rho * vbar / (s_star * d * std::sqrt(2 * M_PI));
    const double t0_measured_rate = 4 / ((1 - r * r) * s.omega_measured);

    const bool dsmc = p.flag("run_dsmc");
    Trace ed, ds;
    Progress progress("cooling", dsmc ? 2 : 1, ctx.quiet);
    parallel_sweep(dsmc ? 2 : 1, ctx.threads, &progress, [&](long which) {
        const auto start = Clock::now();
        Trace& tr = which == 0 ? ed : ds;
        tr = which == 0 ? run_ed(ctx, s, start) : run_dsmc(ctx, s, start);
        tr.wall_seconds += seconds_since(start);
    });

    Result res;
    res.scalar("N", double(s.pos.size()), "1", "number of disks");
    res.scalar(
        "wall_time_ed", ed.wall_seconds, "s",
        "wall time of the ED run from t = 0 with its observables, summed over resumed parts");
    if (dsmc)
        res.scalar(
            "wall_time_dsmc", ds.wall_seconds, "s",
            "wall time of the DSMC run from t = 0 with its observables, summed over resumed parts");
    res.scalar("box", s.L, "m", "side of the periodic box");
    res.scalar("t0_inv_eq19_printed", 1 / t0_printed, "1/s", "1/t0 from Eq. (19) as printed (sqrt(pi))");
    res.scalar("t0_inv_kinetic_theory", 1 / t0_kinetic, "1/s", "1/t0 = (1-r^2) omega_E / 4 with Henderson's g(d): sqrt(2 pi)");
    res.scalar("omega_equilibration_over_enskog", s.omega_measured / omega_enskog, "1",
               "elastic ED collision rate over the second half of the equilibration over the Enskog-Henderson rate");
    res.scalar("t0_inv_measured_rate", 1 / t0_measured_rate, "1/s", "1/t0 from the measured elastic collision rate");

    auto add_energy = [&](const Trace& tr, const char* name) {
        Table& t = res.table(std::string("energy_") + name, std::string("K/K0 against t/t0, ") + name);
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
    res.scalar("ed_eq18_max_dev_2t0", max_dev(ed, t0_kinetic, 2 * t0_kinetic), "1", "max |K/K_18 - 1| for t <= 2 t0, ED");
    res.scalar("ed_over_eq18_10t0", ratio_at(ed, t0_kinetic, 10 * t0_kinetic), "1", "K/K_18 at t = 10 t0, ED");
    res.scalar("ed_over_eq18_end", ratio_at(ed, t0_kinetic, ed.t.back()), "1", "K/K_18 at t_end, ED");
    res.scalar("ed_C_over_N_end", ed.cn.back(), "1", "collisions per particle at t_end, ED");
    res.scalar("ed_elastic_fraction_end", ed.elastic_cn.back() / ed.cn.back(), "1", "TC-elastic share of collisions, ED");

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
        res.scalar("pbd_grazing_ratio_first", ratio(ed.pbd.front()), "1", "P(b/d>0.8)/P(b/d<0.2), first window, ED");
        res.scalar("pbd_grazing_ratio_last", ratio(ed.pbd.back()), "1", "P(b/d>0.8)/P(b/d<0.2), last window, ED");
        res.scalar("pbd_collisions_first", double(ed.pbd.front().total), "1", "collisions in the first window");
    }

    // g(r/d) and S(k), Figs. 6 and 7.
    std::vector<double> snaps;
    for (double t : p.reals("snapshot_times"))
        if (t <= p.real("t_end")) snaps.push_back(t);
    auto add_structure = [&](const Trace& tr, const char* name) {
        Table& g = res.table(std::string("gr_") + name, std::string("g(r/d) at the snapshot times, ") + name);
        g.add("r_over_d", "1").values = tr.g_r;
        for (std::size_t i = 0; i < tr.g.size(); ++i) g.add("g_" + time_label(snaps[i]), "1").values = tr.g[i];
        Table& sk = res.table(std::string("sk_") + name, std::string("S(k), k = l/lambda, at the snapshot times, ") + name);
        sk.add("k", "1").values = tr.S_k;
        for (std::size_t i = 0; i < tr.S.size(); ++i) sk.add("S_" + time_label(snaps[i]), "1").values = tr.S[i];
    };
    add_structure(ed, "ed");
    const auto& g_last = ed.g.back();
    res.scalar("ed_g_inside_contact_max", max_over(g_last, ed.g_r, 0.0, 0.98), "1", "largest g(r/d) for r/d < 0.98, last snapshot, ED");
    res.scalar("ed_g_peak_sqrt3_contrast", max_over(g_last, ed.g_r, 1.68, 1.78) / min_over(g_last, ed.g_r, 1.4, 1.6), "1",
               "max g near sqrt(3) over min g in [1.4, 1.6], last snapshot, ED");
    res.scalar("ed_g_peak_2_contrast", max_over(g_last, ed.g_r, 1.95, 2.05) / min_over(g_last, ed.g_r, 1.8, 1.9), "1",
               "max g near 2 over min g in [1.8, 1.9], last snapshot, ED");
    res.scalar("ed_g_contact", max_over(g_last, ed.g_r, 1.0, 1.04), "1", "g at contact, last snapshot, ED");
    const double s_growth = mean_over(ed.S.back(), ed.S_k, 1, 25) / mean_over(ed.S.front(), ed.S_k, 1, 25);
    res.scalar("ed_Sk_small_k_growth", s_growth, "1", "mean S(k <= 25) at the last snapshot over that at t = 0, ED");
    // Stationarity: relative change of mean S(k <= 25) between the snapshot at 20 s and the last one.
    double s20 = NAN;
    for (std::size_t i = 0; i < snaps.size(); ++i)
        if (std::abs(snaps[i] - 20.0) < 1e-9) s20 = mean_over(ed.S[i], ed.S_k, 1, 25);
    res.scalar("ed_Sk_change_after_20s", mean_over(ed.S.back(), ed.S_k, 1, 25) / s20 - 1, "1",
               "relative change of mean S(k <= 25) from t = 20 s to the last snapshot, ED");

    if (dsmc) {
        add_energy(ds, "dsmc");
        add_structure(ds, "dsmc");
        res.scalar("dsmc_eq18_max_dev_2t0", max_dev(ds, t0_kinetic, 2 * t0_kinetic), "1", "max |K/K_18 - 1| for t <= 2 t0, DSMC");
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
        res.scalar("dsmc_g_inside_contact_mean", mean_over(ds.g.back(), ds.g_r, 0.0, 0.9), "1",
                   "mean g(r/d < 0.9), last snapshot, DSMC (no exclusion hole: about 1)");
        res.scalar("dsmc_g_contact_peak", max_over(ds.g.back(), ds.g_r, 0.9, 1.1) / mean_over(ds.g.back(), ds.g_r, 2.5, 5.0), "1",
                   "g near contact over g at 2.5-5 d, last snapshot, DSMC");
        // Agreement of S(k) at small k: mean |ln(S_ED/S_DSMC)| over 1 <= k <= 25, last snapshot.
        double sum = 0;
        int cnt = 0;
        for (std::size_t i = 0; i < ed.S_k.size() && i < ds.S_k.size(); ++i)
            if (ed.S_k[i] >= 1 && ed.S_k[i] <= 25 && ed.S.back()[i] > 0 && ds.S.back()[i] > 0) {
                sum += std::abs(std::log(ed.S.back()[i] / ds.S.back()[i]));
                ++cnt;
            }
        res.scalar("Sk_ed_dsmc_mean_abs_log_ratio", cnt ? sum / cnt : NAN, "1",
                   "mean |ln(S_ED/S_DSMC)| over 1 <= k <= 25 at the last snapshot");
        res.scalar("dsmc_Sk_small_k_growth", mean_over(ds.S.back(), ds.S_k, 1, 25) / mean_over(ds.S.front(), ds.S_k, 1, 25), "1",
                   "mean S(k <= 25) at the last snapshot over that at t = 0, DSMC");
        const auto& pw = ds.pbd.back();
        res.scalar("dsmc_pbd_grazing_ratio_last", mean_over(pw.p, ds.pbd_centres, 0.8, 1.0) / mean_over(pw.p, ds.pbd_centres, 0.0, 0.2), "1",
                   "P(b/d>0.8)/P(b/d<0.2), last window, DSMC (molecular chaos: 1)");
    }
    return res;
}

} // namespace

Experiment cooling() { return {"cooling", &validate, &run}; }

} // namespace granrepro::experiments
