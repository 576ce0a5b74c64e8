// brake-failure's reports: Fig. 3, the head-on Eq. (4) checks, the 1/v tail, the sqrt(beta)
// collapse and the readings of Eq. (2).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "experiments/brake_failure/spec.hpp"

namespace granrepro::experiments::brake_failure_detail {

const ScalarOut out_xi_max_over_vtcol_pi = outputs.scalar("xi_max_over_vtcol_pi", "1",
    "head-on free-wall xi_max over v_N t_col / pi, paper parameters (v_N = 1 m/s)");
const ScalarOut out_xi_max_over_vtcol_pi_elastic = outputs.scalar("xi_max_over_vtcol_pi_elastic", "1",
    "the same for gamma_N = 0");
const ScalarOut out_e_N_free_free = outputs.scalar("e_N_free_free", "1",
    "head-on restitution of two free grains at the same gamma_N");
const ScalarOut out_e_N_wall_over_free = outputs.scalar("e_N_wall_over_free", "1",
    "free-wall over free-free restitution (< 1: the wall dissipates more)");
const ScalarOut out_t_col_eq4 = outputs.scalar("t_col_eq4", "s", "contact duration of a free-wall pair from Eq. (4)");
const ScalarOut out_e_N_eq4 = outputs.scalar("e_N_eq4", "1", "e_N = exp(-gamma_N t_col/2)");
const ScalarOut out_t_col_measured = outputs.scalar("t_col_measured", "s",
    "head-on free-wall contact duration at the run's dt");
const ScalarOut out_e_N_measured = outputs.scalar("e_N_measured", "1", "head-on free-wall restitution at the run's dt");
const ScalarOut out_dt = outputs.scalar("dt", "s", "time step");

// Eq. (4) and the text below it, measured head-on (the points of HeadOnKind).
void report_head_on(Result& r, const ImpactShotSpec& s, const Sweep& w, const std::array<HeadOn, kHeadOns>& h) {
    const LinearSpringDashpot& law = w.law;
    const double m = s.m_free, t_col = law.collision_time(m);
    const HeadOn &head_on = h[kHeadOn], &fine = h[kHeadOnFine], &fine_elastic = h[kHeadOnElastic], &twin = h[kHeadOnTwin];
    // Text below Eq. (4): xi_max <= v_N t_col / pi, with equality for gamma_N = 0; and the m_red
    // in Eq. (1)'s dashpot makes free-wall collisions more dissipative than free-free ones.
    const LinearSpringDashpot undamped{law.k_N, 0.0};
    r.put(out_xi_max_over_vtcol_pi, fine.xi_max / (1.0 * t_col / M_PI));
    r.put(out_xi_max_over_vtcol_pi_elastic, fine_elastic.xi_max / (1.0 * undamped.collision_time(m) / M_PI));
    r.put(out_e_N_free_free, twin.e_N);
    r.put(out_e_N_wall_over_free, head_on.e_N / twin.e_N);
    r.put(out_t_col_eq4, t_col);
    r.put(out_e_N_eq4, law.restitution(m));
    r.put(out_t_col_measured, head_on.t_col);
    r.put(out_e_N_measured, head_on.e_N);
    r.put(out_dt, w.dt);
}

// Columns dvy<suffix>, dvx<suffix> and, with shear, dvy_shear<suffix> of a curve [m/s].
void add_curve(Table& t, const Curve& c, const std::string& suffix, bool shear = false) {
    t.add({{"dvy" + suffix, "m/s", c.dvy}, {"dvx" + suffix, "m/s", c.dvx}});
    if (shear) t.add("dvy_shear" + suffix, "m/s").values = c.dvy_shear;
}

// y at x0 by linear interpolation in log x on an increasing grid x (end values outside it).
double log_interpolate(const std::vector<double>& x, const std::vector<double>& y, double x0) {
    if (x0 <= x.front()) return y.front();
    for (std::size_t i = 1; i < x.size(); ++i)
        if (x0 <= x[i]) {
            const double u = std::log(x0 / x[i - 1]) / std::log(x[i] / x[i - 1]);
            return y[i - 1] + u * (y[i] - y[i - 1]);
        }
    return y.back();
}

// Exponent a of y ∝ x^a over the last decade of the grid x.
double tail_exponent(const std::vector<double>& x, const std::vector<double>& y) {
    return fit_power_law(x, y, x.back() / 10, x.back()).exponent;
}

const TableOut out_fig3 = outputs.table("fig3",
    "Δv_y and Δv_x vs v_y^i, one wall grain (linear law, dt = t_col/steps_per_contact)");
const ScalarOut out_v_crit = outputs.scalar("v_crit", "m/s",
    "v_y^i at the maximum of Δv_y (Eq. 8's critical velocity)");
const ScalarOut out_dvy_max = outputs.scalar("dvy_max", "m/s", "maximum of Δv_y");
const ScalarOut out_v_crit_dvx = outputs.scalar("v_crit_dvx", "m/s", "v_y^i at the maximum of Δv_x");
const ScalarOut out_n_maxima_dvy = outputs.scalar("n_maxima_dvy", "1", "number of maxima of Δv_y(v_y^i)");
const ScalarOut out_n_maxima_dvx = outputs.scalar("n_maxima_dvx", "1", "number of maxima of Δv_x(v_y^i)");
const ScalarOut out_tail_exponent_dvy = outputs.scalar("tail_exponent_dvy", "1",
    "exponent of Δv_y ∝ v^a over the last decade of v_y^i");
const ScalarOut out_tail_exponent_dvy_err = outputs.scalar("tail_exponent_dvy_err", "1", "its standard error");
const ScalarOut out_tail_exponent_dvx = outputs.scalar("tail_exponent_dvx", "1",
    "exponent of Δv_x ∝ v^a over the last decade");
const ScalarOut out_low_v_exponent_dvy = outputs.scalar("low_v_exponent_dvy", "1",
    "exponent of Δv_y ∝ v^a over the lowest half decade");
const ScalarOut out_low_v_exponent_dvx = outputs.scalar("low_v_exponent_dvx", "1",
    "exponent of Δv_x ∝ v^a over the lowest half decade");
const ScalarOut out_dt_fine_max_rel_diff = outputs.scalar("dt_fine_max_rel_diff", "1",
    "largest |Δv_y(dt/fine) - Δv_y(dt)| relative to max Δv_y");
const ScalarOut out_hkk_v_crit = outputs.scalar("hkk_v_crit", "m/s",
    "v_crit with the Hertz-Kuwabara-Kono normal force");
const ScalarOut out_hkk_v_crit_over_linear = outputs.scalar("hkk_v_crit_over_linear", "1",
    "v_crit(HKK) / v_crit(linear)");
const ScalarOut out_hkk_n_maxima_dvy = outputs.scalar("hkk_n_maxima_dvy", "1", "maxima of Δv_y with HKK");
const ScalarOut out_hkk_tail_exponent_dvy = outputs.scalar("hkk_tail_exponent_dvy", "1",
    "tail exponent of Δv_y with HKK");

// Panel (a): Δv_y, Δv_x against v_y^i, with dt / fine_factor and with HKK. Returns the maximum of Δv_y.
Peak report_fig3(Result& r, const Sweep& w, const std::vector<Curve>& curves) {
    const std::vector<double>& vy = w.vy;
    const Curve &c = curves[kFig3], &hkk = curves[kHkk];
    Table& t = r.table(out_fig3);
    t.add("vy_i", "m/s").values = vy;
    add_curve(t, c, "");
    add_curve(t, curves[kFine], "_fine");
    add_curve(t, hkk, "_hkk");

    const Peak pk = first_maximum(vy, c.dvy);
    r.put(out_v_crit, pk.x);
    r.put(out_dvy_max, pk.y);
    r.put(out_v_crit_dvx, first_maximum(vy, c.dvx).x);
    r.put(out_n_maxima_dvy, count_maxima(vy, c.dvy));
    r.put(out_n_maxima_dvx, count_maxima(vy, c.dvx));
    const double vmax = vy.back();
    const auto tail = fit_power_law(vy, c.dvy, vmax / 10, vmax);
    r.put(out_tail_exponent_dvy, tail.exponent);
    r.put(out_tail_exponent_dvy_err, tail.exponent_err);
    r.put(out_tail_exponent_dvx, tail_exponent(vy, c.dvx));
    // Normal regime: Δv_y ∝ v_y^i below v_crit. Slope of log Δv_y over the lowest half decade.
    const auto low = fit_power_law(vy, c.dvy, vy.front(), vy.front() * std::sqrt(10.0));
    r.put(out_low_v_exponent_dvy, low.exponent);
    r.put(out_low_v_exponent_dvx, fit_power_law(vy, c.dvx, vy.front(), vy.front() * std::sqrt(10.0)).exponent);
    r.put(out_dt_fine_max_rel_diff, max_relative_difference(curves[kFine].dvy, c.dvy));

    const Peak ph = first_maximum(vy, hkk.dvy);
    r.put(out_hkk_v_crit, ph.x);
    r.put(out_hkk_v_crit_over_linear, ph.x / pk.x);
    r.put(out_hkk_n_maxima_dvy, count_maxima(vy, hkk.dvy));
    r.put(out_hkk_tail_exponent_dvy, tail_exponent(vy, hkk.dvy));
    return pk;
}

// The straight-path limit of Δv_y [m/s] under the reading r of Eq. (2) (derivation below).
double straight_path_limit(const BrakeFailureSpec& s, const LinearSpringDashpot& law, FrictionNormal r) {
    const double reach = s.reach(), h = s.offset, yc = s.half_chord();
    if (r == FrictionNormal::Clipped) return NAN;
    const double f = r == FrictionNormal::Magnitude ? 1.0 : 0.0;
    return law.gamma_N * (f * s.mu * h * std::log(reach * reach / (h * h)) + 2 * (yc - h * std::atan(yc / h)));
}

// P of the least-squares fit y = P + A/x + B/x^2 over the last decade of x [units of y]: the
// expansion of Δv_y in 1/v_y^i beyond the maximum (the shear part's 1/v, Eqs. 6-8, and the path's
// deflection at second order).
double fit_limit_one_over_v(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] >= x.back() / 10) rows.push_back(i);
    if (rows.size() < 4) return NAN;
    Eigen::MatrixXd a(rows.size(), 3);
    Eigen::VectorXd b(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const double u = 1 / x[rows[k]];
        a.row(Eigen::Index(k)) << 1.0, u, u * u;
        b(Eigen::Index(k)) = y[rows[k]];
    }
    return a.colPivHouseholderQr().solve(b)(0);
}

