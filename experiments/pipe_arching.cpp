// pipe-arching: Luding (1998) Section 5, Figs. 13 and 14. N disks on a triangular lattice in a
// pipe of width L relax elastically and smoothly on a floor under gravity (t = -t_r .. 0); at
// t = 0 the floor is removed and dissipation and friction are switched on (ε, μ, β0 for disks and
// side walls alike, Eqs. (1)-(6), TC model Eq. (7)), and the column falls.
//
// Measured per run, every frame_dt (= the paper's Δt of Fig. 13): the collision frequency N_c of
// every disk over the last frame (walls included, Sec. 5 "collisions in which a particle
// participates"), side-wall collisions per unit time and height, and the empty horizontal strips.
// From these, without looking at pictures:
//   arch  = a connected band of hot disks (N_c >= hot_rate) that touches both side walls, with
//           wall collisions per unit time and height at both its feet at least
//           arch_pressure_factor times the column mean (large N_c and large pressure, Sec. 5);
//   crack = a gap from wall to wall through which a probe disk crack_opening wide passes, with
//           crack_min_particles disks below and crack_min_above above (any shape: horizontal,
//           V-shaped, ragged; src/analysis/crack_detector.hpp);
//   first hot wall disk of the arch = earliest frame within precursor_window before the arch with
//           a hot disk at a wall that started (t = 0) within precursor_band of the arch's height.
// P(N_c) over dist_dt (Fig. 14) is fitted with Eqs. (21) and (22) by binned maximum likelihood.
// One run's timing is random, so n_seeds runs are made (index k uses RngStream(seed, k)); run 0
// makes the figures, all runs make the distribution of the first-arch time.
//
// Momentum balance of the falling column (exact for hard disks: pair impulses cancel):
//   P_y(t) - P_y(0) = -M g t + J_y,  J_y = sum of the side walls' impulses (friction) since t = 0.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "analysis/crack_detector.hpp"
#include "analysis/arch_waves.hpp"
#include "analysis/disjoint_sets.hpp"
#include "analysis/seed_stats.hpp"
#include "core/rng_stream.hpp"
#include "data/spec.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "harness/progress.hpp"
#include "harness/protocol.hpp"
#include "observables/collision_counter.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/column_bands.hpp"
#include "observables/rate_histogram.hpp"

