// brake-failure: Schäfer & Wolf (1995) Fig. 3. A free grain flies parallel to the wall line,
// 0.82 mm from the centre of a single wall grain, and grazes it; Δv_y and Δv_x against v_y^i.
// Besides the figure's curve it runs the paper's three robustness statements: the same curve with
// dt/100, the √β collapse of k' = β k_N, and the Hertz-Kuwabara-Kono normal force.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "engines/soft/few_body_engine.hpp"
#include "experiments/brake_failure/spec.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace brake_failure_detail {
namespace {


void validate(const ParameterSet& p) {
    const auto s = read_spec<BrakeFailureSpec>(p);
    const double dt = validate_free_wall_law(p, s);
    if (s.offset >= s.reach())
        p.reject(std::vector<std::string>{"offset", "d_free", "d_wall"}, "offset must be below (d_free + d_wall)/2 = " + number_text(s.reach()) + " m or the grains never touch");
    if (s.vy_min >= s.vy_max) p.reject(std::vector<std::string>{"vy_min", "vy_max"}, "vy_min must be below vy_max");
    // The slowest shot (vy_min, dt/fine_factor) starts 1e-3 d_free before contact and crosses the
    // chord 2 y_c; each shot must end within max_steps (d_free = 1e10 ran for ever).
    const double yc = s.half_chord();
    limit_shot_steps(p, {"d_free", "d_wall", "offset", "vy_min", "fine_factor", "k_N", "m_free", "steps_per_contact"},
                     1e-3 * s.d_free + 2 * yc, s.vy_min, dt / s.fine_factor, s.steps_per_contact * s.fine_factor);
    // The fastest shot (10 vy_max with dt/10) must take at least one step inside the contact
    // chord, or it passes through the wall grain unresolved (vy_max = 1e308 ran for ever).
    if (!(s.vy_max * dt <= 2 * yc))
        p.reject(std::vector<std::string>{"vy_max", "offset", "k_N", "m_free", "steps_per_contact"},
                 "at 10 vy_max with dt/10 = " + number_text(dt / 10) + " s the grain crosses the contact chord 2 y_c = " +
                     number_text(2 * yc) + " m in less than one time step; vy_max must be at most " +
                     number_text(2 * yc / dt) + " m/s");
    // The same for the speed towards the wall grain.
    if (!(s.vx_i * dt <= 2 * yc))
        p.reject(std::vector<std::string>{"vx_i", "offset", "k_N", "m_free", "steps_per_contact"},
                 "vx_i must be at most " + number_text(2 * yc / dt) + " m/s: at dt = " + number_text(dt) +
                     " s the grain would cross the contact chord 2 y_c in less than one time step");
}

// The Fig. 3 geometry: wall grain at the origin, free grain on the line x = offset, starting just
// before first contact.
ImpactSetup geometry(const BrakeFailureSpec& s, double vy, double dt) {
    ImpactSetup shot = s.shot(s.offset, s.vx_i, vy, dt);
    shot.y0 = -s.half_chord() - 1e-3 * s.d_free;
    return shot;
}

ImpactOutcome shoot_point(const BrakeFailureSpec& s, const Sweep& w, std::size_t c, std::size_t i) {
    const LinearSpringDashpot& law = w.law;
    const CoulombShear shear = s.shear();
    if (c == kFig3) return shoot(law, shear, geometry(s, w.vy[i], w.dt));
    if (c == kFine) return shoot(law, shear, geometry(s, w.vy[i], w.dt / s.fine_factor));
    if (c == kHkk) return shoot(w.hkk, shear, geometry(s, w.vy[i], w.dt));
    // At 10 vy_max a grazing contact lasts less than one step of t_col/50: resolve it with dt/10.
    if (c == kElasticExt) return shoot(LinearSpringDashpot{law.k_N, 0.0}, shear, geometry(s, w.vy_ext[i], w.dt / 10));
    if (c == kPaperExt) return shoot(law, shear, geometry(s, w.vy_ext[i], w.dt / 10));
    if (c < kFirstBeta) {
        const CoulombShear reading{shear.mu, kFrictionNormals[(c - kFirstReading) / 2]};
        if ((c - kFirstReading) % 2 == 1) return shoot(law, reading, geometry(s, w.vy_ext[i], w.dt / 10));
        return shoot(law, reading, geometry(s, w.vy[i], w.dt));
    }
    // k' = beta k_N with gamma' = sqrt(beta) gamma_N: time scales by 1/sqrt(beta), lengths are
    // unchanged, so velocities scale by sqrt(beta).
    const double beta = s.betas[c - kFirstBeta], sb = std::sqrt(beta);
    const LinearSpringDashpot scaled{law.k_N * beta, law.gamma_N * sb};
    return shoot(scaled, shear, geometry(s, w.vy[i] * sb, w.dt / sb));
}

// Head-on collision at time step dt of the free grain with the wall grain or with a free twin,
// starting 1 µm apart at 1 m/s: the contact's start and end events give t_col and e_N (Eq. 4),
// the step ends the largest overlap (text below Eq. 4).
HeadOn measure_head_on(const LinearSpringDashpot& law, const ImpactShotSpec& s, double dt, bool wall = true) {
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, s.shear(), dt);
    const double R = 0.5 * s.d_free, r = wall ? 0.5 * s.d_wall : R;
    eng.add_free({{R + r + 1e-6, 0.0}, {-1.0, 0.0}, R, s.m_free});
    if (wall) eng.add_fixed({{0.0, 0.0}, r});
    else eng.add_free({{0.0, 0.0}, {0.0, 0.0}, R, s.m_free});
    double xi_max = 0;
    for (long step = 0; step < 10'000'000 && eng.events().size() < 2; ++step) {
        eng.step();
        const auto& g = eng.grains();
        const double other = wall ? 0.0 : g[1].r.x;
        xi_max = std::max(xi_max, R + r - (g[0].r.x - other));
    }
    const auto& ev = eng.events();
    if (ev.size() < 2) return {};
    return {ev[1].t - ev[0].t, -ev[1].xi_dot / ev[0].xi_dot, xi_max};
}