// The 1/v argument of Eqs. (6)-(8) and why the damped law departs from it at high v_y.

const TableOut out_high_velocity = outputs.table("high_velocity",
    "Δv_y up to 10 vy_max: elastic limit (gamma_N = 0) and paper parameters");
const ScalarOut out_tail_exponent_dvy_elastic = outputs.scalar("tail_exponent_dvy_elastic", "1",
    "exponent of Δv_y ∝ v^a over the last decade of the extended grid, gamma_N = 0");
const ScalarOut out_tail_exponent_dvx_far = outputs.scalar("tail_exponent_dvx_far", "1",
    "exponent of Δv_x ∝ v^a over [vy_max, 10 vy_max], paper parameters");
const ScalarOut out_dvy_plateau_theory = outputs.scalar("dvy_plateau_theory", "m/s",
    "high-v_y limit of Δv_y under Eqs. (1)-(2) (straight path), reading ");
const ScalarOut out_dvy_limit_fit = outputs.scalar("dvy_limit_fit", "m/s",
    "P of a fit Δv_y = P + A/v + B/v^2 over [vy_max, 10 vy_max]");
const ScalarOut out_dvy_limit_over_plateau = outputs.scalar("dvy_limit_over_plateau", "1",
    "that fitted limit over the straight-path limit");
