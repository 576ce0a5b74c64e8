// Event-driven (ED) hard-disk engine, Luding 1998 Sec. 2.1-2.2: rigid rough disks with a
// collision operator (Walton-Braun, Eqs. (1)-(6), by default), flat walls (m_2 = infinity),
// uniform gravity and the TC model (Eq. (7)). It owns the state (EdParticles, clock, queue) and
// runs Lubachevsky's event loop (the paper's Ref. [24]) over, DynamO-style, EdCellGrid (linked
// cells), EdEventPredictor (next event of a particle) and EdEventExecutor (collisions).
// The loop is a template on the operator's frictional/smooth form and on the observer, so an
// unset observer costs nothing and smooth runs skip the tangential algebra. The operator is any
// EdCollisionOperator (ed_collision_operator.hpp); its parameters are BasicEdConfig<C>::law.
#pragma once
#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "engines/ed/dary_heap_queue.hpp"
#include "engines/ed/ed_cell_grid.hpp"
#include "engines/ed/ed_collision_operator.hpp"
#include "engines/ed/ed_config.hpp"
#include "engines/ed/ed_event_executor.hpp"
#include "engines/ed/ed_event_predictor.hpp"
#include "engines/ed/ed_kinetic_energy.hpp"
#include "engines/ed/ed_particles.hpp"
#include "engines/ed/ed_state.hpp"
#include "engines/hard_particle_engine.hpp"
#include "models/rough_disk_collision.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace granrepro {

template <class Queue, EdCollisionOperator Collision = RoughDiskCollision>
class BasicEdEngine {
public:
    using QueueType = Queue;
    using CollisionType = Collision;
    using Config = BasicEdConfig<Collision>;
    using State = BasicEdState<Collision>;
    using Predictor = EdEventPredictor<Config>;
    using PairEvent = typename Predictor::PairEvent;

    // pos [m], vel [m/s], radius [m], mass [kg], spin [1/s] (empty = 0), t0 [s].
    BasicEdEngine(const Config& cfg, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                  const std::vector<double>& radius, const std::vector<double>& mass,
                  const std::vector<double>& spin = {}, double t0 = 0.0) {
        const std::size_t n = pos.size();
        if (n == 0) throw InputError("ED: no particles");
        if (vel.size() != n || radius.size() != n || mass.size() != n || (!spin.empty() && spin.size() != n))
            throw InputError("ED: position, velocity, radius, mass and spin arrays differ in size");
        cfg_ = cfg;
        t_now_ = t0;
        ps_.p.assign(n, Hot{}); ps_.mw.assign(n, Mw{}); ps_.e.assign(n, Book{});
        for (std::size_t i = 0; i < n; ++i) {
            if (!(radius[i] > 0.0) || !(mass[i] > 0.0)) throw InputError("ED: radius and mass must be > 0");
            ps_.p[i] = Hot{pos[i].x, pos[i].y, vel[i].x, vel[i].y, t0, radius[i], 0, EdParticles::kNoPartner, -1};
            ps_.mw[i] = Mw{mass[i], spin.empty() ? 0.0 : spin[i]};
        }
        setup();
        for (auto& h : ps_.p) {
            if (cfg_.periodic_x) h.x = EdCellGrid::wrap(h.x, cfg_.lx);
            if (cfg_.periodic_y) h.y = EdCellGrid::wrap(h.y, cfg_.ly);
        }
        grid_.build(ps_);
        if (current_max_overlap() > 1e-9 * 2.0 * *std::max_element(radius.begin(), radius.end()))
            throw InputError("ED: initial configuration has overlapping disks");
        queue_.reset(n);
        predict_all();
    }
    explicit BasicEdEngine(const State& s) { restore_state(s); }

    // ---- running ----------------------------------------------------------------------------
    // Process every event with time <= t_end [s], reporting each collision to obs (any callable
    // taking const CollisionRecord&); afterwards time() == t_end.
    template <class Obs = NoCollisionObserver>
    void run_until(double t_end, Obs&& obs = {}) { run_impl(t_end, kMaxCount, obs); }
    // Process events until n more particle-particle collisions happened (or no event is left).
    template <class Obs = NoCollisionObserver>
    void run_collisions(std::uint64_t n, Obs&& obs = {}) { run_impl(kInf, n, obs); }

    // ---- run-time changes ---------------------------------------------------------------------
    void set_law(const Collision& law) { cfg_.law = law; exec_.setup(cfg_); }
    void set_tc(double t_c) { cfg_.t_c = t_c; exec_.setup(cfg_); }
    void set_wall_law(std::size_t w, double r, double mu, double beta0) {
        auto& wl = cfg_.walls.at(w);
        wl.r = r; wl.mu = mu; wl.beta0 = beta0;
        exec_.setup(cfg_);
    }
    // Adding/removing a wall changes predictions: all particles are synchronised and re-predicted.
    void set_wall_enabled(std::size_t w, bool on) {
        cfg_.walls.at(w).enabled = on;
        setup();
        synchronize();
        predict_all();
    }
    const Config& config() const { return cfg_; }

