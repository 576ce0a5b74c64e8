// Event-driven (ED) hard-disk engine, Luding 1998 Sec. 2.1-2.2: rigid rough disks with the
// Walton-Braun operator (Eqs. (1)-(6)), flat walls (m_2 = infinity), uniform gravity and the TC
// model (Eq. (7)).
//
// Algorithm (Lubachevsky 1991, the paper's Ref. [24]): every particle carries its own clock
// local_time and is advanced lazily; each particle has exactly ONE pending event in the queue,
// the earliest of (best predicted pair collision, wall contact, exit from its linked-list cell).
// A predicted pair collision stores the partner's collision counter; if the partner collided in
// between, the event is stale and the particle is re-predicted when it is popped. When a
// particle enters a new cell only the newly adjacent row/column of cells is scanned: its stored
// best pair collision (if still valid) is the minimum over the old neighbourhood already.
// Why this finds every collision: a collision i-j is always the stored best of i or of j at the
// moment it becomes the earlier of their pending events, because whoever changed trajectory or
// cell last scanned the other.
//
// Geometry: the box [0,lx) x [0,ly) is tiled by cells at least one largest diameter wide.
// Periodic axes wrap (>= 3 cells needed for the minimum image); walled axes have edge cells
// that extend to +-infinity, so disks may leave the box (a pipe whose bottom was removed).
//
// Round-off: pairs (and walls) found at or inside contact while approaching collide at once, so
// overlaps cannot accumulate; two disks whose latest collisions were with each other are never
// re-predicted against each other (their relative motion is a straight line away from contact,
// gravity cancelling), which removes grazing re-collision loops. max_overlap() reports the
// largest overlap seen at any executed contact [m].
//
// The event loop is a template on the collision operator's frictional/smooth form and on the
// observer, so an unset observer costs nothing and smooth runs skip the tangential algebra.
#pragma once
#include "core/collision_record.hpp"
#include "core/input_error.hpp"
#include "core/vec2.hpp"
#include "engines/ed/dary_heap_queue.hpp"
#include "engines/ed/calendar_queue.hpp"
#include "engines/ed/ed_config.hpp"
#include "engines/ed/ed_kinetic_energy.hpp"
#include "engines/ed/ed_state.hpp"
#include "engines/ed/flight_roots.hpp"
#include "engines/ed/huge_page_allocator.hpp"
#include "models/rough_disk_collision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace granrepro {

template <class Queue>
class BasicEdEngine {
public:
    using QueueType = Queue;

    // The earliest pair collision from a given state (used to test the cell search).
    struct PairEvent {
        double t = std::numeric_limits<double>::infinity(); // absolute time [s]
        int i = -1;
        int j = -1;
    };

    // pos [m], vel [m/s], radius [m], mass [kg], spin [1/s] (empty = 0), t0 [s].
    BasicEdEngine(const EdConfig& cfg, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                  const std::vector<double>& radius, const std::vector<double>& mass,
                  const std::vector<double>& spin = {}, double t0 = 0.0) {
        const std::size_t n = pos.size();
        if (n == 0) throw InputError("ED: no particles");
        if (vel.size() != n || radius.size() != n || mass.size() != n || (!spin.empty() && spin.size() != n))
            throw InputError("ED: position, velocity, radius, mass and spin arrays differ in size");
        cfg_ = cfg;
        t_now_ = t0;
        p_.assign(n, Hot{});
        mw_.assign(n, Mw{});
        e_.assign(n, Book{});
        for (std::size_t i = 0; i < n; ++i) {
            if (!(radius[i] > 0.0) || !(mass[i] > 0.0)) throw InputError("ED: radius and mass must be > 0");
            p_[i] = Hot{pos[i].x, pos[i].y, vel[i].x, vel[i].y, t0, radius[i], 0, kNoPartner, -1};
            mw_[i] = Mw{mass[i], spin.empty() ? 0.0 : spin[i]};
        }
        setup_geometry();
        for (std::size_t i = 0; i < n; ++i) {
            if (cfg_.periodic_x) p_[i].x = wrap(p_[i].x, cfg_.lx);
            if (cfg_.periodic_y) p_[i].y = wrap(p_[i].y, cfg_.ly);
        }
        build_cells();
        if (current_max_overlap() > 1e-9 * 2.0 * max_rad_)
            throw InputError("ED: initial configuration has overlapping disks");
        queue_.reset(n);
        predict_all();
    }
    explicit BasicEdEngine(const EdState& s) { restore_state(s); }

    // ---- running ----------------------------------------------------------------------------
    // Process every event with time <= t_end [s]; afterwards time() == t_end.
    void run_until(double t_end) { NoObserver none; run_impl(t_end, kMaxCount, none); }
    // Process events until n more particle-particle collisions happened (or no event is left).
    void run_collisions(std::uint64_t n) { NoObserver none; run_impl(kInf, n, none); }
    // Same, reporting each collision to obs (any callable taking const CollisionRecord&).
    template <class Obs>
    void run_until(double t_end, Obs&& obs) { run_impl(t_end, kMaxCount, obs); }
    template <class Obs>
    void run_collisions(std::uint64_t n, Obs&& obs) { run_impl(kInf, n, obs); }

