// The ED engine's per-particle state. Clocks are lazy (Lubachevsky 1991): a particle's position
// and velocity are stored at its own time tau and advanced along its free flight (a parabola
// under gravity) only when one of its events is executed.
// Three arrays of records: a structure of arrays at the granularity of cache lines. Pure
// per-field arrays were measured 10-15% slower at N = 1e6: one event touches ~15 fields of a
// random particle, i.e. ~15 cache misses instead of 2-3.
#pragma once
#include "core/vec2.hpp"
#include "engines/ed/huge_page_allocator.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace granrepro {

struct EdParticles {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    static constexpr std::int32_t kNoPartner = std::numeric_limits<std::int32_t>::min();
    enum : std::uint8_t { kCollision = 0, kWall = 1, kCross = 2, kNone = 3 }; // EdState::event_kind

    // Everything the neighbour scan touches of a particle, in one cache line:
    struct alignas(64) Hot {
        double x, y;              // position at tau [m]
        double vx, vy;            // velocity at tau [m/s]
        double tau;               // local clock [s]
        double rad;               // radius [m]
        std::uint64_t count;      // collisions so far (stale-event detection)
        std::int32_t last_partner;
        std::int32_t next;        // next particle in the same cell, -1 = end
    };
    static_assert(sizeof(Hot) == 64);
    // Event bookkeeping of a particle, one cache line.
    struct alignas(64) Book {
        double ev_t = kInf;        // pending event time (the queue key) [s]
        double col_t = kInf;       // best predicted pair collision [s]
        std::uint64_t pcount = 0;  // partner's collision count at prediction
        double last_t = -kInf;     // last collision [s] (TC model, Eq. 7)
        double burst_t0 = -kInf;   // collapse-guard window start [s]
        std::int32_t partner = -1; // predicted partner, -1 none
        std::int32_t cell = 0;     // linked-list cell
        std::int32_t prev = -1;    // previous particle in the cell list
        std::uint32_t burst_n = 0; // collisions in the current guard window
        std::uint8_t kind = kNone; // pending event type
        std::uint8_t arg = 0;      // wall index or crossing direction
    };
    static_assert(sizeof(Book) == 64);
    struct Mw {
        double m = 0.0; // mass [kg]
        double w = 0.0; // spin [1/s]
    };

    HugeVector<Hot> p;
    HugeVector<Book> e;
    HugeVector<Mw> mw;
    double gx = 0.0, gy = 0.0; // uniform gravity [m/s^2]

    std::size_t size() const { return p.size(); }
    bool has_gravity() const { return gx != 0.0 || gy != 0.0; }
    void advance(int i, double t) {
        const double dt = t - p[i].tau;
        if (dt == 0.0) return;
        if (has_gravity()) {
            p[i].x += (p[i].vx + 0.5 * gx * dt) * dt;
            p[i].y += (p[i].vy + 0.5 * gy * dt) * dt;
            p[i].vx += gx * dt;
            p[i].vy += gy * dt;
        } else {
            p[i].x += p[i].vx * dt;
            p[i].y += p[i].vy * dt;
        }
        p[i].tau = t;
    }
    // Where i is at time t (unwrapped), without moving its clock.
    Vec2 position_at(int i, double t) const {
        const double dt = t - p[i].tau;
        return {p[i].x + (p[i].vx + 0.5 * gx * dt) * dt, p[i].y + (p[i].vy + 0.5 * gy * dt) * dt};
    }
    Vec2 velocity_at(int i, double t) const {
        const double dt = t - p[i].tau;
        return {p[i].vx + gx * dt, p[i].vy + gy * dt};
    }
    // Store i's best pair collision, dt [s] after its clock; j < 0: none.
    void set_pair(int i, double dt, int j) {
        e[i].partner = j;
        if (j >= 0) {
            e[i].col_t = p[i].tau + dt;
            e[i].pcount = p[j].count;
        } else {
            e[i].col_t = kInf;
        }
    }

    template <class S, class T>
    static std::vector<T> gather(const HugeVector<S>& v, T S::*f) {
        std::vector<T> out(v.size());
        for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i].*f;
        return out;
    }
    // f(EdState array, record array, member) for every per-particle field: listed once, so save
    // and restore cannot drift apart.
    template <class Ps, class State, class F>
    static void fields(Ps& ps, State& s, F&& f) {
        f(s.x, ps.p, &Hot::x); f(s.y, ps.p, &Hot::y); f(s.vx, ps.p, &Hot::vx); f(s.vy, ps.p, &Hot::vy);
        f(s.local_time, ps.p, &Hot::tau); f(s.radius, ps.p, &Hot::rad); f(s.collision_count, ps.p, &Hot::count);
        f(s.last_partner, ps.p, &Hot::last_partner); f(s.cell_next, ps.p, &Hot::next);
        f(s.predicted_time, ps.e, &Book::ev_t); f(s.collision_time, ps.e, &Book::col_t);
        f(s.partner_count, ps.e, &Book::pcount); f(s.last_collision_time, ps.e, &Book::last_t);
        f(s.burst_start, ps.e, &Book::burst_t0); f(s.partner, ps.e, &Book::partner); f(s.cell, ps.e, &Book::cell);
        f(s.cell_prev, ps.e, &Book::prev); f(s.burst_count, ps.e, &Book::burst_n); f(s.event_kind, ps.e, &Book::kind);
        f(s.event_arg, ps.e, &Book::arg); f(s.mass, ps.mw, &Mw::m); f(s.spin, ps.mw, &Mw::w);
    }
    template <class State> // a BasicEdState
    void save(State& s) const {
        fields(*this, s, [](auto& v, const auto& a, auto m) { v = gather(a, m); });
    }
    // Returns false when the arrays of s differ in size.
    template <class State>
    bool restore(const State& s) {
        const std::size_t n = s.x.size();
        bool same = true;
        fields(*this, s, [&](const auto& v, auto&, auto) { same = same && v.size() == n; });
        if (!same) return false;
        p.assign(n, Hot{});
        e.assign(n, Book{});
        mw.assign(n, Mw{});
        fields(*this, s, [n](const auto& v, auto& a, auto m) { for (std::size_t i = 0; i < n; ++i) a[i].*m = v[i]; });
        return true;
    }
};

} // namespace granrepro
