// Few-body soft-sphere integrator for binary-impact studies (Schäfer & Wolf 1995, Figs. 3-5, and
// the analytic two-grain tests of every contact law).
//
// Within a step the equations of motion are integrated with classical RK4 with the set of
// touching pairs held fixed. A contact law is smooth while a pair touches and switches on or off
// when the overlap changes sign; integrating across that switch would cost one order of accuracy
// (the dashpot force jumps from 0 to gamma m_red v_N). So each step is split at the first sign
// change of any pair's overlap, found on the cubic Hermite interpolant of xi(t), and the pair's
// contact is toggled there. The result is accurate to O(dt^4) including the contact boundaries,
// which is what makes Eq. (5)'s "1e-4 at dt = t_col/50" attainable. Every contact start and end is
// logged with its time and normal velocity, so tests can read t_col and e_N off the log.
//
// Template parameters: NormalLaw has normal_force(xi, xi_dot, m_red) -> NormalForce; ShearLaw has
// applied_normal(NormalForce) and shear_force(NormalForce, v_S). Both are small value structs in
// src/models/. A shear law with history (models/stateful_shear.hpp, e.g. Luding's tangential
// spring, Eq. 13) gets its per-contact state from the engine: created at 0 when a contact begins,
// integrated as d(state)/dt = v_S by the same RK4 stages as the grains, held by the law after
// every (sub)step, and removed when the contact ends.
#pragma once
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/interrupt.hpp"
#include "core/vec2.hpp"
#include "engines/soft/hermite_crossing.hpp"
#include "engines/soft/soft_grain.hpp"
#include "models/normal_force.hpp"
#include "models/stateful_shear.hpp"

namespace granrepro {

// Who grain i touches: another free grain, a fixed grain, or grain k of a row.
struct Partner {
    enum class Kind { Free, Fixed, Row } kind = Kind::Free;
    int index = 0; // free/fixed grain index, or row index
    long k = 0;    // position in the row
    friend bool operator==(const Partner&, const Partner&) = default;
};

struct ContactEvent {
    double t = 0;       // time of the sign change of xi [s]
    int i = 0;          // free grain
    Partner partner;    //
    bool begins = true; // contact starts (true) or ends (false)
    double xi_dot = 0;  // d(xi)/dt at that instant [m/s]: approach speed at a start, -(rebound) at an end
};

template <class NormalLaw, class ShearLaw>
class FewBodyEngine {
public:
    FewBodyEngine(NormalLaw normal, ShearLaw shear, double dt, Vec2 gravity = {})
        : normal_(normal), shear_(shear), dt_(dt), gravity_(gravity) {
        if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
    }

    int add_free(const SoftGrain& g) { grains_.push_back(g); return int(grains_.size()) - 1; }
    void add_fixed(const FixedGrain& g) { fixed_.push_back(g); }
    void add_row(const GrainRow& row) { rows_.push_back(row); }

    double time() const { return t_; }
    double dt() const { return dt_; }
    const std::vector<SoftGrain>& grains() const { return grains_; }
    const std::vector<ContactEvent>& events() const { return events_; }
    std::size_t active_contacts() const { return active_.size(); }
    // Velocity change of free grain i caused by shear forces alone and by normal forces alone
    // since the start [m/s]: the RK4-weighted sums of the stage forces, so that together with
    // gravity they add up to the grain's velocity change (Eq. (6) asks for the shear part).
    Vec2 shear_dv(int i) const { return i < int(shear_dv_.size()) ? shear_dv_[std::size_t(i)] : Vec2{}; }
    Vec2 normal_dv(int i) const { return i < int(normal_dv_.size()) ? normal_dv_[std::size_t(i)] : Vec2{}; }