    // ---- run-time changes ---------------------------------------------------------------------
    void set_law(const RoughDiskCollision& law) { cfg_.law = law; setup_laws(); }
    void set_tc(double t_c) { cfg_.t_c = t_c; setup_laws(); }
    void set_wall_law(std::size_t w, double r, double mu, double beta0) {
        auto& wl = cfg_.walls.at(w);
        wl.r = r; wl.mu = mu; wl.beta0 = beta0;
        setup_laws();
    }
    // Adding/removing a wall changes predictions: all particles are synchronised and re-predicted.
    void set_wall_enabled(std::size_t w, bool on) {
        cfg_.walls.at(w).enabled = on;
        reset_predictions();
    }
    const EdConfig& config() const { return cfg_; }

    // ---- state access -----------------------------------------------------------------------
    // Advance every particle to time() (positions/velocities stored at a common time).
    void synchronize() {
        for (std::size_t i = 0; i < size(); ++i) advance(static_cast<int>(i), t_now_);
    }
    double time() const { return t_now_; }
    std::size_t size() const { return p_.size(); }
    // Values at time() without mutating the lazy state; positions wrapped into periodic boxes.
    Vec2 position(std::size_t i) const {
        const double dt = t_now_ - p_[i].tau;
        double px = p_[i].x + (p_[i].vx + 0.5 * gx_ * dt) * dt;
        double py = p_[i].y + (p_[i].vy + 0.5 * gy_ * dt) * dt;
        if (cfg_.periodic_x) px = wrap(px, cfg_.lx);
        if (cfg_.periodic_y) py = wrap(py, cfg_.ly);
        return {px, py};
    }
    Vec2 velocity(std::size_t i) const {
        const double dt = t_now_ - p_[i].tau;
        return {p_[i].vx + gx_ * dt, p_[i].vy + gy_ * dt};
    }
    double spin(std::size_t i) const { return mw_[i].w; }
    double radius(std::size_t i) const { return p_[i].rad; }
    double mass(std::size_t i) const { return mw_[i].m; }
    double moment_of_inertia(std::size_t i) const { return cfg_.law.q * mw_[i].m * p_[i].rad * p_[i].rad; }
    std::vector<Vec2> positions() const { return collect([this](std::size_t i) { return position(i); }); }
    std::vector<Vec2> velocities() const { return collect([this](std::size_t i) { return velocity(i); }); }
    std::vector<double> spins() const { return gather(mw_, &Mw::w); }
    std::vector<double> radii() const { return gather(&Hot::rad); }
    std::vector<double> masses() const { return gather(mw_, &Mw::m); }
    // Collisions (with particles and walls) each particle took part in.
    std::vector<std::uint64_t> collision_counts() const { return gather(&Hot::count); }
    std::uint64_t collision_count(std::size_t i) const { return p_[i].count; }
    int last_partner(std::size_t i) const { return p_[i].last_partner; }
    double last_collision_time(std::size_t i) const { return e_[i].last_t; }
    std::uint64_t total_collisions() const { return pair_collisions_; } // particle-particle
    std::uint64_t wall_collisions() const { return wall_collisions_; }
    std::uint64_t elastic_collisions() const { return elastic_; }        // made elastic by TC
    std::uint64_t events_processed() const { return events_; }
    std::uint64_t cell_crossings() const { return crossings_; }
    std::uint64_t stale_events() const { return stale_; }
    double max_overlap() const { return max_overlap_; }

