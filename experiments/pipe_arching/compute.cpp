// pipe-arching: one seed run: the column's set-up and relaxation, the release, the fall frame by frame and its arches.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>

#include "analysis/disjoint_sets.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/pipe_arching/spec.hpp"
#include "harness/sampled_run.hpp"
#include "observables/collision_counter.hpp"

namespace granrepro::experiments::pipe_arching_detail {

Pipe::Pipe(const PipeArchingSpec& spec) : PipeArchingSpec(spec) {
    L = width * d; a = lattice * d;
    // Rows alternate floor(L/a) and one fewer site; the column height sets where the floor goes.
    const double per_two_rows = 2.0 * std::floor((L - d) / a + 1e-9) + 1.0;
    const double rows = std::ceil(2.0 * double(n_particles) / per_two_rows);
    const double h = rows * a * std::sqrt(3.0) / 2.0 + d;
    // The floor sits high enough in the cell grid that the falling column never reaches the
    // bottom edge cells, which extend to -infinity and would collect all disks in one row.
    y_floor = 0.5 * g * t_end * t_end + 10 * d;
    ly = y_floor + 1.3 * h + 10 * d;
    n_frames = frame_of(t_end, frame_dt);
    detect_from = long(std::ceil(t_detect_min / frame_dt - 1e-9));
    cs = {.diameter = d, .width = L, .min_below = std::size_t(crack_min_particles),
          .min_above = std::size_t(crack_min_above), .max_opening = 3 * d};
}

namespace {

// The lattice at t = 0 (Sec. 5: "still arranged on a triangular lattice, except for a few layers
// at the top which are fluidized"). A disk keeps its place when it is still within 1.2 s of every
// lattice neighbour it had at t = -t_r (s = lattice constant). Rows are counted from the top;
// the fluidized layers are the top rows in which at least half of the disks lost a neighbour.
void lattice_state(SeedRun& out, const std::vector<Vec2>& lat, const std::vector<Vec2>& now, double s) {
    const std::size_t n = lat.size();
    std::vector<int> kept(n, 1);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (lat[j].y - lat[i].y > 1.1 * s) break; // rows are built bottom-up: y is sorted
            if (norm(lat[j] - lat[i]) > 1.1 * s) continue;
            if (norm(now[j] - now[i]) > 1.2 * s) kept[i] = kept[j] = 0;
        }
    // Rows (equal initial heights) hold consecutive disks: row k is [start[k], start[k + 1]).
    std::vector<std::size_t> start;
    for (std::size_t i = 0; i < n; ++i)
        if (start.empty() || std::abs(lat[i].y - lat[start.back()].y) > 0.1 * s) start.push_back(i);
    start.push_back(n);
    auto lost = [&](std::size_t a, std::size_t b) { return std::count(kept.begin() + long(a), kept.begin() + long(b), 0); };
    std::size_t r = start.size() - 1; // rows below the fluidized ones
    while (r > 0 && 2 * lost(start[r - 1], start[r]) >= long(start[r] - start[r - 1])) --r;
    out.fluid_layers = double(start.size() - 1 - r);
    out.lattice_broken_below = start[r] > 0 ? double(lost(0, start[r])) / double(start[r]) : NAN;
}

// The engine of the column: disks at pos with velocities vel from t0 on, side walls at x = 0 and
// x = x_right, the floor, gravity g_y; elastic and smooth (Sec. 5: r = r_w = 1, mu = mu_w = 0).
EdEngine column_engine(const Pipe& s, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double x_right,
                       double g_y, double t0, const std::vector<double>& spin = {}) {
    const std::size_t n = pos.size();
    const EdConfig cfg{.lx = x_right, .ly = s.ly, .periodic_x = false, .periodic_y = false, .gravity = {0.0, g_y},
                       .law = RoughDiskCollision{1.0, 0.0, -1.0, s.q},
                       .walls = {EdWall{0, 0.0, +1}, EdWall{0, x_right, -1}, EdWall{1, s.y_floor, +1}},
                       .t_c = 0.0, .tc_both = s.tc_rule == TcRule::both, .tc_keep_friction = s.tc_friction == TcFriction::keep};
    return EdEngine(cfg, pos, vel, std::vector<double>(n, 0.5 * s.d), std::vector<double>(n, s.mass), spin, t0);
}

// The column at t = -t_r: the lattice on the floor, velocities uniform in [-v0, v0] from
// RngStream(seed, index), then (only when asked, so that the defaults draw nothing more and keep
// every run bit for bit) the side walls' outward displacements and the lattice's offset from the
// same stream. Wall jitter (issue 43 §1 item 2; Sec. 5 names "fluctuations of the wall surface"
// as a cause of cracks): each flat side wall moves outward by a uniform random amount in
// [0, wall_jitter] d, constant along the pipe (the event-driven walls are straight lines; a
// profile varying along y needs an engine feature). The left wall stays at x = 0 and the lattice
// moves with it, so the detectors' frame (x from the left wall) is unchanged. Registration
// (item 3): the widest row's free room L - d - span (0.01 d at L = 20.2, s = 1.01 d) goes to the
// right wall (left, today), half to each side (centred), or a uniform random share (random).
struct Column {
    std::vector<Vec2> lat, vel;
    double x_right = 0; // [m] the right wall
};
Column initial_column(const Pipe& s, SeedRun& out, std::uint64_t seed, long index) {
    const std::size_t n = std::size_t(s.n_particles);
    RngStream rng(seed, std::uint64_t(index));
    Column c;
    c.vel = uniform_velocities(n, s.v0, rng);
    double jl = 0, jr = 0, shift = 0;
    if (s.wall_jitter > 0) {
        jl = s.wall_jitter * s.d * rng.uniform();
        jr = s.wall_jitter * s.d * rng.uniform();
    }
    const double span = std::floor((s.L - s.d) / s.a + 1e-9) * s.a, room = std::max(0.0, s.L - s.d - span);
    if (s.registration == Registration::centred) shift = 0.5 * room;
    if (s.registration == Registration::random) shift = room * rng.uniform();
    c.x_right = s.L + jl + jr;
    out.wall_left = jl / s.d;
    out.wall_right = jr / s.d;
    out.lattice_shift = shift / s.d;
    if (jl == 0 && shift == 0 && jr == 0) // today's lattice, bit for bit
        c.lat = triangular_lattice_positions(n, 0.5 * s.d, s.L - 0.5 * s.d, s.y_floor + 0.5 * s.d, s.a);
    else // the same rows, moved right by jl + shift (the last site of a row stays inside: 1e-9 a of slack)
        c.lat = triangular_lattice_positions(n, 0.5 * s.d + jl + shift, 0.5 * s.d + jl + shift + span + 1e-9 * s.a,
                                             s.y_floor + 0.5 * s.d, s.a);
    return c;
}

// v̄ = sqrt(<v^2>) sampled over the relaxation, t = -t_r .. 0 (Relaxation).
constexpr int kRelaxSamples = 60;
Relaxation relax(EdEngine& eng, double t_r) {
    Relaxation rel;
    auto at = [&](long k) { return k <= kRelaxSamples ? std::optional(-t_r + t_r * double(k) / kRelaxSamples) : std::nullopt; };
    SampledRun<>().run(eng, at, NoCollisionObserver{}, [&](long, double) {
        const std::vector<Vec2> vel = eng.velocities();
        double s = 0;
        for (const Vec2& v : vel) s += norm2(v);
        rel.t.push_back(eng.time());
        rel.vbar.push_back(std::sqrt(s / double(vel.size())));
        return false;
    }, 0.0);
    return rel;
}

// t = 0: floor removed, dissipation and friction on, for disks and side walls alike (Eqs. (1)-(7)).
void release(EdEngine& eng, const PipeArchingSpec& s) {
    eng.set_law(RoughDiskCollision{s.epsilon, s.mu, s.beta0, s.q});
    eng.set_wall_law(kLeft, s.epsilon_w, s.mu_w, s.beta0_w);
    eng.set_wall_law(kRight, s.epsilon_w, s.mu_w, s.beta0_w);
    eng.set_tc(s.t_c);
    eng.set_wall_enabled(kFloor, false);
}

// The largest arch among a frame's hot disks r[hot] (Sec. 5: large N_c and large pressure): a
// band of hot disks, each within `link` of the next, that touches both side walls, with wall
// collisions per unit time and height at both its feet at least arch_pressure_factor times the
// column mean. hits: the frame's side-wall collisions.
ArchFound find_arch(const Pipe& s, const std::vector<double>& y0, const std::vector<int>& hot,
                    const std::vector<Vec2>& r, const std::vector<WallHit>& hits) {
    const double d = s.d, L = s.L, fdt = s.frame_dt, reach = s.wall_reach * d, band = s.pressure_band * d;
    const double link2 = std::pow(s.link * d, 2);
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end(), [](const Vec2& a, const Vec2& b) { return a.y < b.y; });
    const double col_h = hi->y - lo->y + d;
    DisjointSets dsu(hot.size());
    for (std::size_t a = 0; a < hot.size(); ++a)
        for (std::size_t b = a + 1; b < hot.size(); ++b)
            if (norm2(r[hot[a]] - r[hot[b]]) <= link2) dsu.join(int(a), int(b));
    std::vector<std::vector<int>> groups(hot.size());
    for (std::size_t a = 0; a < hot.size(); ++a) groups[dsu.find(int(a))].push_back(hot[a]);
    // Column mean of wall collisions per unit time and height, per wall.
    const double mean_p = double(hits.size()) / 2.0 / (fdt * col_h);
    auto foot = [&](int wall, double y) {
        const auto k = std::count_if(hits.begin(), hits.end(), [&](const WallHit& h) {
            return h.wall == wall && std::abs(h.y - y) <= band;
        });
        return double(k) / (fdt * 2 * band) / mean_p;
    };
    ArchFound arch;
    for (const auto& grp : groups) {
        if (grp.empty()) continue;
        double yl = 0, yr = 0;
        int nl = 0, nr = 0;
        for (int i : grp) {
            if (r[i].x <= reach) { yl += r[i].y; ++nl; }
            if (r[i].x >= L - reach) { yr += r[i].y; ++nr; }
        }
        if (nl == 0 || nr == 0) continue;
        yl /= nl; yr /= nr;
        const double pl = mean_p > 0 ? foot(kLeft, yl) : 0, pr = mean_p > 0 ? foot(kRight, yr) : 0;
        if (std::min(pl, pr) < s.arch_pressure_factor) continue;
        if (double(grp.size()) > arch.size) {
            double ym = 0, ys = 0;
            for (int i : grp) { ym += r[i].y; ys += y0[std::size_t(i)]; }
            arch = {true, (ym / double(grp.size()) - s.y_floor) / d, ys / double(grp.size()),
                    double(grp.size()), pl, pr, grp};
        }
    }
    return arch;
}

