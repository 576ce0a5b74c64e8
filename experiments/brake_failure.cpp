// brake-failure: Schäfer & Wolf (1995) Fig. 3. A free grain flies parallel to the wall line,
// 0.82 mm from the centre of a single wall grain, and grazes it; Δv_y and Δv_x against v_y^i.
// Besides the figure's curve it runs the paper's three robustness statements: the same curve with
// dt/100, the √β collapse of k' = β k_N, and the Hertz-Kuwabara-Kono normal force.
#include <array>
#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "scenarios/impact_shot.hpp"
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "models/hertz_kuwabara_kono.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

constexpr std::array kReadings{FrictionNormal::Magnitude, FrictionNormal::Clipped, FrictionNormal::Elastic,
                               FrictionNormal::Signed};

void validate(const ParameterSet& p) {
    const double dt = validate_free_wall_law(p);
    const double reach = 0.5 * (p.real("d_free") + p.real("d_wall"));
    if (p.real("offset") >= reach)
        p.reject("offset", "must be below (d_free + d_wall)/2 = " + number_text(reach) + " m or the grains never touch");
    if (p.real("vy_min") >= p.real("vy_max")) p.reject("vy_min", "must be below vy_max");
    // The slowest shot (vy_min, dt/fine_factor) starts 1e-3 d_free before contact and crosses the
    // chord 2 y_c; each shot must end within max_steps (d_free = 1e10 ran for ever).
    const double yc = std::sqrt(reach * reach - p.real("offset") * p.real("offset"));
    const double fine = p.real("fine_factor");
    limit_shot_steps(p, {"d_free", "d_wall", "offset", "vy_min", "fine_factor", "k_N", "m_free", "steps_per_contact"},
                     1e-3 * p.real("d_free") + 2 * yc, p.real("vy_min"), dt / fine, p.real("steps_per_contact") * fine);
    // The fastest shot (10 vy_max with dt/10) must take at least one step inside the contact
    // chord, or it passes through the wall grain unresolved (vy_max = 1e308 ran for ever).
    if (!(p.real("vy_max") * dt <= 2 * yc))
        p.reject(std::vector<std::string>{"vy_max", "offset", "k_N", "m_free", "steps_per_contact"},
                 "at 10 vy_max with dt/10 = " + number_text(dt / 10) + " s the grain crosses the contact chord 2 y_c = " +
                     number_text(2 * yc) + " m in less than one time step; vy_max must be at most " +
                     number_text(2 * yc / dt) + " m/s");
    // The same for the speed towards the wall grain.
    if (!(p.real("vx_i") * dt <= 2 * yc))
        p.reject(std::vector<std::string>{"vx_i", "offset", "k_N", "m_free", "steps_per_contact"},
                 "vx_i must be at most " + number_text(2 * yc / dt) + " m/s: at dt = " + number_text(dt) +
                     " s the grain would cross the contact chord 2 y_c in less than one time step");
}

// The Fig. 3 geometry: wall grain at the origin, free grain on the line x = offset, starting just
// before first contact.
ImpactSetup geometry(const ParameterSet& p, double vy, double dt) {
    ImpactSetup s;
    s.d_free = p.real("d_free");
    s.m_free = p.real("m_free");
    s.d_wall = p.real("d_wall");
    s.x0 = p.real("offset");
    const double reach = 0.5 * (s.d_free + s.d_wall);
    s.y0 = -std::sqrt(reach * reach - s.x0 * s.x0) - 1e-3 * s.d_free;
    s.vx_toward = p.real("vx_i");
    s.vy = vy;
    s.dt = dt;
    return s;
}

struct Curve {
    std::vector<double> dvy, dvx, dvy_shear;
    std::vector<int> complete;
};