    EdKineticEnergy kinetic_energy() const {
        EdKineticEnergy k;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec2 v = velocity(i);
            k.kx += 0.5 * mw_[i].m * v.x * v.x;
            k.ky += 0.5 * mw_[i].m * v.y * v.y;
            k.krot += 0.5 * moment_of_inertia(i) * mw_[i].w * mw_[i].w;
        }
        return k;
    }
    Vec2 total_momentum() const {
        Vec2 p;
        for (std::size_t i = 0; i < size(); ++i) p += mw_[i].m * velocity(i);
        return p;
    }

    // Largest overlap sigma - |r_ij| [m] among all pairs (cell search) and walls at time().
    double current_max_overlap() const {
        double worst = 0.0;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec2 pi = raw_position(static_cast<int>(i));
            for_neighbour_cells(e_[i].cell, [&](int c) {
                for (int j = head_[c]; j >= 0; j = p_[j].next) {
                    if (j <= static_cast<int>(i)) continue;
                    const Vec2 d = min_image(pi - raw_position(j));
                    worst = std::max(worst, p_[i].rad + p_[j].rad - norm(d));
                }
            });
            for (const auto& wl : cfg_.walls) {
                if (!wl.enabled) continue;
                const double c = wl.axis == 0 ? pi.x : pi.y;
                worst = std::max(worst, p_[i].rad - wl.side * (c - wl.position));
            }
        }
        return worst;
    }

    // Earliest pair collision after time() found with the linked cells (ignoring queue state).
    PairEvent next_pair_collision_cells() const {
        PairEvent best;
        for (std::size_t i = 0; i < size(); ++i) {
            const Probe p = probe(static_cast<int>(i), t_now_);
            double bt = kInf;
            int bj = -1;
            for_neighbour_cells(e_[i].cell, [&](int c) { scan_cell(p, c, bt, bj); });
            if (t_now_ + bt < best.t) best = {t_now_ + bt, static_cast<int>(i), bj};
        }
        if (best.i > best.j) std::swap(best.i, best.j);
        return best;
    }

    std::size_t memory_bytes() const {
        auto b = [](const auto& v) { return v.capacity() * sizeof(typename std::decay_t<decltype(v)>::value_type); };
        return b(p_) + b(mw_) + b(e_) +
               b(head_) + queue_.memory_bytes();
    }

    // ---- checkpoint -------------------------------------------------------------------------
    EdState save_state() const {
        EdState s;
        s.config = cfg_;
        s.time = t_now_;
        s.x = gather(&Hot::x); s.y = gather(&Hot::y); s.vx = gather(&Hot::vx); s.vy = gather(&Hot::vy);
        s.spin = gather(mw_, &Mw::w); s.mass = gather(mw_, &Mw::m);
        s.local_time = gather(&Hot::tau); s.radius = gather(&Hot::rad);
        s.last_collision_time = gather(e_, &Book::last_t); s.burst_start = gather(e_, &Book::burst_t0);
        s.predicted_time = gather(e_, &Book::ev_t); s.collision_time = gather(e_, &Book::col_t);
        s.collision_count = gather(&Hot::count); s.partner_count = gather(e_, &Book::pcount);
        s.last_partner = gather(&Hot::last_partner); s.partner = gather(e_, &Book::partner);
        s.event_kind = gather(e_, &Book::kind); s.event_arg = gather(e_, &Book::arg);
        s.burst_count = gather(e_, &Book::burst_n); s.cell = gather(e_, &Book::cell);
        s.cell_next = gather(&Hot::next); s.cell_prev = gather(e_, &Book::prev);
        s.cell_head.assign(head_.begin(), head_.end());
        s.pair_collisions = pair_collisions_; s.wall_collisions = wall_collisions_;
        s.elastic_collisions = elastic_; s.events = events_; s.crossings = crossings_;
        s.stale_events = stale_; s.max_overlap = max_overlap_;
        return s;
    }
    void restore_state(const EdState& s) {
        const std::size_t n = s.x.size();
        auto check = [n](std::size_t k) {
            if (k != n) throw InputError("ED: inconsistent EdState array sizes");
        };
        for (std::size_t k : {s.y.size(), s.vx.size(), s.vy.size(), s.spin.size(), s.local_time.size(),
                              s.radius.size(), s.mass.size(), s.last_collision_time.size(),
                              s.burst_start.size(), s.predicted_time.size(), s.collision_time.size(),
                              s.collision_count.size(), s.partner_count.size(), s.last_partner.size(),
                              s.partner.size(), s.event_kind.size(), s.event_arg.size(),
                              s.burst_count.size(), s.cell.size(), s.cell_next.size(), s.cell_prev.size()})
            check(k);
        cfg_ = s.config;
        t_now_ = s.time;
        p_.assign(n, Hot{});
        for (std::size_t i = 0; i < n; ++i)
            p_[i] = Hot{s.x[i], s.y[i], s.vx[i], s.vy[i], s.local_time[i], s.radius[i],
                        s.collision_count[i], s.last_partner[i], s.cell_next[i]};
        mw_.assign(n, Mw{});
        e_.assign(n, Book{});
        for (std::size_t i = 0; i < n; ++i) {
            mw_[i] = Mw{s.mass[i], s.spin[i]};
            e_[i] = Book{s.predicted_time[i], s.collision_time[i], s.partner_count[i], s.last_collision_time[i],
                         s.burst_start[i], s.partner[i], s.cell[i], s.cell_prev[i], s.burst_count[i],
                         s.event_kind[i], s.event_arg[i]};
        }
        setup_geometry();
        if (s.cell_head.size() != static_cast<std::size_t>(ncx_) * static_cast<std::size_t>(ncy_))
            throw InputError("ED: EdState cell grid does not match its configuration");
        head_.assign(s.cell_head.begin(), s.cell_head.end());
        pair_collisions_ = s.pair_collisions; wall_collisions_ = s.wall_collisions;
        elastic_ = s.elastic_collisions; events_ = s.events; crossings_ = s.crossings;
        stale_ = s.stale_events; max_overlap_ = s.max_overlap;
        queue_.rebuild(gather(e_, &Book::ev_t));
    }

    // Largest distance [m] by which any disk at time() lies outside its linked-list cell (0 when
    // the cell lists are consistent; round-off level otherwise). Walled edge cells are unbounded.
    double max_cell_excursion() const {
        double worst = 0.0;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec2 r = raw_position(static_cast<int>(i));
            const int cx = e_[i].cell % ncx_, cy = e_[i].cell / ncx_;
            const double lox = (cx == 0 && !cfg_.periodic_x) ? -kInf : cx * csx_;
            const double hix = (cx == ncx_ - 1 && !cfg_.periodic_x) ? kInf : (cx + 1) * csx_;
            const double loy = (cy == 0 && !cfg_.periodic_y) ? -kInf : cy * csy_;
            const double hiy = (cy == ncy_ - 1 && !cfg_.periodic_y) ? kInf : (cy + 1) * csy_;
            worst = std::max({worst, lox - r.x, r.x - hix, loy - r.y, r.y - hiy});
        }
        return worst;
    }
    // Geometry of the cell grid (for tests and diagnostics).
    int cells_x() const { return ncx_; }
    int cells_y() const { return ncy_; }