const ScalarOut out_dvy_far_over_plateau = outputs.scalar("dvy_far_over_plateau", "1",
    "Δv_y at 10 vy_max over that limit");

void report_high_velocity(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves) {
    const Curve &elastic = curves[kElasticExt], &paper = curves[kPaperExt];
    Table& t = r.table(out_high_velocity);
    t.add("vy_i", "m/s").values = w.vy_ext;
    add_curve(t, elastic, "_elastic");
    add_curve(t, paper, "");
    r.put(out_tail_exponent_dvy_elastic, tail_exponent(w.vy_ext, elastic.dvy));
    r.put(out_tail_exponent_dvx_far, tail_exponent(w.vy_ext, paper.dvx));
    // Why the damped law has no 1/v tail: at high v_y the path is straight and the dashpot force
    // gamma_N m dxi/dt does not vanish with the contact time. Along the path x = h, with
    // R = (d_free + d_wall)/2 and half-chord y_c = sqrt(R^2 - h^2), the friction of Eq. (2) and
    // the normal force's y-component give (integrating over y instead of t)
    //     Δv_y -> gamma_N [ f mu h ln(R^2/h^2) + 2 (y_c - h atan(y_c/h)) ],
    // a constant instead of zero. f is the share of the dashpot's friction impulse the reading of
    // Eq. (2) keeps: 1 for |F_N| (both halves of the contact), 0 for k_N xi and for signed F_N
    // (there the two halves cancel). The remaining terms fall
    // like 1/v_y^i, so the limit is read off a fit Δv_y = P + A/v + B/v^2 over the extended
    // grid's last decade. Clipped also clips the normal force itself, so its normal part differs
    // and has no limit here.
    const double plateau = straight_path_limit(s, w.law, s.friction_normal);
    const double limit = fit_limit_one_over_v(w.vy_ext, paper.dvy);
    r.put(out_dvy_plateau_theory, plateau, {}, std::string(to_string(s.friction_normal)));
    r.put(out_dvy_limit_fit, limit);
    r.put(out_dvy_limit_over_plateau, limit / plateau);
    r.put(out_dvy_far_over_plateau, paper.dvy.back() / plateau);
}

