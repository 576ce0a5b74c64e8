// Collisions of the ED engine: the operator (Luding Eqs. (1)-(6); a wall is body 2 with m_2 =
// infinity) or, under the TC model (Eq. (7)), its elastic version changes velocities and spins;
// the inelastic-collapse guard watches collision rates; the observer gets a CollisionRecord.
// Round-off: pairs (and walls) found at or inside contact while approaching collide at once, so
// overlaps cannot accumulate; max_overlap() is the largest seen at an executed contact [m].
#pragma once
#include "core/collision_record.hpp"
#include "core/input_error.hpp"
#include "engines/ed/ed_cell_grid.hpp"
#include "engines/ed/ed_collision_operator.hpp"
#include "engines/ed/ed_config.hpp"
#include "engines/ed/ed_particles.hpp"
#include "engines/ed/ed_state.hpp"
#include "engines/hard_particle_engine.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace granrepro {

// The operator (an EdCollisionOperator) is used through its concept only.
template <EdCollisionOperator Collision>
class EdEventExecutor {
public:
    // Validates the parameters and builds the operators (the TC ones: law.elastic_version()).
    void setup(const BasicEdConfig<Collision>& cfg) {
        cfg.law.validate();
        if (!(cfg.t_c >= 0.0)) throw InputError("ED: t_c must be >= 0");
        t_c_ = cfg.t_c;
        tc_both_ = cfg.tc_both;
        collapse_limit_ = cfg.collapse_limit;
        law_ = cfg.law;
        law_tc_ = cfg.law.elastic_version(cfg.tc_keep_friction);
        rough_ = law_.frictional() || law_tc_.frictional();
        wlaw_.clear();
        wlaw_tc_.clear();
        for (const auto& wl : cfg.walls) {
            if ((wl.axis != 0 && wl.axis != 1) || (wl.side != 1 && wl.side != -1))
                throw InputError("ED: wall axis must be 0/1 and side +1/-1");
            const Collision l = cfg.law.against(wl);
            wlaw_.push_back(l);
            wlaw_tc_.push_back(l.elastic_version(cfg.tc_keep_friction));
            rough_ = rough_ || wlaw_.back().frictional() || wlaw_tc_.back().frictional();
        }
    }
    // Smooth runs skip the tangential algebra (the event loop is instantiated for both).
    bool rough() const { return rough_; }

    // Fixes the collapse guard's window for a run: collapse_window, or 1e-7 of the time a disk
    // needs to fly one mean diameter at the rms speed (or the free-fall speed over a diameter).
    void start_run(const EdParticles& ps, double t_now, double window) {
        if (window > 0.0) { window_ = window; return; }
        double v2 = 0.0, dsum = 0.0;
        for (std::size_t i = 0; i < ps.size(); ++i) {
            v2 += norm2(ps.velocity_at(static_cast<int>(i), t_now));
            dsum += 2.0 * ps.p[i].rad;
        }
        const double n = static_cast<double>(ps.size()), d = dsum / n;
        const double vref = std::max(std::sqrt(v2 / n), std::sqrt(std::hypot(ps.gx, ps.gy) * d));
        window_ = vref > 0.0 ? 1e-7 * d / vref : 0.0;
    }

    template <bool kRough, class Obs>
    void pair(EdParticles& ps, const EdCellGrid& grid, int i, int j, double t, Obs& obs) {
        ps.advance(i, t);
        ps.advance(j, t);
        auto &a = ps.p[i], &b = ps.p[j];
        double dx = a.x - b.x, dy = a.y - b.y;
        grid.min_image(dx, dy);
        const double dist = std::sqrt(dx * dx + dy * dy);
        max_overlap_ = std::max(max_overlap_, a.rad + b.rad - dist);
        const Vec2 n{dx / dist, dy / dist};
        // Eq. (7) speaks of one particle; EdConfig::tc_both says how a pair combines its partners.
        const bool el = tc_both_ ? (tc_elastic(ps, t, i) && tc_elastic(ps, t, j)) : (tc_elastic(ps, t, i) || tc_elastic(ps, t, j));
        const Vec2 vi{a.vx, a.vy}, vj{b.vx, b.vy};
        const auto res = (el ? law_tc_ : law_).template collide<kRough>(vi, ps.mw[i].w, ps.mw[i].m, a.rad, vj, ps.mw[j].w,
                                                                        ps.mw[j].m, b.rad, n);
        kick<kRough>(ps, i, res.dP, res.dw1, t);
        kick<kRough>(ps, j, -res.dP, res.dw2, t);
        ++pair_collisions_;
        elastic_ += el;
        a.last_partner = j;
        b.last_partner = i;
        if constexpr (!std::is_same_v<std::decay_t<Obs>, NoCollisionObserver>)
            obs(record(t, i, j, {a.x, a.y}, {a.x - dx, a.y - dy}, n, res.dP, vi - vj, el));
    }

