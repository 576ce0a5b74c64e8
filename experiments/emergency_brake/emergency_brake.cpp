// emergency-brake: Schäfer & Wolf (1995) Figs. 4 and 5. A free grain is shot onto a row of
// touching wall grains with v_x^i towards the wall and v_y^i along it; each point is the mean
// over start positions spaced equally over one wall wavelength. Far in the brake-failure regime
// the grain ploughs through several wall grains and Δv_y rises again (the "emergency brake").
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "data/fields.hpp"
#include "analysis/curve_analysis.hpp"
#include "scenarios/impact_shot.hpp"
#include "harness/protocol.hpp"
#include "data/spec.hpp"
#include "experiments/common/columns.hpp"
#include "models/hertz_kuwabara_kono.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {

namespace {

// The catalog every output handle of emergency-brake registers with (data/outputs.hpp).
constexpr Outputs outputs{"emergency-brake"};

struct EmergencyBrakeSpec : ImpactShotSpec {
    double wall_spacing = 0;       // wall-grain centre distance, the wall's wavelength [m]
    double pipe_wall_spacing = 0;  // the bistable pipe's, for its impact curves [m]
    double x_start = 0;            // start line's distance from the wall grains' centres [m]
    long n_positions = 0;          // start positions over one wavelength
    std::vector<double> vx_list;   // v_x^i towards the wall [m/s]
    double vy_min = 0, vy_max = 0; // [m/s]
    int n_vy = 0;
    std::vector<double> kN_scan;   // further k_N at vx_list[0], e_N held [N/m]
    double hkk_xi_ref = 0;         // overlap at which the HKK series matches the linear law [m]
    GRANREPRO_FIELDS_BASE(ImpactShotSpec, wall_spacing, pipe_wall_spacing, x_start, n_positions, vx_list, vy_min,
                     vy_max, n_vy, kN_scan, hkk_xi_ref)
};

void validate(const ParameterSet& p) {
    const auto s = read_spec<EmergencyBrakeSpec>(p);
    const double dt = validate_free_wall_law(p, s);
    if (s.x_start < s.reach())
        p.reject("x_start", "the free grain would start overlapping the wall grains; must be at least (d_free + d_wall)/2 = " +
                                number_text(s.reach()) + " m");
    if (s.vy_min >= s.vy_max) p.reject(std::vector<std::string>{"vy_min", "vy_max"}, "vy_min must be below vy_max");
    // A wall: the free grain must not fit through the gap between two wall grains, or it never
    // comes back and each shot runs to max_steps.
    for (const auto& [name, spacing] : {std::pair{"wall_spacing", s.wall_spacing}, std::pair{"pipe_wall_spacing", s.pipe_wall_spacing}}) {
        if (spacing < s.d_wall * (1 - 1e-12))
            p.reject(std::vector<std::string>{name, "d_wall"}, std::string(name) + " must be at least d_wall (wall grains would overlap)");
        if (spacing - s.d_wall >= s.d_free)
            p.reject(std::vector<std::string>{name, "d_wall", "d_free"},
                     "the gap between wall grains (" + std::string(name) + " - d_wall) must be narrower than d_free");
    }
    double k_min = s.k_N, k_max = s.k_N;
    for (double k : s.kN_scan) { k_min = std::min(k_min, k); k_max = std::max(k_max, k); }
    const auto [vx_min, vx_max] = std::minmax_element(s.vx_list.begin(), s.vx_list.end());
    // The fastest shot must take several steps over a wall grain: at most d_wall/2 per step at
    // the softest law of the k_N scan (the largest dt).
    const double dt_max = dt * std::sqrt(s.k_N / k_min);
    if (!(dt_max <= max_impact_step(s.d_wall, std::max(s.vy_max, *vx_max))))
        p.reject(std::vector<std::string>{"vy_max", "vx_list", "kN_scan", "k_N", "m_free", "steps_per_contact"},
                 "vy_max and every v_x^i must be at most d_wall / (2 dt) = " + number_text(0.5 * s.d_wall / dt_max) +
                     " m/s (dt = " + number_text(dt_max) + " s at the softest k_N): faster grains skip through the wall");
    // A shot whose grain can reach a wall grain's centre goes through the wall and never comes
    // back: it runs to max_steps (vx_list=16 with the default kN_scan entry 200 took 22 s for five
    // such shots, issue 40) and its Δv_y means nothing, so its cost has no bound. The head-on
    // overlap peaks below v_x sqrt(m_free/k_N) (undamped; damping only lowers it).
    auto refuse_piercing = [&](double vx, double k, const char* law) {
        const double overlap = vx * std::sqrt(s.m_free / k);
        if (!(overlap < s.reach()))
            p.reject(std::vector<std::string>{"vx_list", law, "m_free", "d_free", "d_wall"},
                     "at v_x^i = " + number_text(vx) + " m/s and k_N = " + number_text(k) + " N/m (" + law +
                         ") the head-on overlap reaches v_x sqrt(m_free/k_N) = " + number_text(overlap) +
                         " m, not below (d_free + d_wall)/2 = " + number_text(s.reach()) +
                         " m: the grain can pass through the wall and its shots run to max_steps (" +
                         number_text(double(ImpactSetup{}.max_steps)) + " steps each); v_x^i must be below " +
                         number_text(s.reach() * std::sqrt(k / s.m_free)) + " m/s there");
    };
    refuse_piercing(*vx_max, s.k_N, "k_N");
    for (double k : s.kN_scan) refuse_piercing(s.vx_list.front(), k, "kN_scan");
    // The slowest shot: the smallest v_x^i from x_start to the wall and a diameter into it, at
    // the time step of the stiffest law of the k_N scan.
    limit_shot_steps(p, {"x_start", "d_free", "vx_list", "kN_scan", "k_N", "m_free", "steps_per_contact"},
                     s.x_start - s.reach() + s.d_free, *vx_min, dt * std::sqrt(s.k_N / k_max),
                     s.steps_per_contact * std::sqrt(k_max / s.k_N));
}

struct Point {
    double dvy = 0, dvy_sem = 0, contacts = 0, multi_fraction = 0;
    double vx_return = 0; // mean v_x^f / v_x^i: how much of the speed towards the wall comes back
    int incomplete = 0;
    GRANREPRO_FIELDS(dvy, dvy_sem, contacts, multi_fraction, vx_return, incomplete)
};

// One series' points over the v_y^i grid: a sweep point.
struct SeriesPoints {
    std::vector<Point> points;
    GRANREPRO_FIELDS(points)
};

// Series: one per v_x^i at the experiment's k_N (the figures), one per extra k_N at vx_list[0],
// one per v_x^i on the pipe's wall spacing (Fig. 6's construction needs the impact curves of the
// pipe's own wall), one per other reading of Eq. (2) and v_x^i, and one per v_x^i with the
// Hertz-Kuwabara-Kono normal force ("we used this force to check the generality of our results
// obtained with (1)", text after Eq. 3).
struct Series {
    double vx;
    LinearSpringDashpot law;
    CoulombShear shear;
    double spacing;
    std::string kind;      // its outputs' names end in kind then at (a word of series_kinds)
    double at;             // v_x^i, or k_N in the scan: "vx0.3", "kN200", "eq2_signed_vx0.3"
    std::string what;      // table description
    bool scan = false;     // k_N scan: only its maximum is reported
    std::optional<HertzKuwabaraKono> hkk = std::nullopt; // the normal force instead of law (law still sets dt)
};

std::vector<Series> all_series(const EmergencyBrakeSpec& s, const LinearSpringDashpot& law) {
    const double e_N = law.restitution(s.m_free);
    const CoulombShear shear = s.shear();
    const auto at = [](double vx) { return " at v_x^i = " + number_text(vx) + " m/s"; };
    std::vector<Series> series;
    for (double vx : s.vx_list)
        series.push_back({vx, law, shear, s.wall_spacing, "vx", vx, "mean over start positions" + at(vx)});
    for (double k : s.kN_scan)
        series.push_back({s.vx_list.front(), LinearSpringDashpot::from_restitution(k, e_N, s.m_free), shear, s.wall_spacing,
                          "kN", k, "k_N scan at the first v_x^i, e_N held fixed", true});
    if (s.pipe_wall_spacing != s.wall_spacing)
        for (double vx : s.vx_list)
            series.push_back({vx, law, shear, s.pipe_wall_spacing, "pipe_vx", vx, "on the pipe's wall spacing" + at(vx)});
    for (auto reading : kFrictionNormals)
        if (reading != shear.reading)
            for (double vx : s.vx_list)
                series.push_back({vx, law, CoulombShear{shear.mu, reading}, s.wall_spacing,
                                  std::string("eq2_") + to_string(reading) + "_vx", vx,
                                  std::string("reading ") + to_string(reading) + " of Eq. (2)" + at(vx)});
    const auto hkk = HertzKuwabaraKono::matched_at(law.k_N, law.gamma_N, s.hkk_xi_ref);
    for (double vx : s.vx_list)
        series.push_back({vx, law, shear, s.wall_spacing, "hkk_vx", vx,
                          "Hertz-Kuwabara-Kono normal force" + at(vx), false, hkk});
    return series;
}

// One point of a series: the mean over n_positions start positions spaced over one wavelength.
Point mean_impact(const EmergencyBrakeSpec& s, const Series& se, double vy) {
    ImpactSetup setup = s.shot(s.x_start, se.vx, vy, se.law.collision_time(s.m_free) / s.steps_per_contact);
    setup.wall_spacing = se.spacing;
    const long npos = s.n_positions;
    double sum = 0, sum2 = 0, contacts = 0, multi = 0, back = 0;
    Point out;
    for (long k = 0; k < npos; ++k) {
        setup.y0 = setup.wall_spacing * double(k) / double(npos);
        const ImpactOutcome o = se.hkk ? shoot(*se.hkk, se.shear, setup) : shoot(se.law, se.shear, setup);
        sum += o.dvy;
        sum2 += o.dvy * o.dvy;
        contacts += o.wall_grains;
        multi += o.wall_grains >= 2;
        back += (o.dvx - se.vx) / se.vx;
        out.incomplete += !o.completed;
    }
    const double mean = sum / double(npos);
    out.dvy = mean;
    out.dvy_sem = npos > 1 ? std::sqrt(std::max(0.0, sum2 / double(npos) - mean * mean) / double(npos - 1)) : 0.0;
    out.contacts = contacts / double(npos);
    out.multi_fraction = multi / double(npos);
    out.vx_return = back / double(npos);
    return out;
}

// What a series' names say before its v_x^i (or k_N): the kinds of all_series. Every reading of
// Eq. (2) is one, since which is the experiment's own (friction_normal) is chosen at run time; the
// k_N scan (kN) reports only its first maximum.
Words series_kinds(bool scan) {
    Words w{"vx"};
    if (scan) w.push_back("kN");
    w.push_back("pipe_vx");
    for (FrictionNormal f : kFrictionNormals) w.push_back(std::string("eq2_") + to_string(f) + "_vx");
    w.push_back("hkk_vx");
    return w;
}

// A table's description is its series' what, given where it is written.
const TableOut out_impacts = outputs.table("impacts_<w><n>", "", series_kinds(true));
const ScalarOut out_v_crit = outputs.scalar("v_crit_<w><n>", "m/s", "v_y^i at the first maximum of mean Δv_y", series_kinds(true));
const ScalarOut out_dvy_peak = outputs.scalar("dvy_peak_<w><n>", "m/s", "height of the first maximum", series_kinds(true));
const ScalarOut out_v_min = outputs.scalar("v_min_<w><n>", "m/s",
    "v_y^i where Δv_y is smallest after the first maximum (rise begins)", series_kinds(false));
const ScalarOut out_rise_ratio = outputs.scalar("rise_ratio_<w><n>", "1", "Δv_y at vy_max over its minimum after the peak",
    series_kinds(false));
const ScalarOut out_rise_z = outputs.scalar("rise_z_<w><n>", "1",
    "rise of Δv_y from its minimum after the peak to vy_max in units of its standard error", series_kinds(false));
const ScalarOut out_v_multi_onset = outputs.scalar("v_multi_onset_<w><n>", "m/s",
    "v_y^i at which the mean number of wall grains touched reaches 2", series_kinds(false));
const ScalarOut out_onset_over_vmin = outputs.scalar("onset_over_vmin_<w><n>", "1",
    "multi-contact onset over the start of the Δv_y rise", series_kinds(false));
const ScalarOut out_contacts_at_vmax = outputs.scalar("contacts_at_vmax_<w><n>", "1", "mean wall grains touched at vy_max",
    series_kinds(false));
const ScalarOut out_vx_return_at_vmax = outputs.scalar("vx_return_at_vmax_<w><n>", "1",
    "mean v_x^f / v_x^i at vy_max (the wall's return of the speed towards it)", series_kinds(false));

// Figs. 4 and 5 for one series: its table, the first maximum of Δv_y (brake failure sets in),
// the minimum after it and the rise to vy_max, and where multiple contacts set in.
void report_series(Result& r, const std::vector<double>& vy, const Series& se, const std::vector<Point>& pts) {
    const std::size_t n = vy.size();
    Table& t = r.table(out_impacts, {se.kind, se.at}, se.what);
    const auto dvy = column(pts, &Point::dvy), cont = column(pts, &Point::contacts);
    const auto back = column(pts, &Point::vx_return), sem = column(pts, &Point::dvy_sem);
    t.add({{"vy_i", "m/s", vy}, {"dvy", "m/s", dvy}, {"dvy_sem", "m/s", sem}, {"contacts", "1", cont},
           {"multi_fraction", "1", column(pts, &Point::multi_fraction)}, {"vx_return", "1", back}});

    const Peak pk = first_maximum(vy, dvy);
    std::size_t imin = std::size_t(std::max(pk.index, 0));
    for (std::size_t i = imin; i < n; ++i)
        if (dvy[i] < dvy[imin]) imin = i;
    r.put(out_v_crit, pk.x, {se.kind, se.at});
    r.put(out_dvy_peak, pk.y, {se.kind, se.at});
    if (se.scan) return;
    r.put(out_v_min, vy[imin], {se.kind, se.at});
    r.put(out_rise_ratio, dvy.back() / dvy[imin], {se.kind, se.at});
    // The paper says only that Δv_y "must ultimately increase again" (text before Fig. 4), so a
    // rise is judged against the sampling error of the 10-position mean at both ends: each point's
    // standard error over the start positions, independent between the two v_y^i.
    r.put(out_rise_z, (dvy.back() - dvy[imin]) / std::hypot(sem.back(), sem[imin]), {se.kind, se.at});
    // Fig. 5 plots the mean number of contacts; the multiple-contact regime starts where it reaches 2.
    const double onset = first_upward_crossing(vy, cont, 2.0);
    r.put(out_v_multi_onset, onset, {se.kind, se.at});
    r.put(out_onset_over_vmin, onset / vy[imin], {se.kind, se.at});
    r.put(out_contacts_at_vmax, cont.back(), {se.kind, se.at});
    r.put(out_vx_return_at_vmax, back.back(), {se.kind, se.at});
}

// v_crit and the peak height must grow with k_N (text below Fig. 5): 1 if they do over the
// experiment's k_N and the scan, at the first v_x^i.
double grows_with_kN(const Result& r, const EmergencyBrakeSpec& s) {
    std::vector<std::pair<double, std::string>> ks;
    ks.push_back({s.k_N, "vx" + number_text(s.vx_list.front())});
    for (double k : s.kN_scan) ks.push_back({k, "kN" + number_text(k)});
    std::sort(ks.begin(), ks.end());
    double monotone = 1;
    const auto at = [&](const char* name, std::size_t a) { return r.find_scalar(name + ks[a].second)->value; };
    for (std::size_t a = 1; a < ks.size(); ++a)
        monotone = monotone && at("v_crit_", a) > at("v_crit_", a - 1) && at("dvy_peak_", a) > at("dvy_peak_", a - 1);
    return monotone;
}

const ScalarOut out_incomplete_impacts = outputs.scalar("incomplete_impacts", "1",
    "impacts that had not ended within max_steps");
const ScalarOut out_e_N = outputs.scalar("e_N", "1", "free-wall restitution of the linear law, Eq. (4)");
const ScalarOut out_t_col = outputs.scalar("t_col", "s", "free-wall contact duration, Eq. (4)");
const ScalarOut out_v_crit_and_peak_grow_with_kN = outputs.scalar("v_crit_and_peak_grow_with_kN", "1",
    "1 if v_crit and the peak height increase with k_N");

// Figs. 4 and 5 as a protocol (harness/protocol.hpp): one sweep point per series (milliseconds
// each, so none is saved), in series order.
struct EmergencyBrake {
    static constexpr const char* name = outputs.experiment();
    static constexpr PointFiles files = PointFiles::None;
    using Spec = EmergencyBrakeSpec;
    using Outcome = SeriesPoints;
    struct Shared {
        LinearSpringDashpot law;
        std::vector<double> vy; // the v_y^i grid [m/s]
        std::vector<Series> series;
    };
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Shared prepare(const Spec& s, const RunContext&) {
        const LinearSpringDashpot law = s.law();
        return {law, log_space(s.vy_min, s.vy_max, s.n_vy), all_series(s, law)};
    }
    static std::vector<long> points(const Spec&, const Shared& sh) { return index_order(sh.series.size()); }
    static Outcome compute(const Spec& s, const Shared& sh, long si, const PointContext&) {
        SeriesPoints out;
        for (double vy : sh.vy) out.points.push_back(mean_impact(s, sh.series[std::size_t(si)], vy));
        return out;
    }
    static Result report(const Spec& s, const Shared& sh, const Swept<Outcome>& swept, const RunContext&) {
        Result r;
        int incomplete = 0;
        for (const auto& se : swept.outcomes)
            for (const auto& q : se.points) incomplete += q.incomplete;
        r.put(out_incomplete_impacts, incomplete);
        r.put(out_e_N, sh.law.restitution(s.m_free));
        r.put(out_t_col, sh.law.collision_time(s.m_free));
        for (std::size_t si = 0; si < sh.series.size(); ++si) report_series(r, sh.vy, sh.series[si], swept.outcomes[si].points);
        if (!s.kN_scan.empty())
            r.put(out_v_crit_and_peak_grow_with_kN, grows_with_kN(r, s));
        return r;
    }
};

} // namespace

Experiment emergency_brake() { return protocol_experiment<EmergencyBrake>(); }

} // namespace granrepro::experiments