const TableOut out_collapse = outputs.table("collapse_beta<n>", "k' = beta k_N: raw and √β-scaled Δv_y (gamma scaled to keep e_N)");
const ScalarOut out_collapse_max_rel_diff = outputs.scalar("collapse_max_rel_diff_beta<n>", "1",
    "largest deviation of the √β-scaled curve from Fig. 3, relative to max Δv_y");
const ScalarOut out_v_crit_beta = outputs.scalar("v_crit_beta<n>", "m/s", "v_crit for k' = beta k_N");
const ScalarOut out_v_crit_ratio_over_sqrt = outputs.scalar("v_crit_ratio_over_sqrt_beta<n>", "1",
    "v_crit(beta k_N) / v_crit(k_N) / √β (Eq. 8 predicts 1)");

// The √β collapse of k' = beta k_N onto Fig. 3 (text below Fig. 3); pk is Fig. 3's maximum.
void report_collapse(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves,
                     const Peak& pk) {
    for (std::size_t b = 0; b < s.betas.size(); ++b) {
        const double sb = std::sqrt(s.betas[b]);
        const Curve& c = curves[kFirstBeta + b];
        Table& t = r.table(out_collapse, {s.betas[b]});
        const auto over_sb = [sb](double x) { return x / sb; };
        const auto v_raw = column(w.vy, [sb](double x) { return x * sb; });
        const auto dvy_scaled = column(c.dvy, over_sb), dvx_scaled = column(c.dvx, over_sb);
        t.add({{"vy_i", "m/s", v_raw}, {"dvy", "m/s", c.dvy}, {"vy_i_scaled", "m/s", w.vy},
               {"dvy_scaled", "m/s", dvy_scaled}, {"dvx_scaled", "m/s", dvx_scaled}});
        r.put(out_collapse_max_rel_diff, max_relative_difference(dvy_scaled, curves[kFig3].dvy), {s.betas[b]});
        const Peak pb = first_maximum(v_raw, c.dvy);
        r.put(out_v_crit_beta, pb.x, {s.betas[b]});
        r.put(out_v_crit_ratio_over_sqrt, pb.x / pk.x / sb, {s.betas[b]});
    }
}

// The readings of Eq. (2) name their families ("eq2_<w>_v_crit": eq2_magnitude_v_crit, ...).
Words reading_words() {
    Words w;
    for (FrictionNormal f : kFrictionNormals) w.push_back(to_string(f));
    return w;
}
ScalarOut eq2(const char* what, const char* unit, const char* description) {
    return outputs.scalar(std::string("eq2_<w>_") + what, unit, description, reading_words());
}
const ScalarOut out_eq2_v_crit = eq2("v_crit", "m/s", "v_y^i at the maximum of Δv_y");
const ScalarOut out_eq2_dvy_max = eq2("dvy_max", "m/s", "maximum of Δv_y");
const ScalarOut out_eq2_tail_exponent_dvy = eq2("tail_exponent_dvy", "1", "exponent of Δv_y over the last decade of the figure");
const ScalarOut out_eq2_tail_exponent_dvy_shear = eq2("tail_exponent_dvy_shear", "1",
    "exponent of the shear part of Δv_y (Eq. 6) over the last decade of the figure");
const ScalarOut out_eq2_far_exponent_dvy_shear = eq2("far_exponent_dvy_shear", "1",
    "exponent of the shear part of Δv_y over [vy_max, 10 vy_max]");
const ScalarOut out_eq2_tail_exponent_dvx = eq2("tail_exponent_dvx", "1", "exponent of Δv_x over the last decade of the figure");
const ScalarOut out_eq2_dvy_end_over_max = eq2("dvy_end_over_max", "1", "Δv_y at vy_max over its maximum (0: back at the abscissa)");
const ScalarOut out_eq2_far_exponent_dvy = eq2("far_exponent_dvy", "1", "exponent of Δv_y over [vy_max, 10 vy_max]");
const ScalarOut out_eq2_far_exponent_dvx = eq2("far_exponent_dvx", "1", "exponent of Δv_x over [vy_max, 10 vy_max]");
const ScalarOut out_eq2_far_dvy_over_plateau = eq2("far_dvy_over_plateau", "1",
    "Δv_y at 10 vy_max over the magnitude reading's straight-path limit");
