// emergency-brake: Schäfer & Wolf (1995) Figs. 4 and 5. A free grain is shot onto a row of
// touching wall grains with v_x^i towards the wall and v_y^i along it; each point is the mean
// over start positions spaced equally over one wall wavelength. Far in the brake-failure regime
// the grain ploughs through several wall grains and Δv_y rises again (the "emergency brake").
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "scenarios/impact_shot.hpp"
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

void validate(const ParameterSet& p) {
    const double dt = validate_free_wall_law(p);
    const double reach = 0.5 * (p.real("d_free") + p.real("d_wall"));
    if (p.real("x_start") < reach)
        p.reject("x_start", "the free grain would start overlapping the wall grains; must be at least (d_free + d_wall)/2 = " +
                                number_text(reach) + " m");
    if (p.real("vy_min") >= p.real("vy_max")) p.reject("vy_min", "must be below vy_max");
    // A wall: the free grain must not fit through the gap between two wall grains, or it never
    // comes back and each shot runs to max_steps.
    for (const char* spacing : {"wall_spacing", "pipe_wall_spacing"}) {
        if (p.real(spacing) < p.real("d_wall") * (1 - 1e-12))
            p.reject(std::vector<std::string>{spacing, "d_wall"}, std::string(spacing) + " must be at least d_wall (wall grains would overlap)");
        if (p.real(spacing) - p.real("d_wall") >= p.real("d_free"))
            p.reject(std::vector<std::string>{spacing, "d_wall", "d_free"},
                     "the gap between wall grains (" + std::string(spacing) + " - d_wall) must be narrower than d_free");
    }
    // The fastest shot must take several steps over a wall grain: at most d_wall/2 per step at
    // the softest law of the k_N scan (the largest dt).
    double k_min = p.real("k_N");
    for (double k : p.reals("kN_scan")) k_min = std::min(k_min, k);
    const double dt_max = dt * std::sqrt(p.real("k_N") / k_min);
    const double v_fast = std::max(p.real("vy_max"), *std::max_element(p.reals("vx_list").begin(), p.reals("vx_list").end()));
    if (!(v_fast * dt_max <= 0.5 * p.real("d_wall")))
        p.reject(std::vector<std::string>{"vy_max", "vx_list", "kN_scan", "k_N", "m_free", "steps_per_contact"},
                 "vy_max and every v_x^i must be at most d_wall / (2 dt) = " + number_text(0.5 * p.real("d_wall") / dt_max) +
                     " m/s (dt = " + number_text(dt_max) + " s at the softest k_N): faster grains skip through the wall");
    // The slowest shot: the smallest v_x^i from x_start to the wall and a diameter into it, at
    // the time step of the stiffest law of the k_N scan.
    double k_max = p.real("k_N");
    for (double k : p.reals("kN_scan")) k_max = std::max(k_max, k);
    const double vx_min = *std::min_element(p.reals("vx_list").begin(), p.reals("vx_list").end());
    limit_shot_steps(p, {"x_start", "d_free", "vx_list", "kN_scan", "k_N", "m_free", "steps_per_contact"},
                     p.real("x_start") - reach + p.real("d_free"), vx_min, dt * std::sqrt(p.real("k_N") / k_max),
                     p.real("steps_per_contact") * std::sqrt(k_max / p.real("k_N")));
}

struct Point {
    double dvy = 0, dvy_sem = 0, contacts = 0, multi_fraction = 0;
    double vx_return = 0; // mean v_x^f / v_x^i: how much of the speed towards the wall comes back
    int incomplete = 0;
};

constexpr std::array kReadings{FrictionNormal::Magnitude, FrictionNormal::Clipped, FrictionNormal::Elastic,
                               FrictionNormal::Signed};