namespace granrepro::experiments {

namespace {

enum class TcRule { either, both };    // Eq. (7) for a pair: elastic if either or both partners collided within t_c
enum class TcFriction { drop, keep }; // what a TC-elastic collision does to mu and beta0
void parse_choice(const std::string& s, TcRule& x) { x = s == "both" ? TcRule::both : TcRule::either; }
void parse_choice(const std::string& s, TcFriction& x) { x = s == "keep" ? TcFriction::keep : TcFriction::drop; }
// Read once from experiments/pipe-arching.toml, which holds every parameter's unit, range and source.
struct PipeArchingSpec {
    long n_particles = 0, n_seeds = 0, crack_min_particles = 0, crack_min_above = 0;
    double width = 0, lattice = 0;                            // [d]
    double d = 0, mass = 0, g = 0, v0 = 0;                    // [m], [kg], [m/s^2], [m/s]
    double t_relax = 0, t_end = 0, frame_dt = 0, dist_dt = 0; // [s]
    double epsilon = 0, mu = 0, beta0 = 0, q = 0, t_c = 0;    // t_c [s]
    double epsilon_w = 0, mu_w = 0, beta0_w = 0;
    TcRule tc_rule = TcRule::either;
    TcFriction tc_friction = TcFriction::drop;
    std::vector<double> snapshot_times, dist_times_before, dist_times_after; // [s]
    double hot_rate = 0;                                      // [1/s]
    double link = 0, wall_reach = 0, pressure_band = 0, crack_opening = 0; // [d]
    double precursor_band = 0, plug_half_height = 0, below_depth = 0, arch_separation = 0; // [d]
    double arch_pressure_factor = 0;
    double t_detect_min = 0, precursor_window = 0, arch_window = 0; // [s]
    template <class V> void fields(V&& v) {
        v("n_particles", n_particles); v("n_seeds", n_seeds); v("crack_min_particles", crack_min_particles);
        v("crack_min_above", crack_min_above); v("width", width); v("lattice", lattice); v("d", d); v("mass", mass);
        v("g", g); v("v0", v0); v("t_relax", t_relax); v("t_end", t_end); v("frame_dt", frame_dt);
        v("dist_dt", dist_dt); v("epsilon", epsilon); v("mu", mu); v("beta0", beta0); v("q", q); v("t_c", t_c);
        v("epsilon_w", epsilon_w); v("mu_w", mu_w); v("beta0_w", beta0_w); v("tc_rule", tc_rule);
        v("tc_friction", tc_friction); v("snapshot_times", snapshot_times);
        v("dist_times_before", dist_times_before); v("dist_times_after", dist_times_after);
        v("hot_rate", hot_rate); v("link", link); v("wall_reach", wall_reach); v("pressure_band", pressure_band);
        v("crack_opening", crack_opening); v("precursor_band", precursor_band);
        v("plug_half_height", plug_half_height); v("below_depth", below_depth);
        v("arch_separation", arch_separation); v("arch_pressure_factor", arch_pressure_factor);
        v("t_detect_min", t_detect_min); v("precursor_window", precursor_window); v("arch_window", arch_window);
    }
};

constexpr int kLeft = 0, kRight = 1, kFloor = 2; // wall indices

long frame_of(double t, double frame_dt) { return std::lround(t / frame_dt); }

void validate(const ParameterSet& p) {
    const auto s = read_spec<PipeArchingSpec>(p);
    const double fdt = s.frame_dt;
    // N_c frames of every run (each holds per-particle counts); t_end = 1e308 would never end.
    p.limit_work({"t_end", "t_relax", "frame_dt"}, (s.t_relax + s.t_end) / fdt, 1e7, "frames");
    auto on_grid = [&](const char* name, const std::vector<double>& times, double window) {
        for (double t : times) {
            if (t > s.t_end) p.reject(name, "every time must be <= t_end");
            if (t < window)
                p.reject(std::vector<std::string>{name, window == fdt ? "frame_dt" : "dist_dt"},
                         std::string(name) + ": every time must be >= its N_c window");
            if (std::abs(t / fdt - double(frame_of(t, fdt))) > 1e-6) p.reject(name, "times must be multiples of frame_dt");
        }
    };
    on_grid("snapshot_times", s.snapshot_times, fdt);
    on_grid("dist_times_before", s.dist_times_before, s.dist_dt);
    on_grid("dist_times_after", s.dist_times_after, s.dist_dt);
    if (s.dist_dt < fdt) p.reject("dist_dt", "must be >= frame_dt");
    // Each window becomes a frame count (long(ceil(t / frame_dt))): bounded by the run's frames
    // (limited above), it cannot overflow (t_detect_min = 1e308 crashed the run).
    for (const auto& [name, t] : {std::pair{"t_detect_min", s.t_detect_min}, std::pair{"precursor_window", s.precursor_window},
                                  std::pair{"arch_window", s.arch_window}, std::pair{"frame_dt", fdt}})
        if (!(t <= s.t_end))
            p.reject(std::vector<std::string>{name, "t_end"}, std::string(name) + " must be at most t_end");
    if (s.width < 2 * s.lattice) p.reject("width", "must hold at least two lattice sites");
    if (s.crack_min_particles + s.crack_min_above >= s.n_particles)
        p.reject("crack_min_above", "crack_min_particles + crack_min_above must be below n_particles");
}

// The spec and what it implies: lengths [m] (pipe width L, lattice constant a, the removed
// floor's height, the box height), the frames (frame f ends at t = f frame_dt; arches, hot wall
// disks and cracks are searched from frame detect_from on) and the crack search.
struct Pipe : PipeArchingSpec {
    double L = 0, a = 0, y_floor = 0, ly = 0;
    long n_frames = 0, detect_from = 0;
    CrackSearch cs;
    explicit Pipe(const PipeArchingSpec& spec);
    double t(long f) const { return double(f) * frame_dt; }
    long frames(double dt) const { return long(std::lround(dt / frame_dt)); }
    bool at(const std::vector<double>& times, long f) const {
        return std::any_of(times.begin(), times.end(), [&](double x) { return frame_of(x, frame_dt) == f; });
    }
};

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

std::string tlabel(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t%.3f", t);
    return buf;
}

// Eq. (21) (a Fig. 14(a) time) or Eq. (22) (a (b) time) fitted at one time alone (NaN: no fit).
struct TimeFit {
    double t = NAN, value = NAN, error = NAN; // [s], [1/s], [1/s]
    template <class V> void fields(V&& v) { v("t", t); v("value", value); v("error", error); }
};

// One of run 0's tables (relaxation, Figs. 13 and 14), built by the run and carried through the
// sweep's JSON into the result as it is.
struct FigureTable {
    std::string name, description;
    std::vector<std::string> columns = {}, units = {};
    std::vector<std::vector<double>> values = {};
    void add(const char* column, const char* unit, std::vector<double> v) {
        columns.push_back(column);
        units.push_back(unit);
        values.push_back(std::move(v));
    }
    template <class V> void fields(V&& v) {
        v("name", name); v("description", description); v("columns", columns); v("units", units); v("values", values);
    }
};

// One run (one seed). Times in s, heights in d above the removed floor unless named otherwise.
// Its JSON (the sweep's checkpoint format) names every field as below; NaN is null.
struct SeedRun {
    double vbar0 = NAN, vbar_relax_late = NAN;
    double fluid_layers = NAN, lattice_broken_below = NAN; // state at t = 0 (Sec. 5: lattice intact but the top)
    double t_hot_wall = NAN;                        // first hot disk at a wall (any)
    double t_arch = NAN, y_arch = NAN, y0_arch = NAN; // first arch: time, lab and initial height
    double arch_size = NAN, arch_pL = NAN, arch_pR = NAN;
    double t_precursor = NAN, react_lag = NAN;
    double arch_left_4ms = NAN, arch_above_later = NAN, arch_below_later = NAN;
    double wave_steps = NAN, wave_steps_up = NAN;  // successive distinct arches ("momentum waves") and how many rose
    double wave_stronger = NAN;                     // 1 if a later wave elsewhere had more hot disks than the first arch
    double plug_wall_load = NAN, arch_brake = NAN, opening_below = NAN;
    double wall_slowdown_arch = NAN, wall_slowdown_before = NAN;
    double t_crack = NAN, y_crack = NAN, y0_crack = NAN, crack_opening = NAN;
    double crack_below_arch = NAN, crack_at_initiator = NAN;
    double opening_max_before = NAN, opening_max_after = NAN, opening_max_all = NAN;
    double A = NAN, A_err = NAN, A_chi2 = NAN, B = NAN, B_err = NAN, B_chi2 = NAN;
    double times_before = NAN, times_after = NAN; // Fig. 14 times pooled into A and B
    double dev_exp_early = NAN, dev_pow_early = NAN, dev_exp_late = NAN, dev_pow_late = NAN;
    double mean_rate_early = NAN;
    double momentum_residual = NAN, friction_share = NAN, wall_load_peak = NAN;
    double wall_seconds = NAN, collisions = NAN, elastic_share = NAN;
    std::vector<TimeFit> per_time;    // every run: at each Fig. 14 time
    std::vector<FigureTable> figure;  // run 0 only
    template <class V> void fields(V&& v) {
        v("vbar0", vbar0); v("vbar_relax_late", vbar_relax_late); v("fluid_layers", fluid_layers);
        v("lattice_broken_below", lattice_broken_below); v("t_hot_wall", t_hot_wall); v("t_arch", t_arch);
        v("y_arch", y_arch); v("y0_arch", y0_arch); v("arch_size", arch_size); v("arch_pL", arch_pL);
        v("arch_pR", arch_pR); v("t_precursor", t_precursor);
        v("react_lag", react_lag); v("arch_left_4ms", arch_left_4ms); v("arch_above_later", arch_above_later);
        v("wave_steps", wave_steps); v("wave_steps_up", wave_steps_up); v("wave_stronger", wave_stronger);
        v("arch_below_later", arch_below_later); v("plug_wall_load", plug_wall_load); v("arch_brake", arch_brake);
        v("opening_below", opening_below); v("wall_slowdown_arch", wall_slowdown_arch);
        v("wall_slowdown_before", wall_slowdown_before); v("t_crack", t_crack); v("y_crack", y_crack);
        v("y0_crack", y0_crack); v("crack_opening", crack_opening); v("crack_below_arch", crack_below_arch);
        v("crack_at_initiator", crack_at_initiator); v("opening_max_before", opening_max_before);
        v("opening_max_after", opening_max_after); v("opening_max_all", opening_max_all); v("A", A);
        v("A_err", A_err); v("A_chi2", A_chi2); v("B", B); v("B_err", B_err); v("B_chi2", B_chi2);
        v("times_before", times_before); v("times_after", times_after); v("dev_exp_early", dev_exp_early);
        v("dev_pow_early", dev_pow_early); v("dev_exp_late", dev_exp_late); v("dev_pow_late", dev_pow_late);
        v("mean_rate_early", mean_rate_early); v("momentum_residual", momentum_residual);
        v("friction_share", friction_share); v("wall_load_peak", wall_load_peak); v("wall_seconds", wall_seconds);
        v("collisions", collisions); v("elastic_share", elastic_share); v("per_time", per_time); v("figure", figure);
    }
};

// f (a field or a function of a SeedRun) of every run.
template <class F> std::vector<double> per_seed(const std::vector<SeedRun>& runs, F f) {
    std::vector<double> v;
    for (const auto& r : runs) v.push_back(std::invoke(f, r));
    return v;
}

// A converged fit, or none (too few counts, or no convergence).
std::optional<CollisionRateFit> try_fit(const RateHistogram& h, CollisionRateFit::Model m, double lo, double hi) {
    try {
        if (const CollisionRateFit f = CollisionRateFit::fit(h, m, lo, hi); f.converged) return f;
    } catch (const std::invalid_argument&) {
    }
    return std::nullopt;
}

struct WallHit { // a side-wall collision
    double t, y;
    int wall;
};

struct ArchFound {
    bool found = false;
    double y = NAN, y0 = NAN, size = 0, pL = NAN, pR = NAN;
    std::vector<int> members;
};

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

// The column at t = -t_r: the lattice on the floor, velocities uniform in [-v0, v0] from
// RngStream(seed, index), elastic and smooth (Sec. 5: r = r_w = 1, mu = mu_w = 0).
EdEngine build_column(const Pipe& s, const std::vector<Vec2>& lat, std::uint64_t seed, long index) {
    const std::size_t n = std::size_t(s.n_particles);
    RngStream rng(seed, std::uint64_t(index));
    const std::vector<Vec2> vel = uniform_velocities(n, s.v0, rng);
    const EdConfig cfg{.lx = s.L, .ly = s.ly, .periodic_x = false, .periodic_y = false, .gravity = {0.0, -s.g},
                       .law = RoughDiskCollision{1.0, 0.0, -1.0, s.q},
                       .walls = {EdWall{0, 0.0, +1}, EdWall{0, s.L, -1}, EdWall{1, s.y_floor, +1}},
                       .t_c = 0.0, .tc_both = s.tc_rule == TcRule::both, .tc_keep_friction = s.tc_friction == TcFriction::keep};
    return EdEngine(cfg, lat, vel, std::vector<double>(n, 0.5 * s.d), std::vector<double>(n, s.mass), {}, -s.t_relax);
}

// v̄ = sqrt(<v^2>) sampled over the relaxation, t = -t_r .. 0.
struct Relaxation {
    std::vector<double> t, vbar;
};
constexpr int kRelaxSamples = 60;
Relaxation relax(EdEngine& eng, double t_r) {
    Relaxation rel;
    for (int k = 0; k <= kRelaxSamples; ++k) {
        eng.run_until(-t_r + t_r * k / kRelaxSamples);
        const std::vector<Vec2> vel = eng.velocities();
        double s = 0;
        for (const Vec2& v : vel) s += norm2(v);
        rel.t.push_back(eng.time());
        rel.vbar.push_back(std::sqrt(s / double(vel.size())));
    }
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

// One frame of the fall, at its end.
struct Frame {
    std::vector<Vec2> pos;
    std::vector<double> rate;          // N_c over the last frame_dt [1/s]
    std::vector<int> hot;              // disks with N_c >= hot_rate, ascending
    std::vector<int> hot_wall;         // those at a side wall
    ArchFound arch;
    Crack crack;
    double t = 0, vy = 0, wall_rate = 0; // [s]; mean v_y [m/s]; side-wall collisions per disk and unit time [1/s]
    double wall_load = 0;         // side-wall impulse over M g frame_dt
};

// One run from the release on: the column at t = 0, frames 1 .. n_frames (frame 0 stays empty),
// the Lagrangian bands of 1 d of initial height, and N_c over dist_dt at the Fig. 14 times.
struct Fall {
    std::vector<Vec2> pos0; // [m]
    std::vector<double> y0; // initial heights above the removed floor [d]
    std::vector<Frame> frames;
    ColumnBands bands;
    std::vector<std::vector<double>> dist_rates = {};
    std::vector<double> dist_t = {};
    double jy = 0; // side-wall impulse on the column since t = 0 [kg m/s]
    const Frame& at(long f) const { return frames[std::size_t(f)]; }
    template <class F> std::vector<double> per_frame(F x) const { // frames 1 .. n_frames
        std::vector<double> v;
        for (std::size_t f = 1; f < frames.size(); ++f) v.push_back(std::invoke(x, frames[f]));
        return v;
    }
};

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
    std::vector<double> y0;
    for (const Vec2& r : r0) y0.push_back((r.y - s.y_floor) / s.d);
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
    for (long f = 1; f <= s.n_frames; ++f) {
        const double t = s.t(f);
        Frame& fr = fl.frames[std::size_t(f)];
        fr.t = t;
        std::fill(wall_jy.begin(), wall_jy.end(), 0.0);
        eng.run_until(t, obs);
        report_engine_time(t, s.t_end);
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
    }
    return fl;
}

long count_hot(const std::vector<int>& disks, const std::vector<int>& hot) {
    return long(std::count_if(disks.begin(), disks.end(), [&](int j) { return std::binary_search(hot.begin(), hot.end(), j); }));
}

// The first arch (frame fa) and its initiating disk, which the function returns (-1 if none):
// the earliest hot wall disk within precursor_window before the arch that started within
// precursor_band of the arch's initial height (the black bar, Fig. 13).
int first_arch(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const ArchFound& a = fl.at(fa).arch;
    out.t_arch = s.t(fa); out.y_arch = a.y; out.y0_arch = a.y0;
    out.arch_size = a.size; out.arch_pL = a.pL; out.arch_pR = a.pR;
    int i_prec = -1;
    long f_prec = -1;
    for (long k = std::max(s.detect_from, fa - s.frames(s.precursor_window)); k <= fa && i_prec < 0; ++k)
        for (int i : fl.at(k).hot_wall)
            if (std::abs(fl.y0[std::size_t(i)] - a.y0) <= s.precursor_band) {
                f_prec = k;
                i_prec = i;
                out.t_precursor = s.t(k);
                break;
            }
    if (i_prec < 0) return i_prec;
    // Its neighbours react (Sec. 5: "already 0.004 s later"): the first frame from the
    // precursor's on in which at least half of the disks that were its neighbours (within
    // `link` at t = 0) are hot.
    const double link2 = std::pow(s.link * s.d, 2);
    std::vector<int> nb;
    for (std::size_t j = 0; j < fl.pos0.size(); ++j)
        if (int(j) != i_prec && norm2(fl.pos0[j] - fl.pos0[std::size_t(i_prec)]) <= link2) nb.push_back(int(j));
    for (long k = f_prec; k <= s.n_frames && !nb.empty(); ++k)
        if (2 * count_hot(nb, fl.at(k).hot) >= long(nb.size())) {
            out.react_lag = s.t(k) - out.t_precursor;
            break;
        }
    return i_prec;
}

// What follows the first arch (Sec. 5): "0.004 s later this region ... has almost disappeared"
// (the share of its disks still hot 4 ms after it spanned the width) and "new arches above and
// below the original one appeared".
void arch_aftermath(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const ArchFound& a = fl.at(fa).arch;
    const long f4 = fa + s.frames(0.004);
    if (f4 > s.n_frames) return;
    out.arch_left_4ms = double(count_hot(a.members, fl.at(f4).hot)) / double(a.members.size());
    out.arch_above_later = out.arch_below_later = 0;
    for (long k = f4; k <= s.n_frames; ++k) {
        const ArchFound& b = fl.at(k).arch;
        if (!b.found) continue;
        if (b.y0 > a.y0 + s.arch_separation) out.arch_above_later = 1;
        if (b.y0 < a.y0 - s.arch_separation) out.arch_below_later = 1;
    }
    // Successive arches as momentum waves (src/analysis/arch_waves.hpp): do they rise, is a later one stronger.
    std::vector<ArchSighting> seen;
    for (long k = fa; k <= s.n_frames; ++k) {
        const ArchFound& b = fl.at(k).arch;
        seen.push_back({b.found, b.y0, double(b.members.size())});
    }
    const ArchWaves w = follow_arch_waves(seen, std::size_t(f4 - fa), s.arch_separation);
    out.wave_steps = w.steps;
    out.wave_steps_up = w.steps_up;
    out.wave_stronger = w.stronger() ? 1 : 0;
}

// The first arch's plug and the material below it, as Lagrangian bands (initial heights): how
// much of the plug's weight the walls carry around the arch, how much slower the plug falls than
// the material below, and how far the two move apart (an opening crack), all over
// [t_arch - arch_window, t_arch + arch_window] and relative to its start. Disks at the walls slow
// down (Sec. 5): in the plug, v_y at the walls minus v_y inside (> 0: the wall disks fall
// slower), at the arch and at the window's start.
void plug_motion(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const double y0 = fl.at(fa).arch.y0, hp = s.plug_half_height, depth = s.below_depth;
    const long w = s.frames(s.arch_window);
    const long f0 = std::max(1L, fa - w), f1 = std::min(s.n_frames, fa + w);
    auto plug = [&](long f) { return fl.bands.group(std::size_t(f - 1), y0 - hp, y0 + hp); };
    auto below = [&](long f) { return fl.bands.group(std::size_t(f - 1), y0 - hp - depth, y0 - hp); };
    const double dv0 = plug(f0).vy - below(f0).vy, dy0 = plug(f0).y - below(f0).y;
    double jp = 0, jn = 0, brake = -INFINITY, open = -INFINITY;
    for (long f = f0; f <= f1; ++f) {
        const auto P = plug(f), B = below(f);
        if (std::abs(f - fa) <= s.frames(0.004)) { jp += P.jy; jn += 1; }
        brake = std::max(brake, P.vy - B.vy - dv0);
        open = std::max(open, (P.y - B.y - dy0) / s.d);
    }
    const auto P = plug(fa);
    out.plug_wall_load = jp / (P.n * s.mass * s.g * jn * s.frame_dt);
    out.arch_brake = brake;
    out.opening_below = open;
    out.wall_slowdown_arch = P.vy_wall - P.vy_inner;
    out.wall_slowdown_before = plug(f0).vy_wall - plug(f0).vy_inner;
}

// Cracks: the first frame with an opening >= crack_opening and how it relates to the first arch
// (frame fa, -1 if none) and its initiating disk i_prec; the widest openings before the arch,
// within arch_window after it, and at any frame.
void cracks(SeedRun& out, const Pipe& s, const Fall& fl, long fa, int i_prec) {
    const double d = s.d;
    double omax_before = -INFINITY, omax_after = -INFINITY, omax_all = -INFINITY;
    for (long f = s.detect_from; f <= s.n_frames; ++f) {
        const Crack& k = fl.at(f).crack;
        const double o = k.opening / d;
        omax_all = std::max(omax_all, o);
        if (fa < 0 || f < fa) omax_before = std::max(omax_before, o);
        else if (f <= fa + s.frames(s.arch_window)) omax_after = std::max(omax_after, o);
        if (k.opening >= s.crack_opening * d && std::isnan(out.t_crack)) {
            out.t_crack = s.t(f);
            out.crack_opening = o;
            out.y_crack = (k.y_mean - s.y_floor) / d;
            if (k.narrow_i >= 0) out.y0_crack = 0.5 * (fl.y0[std::size_t(k.narrow_i)] + fl.y0[std::size_t(k.narrow_j)]);
            if (fa >= 0) out.crack_below_arch = out.y0_arch - out.y0_crack;
            if (i_prec >= 0) {
                // The course at the initiating disk's wall against the disk's height then.
                const Vec2 rp = fl.at(f).pos[std::size_t(i_prec)];
                const double yc = rp.x < 0.5 * s.L ? k.y_left : k.y_right;
                out.crack_at_initiator = (yc - rp.y) / d;
            }
        }
    }
    auto finite = [](double x) { return std::isfinite(x) ? x : NAN; };
    out.opening_max_before = finite(omax_before); out.opening_max_after = finite(omax_after); out.opening_max_all = finite(omax_all);
}

// Fits of Eqs. (21), (22) to P(N_c) pooled over the Fig. 14 times that lie, in this run, before
// the first arch (panel a: "before the first arch (or crack) occurs") or after it (panel b: "when
// cracks and arches exist"); a run without an arch has no panel (b). Then the same fits at each
// time alone (Fig. 14 draws four times per panel); returns the histograms of those times.
std::vector<RateHistogram> fit_fig14(SeedRun& out, const PipeArchingSpec& s, const Fall& fl) {
    const double ddt = s.dist_dt, rmin = 1.0 / ddt; // one collision per window
    const std::size_t n_before = s.dist_times_before.size();
    auto hist_lin = [&](const std::vector<double>& rs) { return RateHistogram::per_count(rs, ddt, 200); };
    auto hist_log = [&](const std::vector<double>& rs) {
        return RateHistogram::make(rs, ddt, RateHistogram::Binning::Log, 30, 0.5 * rmin, 1.0e6);
    };
    const double hi_lin = (200 + 0.5) / ddt;
    std::vector<double> before, after;
    out.times_before = out.times_after = 0;
    for (std::size_t k = 0; k < fl.dist_rates.size(); ++k) {
        const std::vector<double>& rk = fl.dist_rates[k];
        const bool arched = std::isfinite(out.t_arch) && fl.dist_t[k] >= out.t_arch - 1e-12;
        if (k < n_before && !arched) { before.insert(before.end(), rk.begin(), rk.end()); out.times_before += 1; }
        if (k >= n_before && arched) { after.insert(after.end(), rk.begin(), rk.end()); out.times_after += 1; }
    }
    using Model = CollisionRateFit::Model;
    if (!before.empty()) {
        const RateHistogram h = hist_lin(before);
        const auto fe = try_fit(h, Model::Exponential, 0.5 * rmin, hi_lin), fp = try_fit(h, Model::PowerLaw, 0.5 * rmin, hi_lin);
        if (fe) { out.A = fe->value; out.A_err = fe->error; out.A_chi2 = fe->chi2_reduced; out.dev_exp_early = fe->deviance; }
        if (fp) out.dev_pow_early = fp->deviance;
        out.mean_rate_early = std::accumulate(before.begin(), before.end(), 0.0) / double(before.size());
    }
    if (!after.empty()) {
        const RateHistogram h = hist_log(after);
        const auto fe = try_fit(h, Model::Exponential, 0.5 * rmin, 1.0e6), fp = try_fit(h, Model::PowerLaw, 0.5 * rmin, 1.0e6);
        if (fp) { out.B = fp->value; out.B_err = fp->error; out.B_chi2 = fp->chi2_reduced; out.dev_pow_late = fp->deviance; }
        if (fe) out.dev_exp_late = fe->deviance;
    }
    std::vector<RateHistogram> hs;
    for (std::size_t k = 0; k < fl.dist_rates.size(); ++k) {
        const bool early = k < n_before;
        hs.push_back(early ? hist_lin(fl.dist_rates[k]) : hist_log(fl.dist_rates[k]));
        const auto f = try_fit(hs.back(), early ? Model::Exponential : Model::PowerLaw, 0.5 * rmin, early ? hi_lin : 1.0e6);
        out.per_time.push_back({fl.dist_t[k], f ? f->value : NAN, f ? f->error : NAN});
    }
    return hs;
}

// A Fig. 13 snapshot (run 0): the disks, the frame's arch and the crack.
void add_snapshot(std::vector<FigureTable>& F, const Pipe& s, const Frame& fr) {
    const double d = s.d;
    std::vector<double> x, y, in_arch, side, cx, cy;
    for (std::size_t i = 0; i < fr.pos.size(); ++i) {
        x.push_back(fr.pos[i].x / d);
        y.push_back((fr.pos[i].y - s.y_floor) / d);
        in_arch.push_back(std::find(fr.arch.members.begin(), fr.arch.members.end(), int(i)) != fr.arch.members.end() ? 1 : 0);
        side.push_back(fr.crack.side.empty() ? 0 : fr.crack.side[i]);
    }
    for (std::size_t j = 0; j < fr.crack.course_x.size(); ++j) {
        cx.push_back(fr.crack.course_x[j] / d);
        cy.push_back((fr.crack.course_y[j] - s.y_floor) / d);
    }
    FigureTable& t = F.emplace_back(FigureTable{"snapshot_" + tlabel(fr.t),
        "disk centres (x, y above the removed floor), N_c over the last frame_dt, member of the frame's arch, side of the crack (-1 below, +1 above, 0 loose), run 0"});
    t.add("x", "d", x);
    t.add("y", "d", y);
    t.add("Nc", "1/s", fr.rate);
    t.add("arch", "1", in_arch);
    t.add("crack_side", "1", side);
    FigureTable& c = F.emplace_back(FigureTable{"crack_" + tlabel(fr.t), "course of the widest wall-to-wall crack (mid-height per slice of one diameter), run 0"});
    c.add("x", "d", cx);
    c.add("y", "d", cy);
}

// Run 0's tables: the relaxation, the Fig. 13 snapshots and their marks (the initiating disk, the
// frame's arch, the crack), the timeline per frame, the Fig. 14 histograms.
std::vector<FigureTable> figure_tables(const Pipe& s, const Fall& fl, const Relaxation& rel,
                                       const std::vector<RateHistogram>& hs, int i_prec) {
    std::vector<FigureTable> F{{"relaxation", "v̄ = sqrt(<v^2>) during the elastic relaxation, run 0"}};
    F[0].add("t", "s", rel.t);
    F[0].add("vbar", "m/s", rel.vbar);
    std::vector<const Frame*> snaps;
    for (long f = 1; f <= s.n_frames; ++f)
        if (s.at(s.snapshot_times, f)) add_snapshot(F, s, *snaps.emplace_back(&fl.at(f)));
    auto per_snap = [&](auto x) {
        std::vector<double> v;
        for (const Frame* fr : snaps) v.push_back(x(*fr));
        return v;
    };
    auto arch_y = [](const Frame& fr) { return fr.arch.found ? fr.arch.y : NAN; };
    auto opening = [&](const Frame& fr) { return fr.crack.course_x.empty() ? NAN : fr.crack.opening / s.d; };
    auto initiator = [&](const Frame& fr) { return i_prec >= 0 ? fr.pos[std::size_t(i_prec)] : Vec2{NAN, NAN}; };
    FigureTable& mk = F.emplace_back(FigureTable{"marks", "run 0 per Fig. 13 snapshot: initiating disk (x, y), arch height, crack opening"});
    mk.add("t", "s", per_snap([](const Frame& fr) { return fr.t; }));
    mk.add("initiator_x", "d", per_snap([&](const Frame& fr) { return initiator(fr).x / s.d; }));
    mk.add("initiator_y", "d", per_snap([&](const Frame& fr) { return (initiator(fr).y - s.y_floor) / s.d; }));
    mk.add("arch_y", "d", per_snap(arch_y));
    mk.add("crack_opening", "d", per_snap(opening));
    mk.add("crack_visible", "1", per_snap([&](const Frame& fr) { return opening(fr) >= s.crack_opening ? 1.0 : 0.0; }));
    FigureTable& tl = F.emplace_back(FigureTable{"timeline", "run 0 per frame: hot disks, mean N_c, widest wall-to-wall crack, mean v_y, wall collisions, share of the weight carried by the walls, arch height"});
    tl.add("t", "s", fl.per_frame(&Frame::t));
    tl.add("hot", "1", fl.per_frame([](const Frame& fr) { return double(fr.hot.size()); }));
    tl.add("hot_wall", "1", fl.per_frame([](const Frame& fr) { return double(fr.hot_wall.size()); }));
    tl.add("mean", "1/s", fl.per_frame([](const Frame& fr) {
        return std::accumulate(fr.rate.begin(), fr.rate.end(), 0.0) / double(fr.rate.size());
    }));
    tl.add("opening", "d", fl.per_frame(opening));
    tl.add("vy", "m/s", fl.per_frame(&Frame::vy));
    tl.add("wall_rate", "1/s", fl.per_frame(&Frame::wall_rate));
    tl.add("wall_load", "1", fl.per_frame(&Frame::wall_load));
    tl.add("arch_y", "d", fl.per_frame(arch_y));
    for (std::size_t k = 0; k < hs.size(); ++k) {
        FigureTable& h = F.emplace_back(FigureTable{"pnc_" + tlabel(fl.dist_t[k]), "P(N_c) over the last dist_dt, run 0"});
        h.add("Nc", "1/s", hs[k].centres);
        h.add("P", "s", hs[k].density);
        h.add("err", "s", hs[k].error);
    }
    return F;
}

SeedRun run_seed(const Pipe& s, std::uint64_t seed, long index, bool figure) {
    const auto wall_start = std::chrono::steady_clock::now();
    const std::vector<Vec2> lat = triangular_lattice_positions(std::size_t(s.n_particles), 0.5 * s.d, s.L - 0.5 * s.d,
                                                               s.y_floor + 0.5 * s.d, s.a);
    EdEngine eng = build_column(s, lat, seed, index);
    SeedRun out;
    const Relaxation rel = relax(eng, s.t_relax);
    out.vbar0 = rel.vbar.back();
    // Mean over the last third: how steady the relaxed state is.
    out.vbar_relax_late = std::accumulate(rel.vbar.end() - kRelaxSamples / 3, rel.vbar.end(), 0.0) / double(kRelaxSamples / 3);
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

double fraction_below(const std::vector<double>& v, double x) {
    double k = 0;
    for (double y : v)
        if (!std::isnan(y) && y <= x + 1e-12) ++k;
    return k / double(v.size());
}
// Over the finite values, from running sums (seed_stats' two-pass mean_sd differs in the last bits).
struct MeanSem {
    double mean = NAN, sd = NAN, sem = NAN, n = 0;
};
MeanSem mean_sem(const std::vector<double>& v) {
    MeanSem m;
    double s = 0, s2 = 0;
    for (double x : v)
        if (std::isfinite(x)) { s += x; s2 += x * x; m.n += 1; }
    if (m.n < 1) return m;
    m.mean = s / m.n;
    if (m.n < 2) return m;
    m.sd = std::sqrt(std::max(0.0, (s2 - m.n * m.mean * m.mean) / (m.n - 1)));
    m.sem = m.sd / std::sqrt(m.n);
    return m;
}
// Share of the finite values for which pred holds (NaN if none is finite).
template <class Pred> double share_finite(const std::vector<double>& v, Pred pred) {
    double k = 0, n = 0;
    for (double y : v)
        if (std::isfinite(y)) { n += 1; k += pred(y) ? 1 : 0; }
    return n > 0 ? k / n : NAN;
}

// v̄ at t = 0 over seeds, after the elastic relaxation.
void report_relaxation(Result& res, const std::vector<SeedRun>& runs) {
    const std::vector<double> v0s = per_seed(runs, &SeedRun::vbar0), vlate = per_seed(runs, &SeedRun::vbar_relax_late);
    res.scalar("vbar_t0", median(v0s), "m/s", "v̄ = sqrt(<v^2>) at t = 0, median over seeds");
    res.scalar("vbar_t0_run0", runs.front().vbar0, "m/s", "v̄ at t = 0, run 0");
    res.scalar("vbar_relax_drift", median(v0s) / median(vlate) - 1, "1",
               "v̄(0) over the mean v̄ of the last third of the relaxation, minus 1 (steadiness)");
}

// Fig. 14 per time: the fits at each time alone (run 0 with its error, median over seeds).
void report_fig14_times(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    const SeedRun& f0 = runs.front();
    const std::size_t n_before = s.dist_times_before.size();
    Table& pt = res.table("fits_per_time", "Eq. (21) A (Fig. 14(a) times) or Eq. (22) B (Fig. 14(b) times) fitted at each time alone: run 0 with its standard error, and the median over seeds");
    std::vector<double> tt, v0, e0, med;
    for (std::size_t k = 0; k < f0.per_time.size(); ++k) {
        const double t = f0.per_time[k].t;
        tt.push_back(t);
        v0.push_back(f0.per_time[k].value);
        e0.push_back(f0.per_time[k].error);
        med.push_back(median(per_seed(runs, [&](const SeedRun& r) { return r.per_time.at(k).value; })));
        const std::string what = k < n_before ? "A_" : "B_", eq = k < n_before ? "Eq. (21)" : "Eq. (22)";
        res.scalar(what + tlabel(t), v0.back(), "1/s", eq + " fit at this time alone, run 0");
        res.scalar(what + "err_" + tlabel(t), e0.back(), "1/s", "its standard error");
        res.scalar(what + tlabel(t) + "_median_seeds", med.back(), "1/s", eq + " fit at this time alone, median over seeds");
    }
    pt.add({{"t", "s", tt}, {"run0", "1/s", v0}, {"run0_err", "1/s", e0}, {"median_seeds", "1/s", med}});
}

// Fig. 14 pooled: Eqs. (21), (22) over each panel's four times, run 0 and over seeds (the
// claims' values), in both readings of the paper's units.
void report_fig14_fits(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs) {
    const SeedRun& f0 = runs.front();
    const double ddt = s.dist_dt;
    res.scalar("A_fit", f0.A, "1/s", "Eq. (21), pooled over the Fig. 14(a) times, run 0");
    res.scalar("A_fit_err", f0.A_err, "1/s", "its standard error (Cramer-Rao)");
    res.scalar("A_fit_chi2_reduced", f0.A_chi2, "1", "Pearson chi^2/dof of that fit");
    res.scalar("B_fit", f0.B, "1/s", "Eq. (22), pooled over the Fig. 14(b) times, run 0");
    res.scalar("B_fit_err", f0.B_err, "1/s", "its standard error (Cramer-Rao)");
    res.scalar("B_fit_chi2_reduced", f0.B_chi2, "1", "Pearson chi^2/dof of that fit");
    res.scalar("A_fit_per_window", f0.A * ddt, "1", "A in collisions per dist_dt window");
    res.scalar("mean_Nc_before", f0.mean_rate_early, "1/s", "mean N_c at the Fig. 14(a) times, run 0");
    const std::vector<double> As = per_seed(runs, &SeedRun::A), Bs = per_seed(runs, &SeedRun::B);
    const auto BA = per_seed(runs, [](const SeedRun& r) { return r.B / r.A; });
    // Deviance of the exponential over that of the power law: < 1 where Eq. (21) fits better.
    const auto ratio_early = per_seed(runs, [](const SeedRun& r) { return r.dev_exp_early / r.dev_pow_early; });
    const auto ratio_late = per_seed(runs, [](const SeedRun& r) { return r.dev_exp_late / r.dev_pow_late; });
    res.scalar("fig14_times_before_median", median(per_seed(runs, &SeedRun::times_before)), "1", "Fig. 14(a) times before the run's first arch, pooled into A, median over seeds");
    res.scalar("fig14_times_after_median", median(per_seed(runs, &SeedRun::times_after)), "1", "Fig. 14(b) times after the run's first arch, pooled into B, median over seeds");
    res.scalar("A_fit_median_seeds", median(As), "1/s", "Eq. (21) A, median over seeds");
    res.scalar("B_fit_median_seeds", median(Bs), "1/s", "Eq. (22) B, median over seeds");
    res.scalar("B_over_A_median_seeds", median(BA), "1", "B/A per seed, median (unit-free)");
    // The paper's numbers come from one run: where they fall in our distribution over seeds.
    res.scalar("B_over_A_fraction_below_paper", share_finite(BA, [](double y) { return y <= 14.0; }), "1",
               "fraction of seeds with B/A <= 14, the paper's value (its percentile in our distribution)");
    res.scalar("B_fraction_below_paper", share_finite(Bs, [](double y) { return y <= 14.0e3; }), "1",
               "fraction of seeds with B <= 14e3 1/s (the paper's B in reading 1)");
    const MeanSem a = mean_sem(As), b = mean_sem(Bs), ba = mean_sem(BA);
    res.scalar("A_fit_seed_sem", a.sem, "1/s", "standard error of the mean of A over seeds");
    res.scalar("B_fit_seed_sem", b.sem, "1/s", "standard error of the mean of B over seeds");
    res.scalar("B_over_A_seed_sem", ba.sem, "1", "standard error of the mean of B/A over seeds");
    res.scalar("B_over_A_seed_sd", ba.sd, "1", "standard deviation of B/A over seeds");
    // The two readings of the paper's 'A = 1, B = 14 s^-1' (Sec. 5): the axis in units of
    // 1e3 1/s, or in collisions per window dist_dt.
    res.scalar("A_in_1e3_per_s", median(As) / 1e3, "1", "A, median over seeds, in 1e3 1/s (reading 1: paper 1)");
    res.scalar("B_in_1e3_per_s", median(Bs) / 1e3, "1", "B, median over seeds, in 1e3 1/s (reading 1: paper 14)");
    res.scalar("A_per_window", median(As) * ddt, "1", "A, median over seeds, in collisions per dist_dt (reading 2: paper 1)");
    res.scalar("B_per_window", median(Bs) * ddt, "1", "B, median over seeds, in collisions per dist_dt (reading 2: paper 14)");
    Table& ft = res.table("fits", "Eqs. (21), (22) pooled over each panel's four times, as drawn in Fig. 14 and checked: median over seeds, standard error of the mean over seeds, run 0 with its fit error");
    const std::vector<std::pair<const char*, double>> cols = {
        {"A", median(As)}, {"A_sem", a.sem}, {"A_run0", f0.A}, {"A_run0_err", f0.A_err},
        {"B", median(Bs)}, {"B_sem", b.sem}, {"B_run0", f0.B}, {"B_run0_err", f0.B_err}};
    for (const auto& [name, x] : cols) ft.add(name, "1/s").values = {x};
    ft.add({{"seeds", "1", {double(runs.size())}}, {"dist_dt", "s", {ddt}}});
    res.scalar("exp_over_pow_deviance_before", median(ratio_early), "1",
               "deviance of Eq. (21) over that of Eq. (22), Fig. 14(a) times, median over seeds (< 1: exponential fits better)");
    res.scalar("exp_over_pow_deviance_after", median(ratio_late), "1",
               "the same at the Fig. 14(b) times (> 1: power law fits better)");
}

void report_seed_table(Result& res, const std::vector<SeedRun>& runs) {
    Table& st = res.table("seeds", "per seed: first hot wall disk, first arch (time, lab and initial height), its precursor, first crack (NaN: none before t_end)");
    std::vector<double> index(runs.size());
    std::iota(index.begin(), index.end(), 0.0);
    st.add("seed_index", "1").values = index;
    using S = SeedRun;
    const std::vector<std::tuple<const char*, const char*, std::function<double(const SeedRun&)>>> cols = {
        {"t_hot_wall", "s", &S::t_hot_wall}, {"t_precursor", "s", &S::t_precursor}, {"t_arch", "s", &S::t_arch},
        {"y_arch", "d", &S::y_arch}, {"y0_arch", "d", &S::y0_arch}, {"arch_size", "1", &S::arch_size},
        {"arch_foot_pressure_ratio", "1", [](const SeedRun& r) { return std::min(r.arch_pL, r.arch_pR); }},
        {"react_lag", "s", &S::react_lag}, {"arch_left_4ms", "1", &S::arch_left_4ms}, {"plug_wall_load", "1", &S::plug_wall_load},
        {"arch_brake", "m/s", &S::arch_brake}, {"opening_below", "d", &S::opening_below},
        {"wall_slowdown_arch", "m/s", &S::wall_slowdown_arch}, {"opening_max_after", "d", &S::opening_max_after},
        {"t_crack", "s", &S::t_crack}, {"y_crack", "d", &S::y_crack}, {"y0_crack", "d", &S::y0_crack},
        {"crack_opening", "d", &S::crack_opening}, {"opening_max_before", "d", &S::opening_max_before},
        {"opening_max_all", "d", &S::opening_max_all}, {"wave_steps", "1", &S::wave_steps},
        {"wave_steps_up", "1", &S::wave_steps_up}, {"wave_stronger", "1", &S::wave_stronger},
        {"friction_share", "1", &S::friction_share}, {"A", "1/s", &S::A},
        {"B", "1/s", &S::B}, {"wall_seconds", "s", &S::wall_seconds}};
    for (const auto& [name, unit, f] : cols) st.add(name, unit).values = per_seed(runs, f);
}

// First arch, its first hot wall disk and first crack over seeds: when (censored at t_end),
// where, and where the paper's single run falls in that distribution.
void report_arch_times(Result& res, const std::vector<SeedRun>& runs) {
    const std::vector<double> ta = per_seed(runs, &SeedRun::t_arch), tp = per_seed(runs, &SeedRun::t_precursor);
    const std::vector<double> tw = per_seed(runs, &SeedRun::t_hot_wall), tc = per_seed(runs, &SeedRun::t_crack);
    const auto crack_after_arch = per_seed(runs, [](const SeedRun& r) { return r.t_crack - r.t_arch; });
    const auto crack_near_arch = per_seed(runs, [](const SeedRun& r) { return std::abs(r.y0_crack - r.y0_arch); });
    const auto precursor_lead = per_seed(runs, [](const SeedRun& r) { return r.t_arch - r.t_precursor; });
    // Empirical distribution of the first-arch time over all seeds (those without an arch never count).
    std::vector<double> tt, fr;
    std::copy_if(ta.begin(), ta.end(), std::back_inserter(tt), [](double x) { return std::isfinite(x); });
    std::sort(tt.begin(), tt.end());
    for (std::size_t k = 0; k < tt.size(); ++k) fr.push_back(double(k + 1) / double(ta.size()));
    Table& cd = res.table("arch_time_cdf", "fraction of seeds with an arch by time t");
    cd.add({{"t_arch", "s", tt}, {"fraction", "1", fr}});
    auto quartiles = [&](const std::string& name, const std::vector<double>& v, const std::string& what) {
        res.scalar(name + "_q25", quantile(v, 0.25, NonFinite::censored), "s", what + ", lower quartile over seeds (none = +inf)");
        res.scalar(name + "_median", quantile(v, 0.5, NonFinite::censored), "s", what + ", median over seeds");
        res.scalar(name + "_q75", quantile(v, 0.75, NonFinite::censored), "s", what + ", upper quartile over seeds");
    };
    quartiles("t_arch", ta, "first arch");
    quartiles("t_precursor", tp, "first hot wall disk of the first arch");
    quartiles("t_hot_wall", tw, "first hot disk at a wall (any)");
    quartiles("t_crack", tc, "first crack");
    auto happened = [](const std::vector<double>& v) {
        return 1 - double(std::count_if(v.begin(), v.end(), [](double x) { return std::isnan(x); })) / double(v.size());
    };
    res.scalar("arch_fraction", happened(ta), "1", "fraction of seeds with an arch before t_end");
    res.scalar("crack_fraction", happened(tc), "1", "fraction of seeds with a crack before t_end");
    res.scalar("arch_time_fraction_by_paper", fraction_below(ta, 0.056), "1",
               "fraction of seeds whose first arch formed by the paper's 0.056 s (its percentile in our distribution)");
    res.scalar("precursor_time_fraction_by_paper", fraction_below(tp, 0.048), "1",
               "fraction of seeds whose arch's first hot wall disk appeared by the paper's 0.048 s");
    res.scalar("crack_time_fraction_by_paper", fraction_below(tc, 0.060), "1",
               "fraction of seeds with a crack by the paper's 0.060 s");
    // Section 5 takes P(N_c) at 0.02-0.05 s as "before the first arch (or crack) occurs".
    res.scalar("arch_by_0.05_fraction", fraction_below(ta, 0.05), "1",
               "fraction of seeds whose first arch formed by 0.05 s, the last Fig. 14(a) time");
    res.scalar("arch_height_median", median(per_seed(runs, &SeedRun::y_arch)), "d", "lab height of the first arch above the removed floor, median");
    res.scalar("arch_initial_height_median", median(per_seed(runs, &SeedRun::y0_arch)), "d", "initial (t = 0) height of the first arch's disks, median");
    res.scalar("crack_initial_height_median", median(per_seed(runs, &SeedRun::y0_crack)), "d", "initial height of the disks bounding the first crack, median");
    res.scalar("precursor_lead_median", median(precursor_lead), "s", "first arch minus its first hot wall disk, median (paper: 0.008 s)");
    res.scalar("crack_after_arch_median", median(crack_after_arch), "s", "first crack minus first arch, median over seeds with both (paper: ~0.004 s)");
    res.scalar("crack_arch_height_offset_median", median(crack_near_arch), "d",
               "|initial height of first crack - that of first arch|, median over seeds with both");
    const SeedRun& f0 = runs.front();
    res.scalar("t_arch_run0", f0.t_arch, "s", "first arch, run 0");
    res.scalar("y_arch_run0", f0.y_arch, "d", "its lab height above the removed floor, run 0");
    res.scalar("t_precursor_run0", f0.t_precursor, "s", "its first hot wall disk, run 0");
    res.scalar("t_crack_run0", f0.t_crack, "s", "first crack, run 0");
    res.scalar("y_crack_run0", f0.y_crack, "d", "its lab height, run 0");
}

// The section's other statements (Sec. 5), per seed, then over seeds.
void report_section(Result& res, const std::vector<SeedRun>& runs) {
    auto med = [&](double SeedRun::*f) { return median(per_seed(runs, f)); };
    res.scalar("fluid_layers_median", med(&SeedRun::fluid_layers), "1",
               "top rows at t = 0 in which at least half of the disks lost a lattice neighbour, median");
    double broken = 0;
    for (double x : per_seed(runs, &SeedRun::lattice_broken_below)) broken = std::max(broken, x);
    res.scalar("lattice_broken_below_max", broken, "1", "share of the disks below those rows that lost a lattice neighbour, largest over seeds");
    res.scalar("react_lag_median", med(&SeedRun::react_lag), "s",
               "first frame with half of the initiating disk's neighbours hot, minus its first hot frame, median (paper: 0.004 s)");
    res.scalar("arch_left_4ms_median", med(&SeedRun::arch_left_4ms), "1",
               "share of the first arch's disks still hot 4 ms after it spanned the width, median");
    // Later arches above and below are 0 or 1, and NaN together (no frame 4 ms after the first).
    const auto above = per_seed(runs, &SeedRun::arch_above_later), below = per_seed(runs, &SeedRun::arch_below_later);
    const auto both = per_seed(runs, [](const SeedRun& r) { return r.arch_above_later * r.arch_below_later; });
    auto one = [](double y) { return y == 1.0; };
    res.scalar("arch_above_later_fraction", share_finite(above, one), "1", "seeds with a later arch (after the first + 4 ms) more than arch_separation above the first");
    res.scalar("arch_below_later_fraction", share_finite(below, one), "1", "the same below");
    res.scalar("arch_above_and_below_fraction", share_finite(both, one), "1", "seeds with later arches both above and below");
    res.scalar("plug_wall_load_median", med(&SeedRun::plug_wall_load), "1",
               "wall impulse on the arch's plug within 4 ms of the arch over the plug's weight times that time, median (1: the walls hold the plug)");
    const auto rel = per_seed(runs, [](const SeedRun& r) { return r.plug_wall_load / r.friction_share; });
    res.scalar("plug_wall_load_over_mean_median", median(rel), "1",
               "plug_wall_load over the column's wall share over the whole fall, per seed, median (> 1: the walls hold the plug harder than the column)");
    res.scalar("arch_brake_median", med(&SeedRun::arch_brake), "m/s",
               "largest gain of v_y(plug) - v_y(material below) within arch_window of the arch, median (> 0: the plug falls slower)");
    res.scalar("opening_below_median", med(&SeedRun::opening_below), "d",
               "largest growth of the distance between plug and material below within arch_window of the arch, median");
    res.scalar("opening_max_before_median", med(&SeedRun::opening_max_before), "d",
               "widest wall-to-wall crack before the first arch, median over seeds (the falling column's own gaps)");
    res.scalar("opening_max_after_median", med(&SeedRun::opening_max_after), "d",
               "widest wall-to-wall crack within arch_window after the first arch, median");
    res.scalar("opening_max_all_median", med(&SeedRun::opening_max_all), "d",
               "widest wall-to-wall crack at any frame from t_detect_min on, median over seeds");
    // The distribution of the widest gap, not only crack yes/no (issue 27).
    for (const auto& [name, f] : {std::pair{"opening_max_all", &SeedRun::opening_max_all}, std::pair{"opening_max_after", &SeedRun::opening_max_after}}) {
        std::vector<double> v = per_seed(runs, f);
        std::erase_if(v, [](double x) { return !std::isfinite(x); });
        res.scalar(std::string(name) + "_q25", v.empty() ? NAN : quantile(v, 0.25, NonFinite::censored), "d", "its lower quartile over seeds");
        res.scalar(std::string(name) + "_q75", v.empty() ? NAN : quantile(v, 0.75, NonFinite::censored), "d", "its upper quartile over seeds");
        res.scalar(std::string(name) + "_max", v.empty() ? NAN : *std::max_element(v.begin(), v.end()), "d", "its largest value over seeds");
    }
    // Successive waves (arch_aftermath): the share of steps that rise, pooled over seeds, and the
    // seeds in which a later wave is stronger than the first arch, among the seeds with an arch.
    double steps = 0, up = 0;
    for (const SeedRun& r : runs)
        if (std::isfinite(r.wave_steps)) { steps += r.wave_steps; up += r.wave_steps_up; }
    res.scalar("wave_steps_total", steps, "1", "steps between successive distinct arches, summed over seeds");
    res.scalar("wave_ascend_share", steps > 0 ? up / steps : NAN, "1",
               "share of those steps in which the new wave starts higher than the previous one");
    res.scalar("wave_stronger_fraction", share_finite(per_seed(runs, &SeedRun::wave_stronger), [](double y) { return y == 1.0; }), "1",
               "seeds in which a later wave (arch more than arch_separation from the first, after its first 4 ms) had more hot disks than the first arch, among seeds with an arch");
    res.scalar("crack_below_arch_median", med(&SeedRun::crack_below_arch), "d",
               "initial height of the first arch minus that of the first crack, median (> 0: crack below)");
    res.scalar("crack_at_initiator_median", med(&SeedRun::crack_at_initiator), "d",
               "crack course at the initiating disk's wall minus the disk's height, at the crack's first frame, median");
    // Disks at the walls slow down (Sec. 5): v_y(wall) - v_y(inside) in the plug at the arch,
    // against the same at the window's start; the mean difference over seeds and its z-score.
    const MeanSem ws = mean_sem(per_seed(runs, &SeedRun::wall_slowdown_arch));
    const MeanSem dd = mean_sem(per_seed(runs, [](const SeedRun& r) { return r.wall_slowdown_arch - r.wall_slowdown_before; }));
    res.scalar("wall_slowdown_arch_mean", ws.mean, "m/s", "v_y(wall disks) - v_y(inner disks) of the plug at the arch, mean over seeds (> 0: wall disks slower)");
    res.scalar("wall_slowdown_gain_mean", dd.mean, "m/s", "the same minus its value arch_window before the arch, mean over seeds");
    res.scalar("wall_slowdown_gain_z", dd.sem > 0 ? dd.mean / dd.sem : NAN, "1", "that mean over its standard error (seed scatter)");
    res.scalar("wall_load_peak_median", med(&SeedRun::wall_load_peak), "1",
               "largest 5-frame mean of the walls' share of the weight, median over seeds");
}

// Momentum balance and costs.
void report_costs(Result& res, const std::vector<SeedRun>& runs) {
    const auto resid = per_seed(runs, [](const SeedRun& r) { return std::abs(r.momentum_residual); });
    res.scalar("momentum_balance_residual_max", *std::max_element(resid.begin(), resid.end()), "1",
               "max over seeds of |dP_y - (-M g t + J_wall)| / (M g t) over the fall");
    res.scalar("wall_friction_share", median(per_seed(runs, &SeedRun::friction_share)), "1", "side-wall impulse over M g t_end, median (0: free fall)");
    res.scalar("seconds_per_seed_median", median(per_seed(runs, &SeedRun::wall_seconds)), "s", "wall time of one seed (relaxation + fall)");
    res.scalar("collisions_per_seed_median", median(per_seed(runs, &SeedRun::collisions)), "1", "pair collisions during the fall, median");
    res.scalar("tc_elastic_share_median", median(per_seed(runs, &SeedRun::elastic_share)), "1", "share of the fall's pair collisions made elastic by TC");
}

// Sec. 5 and Figs. 13-14 as a protocol (harness/protocol.hpp): one sweep point per seed run.
struct PipeArching {
    static constexpr const char* name = "pipe-arching";
    using Spec = PipeArchingSpec;
    using Outcome = SeedRun;
    using Shared = Pipe;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Pipe prepare(const Spec& spec, const RunContext&) { return Pipe(spec); }
    static std::vector<long> points(const Spec&, const Pipe& s) {
        std::vector<long> order(static_cast<std::size_t>(s.n_seeds));
        std::iota(order.begin(), order.end(), 0L);
        return order;
    }
    // Seed run k draws RngStream(seed, k) whatever n_seeds, rank or shard: any split of the seeds
    // (ranks, --points shards) reproduces the single run.
    static SeedRun compute(const Spec&, const Pipe& s, long k, const PointContext& ctx) { return run_seed(s, ctx.seed, k, k == 0); }
    static Result report(const Spec&, const Pipe& s, const Swept<SeedRun>& swept, const RunContext&) {
        const std::vector<SeedRun>& runs = swept.outcomes;
        Result res;
        res.scalar("resumed_points", double(swept.resumed), "1", "seeds loaded from a checkpoint");
        res.scalar("n_seeds", double(s.n_seeds), "1", "independent runs");
        res.scalar("layers", std::ceil(double(s.n_particles) / (std::floor((s.L - s.d) / s.a + 1e-9) + 0.5)), "1",
                   "rows of the initial lattice");
        for (const FigureTable& f : runs.front().figure) {
            Table& t = res.table(f.name, f.description);
            for (std::size_t c = 0; c < f.columns.size(); ++c) t.add(f.columns[c], f.units[c]).values = f.values[c];
        }
        report_relaxation(res, runs);
        report_fig14_times(res, s, runs);
        report_fig14_fits(res, s, runs);
        report_seed_table(res, runs);
        report_arch_times(res, runs);
        report_section(res, runs);
        report_costs(res, runs);
        return res;
    }
};

} // namespace

Experiment pipe_arching() { return protocol_experiment<PipeArching>(); }

} // namespace granrepro::experiments