const ScalarOut out_eq2_plateau_theory = eq2("plateau_theory", "m/s", "straight-path limit of Δv_y");
const ScalarOut out_eq2_limit_over_plateau = eq2("limit_over_plateau", "1",
    "P of a fit Δv_y = P + A/v + B/v^2 over [vy_max, 10 vy_max] over the straight-path limit");
const ScalarOut out_eq2_dvy_10vcrit_over_max = eq2("dvy_10vcrit_over_max", "1", "Δv_y at 10 v_crit over its maximum (1/v from the maximum: 0.1)");
const ScalarOut out_eq2_dvy_shear_10vcrit_over_max = eq2("dvy_shear_10vcrit_over_max", "1",
    "shear part of Δv_y (Eq. 6) at 10 times its own maximum's v_y^i over that maximum");
const TableOut out_readings_extended = outputs.table("readings_extended", "the same up to 10 vy_max (dt/10)");
const TableOut out_readings = outputs.table("readings",
    "Δv_y, Δv_x vs v_y^i per reading of F_N in Eq. (2), figure grid");
const ScalarOut out_eq2_steepest_tail_exponent_dvy = outputs.scalar("eq2_steepest_tail_exponent_dvy", "1",
    "the steepest Δv_y tail over the figure's last decade among the readings of Eq. (2)");

// Panels (b), (c): the readings of Eq. (2) side by side: the figure's tail, its maximum, how far
// Δv_y has come back towards the abscissa at vy_max, and the asymptotic exponents beyond the
// figure.
void report_readings(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves) {
    const double plateau = straight_path_limit(s, w.law, FrictionNormal::Magnitude);
    // Reading k: curve 2k on the figure's grid, 2k + 1 on the extended grid.
    const Curve* c = &curves[kFirstReading];
    for (std::size_t ext : {0, 1}) { // one table at a time: r.table() may move the tables made before
        Table& t = ext ? r.table(out_readings_extended)
                       : r.table(out_readings);
        t.add("vy_i", "m/s").values = ext ? w.vy_ext : w.vy;
        for (std::size_t k = 0; k < kFrictionNormals.size(); ++k)
            add_curve(t, c[2 * k + ext], std::string("_") + to_string(kFrictionNormals[k]), true);
    }
    double steepest = INFINITY;
    for (std::size_t k = 0; k < kFrictionNormals.size(); ++k) {
        const char* name = to_string(kFrictionNormals[k]);
        const std::string at = std::string(", reading ") + name;
        const auto put = [&](const ScalarOut& h, double value) { r.put(h, value, {name}, at); };
        const Curve &f = c[2 * k], &e = c[2 * k + 1];
        const Peak pr = first_maximum(w.vy, f.dvy);
        put(out_eq2_v_crit, pr.x);
        put(out_eq2_dvy_max, pr.y);
        const double tail = tail_exponent(w.vy, f.dvy);
        steepest = std::min(steepest, tail);
        put(out_eq2_tail_exponent_dvy, tail);
        put(out_eq2_tail_exponent_dvy_shear, tail_exponent(w.vy, f.dvy_shear));
        put(out_eq2_far_exponent_dvy_shear, tail_exponent(w.vy_ext, e.dvy_shear));
        put(out_eq2_tail_exponent_dvx, tail_exponent(w.vy, f.dvx));
        put(out_eq2_dvy_end_over_max, f.dvy.back() / pr.y);
        put(out_eq2_far_exponent_dvy, tail_exponent(w.vy_ext, e.dvy));
        put(out_eq2_far_exponent_dvx, tail_exponent(w.vy_ext, e.dvx));
        put(out_eq2_far_dvy_over_plateau, e.dvy.back() / plateau);
        const double own = straight_path_limit(s, w.law, kFrictionNormals[k]);
        put(out_eq2_plateau_theory, own);
        put(out_eq2_limit_over_plateau, fit_limit_one_over_v(w.vy_ext, e.dvy) / own);
        // Fig. 3's shape over the range it shows (one decade past the maximum): a 1/v fall from
        // the maximum (text after Eq. 7) leaves about a tenth of it at 10 v_crit; a floor leaves more.
        const Peak ps = first_maximum(w.vy, f.dvy_shear);
        put(out_eq2_dvy_10vcrit_over_max, log_interpolate(w.vy_ext, e.dvy, 10 * pr.x) / pr.y);
        put(out_eq2_dvy_shear_10vcrit_over_max, log_interpolate(w.vy_ext, e.dvy_shear, 10 * ps.x) / ps.y);
    }
    r.put(out_eq2_steepest_tail_exponent_dvy, steepest);
}

} // namespace granrepro::experiments::brake_failure_detail