// Frame f's hot disks, those at a wall, its arch and its crack.
void detect(Fall& fl, const Pipe& s, long f, const std::vector<WallHit>& hits) {
    Frame& fr = fl.frames[std::size_t(f)];
    const double reach = s.wall_reach * s.d;
    const std::vector<Vec2>& r = fr.pos;
    for (std::size_t i = 0; i < r.size(); ++i)
        if (fr.rate[i] >= s.hot_rate) {
            fr.hot.push_back(int(i));
            if (r[i].x <= reach || r[i].x >= s.L - reach) fr.hot_wall.push_back(int(i));
        }
    if (f >= s.detect_from && !fr.hot.empty()) fr.arch = find_arch(s, fl.y0, fr.hot, r, hits);
    if (f >= s.detect_from) fr.crack = find_crack(r, s.cs);
}

// The fall, t = 0 .. t_end, frame by frame: N_c of every disk over the last frame (walls included,
// Sec. 5), the side walls' collisions and impulses, and N_c over dist_dt at the Fig. 14 times.
Fall fall(EdEngine& eng, const Pipe& s) {
    const std::vector<Vec2> r0 = eng.positions();
    const std::vector<double> y0 = column(r0, [&](const Vec2& r) { return (r.y - s.y_floor) / s.d; });
    Fall fl{.pos0 = r0, .y0 = y0, .frames = std::vector<Frame>(std::size_t(s.n_frames) + 1),
            .bands = ColumnBands(y0, 1.0, s.wall_reach * s.d, s.L)};
    const std::size_t n = fl.y0.size();
    const double fdt = s.frame_dt, M = double(n) * s.mass;
    CollisionCounter counter(n, true);
    std::vector<WallHit> hits;           // side-wall collisions in the current frame
    std::vector<double> wall_jy(n, 0.0); // side-wall impulse per disk in the current frame [kg m/s]
    auto obs = [&](const CollisionRecord& k) {
        counter.add(k);
        if (k.j < 0) {
            fl.jy += k.dP.y;
            wall_jy[std::size_t(k.i)] += k.dP.y;
            hits.push_back({k.t, k.ri.y, -1 - k.j});
        }
    };
    // Frame f's sums start when the previous frame is taken (frame 0: the release).
    auto frame_at = [&](long i) { return i < s.n_frames ? std::optional(s.t(i + 1)) : std::nullopt; };
    SampledRun<>().run(eng, frame_at, obs, [&](long i, double t) {
        const long f = i + 1;
        Frame& fr = fl.frames[std::size_t(f)];
        fr.t = t;
        fr.rate = counter.rates(t, fdt);
        fr.pos = eng.positions();
        const std::vector<Vec2> v = eng.velocities();
        fl.bands.add_frame(t, fr.pos, v, wall_jy);
        std::erase_if(hits, [&](const WallHit& h) { return h.t <= t - fdt; });
        detect(fl, s, f, hits);
        if (s.at(s.dist_times_before, f) || s.at(s.dist_times_after, f)) {
            fl.dist_rates.push_back(counter.rates(t, s.dist_dt));
            fl.dist_t.push_back(t);
        }
        counter.discard_before(t - s.dist_dt - fdt);
        fr.wall_load = std::accumulate(wall_jy.begin(), wall_jy.end(), 0.0) / (M * s.g * fdt);
        for (const Vec2& x : v) fr.vy += x.y;
        fr.vy /= double(n);
        fr.wall_rate = double(hits.size()) / fdt / double(n);
        std::fill(wall_jy.begin(), wall_jy.end(), 0.0);
        return false;
    }, s.t_end);
    return fl;
}

} // namespace

