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
#include <map>
#include <numeric>
#include <string>

#include "analysis/crack_detector.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "harness/experiment.hpp"
#include "harness/progress.hpp"
#include "harness/distributed_sweep.hpp"
#include "observables/collision_counter.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/column_bands.hpp"
#include "observables/rate_histogram.hpp"

namespace granrepro::experiments {

namespace {

constexpr int kLeft = 0, kRight = 1, kFloor = 2; // wall indices

long frame_of(double t, double frame_dt) { return std::lround(t / frame_dt); }

void validate(const ParameterSet& p) {
    const double fdt = p.real("frame_dt"), t_end = p.real("t_end");
    // N_c frames of every run (each holds per-particle counts); t_end = 1e308 would never end.
    p.limit_work({"t_end", "t_relax", "frame_dt"}, (p.real("t_relax") + t_end) / fdt, 1e7, "frames");
    auto on_grid = [&](const char* name, double window) {
        for (double t : p.reals(name)) {
            if (t > t_end) p.reject(name, "every time must be <= t_end");
            if (t < window)
                p.reject(std::vector<std::string>{name, window == fdt ? "frame_dt" : "dist_dt"},
                         std::string(name) + ": every time must be >= its N_c window");
            if (std::abs(t / fdt - double(frame_of(t, fdt))) > 1e-6) p.reject(name, "times must be multiples of frame_dt");
        }
    };
    on_grid("snapshot_times", fdt);
    on_grid("dist_times_before", p.real("dist_dt"));
    on_grid("dist_times_after", p.real("dist_dt"));
    if (p.real("dist_dt") < fdt) p.reject("dist_dt", "must be >= frame_dt");
    if (p.real("width") < 2 * p.real("lattice")) p.reject("width", "must hold at least two lattice sites");
    if (p.integer("crack_min_particles") + p.integer("crack_min_above") >= p.integer("n_particles"))
        p.reject("crack_min_above", "crack_min_particles + crack_min_above must be below n_particles");
}

struct Geometry {
    double d, L, y_floor, ly;
};

Geometry geometry(const ParameterSet& p) {
    const double d = p.real("d");
    const double L = p.real("width") * d;
    const double s = p.real("lattice") * d;
    // Rows alternate floor(L/s) and one fewer site; the column height sets where the floor goes.
    const double per_two_rows = 2.0 * std::floor((L - d) / s + 1e-9) + 1.0;
    const double rows = std::ceil(2.0 * double(p.integer("n_particles")) / per_two_rows);
    const double h = rows * s * std::sqrt(3.0) / 2.0 + d;
    // The floor sits high enough in the cell grid that the falling column never reaches the
    // bottom edge cells, which extend to -infinity and would collect all disks in one row.
    const double fall = 0.5 * p.real("g") * p.real("t_end") * p.real("t_end") + 10 * d;
    return {d, L, fall, fall + 1.3 * h + 10 * d};
}

// One run (one seed). Times in s, heights in d above the removed floor unless named otherwise.
struct SeedRun {
    double vbar0 = NAN, vbar_relax_late = NAN;
    double fluid_layers = NAN, lattice_broken_below = NAN; // state at t = 0 (Sec. 5: lattice intact but the top)
    double t_hot_wall = NAN;                        // first hot disk at a wall (any)
    double t_arch = NAN, y_arch = NAN, y0_arch = NAN; // first arch: time, lab and initial height
    double arch_size = NAN, arch_pL = NAN, arch_pR = NAN;
    double t_precursor = NAN, y_precursor = NAN, react_lag = NAN;
    double arch_left_4ms = NAN, arch_above_later = NAN, arch_below_later = NAN;
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
    nlohmann::json per_time;  // every run: Eq. (21)/(22) fits at each Fig. 14 time
    nlohmann::json figure;    // run 0 only: snapshots, histograms, timeline, relaxation

    static constexpr const char* kKeys[] = {
        "vbar0", "vbar_relax_late", "fluid_layers", "lattice_broken_below", "t_hot_wall", "t_arch", "y_arch",
        "y0_arch", "arch_size", "arch_pL", "arch_pR", "t_precursor", "y_precursor", "react_lag", "arch_left_4ms",
        "arch_above_later", "arch_below_later", "plug_wall_load", "arch_brake", "opening_below",
        "wall_slowdown_arch", "wall_slowdown_before", "t_crack", "y_crack", "y0_crack", "crack_opening",
        "crack_below_arch", "crack_at_initiator", "opening_max_before", "opening_max_after", "opening_max_all", "A", "A_err", "times_before", "times_after",
        "A_chi2", "B", "B_err", "B_chi2", "dev_exp_early", "dev_pow_early", "dev_exp_late", "dev_pow_late",
        "mean_rate_early", "momentum_residual", "friction_share", "wall_load_peak", "wall_seconds", "collisions",
        "elastic_share"};
    double* fields[std::size(kKeys)] = {
        &vbar0, &vbar_relax_late, &fluid_layers, &lattice_broken_below, &t_hot_wall, &t_arch, &y_arch,
        &y0_arch, &arch_size, &arch_pL, &arch_pR, &t_precursor, &y_precursor, &react_lag, &arch_left_4ms,
        &arch_above_later, &arch_below_later, &plug_wall_load, &arch_brake, &opening_below,
        &wall_slowdown_arch, &wall_slowdown_before, &t_crack, &y_crack, &y0_crack, &crack_opening,
        &crack_below_arch, &crack_at_initiator, &opening_max_before, &opening_max_after, &opening_max_all, &A, &A_err, &times_before, &times_after,
        &A_chi2, &B, &B_err, &B_chi2, &dev_exp_early, &dev_pow_early, &dev_exp_late, &dev_pow_late,
        &mean_rate_early, &momentum_residual, &friction_share, &wall_load_peak, &wall_seconds, &collisions,
        &elastic_share};