    // Advance by one time step dt.
    void step() {
        if ((++steps_ & 4095) == 0) engine_pause_point();
        double remaining = dt_;
        // Each pass either finishes the step or toggles one contact; a bound guards against a
        // pathological sequence of switches.
        for (int pass = 0; remaining > 0.0; ++pass) {
            if (pass > 1000) throw std::runtime_error("few-body engine: contact switching did not settle");
            collect_candidates(remaining);
            trial_ = grains_;
            rk4(trial_, remaining, state_trial_);
            double first = remaining;
            int which = -1;
            for (std::size_t c = 0; c < candidates_.size(); ++c) {
                const bool touching = is_active(candidates_[c]);
                const Geometry a = geometry(grains_, candidates_[c]);
                const Geometry b = geometry(trial_, candidates_[c]);
                const HermiteSegment seg{remaining, a.xi, a.xi_dot, b.xi, b.xi_dot};
                const auto root = first_crossing(
                    seg, touching ? CrossingDirection::Downward : CrossingDirection::Upward);
                if (root && *root < first) {
                    first = *root;
                    which = int(c);
                }
            }
            if (which < 0) {
                book_impulses(remaining); // the stage accelerations are still the trial's
                std::swap(grains_, trial_);
                commit_state();
                t_ += remaining;
                remaining = 0.0;
                break;
            }
            rk4(grains_, first, state_trial_);
            book_impulses(first);
            commit_state();
            t_ += first;
            remaining -= first;
            toggle(candidates_[which]);
        }
        // A force the step cannot resolve (an absurd friction or stiffness) sends the grains to
        // inf/NaN, where no contact ever ends and every later step would be wasted.
        for (const SoftGrain& g : grains_)
            if (!std::isfinite(g.r.x) || !std::isfinite(g.r.y) || !std::isfinite(g.v.x) || !std::isfinite(g.v.y))
                throw std::runtime_error("few-body engine: the grains' positions or velocities are no longer finite after " +
                                         std::to_string(steps_) + " steps; the time step does not resolve the contact forces");
    }

private:
    struct Pair {
        int i;
        Partner partner;
        friend bool operator==(const Pair&, const Pair&) = default;
    };
    struct Geometry {
        Vec2 n;        // unit normal from partner to i
        double xi;     // overlap [m]
        double xi_dot; // d(xi)/dt [m/s]
        double v_s;    // tangential relative velocity of i along perp(n) [m/s]
        double m_red;  // [kg]
    };

    Vec2 partner_position(const std::vector<SoftGrain>& g, const Partner& p) const {
        switch (p.kind) {
        case Partner::Kind::Free: return g[p.index].r;
        case Partner::Kind::Fixed: return fixed_[p.index].r;
        default: return rows_[p.index].centre(p.k);
        }
    }
    double partner_radius(const Partner& p) const {
        switch (p.kind) {
        case Partner::Kind::Free: return grains_[p.index].radius;
        case Partner::Kind::Fixed: return fixed_[p.index].radius;
        default: return rows_[p.index].radius;
        }
    }

    Geometry geometry(const std::vector<SoftGrain>& g, const Pair& p) const {
        const SoftGrain& a = g[p.i];
        const Vec2 rb = partner_position(g, p.partner);
        const Vec2 vb = p.partner.kind == Partner::Kind::Free ? g[p.partner.index].v : Vec2{};
        const Vec2 d = a.r - rb;
        const double dist = norm(d);
        const Vec2 n = d / dist;
        const Vec2 vrel = a.v - vb;
        double m_red = a.mass;
        if (p.partner.kind == Partner::Kind::Free) {
            const double mb = g[p.partner.index].mass;
            m_red = a.mass * mb / (a.mass + mb);
        }
        return {n, a.radius + partner_radius(p.partner) - dist, -dot(vrel, n), dot(vrel, perp(n)), m_red};
    }

    static constexpr bool kStateful = StatefulShear<ShearLaw>;

    // Normal and shear force on grain i of active contact c [N], for the contacts' shear states
    // `state` (stateful laws only); the contact's v_S goes to *v_s when asked.
    std::pair<Vec2, Vec2> pair_forces(const std::vector<SoftGrain>& g, std::size_t c, const double* state,
                                      double* v_s = nullptr) const {
        const Geometry geo = geometry(g, active_[c]);
        const NormalForce f = normal_.normal_force(geo.xi, geo.xi_dot, geo.m_red);
        const double fn = shear_.applied_normal(f);
        double fs;
        if constexpr (kStateful) fs = shear_.shear_force(f, geo.v_s, state[c]);
        else fs = shear_.shear_force(f, geo.v_s);
        if (v_s) *v_s = geo.v_s;
        return {geo.n * fn, perp(geo.n) * fs};
    }