SeedRun run_seed(const Pipe& s, std::uint64_t seed, long index, bool figure) {
    const auto wall_start = std::chrono::steady_clock::now();
    SeedRun out;
    const Column col = initial_column(s, out, seed, index);
    const std::vector<Vec2>& lat = col.lat;
    // relax_gravity = off (issue 43 §1 item 4): Sec. 5 relaxes from v0 with r = r_w = 1 and
    // mu = mu_w = 0 and does not say gravity acts then; without it v̄ is set by v0 alone (energy
    // is conserved), with it by the lattice gaps' potential energy (0.596 sqrt(g d), see v0).
    const bool g_relax = s.relax_gravity == RelaxGravity::on;
    EdEngine eng = column_engine(s, lat, col.vel, col.x_right, g_relax ? -s.g : 0.0, -s.t_relax);
    const Relaxation rel = relax(eng, s.t_relax);
    out.vbar0 = rel.vbar.back();
    // Mean over the last third: how steady the relaxed state is.
    out.vbar_relax_late = std::accumulate(rel.vbar.end() - kRelaxSamples / 3, rel.vbar.end(), 0.0) / double(kRelaxSamples / 3);
    // Gravity on at t = 0: a new engine from the relaxed state (the queue's predicted flights
    // assume the old gravity). It forgets the relaxation's collision times, which matters only to
    // Eq. (7) in the first t_c after the release.
    if (!g_relax) eng = column_engine(s, eng.positions(), eng.velocities(), col.x_right, -s.g, eng.time(), eng.spins());
    release(eng, s);
    const double py0 = eng.total_momentum().y;
    const std::uint64_t coll0 = eng.total_collisions(), el0 = eng.elastic_collisions();
    const Fall fl = fall(eng, s);
    lattice_state(out, lat, fl.pos0, s.a);
    for (long f = s.detect_from; f <= s.n_frames && std::isnan(out.t_hot_wall); ++f)
        if (!fl.at(f).hot_wall.empty()) out.t_hot_wall = s.t(f);
    long fa = -1; // the first arch's frame
    for (long f = s.detect_from; f <= s.n_frames && fa < 0; ++f)
        if (fl.at(f).arch.found) fa = f;
    const int i_prec = fa >= 0 ? first_arch(out, s, fl, fa) : -1;
    if (fa >= 0) {
        arch_aftermath(out, s, fl, fa);
        plug_motion(out, s, fl, fa);
    }
    cracks(out, s, fl, fa, i_prec);
    local_crack(out, s, fl, fa, i_prec);
    const std::vector<RateHistogram> hs = fit_fig14(out, s, fl);

    // Momentum balance over the fall; the walls' share of the weight.
    const double M = double(s.n_particles) * s.mass, g = s.g, t_end = s.t_end;
    const double dpy = eng.total_momentum().y - py0;
    out.momentum_residual = (dpy - (-M * g * t_end + fl.jy)) / (M * g * t_end);
    out.friction_share = fl.jy / (M * g * t_end);
    const std::vector<double> load = fl.per_frame(&Frame::wall_load);
    const std::size_t k = 5; // running mean over 5 frames
    out.wall_load_peak = -INFINITY;
    for (std::size_t a = 0; a + k <= load.size(); ++a)
        out.wall_load_peak = std::max(out.wall_load_peak, std::accumulate(load.begin() + long(a), load.begin() + long(a + k), 0.0) / double(k));
    out.collisions = double(eng.total_collisions() - coll0);
    out.elastic_share = double(eng.elastic_collisions() - el0) / std::max(1.0, out.collisions);
    if (figure) out.figure = figure_tables(s, fl, rel, hs, i_prec);
    out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return out;
}

} // namespace granrepro::experiments::pipe_arching_detail