// Head-on collision at the run's time step, of the free grain with the wall grain or with a
// free twin: the measured t_col and e_N of Eq. (4) and the largest overlap (text below Eq. 4).
struct HeadOn {
    double t_col = NAN, e_N = NAN, xi_max = NAN;
};
HeadOn measure_head_on(const LinearSpringDashpot& law, const ParameterSet& p, double dt, bool wall = true,
                       double v0 = 1.0) {
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, coulomb_from(p), dt);
    const double R = 0.5 * p.real("d_free"), r = wall ? 0.5 * p.real("d_wall") : R;
    eng.add_free({{R + r + 1e-6, 0.0}, {-v0, 0.0}, R, p.real("m_free")});
    if (wall) eng.add_fixed({{0.0, 0.0}, r});
    else eng.add_free({{0.0, 0.0}, {0.0, 0.0}, R, p.real("m_free")});
    HeadOn h;
    double xi_max = 0;
    for (long s = 0; s < 10'000'000 && eng.events().size() < 2; ++s) {
        eng.step();
        const auto& g = eng.grains();
        const double other = wall ? 0.0 : g[1].r.x;
        xi_max = std::max(xi_max, R + r - (g[0].r.x - other));
    }
    const auto& ev = eng.events();
    if (ev.size() < 2) return h;
    h.t_col = ev[1].t - ev[0].t;
    h.e_N = -ev[1].xi_dot / ev[0].xi_dot;
    h.xi_max = xi_max;
    return h;
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const double m = p.real("m_free");
    const LinearSpringDashpot law{p.real("k_N"), p.real("gamma_N")};
    const double t_col = law.collision_time(m);
    const double dt = t_col / p.real("steps_per_contact");
    const CoulombShear shear = coulomb_from(p);
    const auto vy = log_space(p.real("vy_min"), p.real("vy_max"), int(p.integer("n_vy")));
    const std::size_t n = vy.size();
    const auto& betas = p.reals("betas");

    // Curves: 0 = Fig. 3, 1 = dt / fine_factor, 2 = HKK, 3 = elastic limit (gamma_N = 0) and
    // 4 = paper parameters, both on a grid extended to 10 vy_max, 5.. = k' = beta k_N, then per
    // reading of Eq. (2) (magnitude, clipped, elastic, signed) one curve on the figure's grid and
    // one on the extended grid (the study of which F_N enters Coulomb's law, panel (b)).
    const std::size_t n_betas = betas.size();
    const std::size_t first_reading = 5 + n_betas;
    const std::size_t n_curves = first_reading + 2 * kReadings.size();
    const auto vy_ext = log_space(p.real("vy_min"), 10 * p.real("vy_max"), int(n));
    const LinearSpringDashpot elastic{law.k_N, 0.0};
    std::vector<Curve> curves(n_curves, Curve{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), std::vector<int>(n)});
    const auto hkk = HertzKuwabaraKono::matched_at(law.k_N, law.gamma_N, p.real("hkk_xi_ref"));

    Progress progress("brake-failure", long(n * n_curves), ctx.quiet);
    parallel_sweep(long(n * n_curves), ctx.threads, &progress, [&](long task) {
        const std::size_t c = std::size_t(task) / n, i = std::size_t(task) % n;
        ImpactOutcome o;
        if (c == 0) o = shoot(law, shear, geometry(p, vy[i], dt));
        else if (c == 1) o = shoot(law, shear, geometry(p, vy[i], dt / p.real("fine_factor")));
        else if (c == 2) o = shoot(hkk, shear, geometry(p, vy[i], dt));
        // At 10 vy_max a grazing contact lasts less than one step of t_col/50: resolve it with dt/10.
        else if (c == 3) o = shoot(elastic, shear, geometry(p, vy_ext[i], dt / 10));
        else if (c == 4) o = shoot(law, shear, geometry(p, vy_ext[i], dt / 10));
        else if (c < first_reading) {
            // k' = beta k_N with gamma' = sqrt(beta) gamma_N: time scales by 1/sqrt(beta), lengths
            // are unchanged, so velocities scale by sqrt(beta).
            const double sb = std::sqrt(betas[c - 5]);
            const LinearSpringDashpot scaled{law.k_N * betas[c - 5], law.gamma_N * sb};
            o = shoot(scaled, shear, geometry(p, vy[i] * sb, dt / sb));
        } else {
            const std::size_t k = (c - first_reading) / 2;
            const bool extended = (c - first_reading) % 2 == 1;
            const CoulombShear reading{shear.mu, kReadings[k]};
            o = extended ? shoot(law, reading, geometry(p, vy_ext[i], dt / 10)) : shoot(law, reading, geometry(p, vy[i], dt));
        }
        curves[c].dvy[i] = o.dvy;
        curves[c].dvx[i] = o.dvx;
        curves[c].dvy_shear[i] = o.dvy_shear;
        curves[c].complete[i] = o.completed;
    });

    Result r;
    int incomplete = 0;
    for (const auto& c : curves)
        for (int ok : c.complete) incomplete += !ok;
    r.scalar("incomplete_impacts", incomplete, "1", "impacts that had not ended within max_steps");

    Table& t = r.table("fig3", "Δv_y and Δv_x vs v_y^i, one wall grain (linear law, dt = t_col/steps_per_contact)");
    t.add("vy_i", "m/s").values = vy;
    t.add("dvy", "m/s").values = curves[0].dvy;
    t.add("dvx", "m/s").values = curves[0].dvx;
    t.add("dvy_fine", "m/s").values = curves[1].dvy;
    t.add("dvx_fine", "m/s").values = curves[1].dvx;
    t.add("dvy_hkk", "m/s").values = curves[2].dvy;
    t.add("dvx_hkk", "m/s").values = curves[2].dvx;

    // The 1/v argument of Eqs. (6)-(8) and why the damped law departs from it at high v_y.
    Table& te = r.table("high_velocity", "Δv_y up to 10 vy_max: elastic limit (gamma_N = 0) and paper parameters");
    te.add("vy_i", "m/s").values = vy_ext;
    te.add("dvy_elastic", "m/s").values = curves[3].dvy;
    te.add("dvx_elastic", "m/s").values = curves[3].dvx;
    te.add("dvy", "m/s").values = curves[4].dvy;
    te.add("dvx", "m/s").values = curves[4].dvx;
    const double vext = vy_ext.back();
    r.scalar("tail_exponent_dvy_elastic", fit_power_law(vy_ext, curves[3].dvy, vext / 10, vext).exponent, "1",
             "exponent of Δv_y ∝ v^a over the last decade of the extended grid, gamma_N = 0");
    r.scalar("tail_exponent_dvx_far", fit_power_law(vy_ext, curves[4].dvx, vext / 10, vext).exponent, "1",
             "exponent of Δv_x ∝ v^a over [vy_max, 10 vy_max], paper parameters");
    // Why the damped law has no 1/v tail: at high v_y the path is straight and the dashpot force
    // gamma_N m dxi/dt does not vanish with the contact time. Along the path x = h, with
    // R = (d_free + d_wall)/2 and half-chord y_c = sqrt(R^2 - h^2), the friction of Eq. (2) and
    // the normal force's y-component give (integrating over y instead of t)
    //     Δv_y -> gamma_N [ mu h ln(R^2/h^2) + 2 (y_c - h atan(y_c/h)) ],
    // a constant (0.120 m/s at the Fig. 3 parameters) instead of zero.
    const double reach = 0.5 * (p.real("d_free") + p.real("d_wall"));
    const double h = p.real("offset"), yc = std::sqrt(reach * reach - h * h);
    const double plateau =
        law.gamma_N * (p.real("mu") * h * std::log(reach * reach / (h * h)) + 2 * (yc - h * std::atan(yc / h)));
    r.scalar("dvy_plateau_theory", plateau, "m/s", "high-v_y limit of Δv_y under Eqs. (1)-(2) (straight path)");
    r.scalar("dvy_far_over_plateau", curves[4].dvy.back() / plateau, "1", "Δv_y at 10 vy_max over that limit");

    const HeadOn head_on = measure_head_on(law, p, dt);
    const double t_meas = head_on.t_col, e_meas = head_on.e_N;
    // Text below Eq. (4): xi_max <= v_N t_col / pi, with equality for gamma_N = 0; and the m_red
    // in Eq. (1)'s dashpot makes free-wall collisions more dissipative than free-free ones.
    // Overlaps are read at step ends, so they are resolved at dt/20 here.
    const HeadOn fine = measure_head_on(law, p, dt / 20);
    const LinearSpringDashpot undamped{law.k_N, 0.0};
    const HeadOn fine_elastic = measure_head_on(undamped, p, undamped.collision_time(m) / 1000);
    r.scalar("xi_max_over_vtcol_pi", fine.xi_max / (1.0 * t_col / M_PI), "1",
             "head-on free-wall xi_max over v_N t_col / pi, paper parameters (v_N = 1 m/s)");
    r.scalar("xi_max_over_vtcol_pi_elastic", fine_elastic.xi_max / (1.0 * undamped.collision_time(m) / M_PI), "1",
             "the same for gamma_N = 0");
    const HeadOn twin = measure_head_on(law, p, law.collision_time(0.5 * m) / p.real("steps_per_contact"), false);
    r.scalar("e_N_free_free", twin.e_N, "1", "head-on restitution of two free grains at the same gamma_N");
    r.scalar("e_N_wall_over_free", e_meas / twin.e_N, "1", "free-wall over free-free restitution (< 1: the wall dissipates more)");
    r.scalar("t_col_eq4", t_col, "s", "contact duration of a free-wall pair from Eq. (4)");
    r.scalar("e_N_eq4", law.restitution(m), "1", "e_N = exp(-gamma_N t_col/2)");
    r.scalar("t_col_measured", t_meas, "s", "head-on free-wall contact duration at the run's dt");
    r.scalar("e_N_measured", e_meas, "1", "head-on free-wall restitution at the run's dt");
    r.scalar("dt", dt, "s", "time step");

    const Peak pk = first_maximum(vy, curves[0].dvy);
    const Peak pkx = first_maximum(vy, curves[0].dvx);
    r.scalar("v_crit", pk.x, "m/s", "v_y^i at the maximum of Δv_y (Eq. 8's critical velocity)");
    r.scalar("dvy_max", pk.y, "m/s", "maximum of Δv_y");
    r.scalar("v_crit_dvx", pkx.x, "m/s", "v_y^i at the maximum of Δv_x");
    r.scalar("n_maxima_dvy", count_maxima(vy, curves[0].dvy), "1", "number of maxima of Δv_y(v_y^i)");
    r.scalar("n_maxima_dvx", count_maxima(vy, curves[0].dvx), "1", "number of maxima of Δv_x(v_y^i)");
    const double vmax = vy.back();
    const auto tail = fit_power_law(vy, curves[0].dvy, vmax / 10, vmax);
    const auto tailx = fit_power_law(vy, curves[0].dvx, vmax / 10, vmax);
    r.scalar("tail_exponent_dvy", tail.exponent, "1", "exponent of Δv_y ∝ v^a over the last decade of v_y^i");
    r.scalar("tail_exponent_dvy_err", tail.exponent_err, "1", "its standard error");
    r.scalar("tail_exponent_dvx", tailx.exponent, "1", "exponent of Δv_x ∝ v^a over the last decade");
    // Normal regime: Δv_y ∝ v_y^i below v_crit. Slope of log Δv_y over the lowest half decade.
    const auto low = fit_power_law(vy, curves[0].dvy, vy.front(), vy.front() * std::sqrt(10.0));
    r.scalar("low_v_exponent_dvy", low.exponent, "1", "exponent of Δv_y ∝ v^a over the lowest half decade");
    r.scalar("dt_fine_max_rel_diff", max_relative_difference(curves[1].dvy, curves[0].dvy), "1",
             "largest |Δv_y(dt/fine) - Δv_y(dt)| relative to max Δv_y");

    for (std::size_t b = 0; b < betas.size(); ++b) {
        const double sb = std::sqrt(betas[b]);
        const Curve& c = curves[5 + b];
        char label[32];
        std::snprintf(label, sizeof label, "beta%g", betas[b]);
        Table& tb = r.table(std::string("collapse_") + label,
                            "k' = beta k_N: raw and √β-scaled Δv_y (gamma scaled to keep e_N)");
        std::vector<double> v_raw(n), dvy_scaled(n), dvx_scaled(n);
        for (std::size_t i = 0; i < n; ++i) {
            v_raw[i] = vy[i] * sb;
            dvy_scaled[i] = c.dvy[i] / sb;
            dvx_scaled[i] = c.dvx[i] / sb;
        }
        tb.add("vy_i", "m/s").values = v_raw;
        tb.add("dvy", "m/s").values = c.dvy;
        tb.add("vy_i_scaled", "m/s").values = vy;
        tb.add("dvy_scaled", "m/s").values = dvy_scaled;
        tb.add("dvx_scaled", "m/s").values = dvx_scaled;
        r.scalar(std::string("collapse_max_rel_diff_") + label, max_relative_difference(dvy_scaled, curves[0].dvy), "1",
                 "largest deviation of the √β-scaled curve from Fig. 3, relative to max Δv_y");
        const Peak pb = first_maximum(v_raw, c.dvy);
        r.scalar(std::string("v_crit_") + label, pb.x, "m/s", "v_crit for k' = beta k_N");
        r.scalar(std::string("v_crit_ratio_over_sqrt_") + label, pb.x / pk.x / sb, "1",
                 "v_crit(beta k_N) / v_crit(k_N) / √β (Eq. 8 predicts 1)");
    }

    // The readings of Eq. (2) side by side: the figure's tail, its maximum, how far Δv_y has
    // come back towards the abscissa at vy_max, and the asymptotic exponents beyond the figure.
    Table& tr = r.table("readings", "Δv_y, Δv_x vs v_y^i per reading of F_N in Eq. (2), figure grid");
    Table& trx = r.table("readings_extended", "the same up to 10 vy_max (dt/10)");
    tr.add("vy_i", "m/s").values = vy;
    trx.add("vy_i", "m/s").values = vy_ext;
    for (std::size_t k = 0; k < kReadings.size(); ++k) {
        const std::string name = to_string(kReadings[k]);
        const Curve& c = curves[first_reading + 2 * k];
        const Curve& ce = curves[first_reading + 2 * k + 1];
        tr.add("dvy_" + name, "m/s").values = c.dvy;
        tr.add("dvx_" + name, "m/s").values = c.dvx;
        tr.add("dvy_shear_" + name, "m/s").values = c.dvy_shear;
        trx.add("dvy_" + name, "m/s").values = ce.dvy;
        trx.add("dvx_" + name, "m/s").values = ce.dvx;
        trx.add("dvy_shear_" + name, "m/s").values = ce.dvy_shear;
        const Peak pr = first_maximum(vy, c.dvy);
        r.scalar("eq2_" + name + "_v_crit", pr.x, "m/s", "v_y^i at the maximum of Δv_y, reading " + name);
        r.scalar("eq2_" + name + "_dvy_max", pr.y, "m/s", "maximum of Δv_y, reading " + name);
        r.scalar("eq2_" + name + "_tail_exponent_dvy", fit_power_law(vy, c.dvy, vmax / 10, vmax).exponent, "1",
                 "exponent of Δv_y over the last decade of the figure, reading " + name);
        r.scalar("eq2_" + name + "_tail_exponent_dvy_shear", fit_power_law(vy, c.dvy_shear, vmax / 10, vmax).exponent, "1",
                 "exponent of the shear part of Δv_y (Eq. 6) over the last decade of the figure, reading " + name);
        r.scalar("eq2_" + name + "_far_exponent_dvy_shear", fit_power_law(vy_ext, ce.dvy_shear, vext / 10, vext).exponent, "1",
                 "exponent of the shear part of Δv_y over [vy_max, 10 vy_max], reading " + name);
        r.scalar("eq2_" + name + "_tail_exponent_dvx", fit_power_law(vy, c.dvx, vmax / 10, vmax).exponent, "1",
                 "exponent of Δv_x over the last decade of the figure, reading " + name);
        r.scalar("eq2_" + name + "_dvy_end_over_max", c.dvy.back() / pr.y, "1",
                 "Δv_y at vy_max over its maximum (0: back at the abscissa), reading " + name);
        r.scalar("eq2_" + name + "_far_exponent_dvy", fit_power_law(vy_ext, ce.dvy, vext / 10, vext).exponent, "1",
                 "exponent of Δv_y over [vy_max, 10 vy_max], reading " + name);
        r.scalar("eq2_" + name + "_far_exponent_dvx", fit_power_law(vy_ext, ce.dvx, vext / 10, vext).exponent, "1",
                 "exponent of Δv_x over [vy_max, 10 vy_max], reading " + name);
        r.scalar("eq2_" + name + "_far_dvy_over_plateau", ce.dvy.back() / plateau, "1",
                 "Δv_y at 10 vy_max over the magnitude reading's straight-path limit, reading " + name);
    }

    double best = INFINITY;
    for (auto reading : kReadings)
        best = std::min(best, r.find_scalar("eq2_" + std::string(to_string(reading)) + "_tail_exponent_dvy")->value);
    r.scalar("eq2_steepest_tail_exponent_dvy", best, "1",
             "the steepest Δv_y tail over the figure's last decade among the readings of Eq. (2)");

    const Peak ph = first_maximum(vy, curves[2].dvy);
    r.scalar("hkk_v_crit", ph.x, "m/s", "v_crit with the Hertz-Kuwabara-Kono normal force");
    r.scalar("hkk_v_crit_over_linear", ph.x / pk.x, "1", "v_crit(HKK) / v_crit(linear)");
    r.scalar("hkk_n_maxima_dvy", count_maxima(vy, curves[2].dvy), "1", "maxima of Δv_y with HKK");
    r.scalar("hkk_tail_exponent_dvy", fit_power_law(vy, curves[2].dvy, vmax / 10, vmax).exponent, "1",
             "tail exponent of Δv_y with HKK");
    return r;
}

} // namespace

Experiment brake_failure() { return {"brake-failure", &validate, &run}; }

} // namespace granrepro::experiments