    // ---- state access -----------------------------------------------------------------------
    // Advance every particle to time() (positions/velocities stored at a common time).
    void synchronize() { for (int i = 0; i < static_cast<int>(size()); ++i) ps_.advance(i, t_now_); }
    double time() const { return t_now_; }
    std::size_t size() const { return ps_.size(); }
    // Values at time() without mutating the lazy state; positions wrapped into periodic boxes.
    Vec2 position(std::size_t i) const { return grid_.wrap(ps_.position_at(static_cast<int>(i), t_now_)); }
    Vec2 velocity(std::size_t i) const { return ps_.velocity_at(static_cast<int>(i), t_now_); }
    double spin(std::size_t i) const { return ps_.mw[i].w; }
    double radius(std::size_t i) const { return ps_.p[i].rad; }
    double mass(std::size_t i) const { return ps_.mw[i].m; }
    double moment_of_inertia(std::size_t i) const { return cfg_.law.q * mass(i) * radius(i) * radius(i); }
    std::vector<Vec2> positions() const { return collect(&BasicEdEngine::position); }
    std::vector<Vec2> velocities() const { return collect(&BasicEdEngine::velocity); }
    std::vector<double> spins() const { return EdParticles::gather(ps_.mw, &Mw::w); }
    std::vector<double> radii() const { return EdParticles::gather(ps_.p, &Hot::rad); }
    std::vector<double> masses() const { return EdParticles::gather(ps_.mw, &Mw::m); }
    // Collisions (with particles and walls) each particle took part in.
    std::vector<std::uint64_t> collision_counts() const { return EdParticles::gather(ps_.p, &Hot::count); }
    std::uint64_t collision_count(std::size_t i) const { return ps_.p[i].count; }
    int last_partner(std::size_t i) const { return ps_.p[i].last_partner; }
    double last_collision_time(std::size_t i) const { return ps_.e[i].last_t; }
    std::uint64_t total_collisions() const { return exec_.pair_collisions(); } // particle-particle
    std::uint64_t wall_collisions() const { return exec_.wall_collisions(); }
    std::uint64_t elastic_collisions() const { return exec_.elastic_collisions(); } // made elastic by TC
    std::uint64_t events_processed() const { return events_; }
    std::uint64_t cell_crossings() const { return crossings_; }
    std::uint64_t stale_events() const { return stale_; }
    double max_overlap() const { return exec_.max_overlap(); } // largest at an executed contact [m]

    EdKineticEnergy kinetic_energy() const {
        EdKineticEnergy k;
        for (std::size_t i = 0; i < size(); ++i) {
            const Vec2 v = velocity(i);
            k.kx += 0.5 * mass(i) * v.x * v.x;
            k.ky += 0.5 * mass(i) * v.y * v.y;
            k.krot += 0.5 * moment_of_inertia(i) * spin(i) * spin(i);
        }
        return k;
    }
    Vec2 total_momentum() const {
        Vec2 p;
        for (std::size_t i = 0; i < size(); ++i) p += mass(i) * velocity(i);
        return p;
    }

    // Largest overlap sigma - |r_ij| [m] among all pairs (cell search) and walls at time().
    double current_max_overlap() const { return predictor().max_overlap(t_now_); }
    // Earliest pair collision after time() found with the linked cells (ignoring queue state).
    PairEvent next_pair_collision_cells() const { return predictor().earliest_pair(t_now_); }
    // Largest distance [m] by which any disk at time() lies outside its linked-list cell (0 when
    // the cell lists are consistent; round-off level otherwise). Walled edge cells are unbounded.
    double max_cell_excursion() const {
        double worst = 0.0;
        for (std::size_t i = 0; i < size(); ++i)
            worst = std::max(worst, grid_.excursion(ps_.e[i].cell, ps_.position_at(static_cast<int>(i), t_now_)));
        return worst;
    }
    // Geometry of the cell grid (for tests and diagnostics).
    int cells_x() const { return grid_.cells_x(); }
    int cells_y() const { return grid_.cells_y(); }

    std::size_t memory_bytes() const {
        auto b = [](const auto& v) { return v.capacity() * sizeof(typename std::decay_t<decltype(v)>::value_type); };
        return b(ps_.p) + b(ps_.mw) + b(ps_.e) + grid_.memory_bytes() + queue_.memory_bytes();
    }