    // Accelerations of all free grains; the shear part alone goes to shear_acc as well. For a
    // stateful shear law, `state` is the contacts' shear state at this stage and rate receives
    // its time derivative v_S.
    void accelerations(const std::vector<SoftGrain>& g, std::vector<Vec2>& acc, std::vector<Vec2>& shear_acc,
                       const std::vector<double>& state, std::vector<double>& rate) const {
        acc.assign(g.size(), gravity_);
        shear_acc.assign(g.size(), Vec2{});
        if constexpr (kStateful) rate.resize(active_.size());
        for (std::size_t c = 0; c < active_.size(); ++c) {
            const Pair& p = active_[c];
            const auto [fn, fs] = pair_forces(g, c, state.data(), kStateful ? &rate[c] : nullptr);
            const Vec2 f = fn + fs;
            acc[p.i] += f / g[p.i].mass;
            shear_acc[p.i] += fs / g[p.i].mass;
            if (p.partner.kind == Partner::Kind::Free) {
                acc[p.partner.index] -= f / g[p.partner.index].mass;
                shear_acc[p.partner.index] -= fs / g[p.partner.index].mass;
            }
        }
    }

    // Classical RK4 for x' = v, v' = a(x, v) (and state' = v_S for a stateful shear law, into
    // state_out) with the active contact set frozen. The stage buffers are members so that a step
    // allocates nothing.
    void rk4(std::vector<SoftGrain>& g, double h, std::vector<double>& state_out) {
        const std::size_t n = g.size();
        g0_ = g;
        s_ = g;
        v2_.resize(n);
        v3_.resize(n);
        v4_.resize(n);
        // The contacts' shear state at a stage: state + c * h * rate (stateful laws only).
        const auto stage_state = [&](double c, const std::vector<double>& rate) {
            if constexpr (kStateful)
                for (std::size_t k = 0; k < state_.size(); ++k) stage_[k] = state_[k] + c * h * rate[k];
        };
        stage_ = state_;
        accelerations(s_, a1_, b1_, stage_, r1_);
        for (std::size_t i = 0; i < n; ++i) { s_[i].r = g0_[i].r + 0.5 * h * g0_[i].v; s_[i].v = g0_[i].v + 0.5 * h * a1_[i]; }
        for (std::size_t i = 0; i < n; ++i) v2_[i] = s_[i].v;
        stage_state(0.5, r1_);
        accelerations(s_, a2_, b2_, stage_, r2_);
        for (std::size_t i = 0; i < n; ++i) { s_[i].r = g0_[i].r + 0.5 * h * v2_[i]; s_[i].v = g0_[i].v + 0.5 * h * a2_[i]; }
        for (std::size_t i = 0; i < n; ++i) v3_[i] = s_[i].v;
        stage_state(0.5, r2_);
        accelerations(s_, a3_, b3_, stage_, r3_);
        for (std::size_t i = 0; i < n; ++i) { s_[i].r = g0_[i].r + h * v3_[i]; s_[i].v = g0_[i].v + h * a3_[i]; }
        for (std::size_t i = 0; i < n; ++i) v4_[i] = s_[i].v;
        stage_state(1.0, r3_);
        accelerations(s_, a4_, b4_, stage_, r4_);
        for (std::size_t i = 0; i < n; ++i) {
            g[i].r = g0_[i].r + (h / 6.0) * (g0_[i].v + 2.0 * v2_[i] + 2.0 * v3_[i] + v4_[i]);
            g[i].v = g0_[i].v + (h / 6.0) * (a1_[i] + 2.0 * a2_[i] + 2.0 * a3_[i] + a4_[i]);
        }
        if constexpr (kStateful) {
            state_out.resize(state_.size());
            for (std::size_t k = 0; k < state_.size(); ++k)
                state_out[k] = state_[k] + (h / 6.0) * (r1_[k] + 2.0 * r2_[k] + 2.0 * r3_[k] + r4_[k]);
        }
    }

    // Takes the shear state of the last rk4() call (its grains are now grains_), held by the law:
    // Eq. (13)'s spring is kept at most mu f_n / k_t long.
    void commit_state() {
        if constexpr (kStateful) {
            state_.swap(state_trial_);
            for (std::size_t c = 0; c < active_.size(); ++c) {
                const Geometry geo = geometry(grains_, active_[c]);
                state_[c] = shear_.hold(normal_.normal_force(geo.xi, geo.xi_dot, geo.m_red), state_[c]);
            }
        }
    }

