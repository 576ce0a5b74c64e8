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
// Why t = t_base 2^k: the paper's instants 0.04, 0.64 and 10.24 s are 0.01 s times powers of two,
// and with Δt = t/2 the window of one instant starts exactly at the previous instant, so storing
// the per-particle counts at every instant gives N_c = (count(t) - count(t/2)) / (t/2) with no
// per-collision bookkeeping (1e8 collisions at paper scale).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "harness/experiment.hpp"
#include "harness/progress.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/ed_state_file.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/rate_histogram.hpp"

namespace granrepro::experiments {

namespace {

void validate(const ParameterSet& p) {
    const long ns = p.integer("n_side");
    if (p.real("box_over_d") / double(ns) < 1.0000001)
        p.reject("box_over_d", "too small for a square-lattice start (lattice spacing below d)");
    if (p.real("box_over_d") < 3.0) p.reject("box_over_d", "must be at least 3 (three cells for the minimum image)");
    if (p.real("t_max") <= p.real("t_base")) p.reject("t_max", "must exceed t_base");
    if (p.reals("paper_cn").empty()) p.reject("paper_cn", "needs at least one value");
}

// One instant t = t_base 2^k and what was measured there.
struct Instant {
    double t = 0, window = 0, cn = 0, elastic_cn = 0;
    std::vector<double> rate;     // N_c per particle over (t/2, t] [1/s]
    std::vector<Vec2> pos;        // positions at t [m]
    RateHistogram hist;
    CollisionRateFit poisson, expo, power;
    CollisionRateFit poisson_full; // Eq. (20) for the counts over (0, t]
    double mean_rate = 0, tail_fraction = 0;
};

RateHistogram histogram(const std::vector<double>& rate, double window, const ParameterSet& p) {
    const double mean = gsl_stats_mean(rate.data(), 1, rate.size());
    if (mean * window <= 30) {
        const double mx = *std::max_element(rate.begin(), rate.end());
        return RateHistogram::per_count(rate, window, int(std::ceil(mx * window)));
    }
    std::vector<double> sorted = rate;
    std::sort(sorted.begin(), sorted.end());
    const double hi = gsl_stats_quantile_from_sorted_data(sorted.data(), 1, sorted.size(), p.real("hist_quantile"));
    return RateHistogram::make(rate, window, RateHistogram::Binning::Linear, int(p.integer("hist_bins")), 0.0,
                               std::max(hi, 2.0 / window));
}

CollisionRateFit fit(const RateHistogram& h, CollisionRateFit::Model m) {
    try {
        return CollisionRateFit::fit(h, m, -INFINITY, INFINITY);
    } catch (const std::exception&) {
        CollisionRateFit f;
        f.model = m;
        f.value = f.error = f.chi2_reduced = NAN;
        return f;
    }
}

std::string label(const char* prefix, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%g", prefix, v);
    return buf;
}

// The per-particle rates and counts of an instant fix everything else in it; the checkpoint
// stores only those (and the positions), and a resumed run recomputes the rest identically.
Instant make_instant(double t, double cn, double elastic_cn, std::vector<double> rate,
                     const std::vector<std::uint64_t>& counts, std::vector<Vec2> pos, const ParameterSet& p) {
    const std::size_t n = rate.size();
    Instant in;
    in.t = t;
    in.window = t / 2;
    in.cn = cn;
    in.elastic_cn = elastic_cn;
    in.rate = std::move(rate);
    std::size_t tail = 0;
    for (double r : in.rate)
        if (r > p.real("tail_rate")) ++tail;
    in.mean_rate = gsl_stats_mean(in.rate.data(), 1, n);
    in.tail_fraction = double(tail) / double(n);
    in.hist = histogram(in.rate, in.window, p);
    in.poisson = fit(in.hist, CollisionRateFit::Model::Poisson);
    in.expo = fit(in.hist, CollisionRateFit::Model::Exponential);
    in.power = fit(in.hist, CollisionRateFit::Model::PowerLaw);
    // The same Poisson fit with the counts since t = 0 (window t instead of t/2): the paper's
    // chi = 6.5 at C/N = 8 is compared with both readings.
    std::vector<double> full(n);
    for (std::size_t i = 0; i < n; ++i) full[i] = double(counts[i]) / t;
    in.poisson_full = fit(histogram(full, t, p), CollisionRateFit::Model::Poisson);
    in.pos = std::move(pos);
    return in;
}

// Everything the sampling loop carries from one sample to the next, besides the engine.
struct LoopState {
    int next_j = 0;                 // index of the next sample time t_base 2^(j/m)
    double omega_eq = 0;            // elastic collision rate of the equilibration [1/s]
    double wall_before = 0;         // wall seconds of earlier, interrupted parts [s]
    std::vector<double> ts, ks, kxs, kys, cns, ecns;
    std::vector<Instant> instants;
    std::vector<std::vector<std::uint64_t>> instant_counts; // counts at each instant (for resume)
    std::vector<std::uint64_t> prev_counts;                 // at the previous instant t/2
};

constexpr const char* kRunSchema = "granrepro-cluster-growth-run";
constexpr long kRunSchemaVersion = 1;

void save_loop(const H5Object& root, const LoopState& s, const EdEngine& eng, double wall_now) {
    root.stamp_schema(kRunSchema, kRunSchemaVersion);
    write_ed_state(root.group("engine"), eng.save_state());
    const H5Object g = root.group("loop");
    g.attr("next_j", long(s.next_j));
    g.attr("omega_eq", s.omega_eq);
    g.attr("wall_seconds", wall_now);
    g.array("t", s.ts);
    g.array("K", s.ks);
    g.array("Kx", s.kxs);
    g.array("Ky", s.kys);
    g.array("C_over_N", s.cns);
    g.array("elastic_C_over_N", s.ecns);
    g.array("prev_counts", s.prev_counts);
    g.attr("instants", long(s.instants.size()));
    for (std::size_t k = 0; k < s.instants.size(); ++k) {
        const Instant& in = s.instants[k];
        const H5Object h = g.group("instant" + std::to_string(k));
        h.attr("t", in.t);
        h.attr("cn", in.cn);
        h.attr("elastic_cn", in.elastic_cn);
        h.array("rate", in.rate);
        h.array("counts", s.instant_counts[k]);
        h.vec2_array("position", in.pos);
    }
}

LoopState load_loop(const H5Object& root, const ParameterSet& p, EdState& engine) {
    root.require_schema(kRunSchema, kRunSchemaVersion);
    engine = read_ed_state(root.open_group("engine"));
    const H5Object g = root.open_group("loop");
    LoopState s;
    s.next_j = int(g.read_long_attr("next_j"));
    s.omega_eq = g.read_double_attr("omega_eq");
    s.wall_before = g.read_double_attr("wall_seconds");
    s.ts = g.read_array<double>("t");
    s.ks = g.read_array<double>("K");
    s.kxs = g.read_array<double>("Kx");
    s.kys = g.read_array<double>("Ky");
    s.cns = g.read_array<double>("C_over_N");
    s.ecns = g.read_array<double>("elastic_C_over_N");
    s.prev_counts = g.read_array<std::uint64_t>("prev_counts");
    const long count = g.read_long_attr("instants");
    for (long k = 0; k < count; ++k) {
        const H5Object h = g.open_group("instant" + std::to_string(k));
        std::vector<Vec2> pos = h.read_vec2_array("position");
        s.instant_counts.push_back(h.read_array<std::uint64_t>("counts"));
        s.instants.push_back(make_instant(h.read_double_attr("t"), h.read_double_attr("cn"),
                                          h.read_double_attr("elastic_cn"), h.read_array<double>("rate"),
                                          s.instant_counts.back(), std::move(pos), p));
    }
    return s;
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

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const long ns = p.integer("n_side");
    const std::size_t n = std::size_t(ns * ns);
    const double d = p.real("d"), L = p.real("box_over_d") * d, r = p.real("r");
    const std::vector<double> rad(n, 0.5 * d), mass(n, p.real("mass"));
    const int m = int(p.integer("samples_per_octave"));
    const double t_base = p.real("t_base"), cn_end = p.real("cn_end"), t_max = p.real("t_max");

    // A resumed run continues from its last checkpoint; a fresh one equilibrates first.
    RunCheckpoint checkpoint(ctx, "ed");
    LoopState st;
    EdState saved;
    const bool resumed = checkpoint.load([&](const H5Object& root) { st = load_loop(root, p, saved); });
    EdEngine eng = resumed ? EdEngine(saved) : [&] {
        RngStream rng(ctx.seed, 0);
        const EquilibratedGas gas = equilibrated_lattice_gas(L, rad, mass, p.real("vbar"), p.real("equilibration"), rng);
        st.omega_eq = gas.collision_rate;
        EdConfig cfg;
        cfg.lx = cfg.ly = L;
        cfg.law.r = r;
        cfg.law.mu = p.real("mu");
        cfg.law.beta0 = p.real("mu") > 0 ? 0.0 : -1.0;
        cfg.t_c = p.real("t_c");
        EdEngine fresh(cfg, gas.pos, gas.vel, rad, mass);
        const EdKineticEnergy k0 = fresh.kinetic_energy();
        st.next_j = -3 * m;
        st.ts = {0.0};
        st.ks = {k0.total()};
        st.kxs = {k0.kx};
        st.kys = {k0.ky};
        st.cns = {0.0};
        st.ecns = {0.0};
        return fresh;
    }();
    const double omega_eq = st.omega_eq;

    // ---- the run ------------------------------------------------------------------------------
    std::string error;
    struct Silent {
        void operator()(const CollisionRecord&) const {}
    } silent;
    Progress progress("cluster-growth", long(std::ceil(std::log2(t_max / t_base))) + 4, ctx.quiet);
    for (int j = -3 * m; j < st.next_j; ++j)
        if (j % m == 0) progress.tick();
    const auto wall0 = std::chrono::steady_clock::now();
    auto wall_now = [&] {
        return st.wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    };
    for (int j = st.next_j;; ++j) {
        const double t = t_base * std::exp2(double(j) / m);
        try {
            eng.run_until(t, silent);
        } catch (const std::runtime_error& e) {
            error = e.what(); // the collapse guard; keep what was measured
            std::fprintf(stderr, "cluster-growth: %s\n", error.c_str());
            break;
        }
        const EdKineticEnergy k = eng.kinetic_energy();
        const double cn = 2.0 * double(eng.total_collisions()) / double(n);
        st.ts.push_back(t);
        st.ks.push_back(k.total());
        st.kxs.push_back(k.kx);
        st.kys.push_back(k.ky);
        st.cns.push_back(cn);
        st.ecns.push_back(2.0 * double(eng.elastic_collisions()) / double(n));
        st.next_j = j + 1;
        if (j % m == 0) {
            progress.tick();
            std::vector<std::uint64_t> counts = eng.collision_counts();
            if (!st.prev_counts.empty()) {
                std::vector<double> rate(n);
                for (std::size_t i = 0; i < n; ++i) rate[i] = double(counts[i] - st.prev_counts[i]) / (t / 2);
                st.instants.push_back(make_instant(t, cn, st.ecns.back(), std::move(rate), counts, eng.positions(), p));
                st.instant_counts.push_back(counts);
            }
            st.prev_counts = std::move(counts);
            if (cn >= cn_end || t >= t_max) break;
        }
        if (checkpoint.due()) checkpoint.save([&](const H5Object& root) { save_loop(root, st, eng, wall_now()); });
    }
    const auto& ts = st.ts;
    const auto& ks = st.ks;
    const auto& kxs = st.kxs;
    const auto& kys = st.kys;
    const auto& cns = st.cns;
    const auto& ecns = st.ecns;
    const auto& instants = st.instants;
    const double wall = wall_now();

    Result res;
    const double rho = M_PI / 4 * double(n) / (p.real("box_over_d") * p.real("box_over_d"));
    const double vbar = p.real("vbar");
    const double s_star = (1 - rho) * (1 - rho) / (1 - 7 * rho / 16);
    const double omega_enskog = 8 * rho * vbar / (s_star * d * std::sqrt(2 * M_PI));
    const double t0 = 4 / ((1 - r * r) * omega_enskog);
    res.scalar("N", double(n), "1", "number of disks");
    res.scalar("rho", rho, "1", "area fraction (pi/4) N / L^2");
    res.scalar("t0_kinetic", t0, "s", "t0 of Eq. (18) from kinetic theory (sqrt(2 pi) in Eq. 19; see cooling.cpp)");
    res.scalar("omega_equilibration_over_enskog", omega_eq / omega_enskog, "1", "elastic collision rate per particle during equilibration over Enskog's");
    res.scalar("wall_seconds_run", wall, "s", "wall time of the cooling run (after equilibration)");
    res.scalar("events_per_second", double(eng.events_processed()) / wall, "1/s", "ED events (collisions, cell crossings, stale) per second");
    res.scalar("collisions_per_second", double(eng.total_collisions()) / wall, "1/s", "pair collisions per second");
    res.scalar("events", double(eng.events_processed()), "1", "ED events of the cooling run");
    res.scalar("t_end", ts.back(), "s", "end of the run");
    res.scalar("C_over_N_end", cns.back(), "1", "collisions per particle at the end");
    res.scalar("stopped_by_engine", error.empty() ? 0.0 : 1.0, "1", "1 if the collapse guard stopped the run");

    // ---- Fig. 10 ------------------------------------------------------------------------------
    {
        Table& t = res.table("energy", "K/K0, C/N and TC-elastic collisions per particle against t");
        std::vector<double> kk, an, e18, s2, s1, efrac;
        for (std::size_t i = 0; i < ts.size(); ++i) {
            kk.push_back(ks[i] / ks[0]);
            an.push_back((kxs[i] - kys[i]) / (kxs[i] + kys[i]));
            e18.push_back(1 / ((1 + ts[i] / t0) * (1 + ts[i] / t0)));
            efrac.push_back(cns[i] > 0 ? ecns[i] / cns[i] : NAN);
        }
        t.add("t", "s").values = ts;
        t.add("K_over_K0", "1").values = kk;
        t.add("eq18", "1").values = e18;
        t.add("anisotropy", "1").values = an;
        t.add("C_over_N", "1").values = cns;
        t.add("elastic_C_over_N", "1").values = ecns;
        t.add("elastic_fraction", "1").values = efrac;
        // Guide lines of Fig. 10(a): slope -2, the t >> t0 asymptote of Eq. (18), (t/t0)^-2; slope -1
        // through the geometric mean of the samples from late_slope_from on.
        double lsum = 0;
        int lcount = 0;
        for (std::size_t i = 1; i < ts.size(); ++i)
            if (ts[i] >= p.real("late_slope_from")) {
                lsum += std::log(kk[i] * ts[i]);
                ++lcount;
            }
        for (std::size_t i = 0; i < ts.size(); ++i) {
            s2.push_back(ts[i] >= t0 ? (t0 / ts[i]) * (t0 / ts[i]) : NAN);
            s1.push_back(ts[i] >= 0.1 * p.real("late_slope_from") && lcount ? std::exp(lsum / lcount) / ts[i] : NAN);
        }
        t.add("slope_minus2", "1").values = s2;
        t.add("slope_minus1", "1").values = s1;

        // Early cooling: Eq. (18) fitted over t <= t0 (1/sqrt(K/K0) - 1 = t/t0, a line through 0).
        std::vector<double> x, y;
        for (std::size_t i = 1; i < ts.size(); ++i)
            if (ts[i] <= t0) {
                x.push_back(ts[i]);
                y.push_back(1 / std::sqrt(kk[i]) - 1);
            }
        double c1 = NAN, cov = 0, ss = 0;
        if (x.size() >= 2) gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
        res.scalar("t0_fit_over_kinetic", c1 * t0, "1", "1/t0 fitted to K(t) over t <= t0 (Eq. 18) over the kinetic-theory value");
        // Steepest local slope d ln K / d ln t (over one octave) before late_slope_from: Eq. (18)
        // tends to -2 only for t >> t0, while clustering sets in at a few t0.
        double steepest = 0;
        for (std::size_t i = std::size_t(m) + 1; i < ts.size() && ts[i] <= p.real("late_slope_from"); ++i)
            steepest = std::min(steepest, std::log(kk[i] / kk[i - std::size_t(m)]) / std::log(2.0));
        res.scalar("K_slope_steepest_early", steepest, "1", "steepest slope of log K against log t over one octave, t <= late_slope_from");
        const PowerLawFit late = fit_power_law(ts, kk, p.real("late_slope_from"), ts.back());
        res.scalar("K_slope_late", late.exponent, "1", "average slope of log K against log t from late_slope_from to the end (GSL fit)");
        res.scalar("K_slope_late_err", late.exponent_err, "1", "its standard error (residual scatter of the 13-per-decade samples)");
        res.scalar("K_over_eq18_end", kk.back() / e18.back(), "1", "K over Eq. (18) at the end: how much slower than homogeneous cooling");
        double early_max = 0, all_max = 0;
        for (std::size_t i = 1; i < ts.size(); ++i) {
            if (!(cns[i] > 0)) continue;
            all_max = std::max(all_max, efrac[i]);
            if (ts[i] <= p.real("elastic_until")) early_max = std::max(early_max, efrac[i]);
        }
        res.scalar("elastic_fraction_early_max", early_max, "1", "largest TC-elastic share of all collisions for t <= elastic_until");
        res.scalar("elastic_fraction_max", all_max, "1", "largest TC-elastic share of all collisions over the run");
        res.scalar("elastic_per_particle_end", ecns.back(), "1", "TC-elastic collisions per particle at the end");
        auto cn_at = [&](double tq) -> double {
            for (std::size_t i = 0; i < ts.size(); ++i)
                if (std::abs(ts[i] / tq - 1) < 1e-9) return cns[i];
            return NAN;
        };
        res.scalar("C_over_N_at_0.04s", cn_at(0.04), "1", "C/N at t = 0.04 s");
        res.scalar("C_over_N_at_0.64s", cn_at(0.64), "1", "C/N at t = 0.64 s");
        res.scalar("C_over_N_at_10.24s", cn_at(10.24), "1", "C/N at t = 10.24 s");
        res.scalar("C_over_N_eq18_at_0.64s", 4 / (1 - r * r) * std::log(1 + 0.64 / t0), "1",
                   "C/N at 0.64 s if the gas stayed homogeneous: 4/(1-r^2) ln(1 + t/t0)");
    }

    // ---- Fig. 12: every instant -----------------------------------------------------------------
    {
        Table& t = res.table("instants", "per instant t = t_base 2^k: C/N, N_c statistics and the fits of Eqs. (20)-(22)");
        auto col = [&](const char* name, const char* unit, auto get) {
            auto& c = t.add(name, unit);
            for (const auto& in : instants) c.values.push_back(get(in));
        };
        col("t", "s", [](const Instant& in) { return in.t; });
        col("window", "s", [](const Instant& in) { return in.window; });
        col("C_over_N", "1", [](const Instant& in) { return in.cn; });
        col("elastic_C_over_N", "1", [](const Instant& in) { return in.elastic_cn; });
        col("mean_Nc", "1/s", [](const Instant& in) { return in.mean_rate; });
        col("tail_fraction", "1", [](const Instant& in) { return in.tail_fraction; });
        col("chi", "1", [](const Instant& in) { return in.poisson.value; });
        col("chi_err", "1", [](const Instant& in) { return in.poisson.error; });
        col("chi2red_poisson", "1", [](const Instant& in) { return in.poisson.chi2_reduced; });
        col("A", "1/s", [](const Instant& in) { return in.expo.value; });
        col("A_err", "1/s", [](const Instant& in) { return in.expo.error; });
        col("chi2red_exponential", "1", [](const Instant& in) { return in.expo.chi2_reduced; });
        col("B", "1/s", [](const Instant& in) { return in.power.value; });
        col("B_err", "1/s", [](const Instant& in) { return in.power.error; });
        col("chi2red_powerlaw", "1", [](const Instant& in) { return in.power.chi2_reduced; });
        col("bins", "1", [](const Instant& in) { return double(in.hist.centres.size()); });
    }
    // The instants nearest to the paper's C/N values: histogram tables and scalars for the claims.
    {
        const auto& pcn = p.reals("paper_cn");
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
            Table& h = res.table("pnc_" + std::to_string(s), "P(N_c) and the fitted Eqs. (20)-(22) at t = " + label("", in.t) + " s");
            std::vector<double> pp, pe, pw, lo, hi;
            for (std::size_t b = 0; b < in.hist.centres.size(); ++b) {
                const double w = in.hist.edges[b + 1] - std::max(0.0, in.hist.edges[b]);
                auto model = [&](const CollisionRateFit& f) {
                    return std::isfinite(f.value) ? CollisionRateFit::bin_probability(in.hist, b, f.model, f.value) / w : NAN;
                };
                pp.push_back(model(in.poisson));
                pe.push_back(model(in.expo));
                pw.push_back(model(in.power));
            }
            h.add("N_c", "1/s").values = in.hist.centres;
            h.add("P", "s").values = in.hist.density;
            h.add("P_err", "s").values = in.hist.error;
            h.add("poisson_eq20", "s").values = pp;
            h.add("exponential_eq21", "s").values = pe;
            h.add("powerlaw_eq22", "s").values = pw;
            const std::string tag = s < pcn.size() ? label("_cn", paper) : std::string("_last");
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
            res.scalar("B_err" + tag, in.power.error, "1/s", "its standard error");
            res.scalar("chi2red_powerlaw" + tag, in.power.chi2_reduced, "1", "Pearson chi^2/dof of the power-law fit");
            res.scalar("mean_Nc" + tag, in.mean_rate, "1/s", "mean N_c");
            res.scalar("tail_fraction" + tag, in.tail_fraction, "1", "fraction of particles with N_c > tail_rate");
            res.scalar("poisson_over_best_other_chi2" + tag, in.poisson.chi2_reduced / std::min(in.expo.chi2_reduced, in.power.chi2_reduced), "1",
                       "chi^2/dof of Eq. (20) over the better of Eqs. (21), (22) (< 1: Poisson fits best)");
            res.scalar("powerlaw_over_exponential_chi2" + tag, in.power.chi2_reduced / in.expo.chi2_reduced, "1",
                       "chi^2/dof of Eq. (22) over that of Eq. (21) (< 1: the power law fits better)");
        }
        // Created last: res.table() may move the tables created before.
        Table& meta = res.table("fig12_selection", "instants shown in Fig. 12: the paper's C/N and ours");
        meta.add("paper_C_over_N", "1").values = mp;
        meta.add("C_over_N", "1").values = mc;
        meta.add("t", "s").values = mt;
        meta.add("window", "s").values = mw;
    }
    // The fitted parameters at exactly the paper's C/N: linear interpolation of ln(parameter)
    // in ln(C/N) between the two instants around it (consecutive instants differ by a factor 2
    // in t and by 1.1-2 in C/N, so the nearest instant alone can be far from the paper's C/N).
    {
        auto interp = [&](double cn, auto get) {
            for (std::size_t k = 1; k < instants.size(); ++k)
                if (instants[k - 1].cn <= cn && instants[k].cn >= cn) {
                    const double f = std::log(cn / instants[k - 1].cn) / std::log(instants[k].cn / instants[k - 1].cn);
                    return std::exp(std::log(get(instants[k - 1])) * (1 - f) + std::log(get(instants[k])) * f);
                }
            return double(NAN);
        };
        for (double c : p.reals("paper_cn")) {
            const std::string tag = label("_at_cn", c);
            res.scalar("chi" + tag, interp(c, [](const Instant& in) { return in.poisson.value; }), "1", "Eq. (20) chi interpolated to the paper's C/N");
            res.scalar("A" + tag, interp(c, [](const Instant& in) { return in.expo.value; }), "1/s", "Eq. (21) A interpolated to the paper's C/N");
            res.scalar("B" + tag, interp(c, [](const Instant& in) { return in.power.value; }), "1/s", "Eq. (22) B interpolated to the paper's C/N");
            res.scalar("t" + tag, interp(c, [](const Instant& in) { return in.t; }), "s", "time at which C/N reached the paper's value (interpolated)");
        }
        // B over the clustered instants 70 <= C/N <= 1404 (the paper quotes one B for them).
        double lsum = 0;
        int cnt = 0;
        double bmin = INFINITY, bmax = -INFINITY;
        for (const auto& in : instants)
            if (in.cn >= 70 && in.cn <= 1404 && std::isfinite(in.power.value)) {
                lsum += std::log(in.power.value);
                ++cnt;
                bmin = std::min(bmin, in.power.value);
                bmax = std::max(bmax, in.power.value);
            }
        res.scalar("B_geomean_70_1404", cnt ? std::exp(lsum / cnt) : NAN, "1/s", "geometric mean of B over the instants with 70 <= C/N <= 1404");
        res.scalar("B_min_70_1404", cnt ? bmin : NAN, "1/s", "smallest B there");
        res.scalar("B_max_70_1404", cnt ? bmax : NAN, "1/s", "largest B there");
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
                       "B at the instant nearest C/N = 1404 over B nearest 183 (shape change)");
            res.scalar("tail_ratio_2567_over_1404", instants[std::size_t(k2)].tail_fraction / instants[std::size_t(k1)].tail_fraction, "1",
                       "P(N_c > tail_rate) nearest C/N = 2567 over that nearest 1404 (< 1: the tail drops again)");
            res.scalar("tail_ratio_last_over_1404", instants.back().tail_fraction / instants[std::size_t(k1)].tail_fraction, "1",
                       "P(N_c > tail_rate) at the last instant over that nearest C/N = 1404");
        }
    }
    // Which form fits best over the instants after C/N = 70 (Section 4.3: power law).
    {
        double n_after = 0, pow_best = 0;
        for (const auto& in : instants)
            if (in.cn > 70 && std::isfinite(in.power.chi2_reduced) && std::isfinite(in.expo.chi2_reduced)) {
                ++n_after;
                if (in.power.chi2_reduced < in.expo.chi2_reduced) ++pow_best;
            }
        res.scalar("powerlaw_better_share_after_70", n_after > 0 ? pow_best / n_after : NAN, "1",
                   "share of the instants with C/N > 70 where Eq. (22) fits better than Eq. (21)");
    }

    // ---- Fig. 11: snapshots --------------------------------------------------------------------
    {
        std::vector<double> mp, mc, mt;
        const auto& scn = p.reals("snapshot_cn");
        for (std::size_t s = 0; s < scn.size(); ++s) {
            const int k = nearest(instants, scn[s]);
            if (k < 0) continue;
            const Instant& in = instants[std::size_t(k)];
            mp.push_back(scn[s]);
            mc.push_back(in.cn);
            mt.push_back(in.t);
            Table& sn = res.table("snapshot_" + std::to_string(mt.size() - 1),
                                  "positions and N_c over the last t/2 at t = " + label("", in.t) + " s");
            std::vector<double> x, y;
            for (const Vec2& q : in.pos) {
                x.push_back(q.x / d);
                y.push_back(q.y / d);
            }
            sn.add("x_over_d", "1").values = std::move(x);
            sn.add("y_over_d", "1").values = std::move(y);
            sn.add("N_c", "1/s").values = in.rate;
        }
        Table& meta = res.table("fig11_selection", "instants of the snapshots");
        meta.add("paper_C_over_N", "1").values = mp;
        meta.add("C_over_N", "1").values = mc;
        meta.add("t", "s").values = mt;
    }
    return res;
}

} // namespace

Experiment cluster_growth() { return {"cluster-growth", &validate, &run}; }

} // namespace granrepro::experiments