    template <bool kRough, class Obs>
    void wall(EdParticles& ps, const EdWall& wl, int w, int i, double t, Obs& obs) {
        ps.advance(i, t);
        auto& a = ps.p[i];
        const Vec2 n = wl.axis == 0 ? Vec2{double(wl.side), 0.0} : Vec2{0.0, double(wl.side)};
        max_overlap_ = std::max(max_overlap_, a.rad - wl.side * ((wl.axis == 0 ? a.x : a.y) - wl.position));
        const bool el = tc_elastic(ps, t, i);
        const Vec2 vi{a.vx, a.vy};
        const auto res = (el ? wlaw_tc_ : wlaw_)[w].template collide<kRough>(vi, ps.mw[i].w, ps.mw[i].m, a.rad, Vec2{}, 0.0,
                                                                             EdParticles::kInf, 0.0, n);
        kick<kRough>(ps, i, res.dP, res.dw1, t);
        ++wall_collisions_;
        elastic_ += el;
        a.last_partner = -1 - w;
        if constexpr (!std::is_same_v<std::decay_t<Obs>, NoCollisionObserver>)
            obs(record(t, i, -1 - w, {a.x, a.y}, Vec2{a.x, a.y} - n * a.rad, n, res.dP, vi, el));
    }

    std::uint64_t pair_collisions() const { return pair_collisions_; }
    std::uint64_t wall_collisions() const { return wall_collisions_; }
    std::uint64_t elastic_collisions() const { return elastic_; }
    double max_overlap() const { return max_overlap_; }
    void save(BasicEdState<Collision>& s) const {
        s.pair_collisions = pair_collisions_; s.wall_collisions = wall_collisions_;
        s.elastic_collisions = elastic_; s.max_overlap = max_overlap_;
    }
    void restore(const BasicEdState<Collision>& s) {
        pair_collisions_ = s.pair_collisions; wall_collisions_ = s.wall_collisions;
        elastic_ = s.elastic_collisions; max_overlap_ = s.max_overlap;
    }

private:
    // Luding Eq. (7): i's previous collision happened at most t_c ago.
    bool tc_elastic(const EdParticles& ps, double t, int i) const { return t_c_ > 0.0 && t - ps.e[i].last_t <= t_c_; }
    // Applies i's share dP [kg m/s], dw [1/s] of a collision at t and feeds the collapse guard.
    template <bool kRough>
    void kick(EdParticles& ps, int i, Vec2 dP, double dw, double t) {
        ps.p[i].vx += dP.x / ps.mw[i].m;
        ps.p[i].vy += dP.y / ps.mw[i].m;
        if constexpr (kRough) ps.mw[i].w += dw;
        ++ps.p[i].count;
        auto& b = ps.e[i];
        if (t - b.burst_t0 > window_) {
            b.burst_t0 = t;
            b.burst_n = 0;
        }
        if (++b.burst_n > collapse_limit_) {
            std::ostringstream os;
            os << "ED: inelastic collapse: particle " << i << " took part in more than " << collapse_limit_
               << " collisions within " << window_ << " s (at t = " << t << " s); the collision rate "
               << "diverges. Use the TC model (t_c > 0, Luding Eq. 7) or weaker dissipation.";
            throw std::runtime_error(os.str());
        }
        b.last_t = t;
    }
    // dv: velocity of i relative to its partner before the collision.
    static CollisionRecord record(double t, int i, int j, Vec2 ri, Vec2 rj, Vec2 n, Vec2 dP, Vec2 dv, bool el) {
        const double vv = norm(dv);
        return {t, i, j, ri, rj, n, dP, vv > 0.0 ? std::fabs(cross(n, dv)) / vv : 0.0, el};
    }

    Collision law_, law_tc_;
    std::vector<Collision> wlaw_, wlaw_tc_;
    bool rough_ = false;
    double t_c_ = 0.0;
    bool tc_both_ = false;
    std::uint32_t collapse_limit_ = 0;
    double window_ = 0.0;
    std::uint64_t pair_collisions_ = 0, wall_collisions_ = 0, elastic_ = 0;
    double max_overlap_ = 0.0;
};

} // namespace granrepro