private:
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    static constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint64_t>::max();
    static constexpr std::int32_t kNoPartner = std::numeric_limits<std::int32_t>::min();
    enum : std::uint8_t { kCollision = 0, kWall = 1, kCross = 2, kNone = 3 };
    // Consecutive events without any advance of time before we call it a loop.
    static constexpr std::uint64_t kZeroTimeLimit = 10'000'000;

    struct NoObserver {};
    struct Probe { // a particle's state at a time
        int i;
        double x, y, vx, vy, t;
    };

    static double wrap(double v, double l) {
        v = std::fmod(v, l);
        if (v < 0.0) v += l;
        return v >= l ? 0.0 : v;
    }
    template <class F>
    std::vector<Vec2> collect(F f) const {
        std::vector<Vec2> out(size());
        for (std::size_t i = 0; i < size(); ++i) out[i] = f(i);
        return out;
    }
    Vec2 raw_position(int i) const {
        const double dt = t_now_ - p_[i].tau;
        return {p_[i].x + (p_[i].vx + 0.5 * gx_ * dt) * dt, p_[i].y + (p_[i].vy + 0.5 * gy_ * dt) * dt};
    }
    Vec2 min_image(Vec2 d) const {
        if (cfg_.periodic_x) { if (d.x > hx_) d.x -= cfg_.lx; else if (d.x < -hx_) d.x += cfg_.lx; }
        if (cfg_.periodic_y) { if (d.y > hy_) d.y -= cfg_.ly; else if (d.y < -hy_) d.y += cfg_.ly; }
        return d;
    }

    void setup_geometry() {
        if (!(cfg_.lx > 0.0) || !(cfg_.ly > 0.0)) throw InputError("ED: box sizes must be > 0");
        if (!(cfg_.cell_size_factor >= 1.0)) throw InputError("ED: cell_size_factor must be >= 1");
        if (!(cfg_.t_c >= 0.0)) throw InputError("ED: t_c must be >= 0");
        max_rad_ = 0.0;
        for (const Hot& h : p_) max_rad_ = std::max(max_rad_, h.rad);
        // A margin above the largest diameter keeps round-off excursions of a disk out of its
        // cell from hiding a contact across two cells.
        const double cmin = 2.0 * max_rad_ * cfg_.cell_size_factor * (1.0 + 1e-9);
        ncx_ = std::max(1, static_cast<int>(std::floor(cfg_.lx / cmin)));
        ncy_ = std::max(1, static_cast<int>(std::floor(cfg_.ly / cmin)));
        if ((cfg_.periodic_x && ncx_ < 3) || (cfg_.periodic_y && ncy_ < 3))
            throw InputError("ED: a periodic box must be at least 3 cell widths (> 3 diameters) wide");
        csx_ = cfg_.lx / ncx_;
        csy_ = cfg_.ly / ncy_;
        hx_ = 0.5 * cfg_.lx;
        hy_ = 0.5 * cfg_.ly;
        gx_ = cfg_.gravity.x;
        gy_ = cfg_.gravity.y;
        for (const auto& wl : cfg_.walls)
            if ((wl.axis != 0 && wl.axis != 1) || (wl.side != 1 && wl.side != -1))
                throw InputError("ED: wall axis must be 0/1 and side +1/-1");
        setup_laws();
    }
    void setup_laws() {
        auto valid = [](const RoughDiskCollision& l) {
            return l.r >= 0.0 && l.r <= 1.0 && l.mu >= 0.0 && l.beta0 >= -1.0 && l.beta0 <= 1.0 && l.q > 0.0;
        };
        if (!valid(cfg_.law)) throw InputError("ED: need 0<=r<=1, mu>=0, -1<=beta0<=1, q>0");
        law_ = cfg_.law;
        law_tc_ = elastic_version(law_);
        wlaw_.clear();
        wlaw_tc_.clear();
        rough_ = law_.frictional() || law_tc_.frictional();
        for (const auto& wl : cfg_.walls) {
            RoughDiskCollision l{wl.r, wl.mu, wl.beta0, cfg_.law.q};
            if (!valid(l)) throw InputError("ED: wall needs 0<=r<=1, mu>=0, -1<=beta0<=1");
            wlaw_.push_back(l);
            wlaw_tc_.push_back(elastic_version(l));
            rough_ = rough_ || l.frictional() || wlaw_tc_.back().frictional();
        }
    }
    RoughDiskCollision elastic_version(RoughDiskCollision l) const {
        l.r = 1.0;
        if (!cfg_.tc_keep_friction) { l.mu = 0.0; l.beta0 = -1.0; }
        return l;
    }

    int cell_of(double px, double py) const {
        const int cx = std::clamp(static_cast<int>(std::floor(px / csx_)), 0, ncx_ - 1);
        const int cy = std::clamp(static_cast<int>(std::floor(py / csy_)), 0, ncy_ - 1);
        return cy * ncx_ + cx;
    }
    void build_cells() {
        const std::size_t n = size();
        head_.assign(static_cast<std::size_t>(ncx_) * static_cast<std::size_t>(ncy_), -1);
        for (std::size_t i = 0; i < n; ++i) link(static_cast<int>(i), cell_of(p_[i].x, p_[i].y));
    }
    void link(int i, int c) {
        e_[i].cell = c;
        e_[i].prev = -1;
        p_[i].next = head_[c];
        if (head_[c] >= 0) e_[head_[c]].prev = i;
        head_[c] = i;
    }
    void unlink(int i) {
        const int c = e_[i].cell;
        if (e_[i].prev >= 0) p_[e_[i].prev].next = p_[i].next; else head_[c] = p_[i].next;
        if (p_[i].next >= 0) e_[p_[i].next].prev = e_[i].prev;
    }
    // Calls f(cell) for the up to 9 cells around c (deduplicated: walled axes clip).
    template <class F>
    void for_neighbour_cells(int c, F&& f) const {
        const int cx = c % ncx_, cy = c / ncx_;
        for (int dy = -1; dy <= 1; ++dy) {
            int ny = cy + dy;
            if (ny < 0 || ny >= ncy_) {
                if (!cfg_.periodic_y) continue;
                ny = ny < 0 ? ny + ncy_ : ny - ncy_;
            }
            for (int dx = -1; dx <= 1; ++dx) {
                int nx = cx + dx;
                if (nx < 0 || nx >= ncx_) {
                    if (!cfg_.periodic_x) continue;
                    nx = nx < 0 ? nx + ncx_ : nx - ncx_;
                }
                f(ny * ncx_ + nx);
            }
        }
    }

    void advance(int i, double t) {
        const double dt = t - p_[i].tau;
        if (dt == 0.0) return;
        if (has_gravity()) {
            p_[i].x += (p_[i].vx + 0.5 * gx_ * dt) * dt;
            p_[i].y += (p_[i].vy + 0.5 * gy_ * dt) * dt;
            p_[i].vx += gx_ * dt;
            p_[i].vy += gy_ * dt;
        } else {
            p_[i].x += p_[i].vx * dt;
            p_[i].y += p_[i].vy * dt;
        }
        p_[i].tau = t;
    }
    bool has_gravity() const { return gx_ != 0.0 || gy_ != 0.0; }
    Probe probe(int i, double t) const {
        const double dt = t - p_[i].tau;
        return {i, p_[i].x + (p_[i].vx + 0.5 * gx_ * dt) * dt, p_[i].y + (p_[i].vy + 0.5 * gy_ * dt) * dt,
                p_[i].vx + gx_ * dt, p_[i].vy + gy_ * dt, t};
    }

    // Earliest contact (interval from p.t) of p with the disks in cell c.
    void scan_cell(const Probe& p, int c, double& best, int& best_j) const {
        const int i = p.i;
        const int lp = p_[i].last_partner;
        for (int j = head_[c]; j >= 0; j = p_[j].next) {
            if (j == i) continue;
            if (j == lp && p_[j].last_partner == i) continue; // separating since their collision
            const double dt = p.t - p_[j].tau;
            double dx = p.x - (p_[j].x + (p_[j].vx + 0.5 * gx_ * dt) * dt);
            double dy = p.y - (p_[j].y + (p_[j].vy + 0.5 * gy_ * dt) * dt);
            if (cfg_.periodic_x) { if (dx > hx_) dx -= cfg_.lx; else if (dx < -hx_) dx += cfg_.lx; }
            if (cfg_.periodic_y) { if (dy > hy_) dy -= cfg_.ly; else if (dy < -hy_) dy += cfg_.ly; }
            const double dvx = p.vx - (p_[j].vx + gx_ * dt);
            const double dvy = p.vy - (p_[j].vy + gy_ * dt);
            const double tc = flight_roots::pair_contact_time(dx, dy, dvx, dvy, p_[i].rad + p_[j].rad);
            if (tc < best) { best = tc; best_j = j; }
        }
    }

    // Full prediction for i at its own clock (tau_i == time of the current event).
    void predict_full(int i) {
        const Probe p{i, p_[i].x, p_[i].y, p_[i].vx, p_[i].vy, p_[i].tau};
        double bt = kInf;
        int bj = -1;
        for_neighbour_cells(e_[i].cell, [&](int c) { scan_cell(p, c, bt, bj); });
        set_pair_prediction(i, bt, bj);
        schedule(i);
    }
    void set_pair_prediction(int i, double dt, int j) {
        e_[i].partner = j;
        if (j >= 0) {
            e_[i].col_t = p_[i].tau + dt;
            e_[i].pcount = p_[j].count;
        } else {
            e_[i].col_t = kInf;
        }
    }
    // After entering a new cell along dir: scan only the newly adjacent cells.
    void predict_after_crossing(int i, int dir) {
        if (e_[i].partner >= 0 && p_[e_[i].partner].count != e_[i].pcount) {
            predict_full(i);
            return;
        }
        const Probe p{i, p_[i].x, p_[i].y, p_[i].vx, p_[i].vy, p_[i].tau};
        double bt = kInf;
        int bj = -1;
        const int cx = e_[i].cell % ncx_, cy = e_[i].cell / ncx_;
        if (dir < 2) {
            int nx = cx + (dir == 1 ? 1 : -1);
            bool ok = true;
            if (nx < 0 || nx >= ncx_) {
                if (cfg_.periodic_x) nx = nx < 0 ? nx + ncx_ : nx - ncx_; else ok = false;
            }
            if (ok) {
                for (int dy = -1; dy <= 1; ++dy) {
                    int ny = cy + dy;
                    if (ny < 0 || ny >= ncy_) {
                        if (!cfg_.periodic_y) continue;
                        ny = ny < 0 ? ny + ncy_ : ny - ncy_;
                    }
                    scan_cell(p, ny * ncx_ + nx, bt, bj);
                }
            }
        } else {
            int ny = cy + (dir == 3 ? 1 : -1);
            bool ok = true;
            if (ny < 0 || ny >= ncy_) {
                if (cfg_.periodic_y) ny = ny < 0 ? ny + ncy_ : ny - ncy_; else ok = false;
            }
            if (ok) {
                for (int dx = -1; dx <= 1; ++dx) {
                    int nx = cx + dx;
                    if (nx < 0 || nx >= ncx_) {
                        if (!cfg_.periodic_x) continue;
                        nx = nx < 0 ? nx + ncx_ : nx - ncx_;
                    }
                    scan_cell(p, ny * ncx_ + nx, bt, bj);
                }
            }
        }
        if (bj >= 0 && p_[i].tau + bt < e_[i].col_t) set_pair_prediction(i, bt, bj);
        schedule(i);
    }

    // Combine the stored pair prediction with wall and cell-exit times; queue the earliest.
    void schedule(int i) {
        double best = e_[i].col_t;
        std::uint8_t kind = e_[i].partner >= 0 ? kCollision : kNone;
        std::uint8_t arg = 0;
        const double t = p_[i].tau;
        const double a = p_[i].rad;
        for (std::size_t w = 0; w < cfg_.walls.size(); ++w) {
            const EdWall& wl = cfg_.walls[w];
            if (!wl.enabled) continue;
            const double s = wl.side;
            double tw;
            if (wl.axis == 0) tw = flight_roots::gap_closing_time(s * (p_[i].x - wl.position) - a, s * p_[i].vx, s * gx_);
            else tw = flight_roots::gap_closing_time(s * (p_[i].y - wl.position) - a, s * p_[i].vy, s * gy_);
            if (t + tw < best) { best = t + tw; kind = kWall; arg = static_cast<std::uint8_t>(w); }
        }
        const int cx = e_[i].cell % ncx_, cy = e_[i].cell / ncx_;
        // Cell boundaries; edge cells of walled axes extend to infinity.
        if (cfg_.periodic_x || cx > 0) {
            const double tc = flight_roots::gap_closing_time(p_[i].x - cx * csx_, p_[i].vx, gx_);
            if (t + tc < best) { best = t + tc; kind = kCross; arg = 0; }
        }
        if (cfg_.periodic_x || cx < ncx_ - 1) {
            const double hi = cx + 1 == ncx_ ? cfg_.lx : (cx + 1) * csx_;
            const double tc = flight_roots::gap_closing_time(hi - p_[i].x, -p_[i].vx, -gx_);
            if (t + tc < best) { best = t + tc; kind = kCross; arg = 1; }
        }
        if (cfg_.periodic_y || cy > 0) {
            const double tc = flight_roots::gap_closing_time(p_[i].y - cy * csy_, p_[i].vy, gy_);
            if (t + tc < best) { best = t + tc; kind = kCross; arg = 2; }
        }
        if (cfg_.periodic_y || cy < ncy_ - 1) {
            const double hi = cy + 1 == ncy_ ? cfg_.ly : (cy + 1) * csy_;
            const double tc = flight_roots::gap_closing_time(hi - p_[i].y, -p_[i].vy, -gy_);
            if (t + tc < best) { best = t + tc; kind = kCross; arg = 3; }
        }
        e_[i].ev_t = best;
        e_[i].kind = kind;
        e_[i].arg = arg;
        queue_.update(i, best);
    }

    void predict_all() {
        for (std::size_t i = 0; i < size(); ++i) predict_full(static_cast<int>(i));
    }
    void reset_predictions() {
        setup_geometry();
        synchronize();
        predict_all();
    }

    // ---- execution --------------------------------------------------------------------------
    template <class Obs>
    void run_impl(double t_end, std::uint64_t n, Obs& obs) {
        start_run();
        if (rough_) loop<true>(t_end, n, obs);
        else loop<false>(t_end, n, obs);
        if (t_end < kInf && t_end > t_now_ && !(queue_.top_time() <= t_end)) t_now_ = t_end;
    }
    void start_run() {
        if (cfg_.collapse_window > 0.0) { window_ = cfg_.collapse_window; return; }
        double v2 = 0.0, dsum = 0.0;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec2 v = velocity(i);
            v2 += norm2(v);
            dsum += 2.0 * p_[i].rad;
        }
        const double d = dsum / static_cast<double>(size());
        const double vref = std::max(std::sqrt(v2 / static_cast<double>(size())),
                                     std::sqrt(std::hypot(gx_, gy_) * d));
        window_ = vref > 0.0 ? 1e-7 * d / vref : 0.0;
    }

    template <bool kRough, class Obs>
    void loop(double t_end, std::uint64_t n, Obs& obs) {
        const std::uint64_t target = n > kMaxCount - pair_collisions_ ? kMaxCount : pair_collisions_ + n;
        while (pair_collisions_ < target) {
            const double t = queue_.top_time();
            if (!(t <= t_end)) break;
            const int i = queue_.top_id();
            // Start loading the probable next particle while this event is processed: at large
            // N nearly every particle access is a cache miss.
            if (const int nx = queue_.runner_up(); nx >= 0) {
                __builtin_prefetch(&p_[nx]);
                __builtin_prefetch(&e_[nx]);
            }
            ++events_;
            if (t == t_last_event_) {
                if (++zero_time_run_ > kZeroTimeLimit) fail_loop(i, t);
            } else {
                zero_time_run_ = 0;
                t_last_event_ = t;
            }
            t_now_ = t;
            switch (e_[i].kind) {
            case kCross: do_cross(i, t); break;
            case kWall: do_wall<kRough>(i, e_[i].arg, t, obs); break;
            case kCollision: {
                const int j = e_[i].partner;
                if (p_[j].count != e_[i].pcount) {
                    ++stale_;
                    advance(i, t);
                    predict_full(i);
                } else {
                    do_pair<kRough>(i, j, t, obs);
                }
                break;
            }
            default: throw std::logic_error("ED: finite event time with no event");
            }
        }
    }

    [[noreturn]] void fail_loop(int i, double t) const {
        std::ostringstream os;
        os << "ED: " << kZeroTimeLimit << " consecutive events at the same time t = " << t
           << " s (particle " << i << "); the event sequence is stuck (inelastic collapse or a "
           << "disk resting on a wall). Use the TC model (t_c > 0, Luding Eq. 7).";
        throw std::runtime_error(os.str());
    }
    void note_collision(int i, double t) {
        ++p_[i].count;
        if (t - e_[i].burst_t0 > window_) {
            e_[i].burst_t0 = t;
            e_[i].burst_n = 0;
        }
        if (++e_[i].burst_n > cfg_.collapse_limit) {
            std::ostringstream os;
            os << "ED: inelastic collapse: particle " << i << " took part in more than "
               << cfg_.collapse_limit << " collisions within " << window_ << " s (at t = " << t
               << " s); the collision rate diverges. Use the TC model (t_c > 0, Luding Eq. 7) "
               << "or weaker dissipation.";
            throw std::runtime_error(os.str());
        }
        e_[i].last_t = t;
    }
    bool tc_elastic(double t, int i) const { return cfg_.t_c > 0.0 && t - e_[i].last_t <= cfg_.t_c; }

    void do_cross(int i, double t) {
        ++crossings_;
        advance(i, t);
        unlink(i);
        const int dir = e_[i].arg;
        int cx = e_[i].cell % ncx_, cy = e_[i].cell / ncx_;
        switch (dir) {
        case 0: if (--cx < 0) { cx += ncx_; p_[i].x += cfg_.lx; } break;
        case 1: if (++cx == ncx_) { cx = 0; p_[i].x -= cfg_.lx; } break;
        case 2: if (--cy < 0) { cy += ncy_; p_[i].y += cfg_.ly; } break;
        default: if (++cy == ncy_) { cy = 0; p_[i].y -= cfg_.ly; } break;
        }
        link(i, cy * ncx_ + cx);
        predict_after_crossing(i, dir);
    }

    template <bool kRough, class Obs>
    void do_pair(int i, int j, double t, Obs& obs) {
        advance(i, t);
        advance(j, t);
        double dx = p_[i].x - p_[j].x, dy = p_[i].y - p_[j].y;
        if (cfg_.periodic_x) { if (dx > hx_) dx -= cfg_.lx; else if (dx < -hx_) dx += cfg_.lx; }
        if (cfg_.periodic_y) { if (dy > hy_) dy -= cfg_.ly; else if (dy < -hy_) dy += cfg_.ly; }
        const double dist = std::sqrt(dx * dx + dy * dy);
        max_overlap_ = std::max(max_overlap_, p_[i].rad + p_[j].rad - dist);
        const Vec2 n{dx / dist, dy / dist};
        const bool el = cfg_.tc_both ? (tc_elastic(t, i) && tc_elastic(t, j)) : (tc_elastic(t, i) || tc_elastic(t, j));
        const RoughDiskCollision& law = el ? law_tc_ : law_;
        const Vec2 vi{p_[i].vx, p_[i].vy}, vj{p_[j].vx, p_[j].vy};
        const auto res = law.template collide<kRough>(vi, mw_[i].w, mw_[i].m, p_[i].rad, vj, mw_[j].w, mw_[j].m, p_[j].rad, n);
        p_[i].vx += res.dP.x / mw_[i].m;
        p_[i].vy += res.dP.y / mw_[i].m;
        p_[j].vx -= res.dP.x / mw_[j].m;
        p_[j].vy -= res.dP.y / mw_[j].m;
        if constexpr (kRough) {
            mw_[i].w += res.dw1;
            mw_[j].w += res.dw2;
        }
        note_collision(i, t);
        note_collision(j, t);
        ++pair_collisions_;
        if (el) ++elastic_;
        p_[i].last_partner = j;
        p_[j].last_partner = i;
        if constexpr (!std::is_same_v<std::decay_t<Obs>, NoObserver>) {
            CollisionRecord rec;
            rec.t = t;
            rec.i = i;
            rec.j = j;
            rec.ri = {p_[i].x, p_[i].y};
            rec.rj = {p_[i].x - dx, p_[i].y - dy};
            rec.n = n;
            rec.dP = res.dP;
            const Vec2 dv = vi - vj;
            const double vv = norm(dv);
            rec.b_over_d = vv > 0.0 ? std::fabs(cross(n, dv)) / vv : 0.0;
            rec.elastic = el;
            obs(rec);
        }
        predict_full(i);
        predict_full(j);
    }

    template <bool kRough, class Obs>
    void do_wall(int i, int w, double t, Obs& obs) {
        advance(i, t);
        const EdWall& wl = cfg_.walls[w];
        const Vec2 n = wl.axis == 0 ? Vec2{double(wl.side), 0.0} : Vec2{0.0, double(wl.side)};
        const double c = wl.axis == 0 ? p_[i].x : p_[i].y;
        max_overlap_ = std::max(max_overlap_, p_[i].rad - wl.side * (c - wl.position));
        const bool el = tc_elastic(t, i);
        const RoughDiskCollision& law = el ? wlaw_tc_[w] : wlaw_[w];
        const Vec2 vi{p_[i].vx, p_[i].vy};
        const auto res = law.template collide<kRough>(vi, mw_[i].w, mw_[i].m, p_[i].rad, Vec2{}, 0.0, kInf, 0.0, n);
        p_[i].vx += res.dP.x / mw_[i].m;
        p_[i].vy += res.dP.y / mw_[i].m;
        if constexpr (kRough) mw_[i].w += res.dw1;
        note_collision(i, t);
        ++wall_collisions_;
        if (el) ++elastic_;
        p_[i].last_partner = -1 - w;
        if constexpr (!std::is_same_v<std::decay_t<Obs>, NoObserver>) {
            CollisionRecord rec;
            rec.t = t;
            rec.i = i;
            rec.j = -1 - w;
            rec.ri = {p_[i].x, p_[i].y};
            rec.rj = rec.ri - n * p_[i].rad;
            rec.n = n;
            rec.dP = res.dP;
            const double vv = norm(vi);
            rec.b_over_d = vv > 0.0 ? std::fabs(cross(n, vi)) / vv : 0.0;
            rec.elastic = el;
            obs(rec);
        }
        predict_full(i);
    }

    // ---- data -------------------------------------------------------------------------------
    EdConfig cfg_;
    RoughDiskCollision law_, law_tc_;
    std::vector<RoughDiskCollision> wlaw_, wlaw_tc_;
    bool rough_ = false;
    double t_now_ = 0.0;
    double max_rad_ = 0.0;
    int ncx_ = 1, ncy_ = 1;
    double csx_ = 1.0, csy_ = 1.0, hx_ = 0.5, hy_ = 0.5, gx_ = 0.0, gy_ = 0.0;
    double window_ = 0.0;
    double t_last_event_ = -kInf;
    std::uint64_t zero_time_run_ = 0;

    // Per-particle data: three arrays (a structure of arrays at the granularity of cache lines).
    // Pure per-field arrays were measured 10-15% slower at N = 1e6: one event touches ~15
    // fields of a random particle, i.e. ~15 cache misses instead of 2-3.
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
    template <class T>
    std::vector<T> gather(T Hot::*f) const {
        std::vector<T> out(p_.size());
        for (std::size_t i = 0; i < p_.size(); ++i) out[i] = p_[i].*f;
        return out;
    }
    HugeVector<Hot> p_;
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
    template <class S, class T>
    static std::vector<T> gather(const HugeVector<S>& v, T S::*f) {
        std::vector<T> out(v.size());
        for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i].*f;
        return out;
    }
    HugeVector<Book> e_;
    HugeVector<Mw> mw_;
    HugeVector<std::int32_t> head_;
    Queue queue_;

    std::uint64_t pair_collisions_ = 0, wall_collisions_ = 0, elastic_ = 0, events_ = 0,
                  crossings_ = 0, stale_ = 0;
    double max_overlap_ = 0.0;
};