// The head-on collision of that kind (HeadOnKind, spec.hpp).
HeadOn head_on_point(const BrakeFailureSpec& s, const Sweep& w, std::size_t kind) {
    const LinearSpringDashpot& law = w.law;
    if (kind == kHeadOn) return measure_head_on(law, s, w.dt);
    if (kind == kHeadOnFine) return measure_head_on(law, s, w.dt / 20);
    if (kind == kHeadOnElastic) {
        const LinearSpringDashpot undamped{law.k_N, 0.0};
        return measure_head_on(undamped, s, undamped.collision_time(s.m_free) / 1000);
    }
    return measure_head_on(law, s, law.collision_time(0.5 * s.m_free) / s.steps_per_contact, false);
}

} // namespace
} // namespace brake_failure_detail

using namespace brake_failure_detail;

namespace {

const ScalarOut out_incomplete_impacts = outputs.scalar("incomplete_impacts", "1",
    "impacts that had not ended within max_steps");

// Fig. 3 and its studies as a protocol (harness/protocol.hpp): one sweep point per curve, in
// curve order, then one per head-on collision of Eq. (4) (milliseconds each, so none is saved).
struct BrakeFailure {
    static constexpr const char* name = outputs.experiment();
    static constexpr PointFiles files = PointFiles::None;
    using Spec = BrakeFailureSpec;
    using Outcome = Point;
    using Shared = Sweep;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Sweep prepare(const Spec& s, const RunContext&) {
        const LinearSpringDashpot law = s.law();
        return {law, law.collision_time(s.m_free) / s.steps_per_contact, log_space(s.vy_min, s.vy_max, s.n_vy),
                log_space(s.vy_min, 10 * s.vy_max, s.n_vy), HertzKuwabaraKono::matched_at(law.k_N, law.gamma_N, s.hkk_xi_ref)};
    }
    static std::vector<long> points(const Spec& s, const Sweep&) { return index_order(curve_count(s) + kHeadOns); }
    static Point compute(const Spec& s, const Sweep& w, long c, const PointContext&) {
        Point point;
        if (std::size_t(c) >= curve_count(s)) {
            point.head_on = head_on_point(s, w, std::size_t(c) - curve_count(s));
            return point;
        }
        Curve& curve = point.curve;
        for (std::size_t i = 0; i < w.vy.size(); ++i) {
            const ImpactOutcome o = shoot_point(s, w, std::size_t(c), i);
            curve.dvy.push_back(o.dvy);
            curve.dvx.push_back(o.dvx);
            curve.dvy_shear.push_back(o.dvy_shear);
            curve.complete.push_back(o.completed);
        }
        return point;
    }
    static Result report(const Spec& s, const Sweep& w, const Swept<Point>& swept, const RunContext&) {
        std::vector<Curve> curves;
        std::array<HeadOn, kHeadOns> head_ons;
        for (std::size_t i = 0; i < swept.outcomes.size(); ++i)
            if (i < curve_count(s)) curves.push_back(swept.outcomes[i].curve);
            else head_ons[i - curve_count(s)] = swept.outcomes[i].head_on;
        Result r;
        int incomplete = 0;
        for (const auto& c : curves)
            for (int ok : c.complete) incomplete += !ok;
        r.put(out_incomplete_impacts, incomplete);
        const Peak pk = report_fig3(r, w, curves);
        report_high_velocity(r, s, w, curves);
        report_head_on(r, s, w, head_ons);
        report_collapse(r, s, w, curves, pk);
        report_readings(r, s, w, curves);
        return r;
    }
};

} // namespace

Experiment brake_failure() { return protocol_experiment<BrakeFailure>(); }

} // namespace granrepro::experiments