std::string label(const char* prefix, double x) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%g", prefix, x);
    return buf;
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const double m = p.real("m_free");
    const LinearSpringDashpot law{p.real("k_N"), p.real("gamma_N")};
    const double e_N = law.restitution(m);
    const auto vy = log_space(p.real("vy_min"), p.real("vy_max"), int(p.integer("n_vy")));
    const auto& vxs = p.reals("vx_list");
    const auto& kscan = p.reals("kN_scan");
    const long npos = p.integer("n_positions");
    const std::size_t n = vy.size();

    // Series: one per v_x^i at the experiment's k_N (the figures), one per extra k_N at
    // vx_list[0], one per v_x^i on the pipe's wall spacing (Fig. 6's construction needs the impact
    // curves of the pipe's own wall), and one per other reading of Eq. (2) and v_x^i.
    enum class Kind { Main, KScan, PipeWall, Reading };
    struct Series {
        Kind kind;
        double vx;
        LinearSpringDashpot law;
        CoulombShear shear;
        double spacing;
        std::string tag;
    };
    const CoulombShear shear = coulomb_from(p);
    const double spacing = p.real("wall_spacing"), pipe_spacing = p.real("pipe_wall_spacing");
    std::vector<Series> series;
    for (double vx : vxs) series.push_back({Kind::Main, vx, law, shear, spacing, label("vx", vx)});
    for (double k : kscan)
        series.push_back({Kind::KScan, vxs.front(), LinearSpringDashpot::from_restitution(k, e_N, m), shear, spacing,
                          label("kN", k)});
    if (pipe_spacing != spacing)
        for (double vx : vxs) series.push_back({Kind::PipeWall, vx, law, shear, pipe_spacing, label("pipe_vx", vx)});
    for (auto reading : kReadings)
        if (reading != shear.reading)
            for (double vx : vxs)
                series.push_back({Kind::Reading, vx, law, CoulombShear{shear.mu, reading}, spacing,
                                  std::string("eq2_") + to_string(reading) + label("_vx", vx)});

    std::vector<std::vector<Point>> pts(series.size(), std::vector<Point>(n));
    Progress progress("emergency-brake", long(series.size() * n), ctx.quiet);
    parallel_sweep(long(series.size() * n), ctx.threads, &progress, [&](long task) {
        const Series& s = series[std::size_t(task) / n];
        const std::size_t i = std::size_t(task) % n;
        ImpactSetup setup;
        setup.d_free = p.real("d_free");
        setup.m_free = m;
        setup.d_wall = p.real("d_wall");
        setup.wall_spacing = s.spacing;
        setup.x0 = p.real("x_start");
        setup.vx_toward = s.vx;
        setup.vy = vy[i];
        setup.dt = s.law.collision_time(m) / p.real("steps_per_contact");
        double sum = 0, sum2 = 0, contacts = 0, multi = 0, back = 0;
        Point& out = pts[std::size_t(task) / n][i];
        for (long k = 0; k < npos; ++k) {
            setup.y0 = setup.wall_spacing * double(k) / double(npos);
            const ImpactOutcome o = shoot(s.law, s.shear, setup);
            sum += o.dvy;
            sum2 += o.dvy * o.dvy;
            contacts += o.wall_grains;
            multi += o.wall_grains >= 2;
            back += (o.dvx - s.vx) / s.vx;
            out.incomplete += !o.completed;
        }
        const double mean = sum / double(npos);
        out.dvy = mean;
        out.dvy_sem = npos > 1 ? std::sqrt(std::max(0.0, sum2 / double(npos) - mean * mean) / double(npos - 1)) : 0.0;
        out.contacts = contacts / double(npos);
        out.multi_fraction = multi / double(npos);
        out.vx_return = back / double(npos);
    });

    Result r;
    int incomplete = 0;
    for (const auto& s : pts)
        for (const auto& q : s) incomplete += q.incomplete;
    r.scalar("incomplete_impacts", incomplete, "1", "impacts that had not ended within max_steps");
    r.scalar("e_N", e_N, "1", "free-wall restitution of the linear law, Eq. (4)");
    r.scalar("t_col", law.collision_time(m), "s", "free-wall contact duration, Eq. (4)");

    for (std::size_t si = 0; si < series.size(); ++si) {
        const Series& se = series[si];
        const bool main = se.kind != Kind::KScan;
        const std::string& tag = se.tag;
        const std::string at = "at v_x^i = " + label("", se.vx) + " m/s";
        Table& t = r.table("impacts_" + tag, se.kind == Kind::Main       ? "mean over start positions " + at
                                             : se.kind == Kind::KScan    ? "k_N scan at the first v_x^i, e_N held fixed"
                                             : se.kind == Kind::PipeWall ? "on the pipe's wall spacing " + at
                                                                         : std::string("reading ") + to_string(se.shear.reading) + " of Eq. (2) " + at);
        std::vector<double> dvy(n), sem(n), cont(n), multi(n), back(n);
        for (std::size_t i = 0; i < n; ++i) {
            dvy[i] = pts[si][i].dvy;
            sem[i] = pts[si][i].dvy_sem;
            cont[i] = pts[si][i].contacts;
            multi[i] = pts[si][i].multi_fraction;
            back[i] = pts[si][i].vx_return;
        }
        t.add("vy_i", "m/s").values = vy;
        t.add("dvy", "m/s").values = dvy;
        t.add("dvy_sem", "m/s").values = sem;
        t.add("contacts", "1").values = cont;
        t.add("multi_fraction", "1").values = multi;
        t.add("vx_return", "1").values = back;

        // The first maximum (brake failure sets in), the minimum after it, and the rise to v_max.
        const Peak pk = first_maximum(vy, dvy);
        std::size_t imin = std::size_t(std::max(pk.index, 0));
        for (std::size_t i = imin; i < n; ++i)
            if (dvy[i] < dvy[imin]) imin = i;
        r.scalar("v_crit_" + tag, pk.x, "m/s", "v_y^i at the first maximum of mean Δv_y");
        r.scalar("dvy_peak_" + tag, pk.y, "m/s", "height of the first maximum");
        if (!main) continue;
        r.scalar("v_min_" + tag, vy[imin], "m/s", "v_y^i where Δv_y is smallest after the first maximum (rise begins)");
        r.scalar("rise_ratio_" + tag, dvy.back() / dvy[imin], "1", "Δv_y at vy_max over its minimum after the peak");
        // Fig. 5 plots the mean number of contacts; the multiple-contact regime starts where it reaches 2.
        const double onset = first_upward_crossing(vy, cont, 2.0);
        r.scalar("v_multi_onset_" + tag, onset, "m/s", "v_y^i at which the mean number of wall grains touched reaches 2");
        r.scalar("onset_over_vmin_" + tag, onset / vy[imin], "1", "multi-contact onset over the start of the Δv_y rise");
        r.scalar("contacts_at_vmax_" + tag, cont.back(), "1", "mean wall grains touched at vy_max");
        r.scalar("vx_return_at_vmax_" + tag, back.back(), "1", "mean v_x^f / v_x^i at vy_max (the wall's return of the speed towards it)");
    }
    if (!kscan.empty()) {
        // v_crit and the peak height must grow with k_N (text below Fig. 5).
        std::vector<std::pair<double, std::string>> ks;
        ks.push_back({law.k_N, label("vx", vxs.front())});
        for (double k : kscan) ks.push_back({k, label("kN", k)});
        std::sort(ks.begin(), ks.end());
        double monotone = 1;
        for (std::size_t a = 1; a < ks.size(); ++a) {
            const double v0 = r.find_scalar("v_crit_" + ks[a - 1].second)->value;
            const double v1 = r.find_scalar("v_crit_" + ks[a].second)->value;
            const double h0 = r.find_scalar("dvy_peak_" + ks[a - 1].second)->value;
            const double h1 = r.find_scalar("dvy_peak_" + ks[a].second)->value;
            monotone = monotone && v1 > v0 && h1 > h0;
        }
        r.scalar("v_crit_and_peak_grow_with_kN", monotone, "1", "1 if v_crit and the peak height increase with k_N");
    }
    return r;
}

} // namespace

Experiment emergency_brake() { return {"emergency-brake", &validate, &run}; }

} // namespace granrepro::experiments