    SeedRun() = default;
    SeedRun(const SeedRun& o) { *this = o; }
    SeedRun& operator=(const SeedRun& o) {
        for (std::size_t k = 0; k < std::size(kKeys); ++k) *fields[k] = *o.fields[k];
        per_time = o.per_time;
        figure = o.figure;
        return *this;
    }
    nlohmann::json to_json() const {
        nlohmann::json j;
        for (std::size_t k = 0; k < std::size(kKeys); ++k)
            j[kKeys[k]] = std::isfinite(*fields[k]) ? nlohmann::json(*fields[k]) : nlohmann::json(nullptr);
        j["per_time"] = per_time;
        j["figure"] = figure;
        return j;
    }
    static SeedRun from_json(const nlohmann::json& j) {
        SeedRun r;
        for (std::size_t k = 0; k < std::size(kKeys); ++k)
            *r.fields[k] = j.at(kKeys[k]).is_null() ? NAN : j.at(kKeys[k]).get<double>();
        r.per_time = j.at("per_time");
        r.figure = j.at("figure");
        return r;
    }
};

struct Fit {
    CollisionRateFit fit;
    bool ok = false;
};
Fit try_fit(const RateHistogram& h, CollisionRateFit::Model m, double lo, double hi) {
    Fit f;
    try {
        f.fit = CollisionRateFit::fit(h, m, lo, hi);
        f.ok = f.fit.converged;
    } catch (const std::invalid_argument&) {
    }
    return f;
}
nlohmann::json jnum(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

// Disjoint-set forest for the hot bands.
struct Dsu {
    std::vector<int> up;
    explicit Dsu(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
    int find(int a) { while (up[a] != a) a = up[a] = up[up[a]]; return a; }
    void join(int a, int b) { up[find(a)] = find(b); }
};

struct WallHit {
    double t, y;
    int wall;
};

struct ArchFound {
    bool found = false;
    double y = NAN, y0 = NAN, size = 0, pL = NAN, pR = NAN;
    std::vector<int> members;
};

struct HotWallDisk {
    int i;
    double y0; // initial height [d]
};

// The lattice at t = 0 (Sec. 5: "still arranged on a triangular lattice, except for a few layers
// at the top which are fluidized"). A disk keeps its place when it is still within 1.2 s of every
// lattice neighbour it had at t = -t_r (s = lattice constant). Rows are counted from the top;
// the fluidized layers are the top rows in which at least half of the disks lost a neighbour.
struct LatticeState {
    double fluid_layers = 0, broken_below = 0;
};
LatticeState lattice_state(const std::vector<Vec2>& lat, const std::vector<Vec2>& now, double s) {
    const std::size_t n = lat.size();
    std::vector<int> kept(n, 1);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (lat[j].y - lat[i].y > 1.1 * s) break; // rows are built bottom-up: y is sorted
            if (norm(lat[j] - lat[i]) > 1.1 * s) continue;
            if (norm(now[j] - now[i]) > 1.2 * s) kept[i] = kept[j] = 0;
        }
    // Rows: equal initial heights.
    std::vector<std::pair<double, std::vector<std::size_t>>> rows;
    for (std::size_t i = 0; i < n; ++i) {
        if (rows.empty() || std::abs(lat[i].y - rows.back().first) > 0.1 * s) rows.push_back({lat[i].y, {}});
        rows.back().second.push_back(i);
    }
    LatticeState st;
    std::size_t r = rows.size();
    while (r > 0) {
        const auto& row = rows[r - 1].second;
        const double lost = double(std::count_if(row.begin(), row.end(), [&](std::size_t i) { return !kept[i]; }));
        if (lost < 0.5 * double(row.size())) break;
        --r;
    }
    st.fluid_layers = double(rows.size() - r);
    double broken = 0, total = 0;
    for (std::size_t k = 0; k < r; ++k)
        for (std::size_t i : rows[k].second) {
            total += 1;
            broken += kept[i] ? 0 : 1;
        }
    st.broken_below = total > 0 ? broken / total : NAN;
    return st;
}

SeedRun run_seed(const ParameterSet& p, const Geometry& G, std::uint64_t seed, long index, bool figure) {
    const auto wall_start = std::chrono::steady_clock::now();
    const double d = G.d, L = G.L;
    const std::size_t n = std::size_t(p.integer("n_particles"));
    const double m = p.real("mass"), g = p.real("g");
    const double t_r = p.real("t_relax"), t_end = p.real("t_end");
    const double fdt = p.real("frame_dt"), ddt = p.real("dist_dt");
    const double hot = p.real("hot_rate");

    const std::vector<Vec2> lat = triangular_lattice_positions(n, 0.5 * d, L - 0.5 * d, G.y_floor + 0.5 * d,
                                                               p.real("lattice") * d);
    RngStream rng(seed, std::uint64_t(index));
    std::vector<Vec2> vel = uniform_velocities(n, p.real("v0"), rng);
    EdConfig cfg;
    cfg.lx = L;
    cfg.ly = G.ly;
    cfg.periodic_x = cfg.periodic_y = false;
    cfg.gravity = {0.0, -g};
    cfg.law = RoughDiskCollision{1.0, 0.0, -1.0, p.real("q")};
    cfg.walls = {EdWall{0, 0.0, +1}, EdWall{0, L, -1}, EdWall{1, G.y_floor, +1}};
    cfg.t_c = 0.0;
    cfg.tc_both = p.text("tc_rule") == "both";
    cfg.tc_keep_friction = p.text("tc_friction") == "keep";
    EdEngine eng(cfg, lat, vel, std::vector<double>(n, 0.5 * d), std::vector<double>(n, m), {}, -t_r);

    auto vbar = [&] {
        double s = 0;
        for (const Vec2& v : eng.velocities()) s += norm2(v);
        return std::sqrt(s / double(n));
    };
    SeedRun out;
    // Relaxation (Sec. 5: r = r_w = 1, mu = mu_w = 0).
    std::vector<double> rt, rv;
    const int relax_samples = 60;
    for (int k = 0; k <= relax_samples; ++k) {
        eng.run_until(-t_r + t_r * k / relax_samples);
        rt.push_back(eng.time());
        rv.push_back(vbar());
    }
    out.vbar0 = rv.back();
    // Mean over the last third: how steady the relaxed state is.
    out.vbar_relax_late = std::accumulate(rv.end() - relax_samples / 3, rv.end(), 0.0) / double(relax_samples / 3);

    // t = 0: floor removed, dissipation and friction on.
    const double eps = p.real("epsilon"), mu = p.real("mu"), b0 = p.real("beta0");
    eng.set_law(RoughDiskCollision{eps, mu, b0, p.real("q")});
    eng.set_wall_law(kLeft, p.real("epsilon_w"), p.real("mu_w"), p.real("beta0_w"));
    eng.set_wall_law(kRight, p.real("epsilon_w"), p.real("mu_w"), p.real("beta0_w"));
    eng.set_tc(p.real("t_c"));
    eng.set_wall_enabled(kFloor, false);
    const std::vector<Vec2> pos0 = eng.positions();
    {
        const LatticeState ls = lattice_state(lat, pos0, p.real("lattice") * d);
        out.fluid_layers = ls.fluid_layers;
        out.lattice_broken_below = ls.broken_below;
    }
    std::vector<double> y0(n);
    for (std::size_t i = 0; i < n; ++i) y0[i] = (pos0[i].y - G.y_floor) / d;
    const double py0 = eng.total_momentum().y;
    const std::uint64_t coll0 = eng.total_collisions(), el0 = eng.elastic_collisions();

    CollisionCounter counter(n, true);
    std::vector<WallHit> hits;
    std::vector<double> wall_jy(n, 0.0); // side-wall impulse per disk in the current frame [kg m/s]
    double jy = 0.0;                     // side-wall impulse on the column since t = 0 [kg m/s]
    auto obs = [&](const CollisionRecord& c) {
        counter.add(c);
        if (c.j < 0) {
            jy += c.dP.y;
            wall_jy[std::size_t(c.i)] += c.dP.y;
            hits.push_back({c.t, c.ri.y, -1 - c.j});
        }
    };
    const double reach = p.real("wall_reach") * d;
    ColumnBands bands(y0, 1.0, reach, L); // bands of 1 d of initial height (y0 in d)

    // Frames.
    const long n_frames = frame_of(t_end, fdt);
    const long detect_from = long(std::ceil(p.real("t_detect_min") / fdt - 1e-9));
    std::vector<long> snap_frames, before_frames, after_frames;
    for (double t : p.reals("snapshot_times")) snap_frames.push_back(frame_of(t, fdt));
    for (double t : p.reals("dist_times_before")) before_frames.push_back(frame_of(t, fdt));
    for (double t : p.reals("dist_times_after")) after_frames.push_back(frame_of(t, fdt));
    auto contains = [](const std::vector<long>& v, long f) { return std::find(v.begin(), v.end(), f) != v.end(); };
    std::vector<std::vector<double>> rates_at;        // per Fig. 14 time
    std::vector<double> rates_at_t;

    const double link2 = std::pow(p.real("link") * d, 2);
    const double band = p.real("pressure_band") * d, pfac = p.real("arch_pressure_factor");
    CrackSearch cs;
    cs.diameter = d;
    cs.width = L;
    cs.min_below = std::size_t(p.integer("crack_min_particles"));
    cs.min_above = std::size_t(p.integer("crack_min_above"));
    cs.max_opening = 3 * d;
    const double crack_open = p.real("crack_opening") * d;

    // Per frame (index f, frame 0 = t = 0 is empty): hot disks, hot wall disks, the arch found,
    // the crack's opening and course.
    std::vector<std::vector<int>> hot_at(std::size_t(n_frames) + 1);
    std::vector<std::vector<HotWallDisk>> hot_wall_at(std::size_t(n_frames) + 1);
    std::vector<ArchFound> arch_at(std::size_t(n_frames) + 1);
    std::vector<Crack> crack_at(std::size_t(n_frames) + 1);
    std::vector<double> tl_t, tl_hot, tl_hot_wall, tl_mean, tl_vy, tl_wall_rate, tl_wall_load;
    std::vector<std::vector<Vec2>> frame_pos(std::size_t(n_frames) + 1);
    std::vector<std::vector<double>> snap_rate;
    std::vector<long> snap_f;
    const double M = double(n) * m;

    for (long f = 1; f <= n_frames; ++f) {
        const double t = double(f) * fdt;
        std::fill(wall_jy.begin(), wall_jy.end(), 0.0);
        eng.run_until(t, obs);
        report_engine_time(t, t_end);
        const std::vector<double> rate = counter.rates(t, fdt);
        const std::vector<Vec2> r = eng.positions();
        const std::vector<Vec2> v = eng.velocities();
        bands.add_frame(t, r, v, wall_jy);
        // Side-wall collisions in this frame.
        std::erase_if(hits, [&](const WallHit& h) { return h.t <= t - fdt; });

        // Hot disks, their bands, and the hot disks at the walls.
        std::vector<int>& hotv = hot_at[std::size_t(f)];
        for (std::size_t i = 0; i < n; ++i)
            if (rate[i] >= hot) {
                hotv.push_back(int(i));
                if (r[i].x <= reach || r[i].x >= L - reach) hot_wall_at[std::size_t(f)].push_back({int(i), y0[i]});
            }
        double ymin = INFINITY, ymax = -INFINITY;
        for (const Vec2& x : r) { ymin = std::min(ymin, x.y); ymax = std::max(ymax, x.y); }
        const double col_h = ymax - ymin + d;
        ArchFound& arch = arch_at[std::size_t(f)];
        if (f >= detect_from && !hotv.empty()) {
            Dsu dsu(hotv.size());
            for (std::size_t a = 0; a < hotv.size(); ++a)
                for (std::size_t b = a + 1; b < hotv.size(); ++b)
                    if (norm2(r[hotv[a]] - r[hotv[b]]) <= link2) dsu.join(int(a), int(b));
            std::vector<std::vector<int>> groups(hotv.size());
            for (std::size_t a = 0; a < hotv.size(); ++a) groups[dsu.find(int(a))].push_back(hotv[a]);
            // Column mean of wall collisions per unit time and height, per wall.
            const double mean_p = double(hits.size()) / 2.0 / (fdt * col_h);
            for (const auto& grp : groups) {
                if (grp.empty()) continue;
                double yl = 0, yr = 0;
                int nl = 0, nr = 0;
                for (int i : grp) {
                    if (r[i].x <= reach) { yl += r[i].y; ++nl; }
                    if (r[i].x >= L - reach) { yr += r[i].y; ++nr; }
                }
                if (nl == 0 || nr == 0) continue;
                yl /= nl;
                yr /= nr;
                auto foot = [&](int wall, double y) {
                    const auto k = std::count_if(hits.begin(), hits.end(), [&](const WallHit& h) {
                        return h.wall == wall && std::abs(h.y - y) <= band;
                    });
                    return double(k) / (fdt * 2 * band) / mean_p;
                };
                const double pl = mean_p > 0 ? foot(kLeft, yl) : 0, pr = mean_p > 0 ? foot(kRight, yr) : 0;
                if (std::min(pl, pr) < pfac) continue;
                if (double(grp.size()) > arch.size) {
                    double ym = 0, ys = 0;
                    for (int i : grp) { ym += r[i].y; ys += y0[std::size_t(i)]; }
                    arch = {true, (ym / double(grp.size()) - G.y_floor) / d, ys / double(grp.size()),
                            double(grp.size()), pl, pr, grp};
                }
            }
        }
        if (f >= detect_from && !hot_wall_at[std::size_t(f)].empty() && std::isnan(out.t_hot_wall)) out.t_hot_wall = t;
        if (f >= detect_from) crack_at[std::size_t(f)] = find_crack(r, cs);
        frame_pos[std::size_t(f)] = r;

        // P(N_c) over dist_dt.
        const bool fb = contains(before_frames, f), fa = contains(after_frames, f);
        if (fb || fa) {
            const std::vector<double> rd = counter.rates(t, ddt);
            rates_at.push_back(rd);
            rates_at_t.push_back(t);
        }
        counter.discard_before(t - ddt - fdt);

        double jf = 0;
        for (double x : wall_jy) jf += x;
        tl_wall_load.push_back(jf / (M * g * fdt));
        if (figure) {
            double vy = 0;
            for (const Vec2& x : v) vy += x.y;
            tl_t.push_back(t);
            tl_hot.push_back(double(hotv.size()));
            tl_hot_wall.push_back(double(hot_wall_at[std::size_t(f)].size()));
            tl_mean.push_back(std::accumulate(rate.begin(), rate.end(), 0.0) / double(n));
            tl_vy.push_back(vy / double(n));
            tl_wall_rate.push_back(double(hits.size()) / fdt / double(n));
            if (contains(snap_frames, f)) {
                snap_rate.push_back(rate);
                snap_f.push_back(f);
            }
        }
    }

    // ---- after the fall: the first arch, what led to it and what followed --------------------
    auto frame_t = [&](long f) { return double(f) * fdt; };
    long fa = -1;
    for (long f = detect_from; f <= n_frames && fa < 0; ++f)
        if (arch_at[std::size_t(f)].found) fa = f;
    long f_prec = -1;
    int i_prec = -1;
    if (fa >= 0) {
        const ArchFound& a = arch_at[std::size_t(fa)];
        out.t_arch = frame_t(fa);
        out.y_arch = a.y;
        out.y0_arch = a.y0;
        out.arch_size = a.size;
        out.arch_pL = a.pL;
        out.arch_pR = a.pR;
        // Its initiating disk: the earliest hot wall disk within precursor_window before the arch
        // that started within precursor_band of the arch's initial height (the black bar, Fig. 13).
        const long back = std::max(detect_from, fa - long(std::lround(p.real("precursor_window") / fdt)));
        for (long k = back; k <= fa && i_prec < 0; ++k)
            for (const HotWallDisk& h : hot_wall_at[std::size_t(k)])
                if (std::abs(h.y0 - a.y0) <= p.real("precursor_band")) {
                    f_prec = k;
                    i_prec = h.i;
                    out.t_precursor = frame_t(k);
                    out.y_precursor = h.y0;
                    break;
                }
        // Its neighbours react (Sec. 5: "already 0.004 s later"): the first frame from the
        // precursor's on in which at least half of the disks that were its neighbours (within
        // `link` at t = 0) are hot.
        if (i_prec >= 0) {
            std::vector<int> nb;
            for (std::size_t j = 0; j < n; ++j)
                if (int(j) != i_prec && norm2(pos0[j] - pos0[std::size_t(i_prec)]) <= link2) nb.push_back(int(j));
            for (long k = f_prec; k <= n_frames && !nb.empty(); ++k) {
                const auto& hv = hot_at[std::size_t(k)];
                const auto k_hot = std::count_if(nb.begin(), nb.end(), [&](int j) { return std::binary_search(hv.begin(), hv.end(), j); });
                if (2 * k_hot >= long(nb.size())) {
                    out.react_lag = frame_t(k) - out.t_precursor;
                    break;
                }
            }
        }
        // Decay (Sec. 5: "0.004 s later this region ... has almost disappeared"): the share of the
        // arch's disks still hot 4 ms after it spanned the width.
        const long f4 = fa + long(std::lround(0.004 / fdt));
        if (f4 <= n_frames) {
            const auto& hv = hot_at[std::size_t(f4)];
            const double still = double(std::count_if(a.members.begin(), a.members.end(),
                                                      [&](int j) { return std::binary_search(hv.begin(), hv.end(), j); }));
            out.arch_left_4ms = still / double(a.members.size());
            // Later arches (Sec. 5: "new arches above and below the original one appeared").
            const double sep = p.real("arch_separation");
            out.arch_above_later = out.arch_below_later = 0;
            for (long k = f4; k <= n_frames; ++k) {
                const ArchFound& b = arch_at[std::size_t(k)];
                if (!b.found) continue;
                if (b.y0 > a.y0 + sep) out.arch_above_later = 1;
                if (b.y0 < a.y0 - sep) out.arch_below_later = 1;
            }
        }
        // The plug and the material below it, as Lagrangian bands (initial heights): how much of
        // the plug's weight the walls carry around the arch, how much slower the plug falls than
        // the material below, and how far the two move apart (an opening crack), all over
        // [t_arch - arch_window, t_arch + arch_window] and relative to its start.
        const double hp = p.real("plug_half_height"), depth = p.real("below_depth");
        const long w = long(std::lround(p.real("arch_window") / fdt));
        const long f0 = std::max(1L, fa - w), f1 = std::min(n_frames, fa + w);
        auto plug = [&](long f) { return bands.group(std::size_t(f - 1), a.y0 - hp, a.y0 + hp); };
        auto below = [&](long f) { return bands.group(std::size_t(f - 1), a.y0 - hp - depth, a.y0 - hp); };
        const double dv0 = plug(f0).vy - below(f0).vy, dy0 = plug(f0).y - below(f0).y;
        double jp = 0, jn = 0, brake = -INFINITY, open = -INFINITY;
        for (long f = f0; f <= f1; ++f) {
            const auto P = plug(f), B = below(f);
            if (std::abs(f - fa) <= long(std::lround(0.004 / fdt))) { jp += P.jy; jn += 1; }
            brake = std::max(brake, P.vy - B.vy - dv0);
            open = std::max(open, (P.y - B.y - dy0) / d);
        }
        const auto P = plug(fa);
        out.plug_wall_load = jp / (P.n * m * g * jn * fdt);
        out.arch_brake = brake;
        out.opening_below = open;
        // Disks at the walls slow down (Sec. 5): in the plug, vy at the walls minus vy inside
        // (> 0: the wall disks fall slower), at the arch and at the window's start.
        out.wall_slowdown_arch = P.vy_wall - P.vy_inner;
        out.wall_slowdown_before = plug(f0).vy_wall - plug(f0).vy_inner;
    }
    // Cracks: the first frame with an opening >= crack_opening, and how it relates to the arch.
    double omax_before = -INFINITY, omax_after = -INFINITY, omax_all = -INFINITY;
    for (long f = detect_from; f <= n_frames; ++f) {
        const Crack& c = crack_at[std::size_t(f)];
        const double o = c.opening / d;
        omax_all = std::max(omax_all, o);
        if (fa < 0 || f < fa) omax_before = std::max(omax_before, o);
        else if (f <= fa + long(std::lround(p.real("arch_window") / fdt))) omax_after = std::max(omax_after, o);
        if (c.opening >= crack_open && std::isnan(out.t_crack)) {
            out.t_crack = frame_t(f);
            out.crack_opening = o;
            out.y_crack = (c.y_mean - G.y_floor) / d;
            if (c.narrow_i >= 0) out.y0_crack = 0.5 * (y0[std::size_t(c.narrow_i)] + y0[std::size_t(c.narrow_j)]);
            if (fa >= 0) out.crack_below_arch = out.y0_arch - out.y0_crack;
            if (i_prec >= 0) {
                // The course at the initiating disk's wall against the disk's height then.
                const Vec2 rp = frame_pos[std::size_t(f)][std::size_t(i_prec)];
                const double yc = rp.x < 0.5 * L ? c.y_left : c.y_right;
                out.crack_at_initiator = (yc - rp.y) / d;
            }
        }
    }
    out.opening_max_before = std::isfinite(omax_before) ? omax_before : NAN;
    out.opening_max_after = std::isfinite(omax_after) ? omax_after : NAN;
    out.opening_max_all = std::isfinite(omax_all) ? omax_all : NAN;

    // Fits of Eqs. (21), (22) to P(N_c) pooled over the Fig. 14 times that lie, in this run,
    // before the first arch (panel a: "before the first arch (or crack) occurs") or after it
    // (panel b: "when cracks and arches exist"); a run without an arch has no panel (b).
    const double rmin = 1.0 / ddt; // one collision per window
    auto hist_lin = [&](const std::vector<double>& rs) { return RateHistogram::per_count(rs, ddt, 200); };
    auto hist_log = [&](const std::vector<double>& rs) {
        return RateHistogram::make(rs, ddt, RateHistogram::Binning::Log, 30, 0.5 * rmin, 1.0e6);
    };
    const double hi_lin = (200 + 0.5) / ddt;
    std::vector<double> rates_before, rates_after;
    out.times_before = out.times_after = 0;
    for (std::size_t k = 0; k < rates_at.size(); ++k) {
        const double t = rates_at_t[k];
        const bool arched = std::isfinite(out.t_arch) && t >= out.t_arch - 1e-12;
        if (k < before_frames.size() && !arched) {
            rates_before.insert(rates_before.end(), rates_at[k].begin(), rates_at[k].end());
            out.times_before += 1;
        }
        if (k >= before_frames.size() && arched) {
            rates_after.insert(rates_after.end(), rates_at[k].begin(), rates_at[k].end());
            out.times_after += 1;
        }
    }
    if (!rates_before.empty()) {
        const RateHistogram h = hist_lin(rates_before);
        const Fit fe = try_fit(h, CollisionRateFit::Model::Exponential, 0.5 * rmin, hi_lin);
        const Fit fp = try_fit(h, CollisionRateFit::Model::PowerLaw, 0.5 * rmin, hi_lin);
        if (fe.ok) { out.A = fe.fit.value; out.A_err = fe.fit.error; out.A_chi2 = fe.fit.chi2_reduced; out.dev_exp_early = fe.fit.deviance; }
        if (fp.ok) out.dev_pow_early = fp.fit.deviance;
        out.mean_rate_early = std::accumulate(rates_before.begin(), rates_before.end(), 0.0) / double(rates_before.size());
    }
    if (!rates_after.empty()) {
        const RateHistogram h = hist_log(rates_after);
        const Fit fe = try_fit(h, CollisionRateFit::Model::Exponential, 0.5 * rmin, 1.0e6);
        const Fit fp = try_fit(h, CollisionRateFit::Model::PowerLaw, 0.5 * rmin, 1.0e6);
        if (fp.ok) { out.B = fp.fit.value; out.B_err = fp.fit.error; out.B_chi2 = fp.fit.chi2_reduced; out.dev_pow_late = fp.fit.deviance; }
        if (fe.ok) out.dev_exp_late = fe.fit.deviance;
    }
    // The same fits at each time separately (Fig. 14 draws four times per panel).
    out.per_time = nlohmann::json::array();
    std::vector<RateHistogram> hs_at;
    for (std::size_t k = 0; k < rates_at.size(); ++k) {
        const bool early = k < before_frames.size();
        const RateHistogram h = early ? hist_lin(rates_at[k]) : hist_log(rates_at[k]);
        const Fit f = try_fit(h, early ? CollisionRateFit::Model::Exponential : CollisionRateFit::Model::PowerLaw,
                              0.5 * rmin, early ? hi_lin : 1.0e6);
        out.per_time.push_back({{"t", rates_at_t[k]}, {"value", f.ok ? jnum(f.fit.value) : nullptr},
                                {"error", f.ok ? jnum(f.fit.error) : nullptr}});
        hs_at.push_back(h);
    }

    // Momentum balance over the fall; the walls' share of the weight.
    const double dpy = eng.total_momentum().y - py0;
    out.momentum_residual = (dpy - (-M * g * t_end + jy)) / (M * g * t_end);
    out.friction_share = jy / (M * g * t_end);
    {
        const std::size_t k = 5; // running mean over 5 frames
        double best = -INFINITY;
        for (std::size_t a = 0; a + k <= tl_wall_load.size(); ++a)
            best = std::max(best, std::accumulate(tl_wall_load.begin() + long(a), tl_wall_load.begin() + long(a + k), 0.0) / double(k));
        out.wall_load_peak = best;
    }
    out.collisions = double(eng.total_collisions() - coll0);
    out.elastic_share = double(eng.elastic_collisions() - el0) / std::max(1.0, out.collisions);

    if (figure) {
        nlohmann::json& F = out.figure;
        F["relax_t"] = rt;
        F["relax_vbar"] = rv;
        // Snapshots with the marks of Fig. 13: the initiating disk, the frame's arch, the crack.
        nlohmann::json snaps = nlohmann::json::array();
        for (std::size_t s = 0; s < snap_f.size(); ++s) {
            const long f = snap_f[s];
            const ArchFound& a = arch_at[std::size_t(f)];
            const Crack& c = crack_at[std::size_t(f)];
            std::vector<double> x, y, nc, in_arch, side;
            for (std::size_t i = 0; i < n; ++i) {
                x.push_back(frame_pos[std::size_t(f)][i].x / d);
                y.push_back((frame_pos[std::size_t(f)][i].y - G.y_floor) / d);
                nc.push_back(snap_rate[s][i]);
                in_arch.push_back(std::find(a.members.begin(), a.members.end(), int(i)) != a.members.end() ? 1 : 0);
                side.push_back(c.side.empty() ? 0 : c.side[i]);
            }
            std::vector<double> cx, cy;
            for (std::size_t k = 0; k < c.course_x.size(); ++k) {
                cx.push_back(c.course_x[k] / d);
                cy.push_back((c.course_y[k] - G.y_floor) / d);
            }
            nlohmann::json js = {{"t", frame_t(f)}, {"x", x}, {"y", y}, {"Nc", nc}, {"arch", in_arch}, {"side", side},
                                 {"arch_y", a.found ? jnum(a.y) : nullptr}, {"course_x", cx}, {"course_y", cy},
                                 {"opening", c.course_x.empty() ? nullptr : jnum(c.opening / d)},
                                 {"prec_x", i_prec >= 0 ? jnum(frame_pos[std::size_t(f)][std::size_t(i_prec)].x / d) : nullptr},
                                 {"prec_y", i_prec >= 0 ? jnum((frame_pos[std::size_t(f)][std::size_t(i_prec)].y - G.y_floor) / d) : nullptr}};
            snaps.push_back(js);
        }
        F["snaps"] = snaps;
        std::vector<nlohmann::json> arch_y, opening;
        for (long f = 1; f <= n_frames; ++f) {
            arch_y.push_back(arch_at[std::size_t(f)].found ? jnum(arch_at[std::size_t(f)].y) : nullptr);
            opening.push_back(crack_at[std::size_t(f)].course_x.empty() ? nullptr : jnum(crack_at[std::size_t(f)].opening / d));
        }
        F["tl"] = {{"t", tl_t}, {"hot", tl_hot}, {"hot_wall", tl_hot_wall}, {"mean", tl_mean}, {"opening", opening},
                   {"vy", tl_vy}, {"wall_rate", tl_wall_rate}, {"wall_load", tl_wall_load}, {"arch_y", arch_y}};
        nlohmann::json hs = nlohmann::json::array();
        for (std::size_t k = 0; k < hs_at.size(); ++k)
            hs.push_back({{"t", rates_at_t[k]}, {"centres", hs_at[k].centres}, {"density", hs_at[k].density},
                          {"error", hs_at[k].error}});
        F["hists"] = hs;
    }
    out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return out;
}

double num(const nlohmann::json& j) { return j.is_null() ? NAN : j.get<double>(); }

// Quantile q of values where NaN means "did not happen before t_end" (ranked as +infinity).
double censored_quantile(std::vector<double> v, double q) {
    for (double& x : v)
        if (std::isnan(x)) x = INFINITY;
    std::sort(v.begin(), v.end());
    if (v.empty()) return NAN;
    const double pos = q * double(v.size() - 1);
    const std::size_t lo = std::size_t(std::floor(pos)), hi = std::size_t(std::ceil(pos));
    const double a = v[lo], b = v[hi];
    if (!std::isfinite(a) || !std::isfinite(b)) return std::isfinite(a) && lo == hi ? a : NAN;
    return a + (pos - double(lo)) * (b - a);
}
double fraction_below(const std::vector<double>& v, double x) {
    double k = 0;
    for (double y : v)
        if (!std::isnan(y) && y <= x + 1e-12) ++k;
    return k / double(v.size());
}
double median_finite(std::vector<double> v) {
    std::erase_if(v, [](double x) { return !std::isfinite(x); });
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t k = v.size() / 2;
    return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

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
double fraction_of(const std::vector<double>& v, double x) { // share of finite values equal to x
    double k = 0, n = 0;
    for (double y : v)
        if (std::isfinite(y)) { n += 1; k += y == x ? 1 : 0; }
    return n > 0 ? k / n : NAN;
}

std::string tlabel(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t%.3f", t);
    return buf;
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const Geometry G = geometry(p);
    const long n_seeds = p.integer("n_seeds");
    std::vector<SeedRun> runs(static_cast<std::size_t>(n_seeds));
    // Seed run k draws RngStream(seed, k) whatever n_seeds, rank or shard: any split of the seeds
    // (ranks, --points shards) reproduces the single run.
    std::vector<long> order(static_cast<std::size_t>(n_seeds));
    std::iota(order.begin(), order.end(), 0L);
    const SweepResult swept = distributed_sweep(ctx, "pipe-arching", order, [&](long k) {
        return run_seed(p, G, ctx.seed, k, k == 0).to_json();
    });
    for (long k = 0; k < n_seeds; ++k) runs[std::size_t(k)] = SeedRun::from_json(swept.points[std::size_t(k)]);

    Result res;
    const SeedRun& f0 = runs.front();
    const nlohmann::json& F = f0.figure;
    res.scalar("resumed_points", double(swept.resumed), "1", "seeds loaded from a checkpoint");
    res.scalar("n_seeds", double(n_seeds), "1", "independent runs");
    res.scalar("layers", std::ceil(double(p.integer("n_particles")) /
                                   (std::floor((G.L - G.d) / (p.real("lattice") * G.d) + 1e-9) + 0.5)),
               "1", "rows of the initial lattice");

    // Relaxation.
    {
        Table& t = res.table("relaxation", "v̄ = sqrt(<v^2>) during the elastic relaxation, run 0");
        t.add("t", "s").values = F.at("relax_t").get<std::vector<double>>();
        t.add("vbar", "m/s").values = F.at("relax_vbar").get<std::vector<double>>();
    }
    std::vector<double> v0s, vlate;
    for (const auto& r : runs) { v0s.push_back(r.vbar0); vlate.push_back(r.vbar_relax_late); }
    res.scalar("vbar_t0", median_finite(v0s), "m/s", "v̄ = sqrt(<v^2>) at t = 0, median over seeds");
    res.scalar("vbar_t0_run0", f0.vbar0, "m/s", "v̄ at t = 0, run 0");
    res.scalar("vbar_relax_drift", median_finite(v0s) / median_finite(vlate) - 1, "1",
               "v̄(0) over the mean v̄ of the last third of the relaxation, minus 1 (steadiness)");

    // Snapshots, Fig. 13, with its marks: the initiating disk, the frame's arch, the crack.
    {
        std::vector<double> mt, px, py, ay, op;
        for (const auto& s : F.at("snaps")) {
            const std::string lab = tlabel(s.at("t").get<double>());
            Table& t = res.table("snapshot_" + lab,
                                 "disk centres (x, y above the removed floor), N_c over the last frame_dt, member of the frame's arch, side of the crack (-1 below, +1 above, 0 loose), run 0");
            t.add("x", "d").values = s.at("x").get<std::vector<double>>();
            t.add("y", "d").values = s.at("y").get<std::vector<double>>();
            t.add("Nc", "1/s").values = s.at("Nc").get<std::vector<double>>();
            t.add("arch", "1").values = s.at("arch").get<std::vector<double>>();
            t.add("crack_side", "1").values = s.at("side").get<std::vector<double>>();
            Table& c = res.table("crack_" + lab, "course of the widest wall-to-wall crack (mid-height per slice of one diameter), run 0");
            c.add("x", "d").values = s.at("course_x").get<std::vector<double>>();
            std::vector<double> cy;
            for (const auto& v : s.at("course_y")) cy.push_back(num(v));
            c.add("y", "d").values = cy;
            mt.push_back(s.at("t").get<double>());
            px.push_back(num(s.at("prec_x")));
            py.push_back(num(s.at("prec_y")));
            ay.push_back(num(s.at("arch_y")));
            op.push_back(num(s.at("opening")));
        }
        Table& mk = res.table("marks", "run 0 per Fig. 13 snapshot: initiating disk (x, y), arch height, crack opening");
        mk.add("t", "s").values = mt;
        mk.add("initiator_x", "d").values = px;
        mk.add("initiator_y", "d").values = py;
        mk.add("arch_y", "d").values = ay;
        mk.add("crack_opening", "d").values = op;
        std::vector<double> vis;
        for (double o : op) vis.push_back(o >= p.real("crack_opening") ? 1 : 0);
        mk.add("crack_visible", "1").values = vis;
    }
    // Timeline of run 0.
    {
        const auto& tl = F.at("tl");
        Table& t = res.table("timeline", "run 0 per frame: hot disks, mean N_c, widest wall-to-wall crack, mean v_y, wall collisions, share of the weight carried by the walls, arch height");
        const std::map<std::string, std::string> units = {{"t", "s"}, {"hot", "1"}, {"hot_wall", "1"}, {"mean", "1/s"},
                                                          {"opening", "d"}, {"vy", "m/s"}, {"wall_rate", "1/s"},
                                                          {"wall_load", "1"}, {"arch_y", "d"}};
        for (const char* k : {"t", "hot", "hot_wall", "mean", "opening", "vy", "wall_rate", "wall_load", "arch_y"}) {
            std::vector<double> v;
            for (const auto& x : tl.at(k)) v.push_back(num(x));
            t.add(k, units.at(k)).values = v;
        }
    }
    // P(N_c), Fig. 14: run 0's histogram per time; fits per time (run 0 and median over seeds)
    // and pooled over the four times of each panel (median over seeds: the claims' values).
    const std::size_t n_before = p.reals("dist_times_before").size();
    const double ddt = p.real("dist_dt");
    {
        Table& pt = res.table("fits_per_time", "Eq. (21) A (Fig. 14(a) times) or Eq. (22) B (Fig. 14(b) times) fitted at each time alone: run 0 with its standard error, and the median over seeds");
        std::vector<double> tt, v0, e0, med;
        for (std::size_t k = 0; k < F.at("hists").size(); ++k) {
            const double t = F.at("hists")[k].at("t").get<double>();
            std::vector<double> vals;
            for (const auto& r : runs) vals.push_back(num(r.per_time.at(k).at("value")));
            tt.push_back(t);
            v0.push_back(num(f0.per_time.at(k).at("value")));
            e0.push_back(num(f0.per_time.at(k).at("error")));
            med.push_back(median_finite(vals));
            const std::string what = k < n_before ? "A_" : "B_";
            const std::string eq = k < n_before ? "Eq. (21)" : "Eq. (22)";
            res.scalar(what + tlabel(t), v0.back(), "1/s", eq + " fit at this time alone, run 0");
            res.scalar(what + "err_" + tlabel(t), e0.back(), "1/s", "its standard error");
            res.scalar(what + tlabel(t) + "_median_seeds", med.back(), "1/s", eq + " fit at this time alone, median over seeds");
        }
        pt.add("t", "s").values = tt;
        pt.add("run0", "1/s").values = v0;
        pt.add("run0_err", "1/s").values = e0;
        pt.add("median_seeds", "1/s").values = med;
    }
    for (const auto& h : F.at("hists")) {
        const double t = h.at("t").get<double>();
        Table& tb = res.table("pnc_" + tlabel(t), "P(N_c) over the last dist_dt, run 0");
        tb.add("Nc", "1/s").values = h.at("centres").get<std::vector<double>>();
        tb.add("P", "s").values = h.at("density").get<std::vector<double>>();
        tb.add("err", "s").values = h.at("error").get<std::vector<double>>();
    }
    res.scalar("A_fit", f0.A, "1/s", "Eq. (21), pooled over the Fig. 14(a) times, run 0");
    res.scalar("A_fit_err", f0.A_err, "1/s", "its standard error (Cramer-Rao)");
    res.scalar("A_fit_chi2_reduced", f0.A_chi2, "1", "Pearson chi^2/dof of that fit");
    res.scalar("B_fit", f0.B, "1/s", "Eq. (22), pooled over the Fig. 14(b) times, run 0");
    res.scalar("B_fit_err", f0.B_err, "1/s", "its standard error (Cramer-Rao)");
    res.scalar("B_fit_chi2_reduced", f0.B_chi2, "1", "Pearson chi^2/dof of that fit");
    res.scalar("A_fit_per_window", f0.A * ddt, "1", "A in collisions per dist_dt window");
    res.scalar("mean_Nc_before", f0.mean_rate_early, "1/s", "mean N_c at the Fig. 14(a) times, run 0");

    std::vector<double> As, Bs, BA, ratio_early, ratio_late;
    for (const auto& r : runs) {
        As.push_back(r.A);
        Bs.push_back(r.B);
        BA.push_back(r.B / r.A);
        // Deviance of the exponential over that of the power law: < 1 where Eq. (21) fits better.
        ratio_early.push_back(r.dev_exp_early / r.dev_pow_early);
        ratio_late.push_back(r.dev_exp_late / r.dev_pow_late);
    }
    {
        std::vector<double> tb, ta2;
        for (const auto& r : runs) { tb.push_back(r.times_before); ta2.push_back(r.times_after); }
        res.scalar("fig14_times_before_median", median_finite(tb), "1", "Fig. 14(a) times before the run's first arch, pooled into A, median over seeds");
        res.scalar("fig14_times_after_median", median_finite(ta2), "1", "Fig. 14(b) times after the run's first arch, pooled into B, median over seeds");
    }
    res.scalar("A_fit_median_seeds", median_finite(As), "1/s", "Eq. (21) A, median over seeds");
    res.scalar("B_fit_median_seeds", median_finite(Bs), "1/s", "Eq. (22) B, median over seeds");
    res.scalar("B_over_A_median_seeds", median_finite(BA), "1", "B/A per seed, median (unit-free)");
    {
        // The paper's numbers come from one run: where they fall in our distribution over seeds.
        auto share_below = [](const std::vector<double>& v, double x) {
            double k = 0, n = 0;
            for (double y : v)
                if (std::isfinite(y)) { n += 1; k += y <= x ? 1 : 0; }
            return n > 0 ? k / n : NAN;
        };
        res.scalar("B_over_A_fraction_below_paper", share_below(BA, 14.0), "1",
                   "fraction of seeds with B/A <= 14, the paper's value (its percentile in our distribution)");
        res.scalar("B_fraction_below_paper", share_below(Bs, 14.0e3), "1",
                   "fraction of seeds with B <= 14e3 1/s (the paper's B in reading 1)");
    }
    {
        const MeanSem a = mean_sem(As), b = mean_sem(Bs), ba = mean_sem(BA);
        res.scalar("A_fit_seed_sem", a.sem, "1/s", "standard error of the mean of A over seeds");
        res.scalar("B_fit_seed_sem", b.sem, "1/s", "standard error of the mean of B over seeds");
        res.scalar("B_over_A_seed_sem", ba.sem, "1", "standard error of the mean of B/A over seeds");
        res.scalar("B_over_A_seed_sd", ba.sd, "1", "standard deviation of B/A over seeds");
        // The two readings of the paper's 'A = 1, B = 14 s^-1' (Sec. 5): the axis in units of
        // 1e3 1/s, or in collisions per window dist_dt.
        res.scalar("A_in_1e3_per_s", median_finite(As) / 1e3, "1", "A, median over seeds, in 1e3 1/s (reading 1: paper 1)");
        res.scalar("B_in_1e3_per_s", median_finite(Bs) / 1e3, "1", "B, median over seeds, in 1e3 1/s (reading 1: paper 14)");
        res.scalar("A_per_window", median_finite(As) * ddt, "1", "A, median over seeds, in collisions per dist_dt (reading 2: paper 1)");
        res.scalar("B_per_window", median_finite(Bs) * ddt, "1", "B, median over seeds, in collisions per dist_dt (reading 2: paper 14)");
        Table& ft = res.table("fits", "Eqs. (21), (22) pooled over each panel's four times, as drawn in Fig. 14 and checked: median over seeds, standard error of the mean over seeds, run 0 with its fit error");
        ft.add("A", "1/s").values = {median_finite(As)};
        ft.add("A_sem", "1/s").values = {a.sem};
        ft.add("A_run0", "1/s").values = {f0.A};
        ft.add("A_run0_err", "1/s").values = {f0.A_err};
        ft.add("B", "1/s").values = {median_finite(Bs)};
        ft.add("B_sem", "1/s").values = {b.sem};
        ft.add("B_run0", "1/s").values = {f0.B};
        ft.add("B_run0_err", "1/s").values = {f0.B_err};
        ft.add("seeds", "1").values = {double(n_seeds)};
        ft.add("dist_dt", "s").values = {ddt};
    }
    res.scalar("exp_over_pow_deviance_before", median_finite(ratio_early), "1",
               "deviance of Eq. (21) over that of Eq. (22), Fig. 14(a) times, median over seeds (< 1: exponential fits better)");
    res.scalar("exp_over_pow_deviance_after", median_finite(ratio_late), "1",
               "the same at the Fig. 14(b) times (> 1: power law fits better)");

    // Arches and cracks over seeds.
    std::vector<double> ta, tp, tw, tc, ya, y0a, yc, y0c, crack_after_arch, crack_near_arch, precursor_lead;
    Table& st = res.table("seeds", "per seed: first hot wall disk, first arch (time, lab and initial height), its precursor, first crack (NaN: none before t_end)");
    const std::vector<std::pair<const char*, const char*>> cols = {
        {"seed_index", "1"}, {"t_hot_wall", "s"}, {"t_precursor", "s"}, {"t_arch", "s"}, {"y_arch", "d"},
        {"y0_arch", "d"}, {"arch_size", "1"}, {"arch_foot_pressure_ratio", "1"}, {"react_lag", "s"},
        {"arch_left_4ms", "1"}, {"plug_wall_load", "1"}, {"arch_brake", "m/s"}, {"opening_below", "d"},
        {"wall_slowdown_arch", "m/s"}, {"opening_max_after", "d"}, {"t_crack", "s"}, {"y_crack", "d"},
        {"y0_crack", "d"}, {"crack_opening", "d"}, {"friction_share", "1"}, {"A", "1/s"}, {"B", "1/s"},
        {"wall_seconds", "s"}};
    std::vector<std::vector<double>> col(cols.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const SeedRun& r = runs[k];
        ta.push_back(r.t_arch); tp.push_back(r.t_precursor); tw.push_back(r.t_hot_wall); tc.push_back(r.t_crack);
        ya.push_back(r.y_arch); y0a.push_back(r.y0_arch); yc.push_back(r.y_crack); y0c.push_back(r.y0_crack);
        crack_after_arch.push_back(r.t_crack - r.t_arch);
        crack_near_arch.push_back(std::abs(r.y0_crack - r.y0_arch));
        precursor_lead.push_back(r.t_arch - r.t_precursor);
        const std::vector<double> vals = {double(k), r.t_hot_wall, r.t_precursor, r.t_arch, r.y_arch, r.y0_arch,
                                          r.arch_size, std::min(r.arch_pL, r.arch_pR), r.react_lag, r.arch_left_4ms,
                                          r.plug_wall_load, r.arch_brake, r.opening_below, r.wall_slowdown_arch,
                                          r.opening_max_after, r.t_crack, r.y_crack, r.y0_crack, r.crack_opening,
                                          r.friction_share, r.A, r.B, r.wall_seconds};
        for (std::size_t c = 0; c < cols.size(); ++c) col[c].push_back(vals[c]);
    }
    for (std::size_t c = 0; c < cols.size(); ++c) st.add(cols[c].first, cols[c].second).values = col[c];
    // Empirical distribution of the first-arch time (censored runs at the end).
    {
        std::vector<double> sorted = ta;
        for (double& x : sorted) if (std::isnan(x)) x = INFINITY;
        std::sort(sorted.begin(), sorted.end());
        Table& cd = res.table("arch_time_cdf", "fraction of seeds with an arch by time t");
        std::vector<double> tt, fr;
        for (std::size_t k = 0; k < sorted.size(); ++k)
            if (std::isfinite(sorted[k])) { tt.push_back(sorted[k]); fr.push_back(double(k + 1) / double(sorted.size())); }
        cd.add("t_arch", "s").values = tt;
        cd.add("fraction", "1").values = fr;
    }
    auto quartiles = [&](const std::string& name, const std::vector<double>& v, const std::string& what) {
        res.scalar(name + "_q25", censored_quantile(v, 0.25), "s", what + ", lower quartile over seeds (none = +inf)");
        res.scalar(name + "_median", censored_quantile(v, 0.5), "s", what + ", median over seeds");
        res.scalar(name + "_q75", censored_quantile(v, 0.75), "s", what + ", upper quartile over seeds");
    };
    quartiles("t_arch", ta, "first arch");
    quartiles("t_precursor", tp, "first hot wall disk of the first arch");
    quartiles("t_hot_wall", tw, "first hot disk at a wall (any)");
    quartiles("t_crack", tc, "first crack");
    res.scalar("arch_fraction", 1 - double(std::count_if(ta.begin(), ta.end(), [](double x) { return std::isnan(x); })) / double(ta.size()),
               "1", "fraction of seeds with an arch before t_end");
    res.scalar("crack_fraction", 1 - double(std::count_if(tc.begin(), tc.end(), [](double x) { return std::isnan(x); })) / double(tc.size()),
               "1", "fraction of seeds with a crack before t_end");
    res.scalar("arch_time_fraction_by_paper", fraction_below(ta, 0.056), "1",
               "fraction of seeds whose first arch formed by the paper's 0.056 s (its percentile in our distribution)");
    res.scalar("precursor_time_fraction_by_paper", fraction_below(tp, 0.048), "1",
               "fraction of seeds whose arch's first hot wall disk appeared by the paper's 0.048 s");
    res.scalar("crack_time_fraction_by_paper", fraction_below(tc, 0.060), "1",
               "fraction of seeds with a crack by the paper's 0.060 s");
    res.scalar("arch_height_median", median_finite(ya), "d", "lab height of the first arch above the removed floor, median");
    res.scalar("arch_initial_height_median", median_finite(y0a), "d", "initial (t = 0) height of the first arch's disks, median");
    res.scalar("crack_initial_height_median", median_finite(y0c), "d", "initial height of the disks bounding the first crack, median");
    res.scalar("precursor_lead_median", median_finite(precursor_lead), "s", "first arch minus its first hot wall disk, median (paper: 0.008 s)");
    res.scalar("crack_after_arch_median", median_finite(crack_after_arch), "s", "first crack minus first arch, median over seeds with both (paper: ~0.004 s)");
    res.scalar("crack_arch_height_offset_median", median_finite(crack_near_arch), "d",
               "|initial height of first crack - that of first arch|, median over seeds with both");
    res.scalar("t_arch_run0", f0.t_arch, "s", "first arch, run 0");
    res.scalar("y_arch_run0", f0.y_arch, "d", "its lab height above the removed floor, run 0");
    res.scalar("t_precursor_run0", f0.t_precursor, "s", "its first hot wall disk, run 0");
    res.scalar("t_crack_run0", f0.t_crack, "s", "first crack, run 0");
    res.scalar("y_crack_run0", f0.y_crack, "d", "its lab height, run 0");

    // The section's other statements, per seed, then over seeds.
    auto per_seed = [&](double SeedRun::*f) {
        std::vector<double> v;
        for (const auto& r : runs) v.push_back(r.*f);
        return v;
    };
    res.scalar("fluid_layers_median", median_finite(per_seed(&SeedRun::fluid_layers)), "1",
               "top rows at t = 0 in which at least half of the disks lost a lattice neighbour, median");
    res.scalar("lattice_broken_below_max", [&] {
        double m = 0;
        for (double x : per_seed(&SeedRun::lattice_broken_below)) m = std::max(m, x);
        return m;
    }(), "1", "share of the disks below those rows that lost a lattice neighbour, largest over seeds");
    res.scalar("react_lag_median", median_finite(per_seed(&SeedRun::react_lag)), "s",
               "first frame with half of the initiating disk's neighbours hot, minus its first hot frame, median (paper: 0.004 s)");
    res.scalar("arch_left_4ms_median", median_finite(per_seed(&SeedRun::arch_left_4ms)), "1",
               "share of the first arch's disks still hot 4 ms after it spanned the width, median");
    {
        const auto above = per_seed(&SeedRun::arch_above_later), below = per_seed(&SeedRun::arch_below_later);
        double both = 0, n_ok = 0;
        for (std::size_t k = 0; k < above.size(); ++k)
            if (std::isfinite(above[k])) { n_ok += 1; both += above[k] * below[k]; }
        res.scalar("arch_above_later_fraction", fraction_of(above, 1.0), "1", "seeds with a later arch (after the first + 4 ms) more than arch_separation above the first");
        res.scalar("arch_below_later_fraction", fraction_of(below, 1.0), "1", "the same below");
        res.scalar("arch_above_and_below_fraction", n_ok > 0 ? both / n_ok : NAN, "1", "seeds with later arches both above and below");
    }
    res.scalar("plug_wall_load_median", median_finite(per_seed(&SeedRun::plug_wall_load)), "1",
               "wall impulse on the arch's plug within 4 ms of the arch over the plug's weight times that time, median (1: the walls hold the plug)");
    {
        std::vector<double> rel;
        for (const auto& r : runs) rel.push_back(r.plug_wall_load / r.friction_share);
        res.scalar("plug_wall_load_over_mean_median", median_finite(rel), "1",
                   "plug_wall_load over the column's wall share over the whole fall, per seed, median (> 1: the walls hold the plug harder than the column)");
    }
    res.scalar("arch_brake_median", median_finite(per_seed(&SeedRun::arch_brake)), "m/s",
               "largest gain of v_y(plug) - v_y(material below) within arch_window of the arch, median (> 0: the plug falls slower)");
    res.scalar("opening_below_median", median_finite(per_seed(&SeedRun::opening_below)), "d",
               "largest growth of the distance between plug and material below within arch_window of the arch, median");
    res.scalar("opening_max_before_median", median_finite(per_seed(&SeedRun::opening_max_before)), "d",
               "widest wall-to-wall crack before the first arch, median over seeds (the falling column's own gaps)");
    res.scalar("opening_max_after_median", median_finite(per_seed(&SeedRun::opening_max_after)), "d",
               "widest wall-to-wall crack within arch_window after the first arch, median");
    res.scalar("opening_max_all_median", median_finite(per_seed(&SeedRun::opening_max_all)), "d",
               "widest wall-to-wall crack at any frame from t_detect_min on, median over seeds");
    res.scalar("crack_below_arch_median", median_finite(per_seed(&SeedRun::crack_below_arch)), "d",
               "initial height of the first arch minus that of the first crack, median (> 0: crack below)");
    res.scalar("crack_at_initiator_median", median_finite(per_seed(&SeedRun::crack_at_initiator)), "d",
               "crack course at the initiating disk's wall minus the disk's height, at the crack's first frame, median");
    {
        // Disks at the walls slow down (Sec. 5): v_y(wall) - v_y(inside) in the plug at the arch,
        // against the same at the window's start; the mean difference over seeds and its z-score.
        std::vector<double> diff;
        for (const auto& r : runs) diff.push_back(r.wall_slowdown_arch - r.wall_slowdown_before);
        const MeanSem ws = mean_sem(per_seed(&SeedRun::wall_slowdown_arch)), dd = mean_sem(diff);
        res.scalar("wall_slowdown_arch_mean", ws.mean, "m/s", "v_y(wall disks) - v_y(inner disks) of the plug at the arch, mean over seeds (> 0: wall disks slower)");
        res.scalar("wall_slowdown_gain_mean", dd.mean, "m/s", "the same minus its value arch_window before the arch, mean over seeds");
        res.scalar("wall_slowdown_gain_z", dd.sem > 0 ? dd.mean / dd.sem : NAN, "1", "that mean over its standard error (seed scatter)");
    }
    res.scalar("wall_load_peak_median", median_finite(per_seed(&SeedRun::wall_load_peak)), "1",
               "largest 5-frame mean of the walls' share of the weight, median over seeds");

    // Momentum balance and costs.
    std::vector<double> resid, share, secs, colls, el;
    for (const auto& r : runs) {
        resid.push_back(std::abs(r.momentum_residual));
        share.push_back(r.friction_share);
        secs.push_back(r.wall_seconds);
        colls.push_back(r.collisions);
        el.push_back(r.elastic_share);
    }
    res.scalar("momentum_balance_residual_max", *std::max_element(resid.begin(), resid.end()), "1",
               "max over seeds of |dP_y - (-M g t + J_wall)| / (M g t) over the fall");
    res.scalar("wall_friction_share", median_finite(share), "1", "side-wall impulse over M g t_end, median (0: free fall)");
    res.scalar("seconds_per_seed_median", median_finite(secs), "s", "wall time of one seed (relaxation + fall)");
    res.scalar("collisions_per_seed_median", median_finite(colls), "1", "pair collisions during the fall, median");
    res.scalar("tc_elastic_share_median", median_finite(el), "1", "share of the fall's pair collisions made elastic by TC");
    return res;
}

} // namespace

Experiment pipe_arching() { return {"pipe-arching", &validate, &run}; }

} // namespace granrepro::experiments