    // ---- checkpoint -------------------------------------------------------------------------
    State save_state() const {
        State s;
        s.config = cfg_;
        s.time = t_now_;
        ps_.save(s);
        grid_.save(s);
        exec_.save(s);
        s.events = events_; s.crossings = crossings_; s.stale_events = stale_;
        return s;
    }
    void restore_state(const State& s) {
        if (!ps_.restore(s)) throw InputError("ED: inconsistent EdState array sizes");
        cfg_ = s.config;
        t_now_ = s.time;
        setup();
        grid_.restore(s);
        exec_.restore(s);
        events_ = s.events; crossings_ = s.crossings; stale_ = s.stale_events;
        queue_.rebuild(EdParticles::gather(ps_.e, &Book::ev_t));
    }

private:
    using Hot = EdParticles::Hot;
    using Book = EdParticles::Book;
    using Mw = EdParticles::Mw;
    static constexpr double kInf = EdParticles::kInf;
    static constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint64_t>::max();
    // Consecutive events without any advance of time before we call it a loop.
    static constexpr std::uint64_t kZeroTimeLimit = 10'000'000;

    template <class F>
    std::vector<Vec2> collect(F f) const {
        std::vector<Vec2> out(size());
        for (std::size_t i = 0; i < size(); ++i) out[i] = (this->*f)(i);
        return out;
    }
    // Derived state (cells, gravity, operators) from cfg_ and the radii; validates cfg_.
    void setup() {
        double max_rad = 0.0;
        for (const Hot& h : ps_.p) max_rad = std::max(max_rad, h.rad);
        grid_.setup(cfg_, max_rad);
        ps_.gx = cfg_.gravity.x;
        ps_.gy = cfg_.gravity.y;
        exec_.setup(cfg_);
    }

    Predictor predictor() const { return {ps_, grid_, cfg_}; }
    // Commits a predicted pair and queues i's earliest event.
    void schedule(int i, const typename Predictor::Pair& pr) {
        if (pr.replace) ps_.set_pair(i, pr.dt, pr.j);
        const auto ev = predictor().next_event(i);
        auto& b = ps_.e[i];
        b.ev_t = ev.t;
        b.kind = ev.kind;
        b.arg = ev.arg;
        queue_.update(i, ev.t);
    }
    // Full prediction for i at its own clock (tau_i == time of the current event).
    void predict(int i) { schedule(i, predictor().pair(i)); }
    void predict_all() { for (int i = 0; i < static_cast<int>(size()); ++i) predict(i); }

    // ---- the event loop ---------------------------------------------------------------------
    template <class Obs>
    void run_impl(double t_end, std::uint64_t n, Obs& obs) {
        exec_.start_run(ps_, t_now_, cfg_.collapse_window);
        if (exec_.rough()) loop<true>(t_end, n, obs);
        else loop<false>(t_end, n, obs);
        if (t_end < kInf && t_end > t_now_ && !(queue_.top_time() <= t_end)) t_now_ = t_end;
    }

    template <bool kRough, class Obs>
    void loop(double t_end, std::uint64_t n, Obs& obs) {
        const std::uint64_t done = exec_.pair_collisions();
        const std::uint64_t target = n > kMaxCount - done ? kMaxCount : done + n;
        while (exec_.pair_collisions() < target) {
            const double t = queue_.top_time();
            if (!(t <= t_end)) break;
            const int i = queue_.top_id();
            // Start loading the probable next particle while this event is processed: at large
            // N nearly every particle access is a cache miss.
            if (const int nx = queue_.runner_up(); nx >= 0) {
                __builtin_prefetch(&ps_.p[nx]);
                __builtin_prefetch(&ps_.e[nx]);
            }
            if ((++events_ & 0xFFFF) == 0) engine_pause_point();
            if (t == t_last_event_) {
                if (++zero_time_run_ > kZeroTimeLimit) fail_loop(i, t);
            } else {
                zero_time_run_ = 0;
                t_last_event_ = t;
            }
            t_now_ = t;
            switch (ps_.e[i].kind) {
            case EdParticles::kCross: {
                ++crossings_;
                ps_.advance(i, t);
                grid_.cross(ps_, i);
                schedule(i, predictor().pair_after_crossing(i, ps_.e[i].arg));
                break;
            }
            case EdParticles::kWall: {
                const int w = ps_.e[i].arg;
                exec_.template wall<kRough>(ps_, cfg_.walls[w], w, i, t, obs);
                predict(i);
                break;
            }
            case EdParticles::kCollision: {
                const int j = ps_.e[i].partner;
                if (ps_.p[j].count != ps_.e[i].pcount) {
                    ++stale_;
                    ps_.advance(i, t);
                    predict(i);
                } else {
                    exec_.template pair<kRough>(ps_, grid_, i, j, t, obs);
                    predict(i);
                    predict(j);
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

    Config cfg_;
    double t_now_ = 0.0;
    EdParticles ps_;
    EdCellGrid grid_;
    EdEventExecutor<Collision> exec_;
    Queue queue_;
    std::uint64_t events_ = 0, crossings_ = 0, stale_ = 0;
    double t_last_event_ = -kInf;
    std::uint64_t zero_time_run_ = 0;
};

// Queue choice, measured with run_ed_benchmark's former queue option (elastic, rho = 0.25,
// periodic, this 2-core EPYC, collisions per CPU second at N = 1e4 / 1e5 / 1e6):
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
