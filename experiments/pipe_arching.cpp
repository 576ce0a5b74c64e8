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
//   crack = a horizontal strip at least crack_gap high without any disk centre across the width,
//           with crack_min_particles disks both above and below;
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
#include <numeric>
#include <string>

#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "harness/experiment.hpp"
#include "harness/parallel_sweep.hpp"
#include "harness/sweep_checkpoint.hpp"
#include "observables/collision_counter.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/rate_histogram.hpp"

namespace granrepro::experiments {

namespace {

constexpr int kLeft = 0, kRight = 1, kFloor = 2; // wall indices

long frame_of(double t, double frame_dt) { return std::lround(t / frame_dt); }

void validate(const ParameterSet& p) {
    const double fdt = p.real("frame_dt"), t_end = p.real("t_end");
    auto on_grid = [&](const char* name, double window) {
        for (double t : p.reals(name)) {
            if (t > t_end) p.reject(name, "every time must be <= t_end");
            if (t < window) p.reject(name, "every time must be >= its N_c window");
            if (std::abs(t / fdt - double(frame_of(t, fdt))) > 1e-6) p.reject(name, "times must be multiples of frame_dt");
        }
    };
    on_grid("snapshot_times", fdt);
    on_grid("dist_times_before", p.real("dist_dt"));
    on_grid("dist_times_after", p.real("dist_dt"));
    if (p.real("dist_dt") < fdt) p.reject("dist_dt", "must be >= frame_dt");
    if (p.real("width") < 2 * p.real("lattice")) p.reject("width", "must hold at least two lattice sites");
    if (p.integer("crack_min_particles") * 2 >= p.integer("n_particles"))
        p.reject("crack_min_particles", "must be below half of n_particles");
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

// One run (one seed).
struct SeedRun {
    double vbar0 = NAN, vbar_relax_late = NAN;
    double t_hot_wall = NAN;                        // first hot disk at a wall (any)
    double t_arch = NAN, y_arch = NAN, y0_arch = NAN; // first arch: time, lab and initial height [d]
    double arch_size = NAN, arch_pL = NAN, arch_pR = NAN;
    double t_precursor = NAN, y_precursor = NAN;
    double t_crack = NAN, y_crack = NAN, y0_crack = NAN, crack_gap = NAN;
    double A = NAN, A_err = NAN, A_chi2 = NAN, B = NAN, B_err = NAN, B_chi2 = NAN;
    double dev_exp_early = NAN, dev_pow_early = NAN, dev_exp_late = NAN, dev_pow_late = NAN;
    double mean_rate_early = NAN;
    double momentum_residual = NAN, friction_share = NAN;
    double wall_seconds = NAN, collisions = NAN, elastic_share = NAN;
    nlohmann::json figure; // run 0 only: snapshots, histograms, timeline, relaxation

    static constexpr const char* kKeys[] = {
        "vbar0", "vbar_relax_late", "t_hot_wall", "t_arch", "y_arch", "y0_arch", "arch_size", "arch_pL", "arch_pR",
        "t_precursor", "y_precursor", "t_crack", "y_crack", "y0_crack", "crack_gap", "A", "A_err", "A_chi2",
        "B", "B_err", "B_chi2", "dev_exp_early", "dev_pow_early", "dev_exp_late", "dev_pow_late",
        "mean_rate_early", "momentum_residual", "friction_share", "wall_seconds", "collisions", "elastic_share"};
    double* fields[std::size(kKeys)] = {
        &vbar0, &vbar_relax_late, &t_hot_wall, &t_arch, &y_arch, &y0_arch, &arch_size, &arch_pL, &arch_pR,
        &t_precursor, &y_precursor, &t_crack, &y_crack, &y0_crack, &crack_gap, &A, &A_err, &A_chi2,
        &B, &B_err, &B_chi2, &dev_exp_early, &dev_pow_early, &dev_exp_late, &dev_pow_late,
        &mean_rate_early, &momentum_residual, &friction_share, &wall_seconds, &collisions, &elastic_share};

    SeedRun() = default;
    SeedRun(const SeedRun& o) { *this = o; }
    SeedRun& operator=(const SeedRun& o) {
        for (std::size_t k = 0; k < std::size(kKeys); ++k) *fields[k] = *o.fields[k];
        figure = o.figure;
        return *this;
    }
    nlohmann::json to_json() const {
        nlohmann::json j;
        for (std::size_t k = 0; k < std::size(kKeys); ++k)
            j[kKeys[k]] = std::isfinite(*fields[k]) ? nlohmann::json(*fields[k]) : nlohmann::json(nullptr);
        j["figure"] = figure;
        return j;
    }
    static SeedRun from_json(const nlohmann::json& j) {
        SeedRun r;
        for (std::size_t k = 0; k < std::size(kKeys); ++k)
            *r.fields[k] = j.at(kKeys[k]).is_null() ? NAN : j.at(kKeys[k]).get<double>();
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
};

SeedRun run_seed(const ParameterSet& p, const Geometry& G, std::uint64_t seed, long index, bool figure) {
    const auto wall_start = std::chrono::steady_clock::now();
    const double d = G.d, L = G.L;
    const std::size_t n = std::size_t(p.integer("n_particles"));
    const double m = p.real("mass"), g = p.real("g");
    const double t_r = p.real("t_relax"), t_end = p.real("t_end");
    const double fdt = p.real("frame_dt"), ddt = p.real("dist_dt");
    const double hot = p.real("hot_rate");

    std::vector<Vec2> pos = triangular_lattice_positions(n, 0.5 * d, L - 0.5 * d, G.y_floor + 0.5 * d,
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
    EdEngine eng(cfg, pos, vel, std::vector<double>(n, 0.5 * d), std::vector<double>(n, m), {}, -t_r);

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
    eng.set_wall_law(kLeft, eps, mu, b0);
    eng.set_wall_law(kRight, eps, mu, b0);
    eng.set_tc(p.real("t_c"));
    eng.set_wall_enabled(kFloor, false);
    const std::vector<Vec2> pos0 = eng.positions();
    const double py0 = eng.total_momentum().y;
    const std::uint64_t coll0 = eng.total_collisions(), el0 = eng.elastic_collisions();

    CollisionCounter counter(n, true);
    std::vector<WallHit> hits;
    double jy = 0.0; // side-wall impulse on the column since t = 0 [kg m/s]
    auto obs = [&](const CollisionRecord& c) {
        counter.add(c);
        if (c.j < 0) {
            jy += c.dP.y;
            hits.push_back({c.t, c.ri.y, -1 - c.j});
        }
    };

    // Frames.
    const long n_frames = frame_of(t_end, fdt);
    const long detect_from = long(std::ceil(p.real("t_detect_min") / fdt - 1e-9));
    std::vector<long> snap_frames, before_frames, after_frames;
    for (double t : p.reals("snapshot_times")) snap_frames.push_back(frame_of(t, fdt));
    for (double t : p.reals("dist_times_before")) before_frames.push_back(frame_of(t, fdt));
    for (double t : p.reals("dist_times_after")) after_frames.push_back(frame_of(t, fdt));
    auto contains = [](const std::vector<long>& v, long f) { return std::find(v.begin(), v.end(), f) != v.end(); };
    std::vector<double> rates_before, rates_after;   // pooled over the times of Fig. 14(a), (b)
    std::vector<std::vector<double>> rates_at;        // per Fig. 14 time (figure run)
    std::vector<double> rates_at_t;

    const double link2 = std::pow(p.real("link") * d, 2), reach = p.real("wall_reach") * d;
    const double band = p.real("pressure_band") * d, pfac = p.real("arch_pressure_factor");
    const double crack_gap = p.real("crack_gap") * d;
    const std::size_t crack_min = std::size_t(p.integer("crack_min_particles"));

    // Per frame: hot wall disks' initial heights (to find an arch's precursor afterwards).
    std::vector<std::vector<double>> hot_wall_y0(std::size_t(n_frames) + 1);
    std::vector<double> tl_t, tl_hot, tl_hot_wall, tl_mean, tl_gap, tl_vy, tl_wall_rate, tl_arch;
    nlohmann::json snaps = nlohmann::json::array();

    for (long f = 1; f <= n_frames; ++f) {
        const double t = double(f) * fdt;
        eng.run_until(t, obs);
        const std::vector<double> rate = counter.rates(t, fdt);
        const std::vector<Vec2> r = eng.positions();
        // Side-wall collisions in this frame.
        std::erase_if(hits, [&](const WallHit& h) { return h.t <= t - fdt; });

        // Hot disks, their bands, and the hot disks at the walls.
        std::vector<int> hotv;
        int hot_wall_n = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (rate[i] >= hot) {
                hotv.push_back(int(i));
                if (r[i].x <= reach || r[i].x >= L - reach) {
                    ++hot_wall_n;
                    hot_wall_y0[std::size_t(f)].push_back((pos0[i].y - G.y_floor) / d);
                }
            }
        double ymin = INFINITY, ymax = -INFINITY;
        for (const Vec2& x : r) { ymin = std::min(ymin, x.y); ymax = std::max(ymax, x.y); }
        const double col_h = ymax - ymin + d;
        ArchFound arch;
        if (f >= detect_from && !hotv.empty()) {
            Dsu dsu(hotv.size());
            for (std::size_t a = 0; a < hotv.size(); ++a)
                for (std::size_t b = a + 1; b < hotv.size(); ++b)
                    if (norm2(r[hotv[a]] - r[hotv[b]]) <= link2) dsu.join(int(a), int(b));
            std::vector<std::vector<int>> bands(hotv.size());
            for (std::size_t a = 0; a < hotv.size(); ++a) bands[dsu.find(int(a))].push_back(hotv[a]);
            // Column mean of wall collisions per unit time and height, per wall.
            const double mean_p = double(hits.size()) / 2.0 / (fdt * col_h);
            for (const auto& bnd : bands) {
                if (bnd.empty()) continue;
                double yl = 0, yr = 0;
                int nl = 0, nr = 0;
                for (int i : bnd) {
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
                if (double(bnd.size()) > arch.size) {
                    double ym = 0, y0 = 0;
                    for (int i : bnd) { ym += r[i].y; y0 += pos0[i].y; }
                    arch = {true, (ym / double(bnd.size()) - G.y_floor) / d,
                            (y0 / double(bnd.size()) - G.y_floor) / d, double(bnd.size()), pl, pr};
                }
            }
        }
        if (arch.found && std::isnan(out.t_arch)) {
            out.t_arch = t;
            out.y_arch = arch.y;
            out.y0_arch = arch.y0;
            out.arch_size = arch.size;
            out.arch_pL = arch.pL;
            out.arch_pR = arch.pR;
            const long back = std::max(detect_from, f - long(std::lround(p.real("precursor_window") / fdt)));
            for (long k = back; k <= f && std::isnan(out.t_precursor); ++k)
                for (double y0 : hot_wall_y0[std::size_t(k)])
                    if (std::abs(y0 - arch.y0) <= p.real("precursor_band")) {
                        out.t_precursor = double(k) * fdt;
                        out.y_precursor = y0;
                        break;
                    }
        }
        if (f >= detect_from && hot_wall_n > 0 && std::isnan(out.t_hot_wall)) out.t_hot_wall = t;

        // Largest empty horizontal strip inside the body of the column.
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return r[a].y < r[b].y; });
        double best_gap = 0;
        std::size_t best_k = 0;
        for (std::size_t k = crack_min; k + crack_min < n; ++k) {
            const double gap = r[order[k]].y - r[order[k - 1]].y;
            if (gap > best_gap) { best_gap = gap; best_k = k; }
        }
        if (f >= detect_from && best_gap >= crack_gap && std::isnan(out.t_crack)) {
            out.t_crack = t;
            out.y_crack = (0.5 * (r[order[best_k]].y + r[order[best_k - 1]].y) - G.y_floor) / d;
            out.y0_crack = (0.5 * (pos0[order[best_k]].y + pos0[order[best_k - 1]].y) - G.y_floor) / d;
            out.crack_gap = best_gap / d;
        }

        // P(N_c) over dist_dt.
        const bool fb = contains(before_frames, f), fa = contains(after_frames, f);
        if (fb || fa) {
            const std::vector<double> rd = counter.rates(t, ddt);
            (fb ? rates_before : rates_after).insert((fb ? rates_before : rates_after).end(), rd.begin(), rd.end());
            if (figure) {
                rates_at.push_back(rd);
                rates_at_t.push_back(t);
            }
        }
        counter.discard_before(t - ddt - fdt);

        if (figure) {
            double vy = 0;
            for (const Vec2& v : eng.velocities()) vy += v.y;
            tl_t.push_back(t);
            tl_hot.push_back(double(hotv.size()));
            tl_hot_wall.push_back(hot_wall_n);
            tl_mean.push_back(std::accumulate(rate.begin(), rate.end(), 0.0) / double(n));
            tl_gap.push_back(best_gap / d);
            tl_vy.push_back(vy / double(n));
            tl_wall_rate.push_back(double(hits.size()) / fdt / double(n));
            tl_arch.push_back(arch.found ? arch.y : NAN);
            if (contains(snap_frames, f)) {
                nlohmann::json s;
                std::vector<double> x, y, c;
                for (std::size_t i = 0; i < n; ++i) {
                    x.push_back(r[i].x / d);
                    y.push_back((r[i].y - G.y_floor) / d);
                    c.push_back(rate[i]);
                }
                s["t"] = t;
                s["x"] = x;
                s["y"] = y;
                s["Nc"] = c;
                s["arch_y"] = arch.found ? nlohmann::json(arch.y) : nlohmann::json(nullptr);
                snaps.push_back(s);
            }
        }
    }

    // Fits of Eqs. (21), (22) to the pooled P(N_c): before arches (C >= 1 per window) and after.
    const double rmin = 1.0 / ddt; // one collision per window
    auto hist_lin = [&](const std::vector<double>& rs) { return RateHistogram::per_count(rs, ddt, 200); };
    auto hist_log = [&](const std::vector<double>& rs) {
        return RateHistogram::make(rs, ddt, RateHistogram::Binning::Log, 30, 0.5 * rmin, 1.0e6);
    };
    const double hi_lin = (200 + 0.5) / ddt;
    {
        const RateHistogram h = hist_lin(rates_before);
        const Fit fe = try_fit(h, CollisionRateFit::Model::Exponential, 0.5 * rmin, hi_lin);
        const Fit fp = try_fit(h, CollisionRateFit::Model::PowerLaw, 0.5 * rmin, hi_lin);
        if (fe.ok) { out.A = fe.fit.value; out.A_err = fe.fit.error; out.A_chi2 = fe.fit.chi2_reduced; out.dev_exp_early = fe.fit.deviance; }
        if (fp.ok) out.dev_pow_early = fp.fit.deviance;
        out.mean_rate_early = std::accumulate(rates_before.begin(), rates_before.end(), 0.0) / double(rates_before.size());
    }
    {
        const RateHistogram h = hist_log(rates_after);
        const Fit fe = try_fit(h, CollisionRateFit::Model::Exponential, 0.5 * rmin, 1.0e6);
        const Fit fp = try_fit(h, CollisionRateFit::Model::PowerLaw, 0.5 * rmin, 1.0e6);
        if (fp.ok) { out.B = fp.fit.value; out.B_err = fp.fit.error; out.B_chi2 = fp.fit.chi2_reduced; out.dev_pow_late = fp.fit.deviance; }
        if (fe.ok) out.dev_exp_late = fe.fit.deviance;
    }

    // Momentum balance over the fall.
    const double M = double(n) * m;
    const double dpy = eng.total_momentum().y - py0;
    out.momentum_residual = (dpy - (-M * g * t_end + jy)) / (M * g * t_end);
    out.friction_share = jy / (M * g * t_end);
    out.collisions = double(eng.total_collisions() - coll0);
    out.elastic_share = double(eng.elastic_collisions() - el0) / std::max(1.0, out.collisions);

    if (figure) {
        nlohmann::json& F = out.figure;
        F["relax_t"] = rt;
        F["relax_vbar"] = rv;
        F["snaps"] = snaps;
        F["tl"] = {{"t", tl_t}, {"hot", tl_hot}, {"hot_wall", tl_hot_wall}, {"mean", tl_mean}, {"gap", tl_gap},
                   {"vy", tl_vy}, {"wall_rate", tl_wall_rate}};
        std::vector<nlohmann::json> arch_y;
        for (double a : tl_arch) arch_y.push_back(std::isfinite(a) ? nlohmann::json(a) : nlohmann::json(nullptr));
        F["tl"]["arch_y"] = arch_y;
        nlohmann::json hs = nlohmann::json::array();
        for (std::size_t k = 0; k < rates_at.size(); ++k) {
            const bool early = k < before_frames.size();
            const RateHistogram h = early ? hist_lin(rates_at[k]) : hist_log(rates_at[k]);
            const Fit fe = try_fit(h, CollisionRateFit::Model::Exponential, 0.5 * rmin, early ? hi_lin : 1.0e6);
            const Fit fp = try_fit(h, CollisionRateFit::Model::PowerLaw, 0.5 * rmin, early ? hi_lin : 1.0e6);
            hs.push_back({{"t", rates_at_t[k]}, {"centres", h.centres}, {"density", h.density}, {"error", h.error},
                          {"A", fe.ok ? nlohmann::json(fe.fit.value) : nlohmann::json(nullptr)},
                          {"A_err", fe.ok ? nlohmann::json(fe.fit.error) : nlohmann::json(nullptr)},
                          {"B", fp.ok ? nlohmann::json(fp.fit.value) : nlohmann::json(nullptr)},
                          {"B_err", fp.ok ? nlohmann::json(fp.fit.error) : nlohmann::json(nullptr)}});
        }
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
    SweepCheckpoint checkpoint(ctx);
    Progress progress("pipe-arching", n_seeds, ctx.quiet);
    parallel_sweep(n_seeds, ctx.threads, &progress, [&](long k) {
        if (auto saved = checkpoint.load(k)) {
            runs[std::size_t(k)] = SeedRun::from_json(*saved);
            return;
        }
        runs[std::size_t(k)] = run_seed(p, G, ctx.seed, k, k == 0);
        checkpoint.save(k, runs[std::size_t(k)].to_json());
    });

    Result res;
    const SeedRun& f0 = runs.front();
    const nlohmann::json& F = f0.figure;
    res.scalar("resumed_points", double(checkpoint.resumed()), "1", "seeds loaded from a checkpoint");
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

    // Snapshots, Fig. 13.
    for (const auto& s : F.at("snaps")) {
        Table& t = res.table("snapshot_" + tlabel(s.at("t").get<double>()),
                             "disk centres (x, y above the removed floor) and N_c over the last frame_dt, run 0");
        t.add("x", "d").values = s.at("x").get<std::vector<double>>();
        t.add("y", "d").values = s.at("y").get<std::vector<double>>();
        t.add("Nc", "1/s").values = s.at("Nc").get<std::vector<double>>();
    }
    // Timeline of run 0.
    {
        const auto& tl = F.at("tl");
        Table& t = res.table("timeline", "run 0 per frame: hot disks, mean N_c, largest empty strip, mean v_y, wall collisions, arch height");
        for (const char* k : {"t", "hot", "hot_wall", "mean", "gap", "vy", "wall_rate", "arch_y"}) {
            std::vector<double> v;
            for (const auto& x : tl.at(k)) v.push_back(num(x));
            const std::string unit = std::string(k) == "t" ? "s" : std::string(k) == "mean" || std::string(k) == "wall_rate" ? "1/s"
                                   : std::string(k) == "gap" || std::string(k) == "arch_y" ? "d" : std::string(k) == "vy" ? "m/s" : "1";
            t.add(k, unit).values = v;
        }
    }
    // P(N_c), Fig. 14: one table per time; fits per time and pooled.
    const double ddt = p.real("dist_dt");
    for (const auto& h : F.at("hists")) {
        const double t = h.at("t").get<double>();
        Table& tb = res.table("pnc_" + tlabel(t), "P(N_c) over the last dist_dt, run 0");
        tb.add("Nc", "1/s").values = h.at("centres").get<std::vector<double>>();
        tb.add("P", "s").values = h.at("density").get<std::vector<double>>();
        tb.add("err", "s").values = h.at("error").get<std::vector<double>>();
        const bool early = t < p.reals("dist_times_after").front() - 1e-12;
        if (early) {
            res.scalar("A_" + tlabel(t), num(h.at("A")), "1/s", "Eq. (21) fit at this time, run 0");
            res.scalar("A_err_" + tlabel(t), num(h.at("A_err")), "1/s", "its standard error");
        } else {
            res.scalar("B_" + tlabel(t), num(h.at("B")), "1/s", "Eq. (22) fit at this time, run 0");
            res.scalar("B_err_" + tlabel(t), num(h.at("B_err")), "1/s", "its standard error");
        }
    }
    {
        Table& ft = res.table("fits", "pooled fits of run 0 drawn in Fig. 14: Eq. (21) A and Eq. (22) B");
        ft.add("A", "1/s").values = {f0.A};
        ft.add("A_err", "1/s").values = {f0.A_err};
        ft.add("B", "1/s").values = {f0.B};
        ft.add("B_err", "1/s").values = {f0.B_err};
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
    res.scalar("A_fit_median_seeds", median_finite(As), "1/s", "Eq. (21) A, median over seeds");
    res.scalar("B_fit_median_seeds", median_finite(Bs), "1/s", "Eq. (22) B, median over seeds");
    res.scalar("B_over_A_median_seeds", median_finite(BA), "1", "B/A per seed, median (unit-free)");
    res.scalar("exp_over_pow_deviance_before", median_finite(ratio_early), "1",
               "deviance of Eq. (21) over that of Eq. (22), Fig. 14(a) times, median over seeds (< 1: exponential fits better)");
    res.scalar("exp_over_pow_deviance_after", median_finite(ratio_late), "1",
               "the same at the Fig. 14(b) times (> 1: power law fits better)");

    // Arches and cracks over seeds.
    std::vector<double> ta, tp, tw, tc, ya, y0a, yc, y0c, crack_after_arch, crack_near_arch, precursor_lead;
    Table& st = res.table("seeds", "per seed: first hot wall disk, first arch (time, lab and initial height), its precursor, first crack (NaN: none before t_end)");
    std::vector<double> col[14];
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const SeedRun& r = runs[k];
        ta.push_back(r.t_arch); tp.push_back(r.t_precursor); tw.push_back(r.t_hot_wall); tc.push_back(r.t_crack);
        ya.push_back(r.y_arch); y0a.push_back(r.y0_arch); yc.push_back(r.y_crack); y0c.push_back(r.y0_crack);
        crack_after_arch.push_back(r.t_crack - r.t_arch);
        crack_near_arch.push_back(std::abs(r.y0_crack - r.y0_arch));
        precursor_lead.push_back(r.t_arch - r.t_precursor);
        const double vals[14] = {double(k), r.t_hot_wall, r.t_precursor, r.t_arch, r.y_arch, r.y0_arch, r.arch_size,
                                 std::min(r.arch_pL, r.arch_pR), r.t_crack, r.y_crack, r.y0_crack, r.A, r.B, r.wall_seconds};
        for (int c = 0; c < 14; ++c) col[c].push_back(vals[c]);
    }
    const char* names[14] = {"seed_index", "t_hot_wall", "t_precursor", "t_arch", "y_arch", "y0_arch", "arch_size",
                             "arch_foot_pressure_ratio", "t_crack", "y_crack", "y0_crack", "A", "B", "wall_seconds"};
    const char* units[14] = {"1", "s", "s", "s", "d", "d", "1", "1", "s", "d", "d", "1/s", "1/s", "s"};
    for (int c = 0; c < 14; ++c) st.add(names[c], units[c]).values = col[c];
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