// Queue choice, measured with run_ed_benchmark (elastic, rho = 0.25, periodic, this 2-core EPYC,
// collisions per CPU second at N = 1e4 / 1e5 / 1e6):
//   binary heap 1.09e6 / 6.9e5 / 3.6e5,  4-ary heap 1.02e6 / 6.2e5 / 3.6e5,
//   calendar    1.22e6 / 7.4e5 / 3.5e5,  (a heap + far-future buckets variant: 0.87e6 / 4.8e5 / 3.3e5).
// At large N the loop is bound by cache misses, so the queues tie there; the binary heap is kept
// as default because its O(log N) bound holds for any distribution of event times (a clustering
// TC run spreads them over many decades, where a calendar's bucket width can be badly off between
// re-estimates).
// Why the per-event cost still rises 3.3-3.5x from N = 1e4 to 1e6 (measured in session 2; none
// of the following is kept, all changed the N = 1e6 cost by less than the run-to-run noise of
// about 10 %):
//   - a complete binary tournament tree (path prefetched, no position index), a two-level queue
//     with lazy deletion (exact heap for the current window, append-only buckets), prefetching
//     the records of the 7-31 heap slots nearest the top or the runner-up's neighbour cells;
//   - random versus spatial order of the particle records (a shuffled lattice start costs the
//     same as an ordered one: one record is one cache line, so neighbours are separate misses in
//     either order; reordering by cell would not help);
//   - larger cells (cell_size_factor 1.4 and 2: fewer crossings, more pairs; slower at all N).
// The cause is the machine: `granrepro bench ed` also measures the latency of a dependent random
// load at the engine's working set, 16 ns at N = 1e4 (1.8 MB, cache) against 160 ns at N = 1e6
// (177 MB, DRAM) on this VM, whose caches stop helping beyond ~4 MB. A cost ratio of 1.5 would
// need nearly every miss of an event hidden.
using EdEngine = BasicEdEngine<BinaryHeapQueue>;

} // namespace granrepro
