// Event prediction of the ED engine from the flights in EdParticles (roots: flight_roots.hpp).
// It only reads the state (the engine commits and queues), so tests and diagnostics can ask it too.
// Of the configuration (a BasicEdConfig, whatever its operator) it reads the walls only.
// One pending event per particle (Lubachevsky 1991): the earliest of its best pair collision,
// wall contact and cell exit. A pair prediction remembers the partner's collision count; if the
// partner collided in between, the event is stale. On entering a new cell only the newly
// adjacent cells are scanned: the stored best pair (if still valid) is already the minimum over
// the old neighbourhood. Why this finds every collision: a collision i-j is always the stored
// best of i or of j at the moment it becomes the earlier of their pending events, because
// whoever changed trajectory or cell last scanned the other.
// Two disks whose latest collisions were with each other are never predicted against each other
// (their relative motion is a straight line away from contact, gravity cancelling), which
// removes grazing re-collision loops.
#pragma once
#include "engines/ed/ed_cell_grid.hpp"
#include "engines/ed/ed_particles.hpp"
#include "engines/ed/ed_wall.hpp"
#include "engines/ed/flight_roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace granrepro {

template <class Config>
class EdEventPredictor {
public:
    static constexpr double kInf = EdParticles::kInf;
    struct PairEvent { double t = kInf; int i = -1, j = -1; }; // an earliest pair collision at t [s]
    struct Pair { double dt; int j; bool replace; }; // partner j (-1 none) dt [s] after i's clock
    struct Event { double t; std::uint8_t kind, arg; }; // [s]; kind and arg as in EdParticles::Book

    EdEventPredictor(const EdParticles& ps, const EdCellGrid& grid, const Config& cfg)
        : ps_(ps), grid_(grid), cfg_(cfg) {}

    // Best pair collision of i, scanning all neighbour cells at its own clock.
    Pair pair(int i) const {
        const Probe p = own(i);
        Pair best{kInf, -1, true};
        grid_.for_neighbours(ps_.e[i].cell, [&](int c) { scan_cell(p, grid_.head(c), best); });
        return best;
    }
    // After i entered its cell across face dir; replace = false keeps the stored prediction.
    Pair pair_after_crossing(int i, int dir) const {
        const auto& b = ps_.e[i];
        if (b.partner >= 0 && ps_.p[b.partner].count != b.pcount) return pair(i);
        const Probe p = own(i);
        Pair best{kInf, -1, false};
        grid_.for_entered(b.cell, dir, [&](int c) { scan_cell(p, grid_.head(c), best); });
        best.replace = best.j >= 0 && ps_.p[i].tau + best.dt < b.col_t;
        return best;
    }
    // The stored pair collision against wall contacts and cell exits: the earliest wins.
    Event next_event(int i) const {
        const auto& h = ps_.p[i];
        double best = ps_.e[i].col_t;
        std::uint8_t kind = ps_.e[i].partner >= 0 ? EdParticles::kCollision : EdParticles::kNone, arg = 0;
        // When the gap between i's edge (off [m] in from its centre) and the line c = at, i on
        // the side s (+1 above), closes; s = -1 mirrors the flight.
        auto closes = [&](int axis, double s, double at, double off, std::uint8_t k, std::size_t a) {
            const double c = axis == 0 ? h.x : h.y, u = axis == 0 ? h.vx : h.vy, g = axis == 0 ? ps_.gx : ps_.gy;
            const double t = h.tau + flight_roots::gap_closing_time(s * (c - at) - off, s * u, s * g);
            if (t < best) { best = t; kind = k; arg = static_cast<std::uint8_t>(a); }
        };
        for (std::size_t w = 0; w < cfg_.walls.size(); ++w) {
            const EdWall& wl = cfg_.walls[w];
            if (wl.enabled) closes(wl.axis, wl.side, wl.position, h.rad, EdParticles::kWall, w);
        }
        grid_.for_faces(ps_.e[i].cell, [&](int dir, int axis, double face) {
            closes(axis, dir % 2 ? -1.0 : 1.0, face, 0.0, EdParticles::kCross, dir);
        });
        return {best, kind, arg};
    }

    // Earliest pair collision after t found with the linked cells (ignoring the queue).
    PairEvent earliest_pair(double t) const {
        PairEvent best;
        for (int i = 0; i < static_cast<int>(ps_.size()); ++i) {
            const Vec2 r = ps_.position_at(i, t), v = ps_.velocity_at(i, t);
            const Probe p{r.x, r.y, v.x, v.y, t, ps_.p[i].rad, i, ps_.p[i].last_partner};
            Pair b{kInf, -1, true};
            grid_.for_neighbours(ps_.e[i].cell, [&](int c) { scan_cell(p, grid_.head(c), b); });
            if (t + b.dt < best.t) best = {t + b.dt, i, b.j};
        }
        if (best.i > best.j) std::swap(best.i, best.j);
        return best;
    }
    // Largest overlap sigma - |r_ij| [m] among all pairs and walls at time t.
    double max_overlap(double t) const {
        double worst = 0.0;
        for (std::size_t i = 0; i < ps_.size(); ++i) {
            const Vec2 pi = ps_.position_at(static_cast<int>(i), t);
            grid_.for_neighbours(ps_.e[i].cell, [&](int c) {
                for (int j = grid_.head(c); j >= 0; j = ps_.p[j].next) {
                    if (j <= static_cast<int>(i)) continue;
                    Vec2 d = pi - ps_.position_at(j, t);
                    grid_.min_image(d.x, d.y);
                    worst = std::max(worst, ps_.p[i].rad + ps_.p[j].rad - norm(d));
                }
            });
            for (const auto& wl : cfg_.walls) {
                if (!wl.enabled) continue;
                const double c = wl.axis == 0 ? pi.x : pi.y;
                worst = std::max(worst, ps_.p[i].rad - wl.side * (c - wl.position));
            }
        }
        return worst;
    }

private:
    struct Probe { // i's flight state at time t, and what a scan needs of i
        double x, y, vx, vy, t, rad;
        int i, last_partner;
    };
    Probe own(int i) const {
        const auto& h = ps_.p[i];
        return {h.x, h.y, h.vx, h.vy, h.tau, h.rad, i, h.last_partner};
    }
    // Earliest contact (interval from p.t) of p with the disks of a cell list from its head j.
    void scan_cell(const Probe& p, int j, Pair& best) const {
        for (; j >= 0; j = ps_.p[j].next) {
            if (j == p.i) continue;
            const auto& q = ps_.p[j];
            if (j == p.last_partner && q.last_partner == p.i) continue; // separating since their collision
            const double dt = p.t - q.tau;
            double dx = p.x - (q.x + (q.vx + 0.5 * ps_.gx * dt) * dt);
            double dy = p.y - (q.y + (q.vy + 0.5 * ps_.gy * dt) * dt);
            grid_.min_image(dx, dy);
            const double dvx = p.vx - (q.vx + ps_.gx * dt);
            const double dvy = p.vy - (q.vy + ps_.gy * dt);
            const double tc = flight_roots::pair_contact_time(dx, dy, dvx, dvy, p.rad + q.rad);
            if (tc < best.dt) best = {tc, j, best.replace};
        }
    }

    const EdParticles& ps_;
    const EdCellGrid& grid_;
    const Config& cfg_;
};

} // namespace granrepro