    // Adds the last rk4() call's velocity change, split into its shear and normal parts.
    void book_impulses(double h) {
        const std::size_t n = grains_.size();
        shear_dv_.resize(n);
        normal_dv_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2 total = (h / 6.0) * (a1_[i] + 2.0 * a2_[i] + 2.0 * a3_[i] + a4_[i]) - h * gravity_;
            const Vec2 shear = (h / 6.0) * (b1_[i] + 2.0 * b2_[i] + 2.0 * b3_[i] + b4_[i]);
            shear_dv_[i] += shear;
            normal_dv_[i] += total - shear;
        }
    }

    bool is_active(const Pair& p) const {
        return std::find(active_.begin(), active_.end(), p) != active_.end();
    }

    void toggle(const Pair& p) {
        const auto it = std::find(active_.begin(), active_.end(), p);
        const Geometry geo = geometry(grains_, p);
        const bool begins = it == active_.end();
        if (begins) {
            active_.push_back(p);
            if constexpr (kStateful) state_.push_back(0.0); // the spring is put in at length 0
        } else {
            if constexpr (kStateful) state_.erase(state_.begin() + (it - active_.begin())); // and removed
            active_.erase(it);
        }
        events_.push_back({t_, p.i, p.partner, begins, geo.xi_dot});
    }

    // Pairs that touch now or could touch within time h (straight-line bound plus gravity).
    void collect_candidates(double h) {
        candidates_.clear();
        for (const auto& p : active_) candidates_.push_back(p);
        auto consider = [&](const Pair& p, double reach) {
            if (is_active(p)) return;
            const Geometry geo = geometry(grains_, p);
            if (-geo.xi < reach) candidates_.push_back(p);
        };
        double vmax = 0.0;
        for (const auto& g : grains_) vmax = std::max(vmax, norm(g.v));
        const double reach = 2.0 * (2.0 * vmax * h + norm(gravity_) * h * h) + 1e-15;
        for (int i = 0; i < int(grains_.size()); ++i) {
            for (int j = i + 1; j < int(grains_.size()); ++j)
                consider({i, {Partner::Kind::Free, j, 0}}, reach);
            for (int f = 0; f < int(fixed_.size()); ++f)
                consider({i, {Partner::Kind::Fixed, f, 0}}, reach);
            for (int r = 0; r < int(rows_.size()); ++r) {
                const GrainRow& row = rows_[r];
                const double span = grains_[i].radius + row.radius + reach;
                const double lo_k = std::floor((grains_[i].r.y - span - row.y0) / row.spacing);
                const double hi_k = std::ceil((grains_[i].r.y + span - row.y0) / row.spacing);
                // Checked before the conversion to long, which overflows for a grain far out.
                if (!(hi_k - lo_k <= 1e6 && std::abs(lo_k) < 1e15))
                    throw std::runtime_error("few-body engine: a grain could reach " + std::to_string(hi_k - lo_k) +
                                             " wall grains within one step; the time step does not resolve its motion");
                const long lo = long(lo_k), hi = long(hi_k);
                for (long k = lo; k <= hi; ++k) consider({i, {Partner::Kind::Row, r, k}}, reach);
            }
        }
    }

    NormalLaw normal_;
    ShearLaw shear_;
    double dt_;
    Vec2 gravity_;
    double t_ = 0.0;
    unsigned long steps_ = 0; // counts step() calls for the pause point
    std::vector<SoftGrain> grains_;
    std::vector<FixedGrain> fixed_;
    std::vector<GrainRow> rows_;
    std::vector<Pair> active_;
    std::vector<Pair> candidates_;
    std::vector<ContactEvent> events_;
    std::vector<SoftGrain> trial_, g0_, s_;   // scratch of step() and rk4()
    std::vector<Vec2> a1_, a2_, a3_, a4_, b1_, b2_, b3_, b4_, v2_, v3_, v4_;
    std::vector<Vec2> shear_dv_, normal_dv_;
    // Shear state per active contact (same order as active_; stateful shear laws only), its value
    // after the last rk4() call, and RK4's stage values and rates.
    std::vector<double> state_, state_trial_, stage_, r1_, r2_, r3_, r4_;
};

} // namespace granrepro
