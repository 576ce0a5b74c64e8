// impact-parameter: Luding 1998 Sec. 3.2, Figs 4 and 5. N = 240 smooth hard disks in a periodic
// square box at area fraction 0.7495, equilibrated at r = 1 (Sec. 3), then freely cooling with
// r = 0.80, 0.90, 0.95 (TC model, Eq. 7) up to t = 1 s:
//   Fig. 4: P(b/d) (Eq. 17, normalised so that its integral over [0, 1] is 1) per r, plus the
//           elastic check "P(b/d) = 1 at any density" at r = 1 from dilute to dense;
//   Fig. 5: the particles and their velocities at t = 1 s, and the principal stresses of Eq. (9)
//           per cell of a coarse grid, averaged over 0.5 s <= t < 1 s.
// Claims are turned into numbers with their Poisson errors: chi^2 of P against 1 per degree of
// freedom, and the grazing-to-central ratio P(b/d > 0.8) / P(b/d < 0.2) with its z-score.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "analysis/eddy_pair.hpp"
#include "core/input_error.hpp"
#include "core/vec3.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "engines/ed3d/hard_sphere_gas.hpp"
#include "experiments/work_limits.hpp"
#include "harness/experiment.hpp"
#include "theory/kinetic_theory.hpp"
#include "harness/parallel_sweep.hpp"
#include "harness/progress.hpp"
#include "observables/collisional_stress.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "observables/kinetic_energy.hpp"

namespace granrepro::experiments {

namespace {

// Side of the periodic square box holding n disks of diameter d [m] at area fraction rho.
double box_side(std::size_t n, double d, double rho) {
    return std::sqrt(static_cast<double>(n) * M_PI * d * d / (4.0 * rho));
}

// A staggered (centred-rectangular) lattice filling the periodic square box: rows alternate by
// half a column. The library's square lattice cannot hold N = 240 at rho = 0.7495 (16 x 15 sites
// are 0.991 d apart), while 16 rows of 15 staggered sites are >= 1.057 d apart. The number of
// rows is even (so the stagger wraps) and chosen to maximise the smallest site distance.
std::vector<Vec2> staggered_lattice(std::size_t n, double l, double d) {
    std::size_t best_rows = 0;
    double best_gap = 0.0;
    for (std::size_t rows = 2; rows <= 2 * n; rows += 2) {
        const std::size_t cols = (n + rows - 1) / rows;
        const double sx = l / static_cast<double>(cols), sy = l / static_cast<double>(rows);
        // Neighbours: along a row, in the next row (half a column over), two rows up.
        double gap = std::min({sx, std::hypot(0.5 * sx, sy), 2.0 * sy});
        if (cols == 1) gap = std::min(gap, l); // a single column meets its own image
        if (gap > best_gap) { best_gap = gap; best_rows = rows; }
    }
    if (!(best_gap > d * (1.0 + 1e-9)))
        throw InputError("rho: too dense for a staggered start lattice (closest sites " +
                         std::to_string(best_gap / d) + " d apart)");
    const std::size_t rows = best_rows, cols = (n + rows - 1) / rows;
    const double sx = l / static_cast<double>(cols), sy = l / static_cast<double>(rows);
    std::vector<Vec2> out;
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t ix = k % cols, iy = k / cols;
        const double off = (iy % 2 == 1) ? 0.5 : 0.0;
        out.push_back({(static_cast<double>(ix) + 0.25 + off) * sx, (static_cast<double>(iy) + 0.5) * sy});
    }
    return out;
}

// Counts of one sweep point; seeds are merged by adding counts.
struct PointResult {
    std::vector<std::vector<std::uint64_t>> counts; // [window][bin]
    std::uint64_t pair_collisions = 0, elastic_by_tc = 0;
    // Only for the inelastic runs of the first seed (Fig. 5 and the cooling curve):
    std::vector<Vec2> pos, vel;
    std::vector<CollisionalStress::Cell> cells;
    std::vector<double> k_t, k_val; // K(t) [s], [J]
    double k0 = 0.0;
    double sigma_max = NAN, flow_fraction = NAN; // every seed, see panel_measures()
    double v_rms = NAN;                          // every seed: rms speed at t_end [m/s]
    // Every seed: the strongest co-rotating eddy pair at t_end (src/analysis/eddy_pair.hpp), the
    // share of velocity shuffles it beats, and the mean pressure of the stress cells in its two
    // cores over that of the other cells.
    double eddy_strength = NAN, eddy_beats = NAN, eddy_core_pressure_ratio = NAN;
};

// P(b/d) from counts: density over [0, 1] with bin width 1/nb, Poisson error sqrt(n) per bin.
struct Histogram {
    std::vector<double> p, err;
    std::uint64_t total = 0;
};

Histogram normalise(const std::vector<std::uint64_t>& counts) {
    Histogram h;
    const std::size_t nb = counts.size();
    h.total = std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
    h.p.assign(nb, NAN);
    h.err.assign(nb, NAN);
    if (h.total == 0) return h;
    const double s = static_cast<double>(nb) / static_cast<double>(h.total);
    for (std::size_t k = 0; k < nb; ++k) {
        h.p[k] = s * static_cast<double>(counts[k]);
        h.err[k] = s * std::sqrt(static_cast<double>(counts[k]));
    }
    return h;
}

// chi^2 of the bins against P = 1, per degree of freedom. The normalisation fixes one
// combination of the bins, so dof = nb - 1; for molecular chaos the expectation is 1 with a
// standard deviation sqrt(2/(nb-1)). Poisson variance is taken from the expected count n/nb,
// which keeps empty or sparse bins from dominating.
double chi2_per_dof(const std::vector<std::uint64_t>& counts) {
    const double nb = static_cast<double>(counts.size());
    const double total = static_cast<double>(std::accumulate(counts.begin(), counts.end(), std::uint64_t{0}));
    if (total <= 0.0 || nb < 2) return NAN;
    const double expect = total / nb;
    double chi2 = 0.0;
    for (auto c : counts) chi2 += (static_cast<double>(c) - expect) * (static_cast<double>(c) - expect) / expect;
    return chi2 / (nb - 1.0);
}

// P(b/d > 0.8) / P(b/d < 0.2) from the counts in those ranges (bins must align with 0.2, 0.8)
// and its Poisson error: R = n_hi/n_lo, sigma_R = R sqrt(1/n_hi + 1/n_lo).
struct Ratio {
    double value = NAN, err = NAN, z = NAN;
};
Ratio grazing_ratio(const std::vector<std::uint64_t>& counts) {
    const std::size_t nb = counts.size();
    const std::size_t lo_end = static_cast<std::size_t>(std::lround(0.2 * static_cast<double>(nb)));
    const std::size_t hi_begin = nb - lo_end;
    double lo = 0, hi = 0;
    for (std::size_t k = 0; k < lo_end; ++k) lo += static_cast<double>(counts[k]);
    for (std::size_t k = hi_begin; k < nb; ++k) hi += static_cast<double>(counts[k]);
    Ratio r;
    if (lo <= 0 || hi <= 0) return r;
    r.value = hi / lo;
    r.err = r.value * std::sqrt(1.0 / hi + 1.0 / lo);
    r.z = (r.value - 1.0) / r.err;
    return r;
}

std::string label(const char* prefix, double x, const char* fmt) {
    char buf[48];
    std::snprintf(buf, sizeof buf, fmt, x);
    return std::string(prefix) + buf;
}

// sigma_max of a panel: the largest principal stress magnitude over the cells. Eq. (9) as
// printed is tension-positive, so in a gas both eigenvalues are negative; the paper's positive
// sigma_max is read as the largest compressive principal stress, max over cells of -sigma_min.
double sigma_max_of(const std::vector<CollisionalStress::Cell>& cells) {
    double s = 0.0;
    for (const auto& c : cells) s = std::max({s, std::fabs(c.sigma_min), std::fabs(c.sigma_max)});
    return s;
}

// Share of the kinetic energy in the velocity field averaged over nc x nc cells: about
// nc^2 / N for uncorrelated velocities (each cell mean carries 1/n_cell of its cell's K), close
// to 1 when layers shear or eddies form (Sec. 3.2, Fig. 5 left).
double flow_fraction(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double l, int nc) {
    std::vector<Vec2> mom(static_cast<std::size_t>(nc * nc));
    std::vector<double> cnt(mom.size(), 0.0);
    auto cell_of = [&](double x) { return std::clamp(static_cast<int>(std::floor(x / l * nc)), 0, nc - 1); };
    double k = 0.0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        const auto c = static_cast<std::size_t>(cell_of(pos[i].x) + nc * cell_of(pos[i].y));
        mom[c] += vel[i];
        cnt[c] += 1.0;
        k += norm2(vel[i]);
    }
    double kflow = 0.0;
    for (std::size_t c = 0; c < mom.size(); ++c)
        if (cnt[c] > 0) kflow += norm2(mom[c]) / cnt[c];
    return k > 0 ? kflow / k : NAN;
}

void validate(const ParameterSet& p) {
    const double t_end = p.real("t_end");
    {
        // Pair collisions, bounded above at the initial Enskog rate (cooling only slows it):
        // t_end = 1e308 s printed nothing for minutes.
        const double n = double(p.integer("N")), rho = p.real("rho");
        const double omega = theory::enskog_collision_rate_vbar(rho, p.real("d"), p.real("vbar"), theory::henderson_contact_value(rho));
        const double eq = p.real("equilibration_collisions");
        const double per_seed = double(p.reals("restitutions").size()) * n / 2 * (omega * t_end + eq) +
                                double(p.reals("elastic_densities").size()) * n / 2 *
                                    (p.real("elastic_collisions_per_particle") + eq);
        p.limit_work({"t_end", "N", "seeds", "vbar", "rho", "d", "equilibration_collisions",
                      "elastic_collisions_per_particle", "restitutions", "elastic_densities"},
                     double(p.integer("seeds")) * per_seed, kMaxCollisions, "pair collisions");
    }
    const auto& edges = p.reals("window_edges");
    if (edges.size() < 2 || edges.front() != 0.0 || std::fabs(edges.back() - t_end) > 1e-12 * t_end)
        p.reject("window_edges", "must start at 0 s and end at t_end = " + number_text(t_end) + " s");
    for (std::size_t k = 1; k < edges.size(); ++k)
        if (!(edges[k] > edges[k - 1])) p.reject("window_edges", "must be strictly increasing");
    if (!(p.real("stress_t_begin") < t_end))
        p.reject("stress_t_begin", "must be below t_end = " + number_text(t_end) + " s");
    const long nb = p.integer("n_bins");
    if (nb % 5 != 0) p.reject("n_bins", "must be a multiple of 5 so that bins end at b/d = 0.2 and 0.8");
    if (p.reals("restitutions").empty()) p.reject("restitutions", "needs at least one value");
    // The start lattice must fit (it throws InputError naming rho otherwise).
    const auto n = static_cast<std::size_t>(p.integer("N"));
    const double d = p.real("d");
    staggered_lattice(n, box_side(n, d, p.real("rho")), d);
    for (double rho : p.reals("elastic_densities")) {
        try {
            staggered_lattice(n, box_side(n, d, rho), d);
        } catch (const InputError& e) {
            p.reject("elastic_densities", std::string("at ") + number_text(rho) + ": " + e.what());
        }
    }
}

Result run(const RunContext& ctx) {
    const ParameterSet& p = ctx.params;
    const auto n = static_cast<std::size_t>(p.integer("N"));
    const double d = p.real("d"), m = p.real("m"), vbar = p.real("vbar"), rho = p.real("rho");
    const double t_end = p.real("t_end"), t_c = p.real("t_c"), eq = p.real("equilibration_collisions");
    const int nb = static_cast<int>(p.integer("n_bins"));
    const int nc = static_cast<int>(p.integer("stress_cells"));
    const double ts0 = p.real("stress_t_begin");
    const long n_snap = p.integer("stress_snapshots");
    const auto& rs = p.reals("restitutions");
    const auto& rhos = p.reals("elastic_densities");
    const auto& edges = p.reals("window_edges");
    const double el_coll = p.real("elastic_collisions_per_particle");
    const auto n_seeds = static_cast<std::size_t>(p.integer("seeds"));
    const std::size_t per_seed = rs.size() + rhos.size();
    const std::size_t nw = edges.size() - 1;

    std::vector<PointResult> points(per_seed * n_seeds);
    Progress progress("impact-parameter", static_cast<long>(points.size()), ctx.quiet);
    parallel_sweep(static_cast<long>(points.size()), ctx.threads, &progress, [&](long task) {
        const auto idx = static_cast<std::size_t>(task);
        const std::size_t seed = idx / per_seed, k = idx % per_seed;
        const bool inelastic = k < rs.size();
        const double rho_k = inelastic ? rho : rhos[k - rs.size()];
        const double l = box_side(n, d, rho_k);
        RngStream rng(ctx.seed, idx);
        EdConfig cfg;
        cfg.lx = cfg.ly = l;
        // Smooth disks (mu = 0, beta0 = -1): Sec. 2.4 says DSMC's collision scheme "is identical
        // to the event driven procedure" with the tangential velocity unchanged, beta0 = -1.
        cfg.law = RoughDiskCollision{inelastic ? rs[k] : 1.0, 0.0, -1.0, 0.4};
        cfg.t_c = inelastic ? t_c : 0.0;
        const std::vector<double> rad(n, 0.5 * d), mass(n, m);
        EdEngine e(cfg, staggered_lattice(n, l, d), maxwellian_velocities(mass, vbar, rng), rad, mass);
        // Sec. 3: "first allowed to evolve with r = 1 for about 10 collisions per particle"; the
        // elastic run conserves K, so vbar is still the initial mean velocity at t = 0.
        equilibrate(e, eq);
        const double t0 = e.time();
        std::vector<double> w_edges(edges.size());
        for (std::size_t w = 0; w < edges.size(); ++w) w_edges[w] = t0 + edges[w];
        PointResult& out = points[idx];

        if (!inelastic) {
            ImpactParameterHistogram hist(nb, {t0, std::numeric_limits<double>::max()});
            e.run_collisions(static_cast<std::uint64_t>(el_coll * static_cast<double>(n) / 2.0 + 0.5),
                             [&](const CollisionRecord& c) { hist.add(c); });
            out.counts = {hist.window(0).counts};
            out.pair_collisions = e.total_collisions();
            return;
        }

        ImpactParameterHistogram hist(nb, w_edges);
        const bool figure_run = seed == 0; // K(t) samples only
        CollisionalStress stress(nc, nc, 0.0, 0.0, l, l, t0 + ts0, t0 + t_end, true);
        const std::uint64_t c_before = e.total_collisions(), el_before = e.elastic_collisions();
        auto observe = [&](const CollisionRecord& c) {
            hist.add(c);
            stress.add(c);
        };
        // Stops: kinetic-term snapshots in the stress window (midpoints of n_snap equal slices)
        // and log-spaced K(t) samples for the cooling curve.
        std::vector<double> stops, snaps;
        for (long s = 0; s < n_snap; ++s)
            snaps.push_back(t0 + ts0 + (static_cast<double>(s) + 0.5) * (t_end - ts0) / static_cast<double>(n_snap));
        stops = snaps;
        const int n_k = 61;
        for (int s = 0; s < n_k; ++s) stops.push_back(t0 + t_end * std::pow(10.0, -5.0 + 5.0 * s / (n_k - 1)));
        std::sort(stops.begin(), stops.end());
        out.k0 = e.kinetic_energy().kx + e.kinetic_energy().ky;
        std::size_t next_snap = 0;
        for (double ts : stops) {
            e.run_until(ts, observe);
            if (next_snap < snaps.size() && ts == snaps[next_snap]) {
                const auto pos = e.positions(), vel = e.velocities();
                stress.add_snapshot(pos, vel, mass);
                ++next_snap;
            } else if (figure_run) {
                const auto k = e.kinetic_energy();
                out.k_t.push_back(ts - t0);
                out.k_val.push_back(k.kx + k.ky);
            }
        }
        e.run_until(t0 + t_end, observe);
        for (std::size_t w = 0; w < nw; ++w) out.counts.push_back(hist.window(w).counts);
        out.pair_collisions = e.total_collisions() - c_before;
        out.elastic_by_tc = e.elastic_collisions() - el_before;
        out.pos = e.positions();
        out.vel = e.velocities();
        out.cells = stress.result();
        out.sigma_max = sigma_max_of(out.cells);
        out.flow_fraction = flow_fraction(out.pos, out.vel, l, nc);
        double v2 = 0.0;
        for (const auto& v : out.vel) v2 += norm2(v);
        out.v_rms = std::sqrt(v2 / static_cast<double>(n));
        {
            const EddyPair ep = find_eddy_pair(out.pos, out.vel, l);
            const long n_sh = p.integer("eddy_shuffles");
            const auto sh = shuffled_eddy_strengths(out.pos, out.vel, l, static_cast<int>(n_sh), mix_seed(ctx.seed, idx));
            out.eddy_strength = ep.strength;
            out.eddy_beats = static_cast<double>(std::count_if(sh.begin(), sh.end(), [&](double x) { return x < ep.strength; })) /
                             static_cast<double>(n_sh);
            // Cores: cells whose centre lies within a quarter box (the quadrant's inscribed circle)
            // of either eddy centre.
            double p_in = 0, n_in = 0, p_out = 0, n_out = 0;
            for (int iy = 0; iy < nc; ++iy)
                for (int ix = 0; ix < nc; ++ix) {
                    const Vec2 c{(ix + 0.5) * l / nc, (iy + 0.5) * l / nc};
                    auto dist = [&](Vec2 a) {
                        const double dx = c.x - a.x - l * std::round((c.x - a.x) / l), dy = c.y - a.y - l * std::round((c.y - a.y) / l);
                        return std::hypot(dx, dy);
                    };
                    const double pr = out.cells[static_cast<std::size_t>(ix + nc * iy)].pressure();
                    if (std::min(dist(ep.centre_a), dist(ep.centre_b)) < 0.25 * l) { p_in += pr; n_in += 1; }
                    else { p_out += pr; n_out += 1; }
                }
            if (n_in > 0 && n_out > 0 && p_out > 0) out.eddy_core_pressure_ratio = (p_in / n_in) / (p_out / n_out);
        }
    });

    // Merge seeds.
    auto merged = [&](std::size_t k, std::size_t w) {
        std::vector<std::uint64_t> c(static_cast<std::size_t>(nb), 0);
        for (std::size_t s = 0; s < n_seeds; ++s) {
            const auto& src = points[s * per_seed + k].counts[w];
            for (std::size_t b = 0; b < c.size(); ++b) c[b] += src[b];
        }
        return c;
    };
    auto merged_all_windows = [&](std::size_t k) {
        std::vector<std::uint64_t> c(static_cast<std::size_t>(nb), 0);
        for (std::size_t w = 0; w < nw; ++w) {
            const auto cw = merged(k, w);
            for (std::size_t b = 0; b < c.size(); ++b) c[b] += cw[b];
        }
        return c;
    };

    Result res;
    const double l = box_side(n, d, rho);
    res.scalar("box_side", l, "m", "side of the periodic square box at rho (N pi d^2 / (4 L^2) = rho)");
    res.scalar("box_side_over_d", l / d, "1", "box side in diameters");

    std::vector<double> centres(static_cast<std::size_t>(nb));
    for (int b = 0; b < nb; ++b) centres[static_cast<std::size_t>(b)] = (b + 0.5) / nb;

    // Fig. 4, inelastic: whole run and the late window (the last of window_edges).
    Table& t4 = res.table("fig4_inelastic", "P(b/d) at rho = 0.7495 per r: whole run 0 <= t < t_end and last window");
    t4.add("b_over_d", "1").values = centres;
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const std::string lb = label("r", rs[k], "%.2f");
        const auto all = merged_all_windows(k), late = merged(k, nw - 1);
        const Histogram ha = normalise(all), hl = normalise(late);
        t4.add("P_" + lb, "1").values = ha.p;
        t4.add("err_" + lb, "1").values = ha.err;
        t4.add("P_late_" + lb, "1").values = hl.p;
        t4.add("err_late_" + lb, "1").values = hl.err;
        const Ratio ra = grazing_ratio(all), rl = grazing_ratio(late);
        res.scalar("collisions_" + lb, static_cast<double>(ha.total), "1", "pair collisions 0 <= t < t_end, all seeds");
        res.scalar("collisions_late_" + lb, static_cast<double>(hl.total), "1", "pair collisions in the last window, all seeds");
        res.scalar("chi2_dof_" + lb, chi2_per_dof(all), "1", "chi^2 per dof of P(b/d) against 1, whole run");
        res.scalar("chi2_dof_late_" + lb, chi2_per_dof(late), "1", "chi^2 per dof of P(b/d) against 1, last window");
        res.scalar("grazing_ratio_" + lb, ra.value, "1", "P(b/d > 0.8) / P(b/d < 0.2), whole run");
        res.scalar("grazing_ratio_err_" + lb, ra.err, "1", "its Poisson error");
        res.scalar("grazing_z_" + lb, ra.z, "1", "(ratio - 1) / error, whole run");
        res.scalar("grazing_ratio_late_" + lb, rl.value, "1", "P(b/d > 0.8) / P(b/d < 0.2), last window");
        res.scalar("grazing_ratio_late_err_" + lb, rl.err, "1", "its Poisson error");
        res.scalar("grazing_z_late_" + lb, rl.z, "1", "(ratio - 1) / error, last window");
        // Seed-to-seed scatter of the ratio: checks the Poisson errors, which assume independent
        // collisions (correlated re-collisions would make them too small).
        if (n_seeds >= 2) {
            double s1 = 0, s2 = 0;
            for (std::size_t s = 0; s < n_seeds; ++s) {
                std::vector<std::uint64_t> c(static_cast<std::size_t>(nb), 0);
                for (const auto& cw : points[s * per_seed + k].counts)
                    for (std::size_t b = 0; b < c.size(); ++b) c[b] += cw[b];
                const double rr = grazing_ratio(c).value;
                s1 += rr;
                s2 += rr * rr;
            }
            const double ns = static_cast<double>(n_seeds), mean = s1 / ns;
            res.scalar("grazing_ratio_seed_sem_" + lb, std::sqrt(std::max(0.0, s2 / ns - mean * mean) / (ns - 1.0)), "1",
                       "standard error of the mean of the per-seed ratios (compare grazing_ratio_err)");
        }
        std::uint64_t el = 0, tot = 0;
        for (std::size_t s = 0; s < n_seeds; ++s) {
            el += points[s * per_seed + k].elastic_by_tc;
            tot += points[s * per_seed + k].pair_collisions;
        }
        res.scalar("tc_elastic_fraction_" + lb, tot ? static_cast<double>(el) / static_cast<double>(tot) : NAN, "1",
                   "fraction of collisions made elastic by the TC model (Eq. 7)");
    }
    // Time-resolved P(b/d) (as Fig. 3 does for the large system): one table per r.
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const std::string lb = label("r", rs[k], "%.2f");
        Table& tw = res.table("windows_" + lb, "P(b/d) per time window (window_edges), all seeds");
        tw.add("b_over_d", "1").values = centres;
        for (std::size_t w = 0; w < nw; ++w) {
            const Histogram h = normalise(merged(k, w));
            const std::string wl = label("t", edges[w], "%g") + label("-", edges[w + 1], "%g");
            tw.add("P_" + wl, "1").values = h.p;
            tw.add("err_" + wl, "1").values = h.err;
            res.scalar("grazing_ratio_" + lb + "_" + wl, grazing_ratio(merged(k, w)).value, "1",
                       "P(b/d > 0.8) / P(b/d < 0.2) in that window");
        }
    }

    // Fig. 4, elastic check (Sec. 3.2, "P(b/d) is not sensitive to the density").
    Table& te = res.table("fig4_elastic", "P(b/d) at r = 1 for N = 240 and several densities");
    te.add("b_over_d", "1").values = centres;
    double worst_chi2 = 0.0;
    for (std::size_t j = 0; j < rhos.size(); ++j) {
        const std::string lb = label("rho", rhos[j], "%g");
        const auto c = merged(rs.size() + j, 0);
        const Histogram h = normalise(c);
        te.add("P_" + lb, "1").values = h.p;
        te.add("err_" + lb, "1").values = h.err;
        const double chi = chi2_per_dof(c);
        worst_chi2 = std::max(worst_chi2, chi);
        res.scalar("elastic_chi2_dof_" + lb, chi, "1", "chi^2 per dof of P(b/d) against 1 at r = 1");
        const Ratio ra = grazing_ratio(c);
        res.scalar("elastic_grazing_z_" + lb, ra.z, "1", "(P(b/d > 0.8)/P(b/d < 0.2) - 1) / error at r = 1");
        res.scalar("elastic_collisions_" + lb, static_cast<double>(h.total), "1", "pair collisions counted, all seeds");
    }
    res.scalar("elastic_chi2_dof_worst", worst_chi2, "1", "largest chi^2 per dof over the elastic densities");

    // Sec. 3.2 in 3D: "P(b/d) = 2b/d in 3D" for elastic spheres (src/engines/ed3d), per packing
    // fraction; chi^2 of the bins against 2 b/d (and, to show the test's power, against 1).
    {
        const auto& etas = p.reals("elastic3d_packing");
        const long side = p.integer("elastic3d_n_side");
        const auto n3 = static_cast<std::size_t>(side * side * side);
        const auto coll3 = static_cast<std::uint64_t>(p.real("elastic3d_collisions"));
        std::vector<std::vector<std::uint64_t>> c3(etas.size(), std::vector<std::uint64_t>(static_cast<std::size_t>(nb), 0));
        parallel_sweep(static_cast<long>(etas.size()), ctx.threads, nullptr, [&](long task) {
            const auto k = static_cast<std::size_t>(task);
            const double box = std::cbrt(static_cast<double>(n3) * M_PI / 6 / etas[k]) * d;
            RngStream rng3(ctx.seed, 1000000 + k);
            std::vector<Vec3> r, v;
            Vec3 mean;
            for (long a = 0; a < side; ++a)
                for (long b = 0; b < side; ++b)
                    for (long c = 0; c < side; ++c) {
                        r.push_back({(a + 0.5) * box / side, (b + 0.5) * box / side, (c + 0.5) * box / side});
                        v.push_back({vbar * rng3.normal(), vbar * rng3.normal(), vbar * rng3.normal()});
                        mean += v.back();
                    }
            for (Vec3& x : v) x -= mean * (1.0 / static_cast<double>(n3));
            HardSphereGas3D g(r, v, d, box);
            g.run_collisions(static_cast<std::uint64_t>(eq * static_cast<double>(n3) / 2.0 + 0.5)); // as Sec. 3: ~10 per sphere at r = 1
            g.run_collisions(coll3, [&](double x) {
                c3[k][std::min(static_cast<std::size_t>(nb) - 1, static_cast<std::size_t>(x * nb))] += 1;
            });
        });
        Table& t3 = res.table("fig4_elastic_3d", "P(b/d) of elastic smooth hard spheres in 3D (periodic cube), per packing fraction, and 2 b/d");
        t3.add("b_over_d", "1").values = centres;
        std::vector<double> two_x;
        for (double x : centres) two_x.push_back(2 * x);
        t3.add("P_2bd", "1").values = two_x;
        for (std::size_t k = 0; k < etas.size(); ++k) {
            const std::string lb = label("eta", etas[k], "%g");
            const Histogram h = normalise(c3[k]);
            t3.add("P_" + lb, "1").values = h.p;
            t3.add("err_" + lb, "1").values = h.err;
            // chi^2 against a density f on [0, 1] with exact bin integrals; dof = bins - 1.
            auto chi2 = [&](auto cdf) {
                const double tot = static_cast<double>(h.total);
                double x2 = 0;
                for (int b = 0; b < nb; ++b) {
                    const double e = tot * (cdf((b + 1.0) / nb) - cdf(static_cast<double>(b) / nb));
                    const double o = static_cast<double>(c3[k][static_cast<std::size_t>(b)]);
                    x2 += (o - e) * (o - e) / e;
                }
                return x2 / (nb - 1.0);
            };
            res.scalar("elastic3d_chi2_dof_" + lb, chi2([](double x) { return x * x; }), "1",
                       "chi^2 per dof of the 3D P(b/d) against 2 b/d (molecular chaos in 3D)");
            res.scalar("elastic3d_chi2_dof_flat_" + lb, chi2([](double x) { return x; }), "1",
                       "chi^2 per dof of the 3D P(b/d) against the 2D form 1 (the test's power)");
            res.scalar("elastic3d_collisions_" + lb, static_cast<double>(h.total), "1", "collisions counted");
        }
    }

    // Fig. 5: seed 0 of each r. Columns are filled as local vectors first: Table::add and
    // Result::table grow vectors, so references into them must not be held across calls.
    std::vector<double> sig_max(rs.size()), v_rms(rs.size()), taus(rs.size());
    const double arrow_rms = p.real("arrow_rms_length");
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const PointResult& pr = points[k];
        const std::string lb = label("r", rs[k], "%.2f");
        double v2 = 0.0;
        for (const auto& v : pr.vel) v2 += norm2(v);
        v_rms[k] = std::sqrt(v2 / static_cast<double>(n));
        // Arrows: a particle moving at the panel's rms speed gets an arrow of arrow_rms_length d;
        // tau [s] turns a velocity into an arrow length (the paper's factors 1, 3, 7 play this role).
        taus[k] = v_rms[k] > 0 ? arrow_rms * d / v_rms[k] : 0.0;
        std::vector<double> cx, cy, avx, avy, vx, vy;
        for (std::size_t i = 0; i < n; ++i) {
            cx.push_back(pr.pos[i].x / d);
            cy.push_back(pr.pos[i].y / d);
            avx.push_back(pr.vel[i].x * taus[k] / d);
            avy.push_back(pr.vel[i].y * taus[k] / d);
            vx.push_back(pr.vel[i].x);
            vy.push_back(pr.vel[i].y);
        }
        {
            Table& ts = res.table("fig5_snapshot_" + lb, "particles at t = t_end with velocity arrows (seed 0)");
            ts.add("x_over_d", "1").values = cx;
            ts.add("y_over_d", "1").values = cy;
            ts.add("arrow_x_over_d", "1").values = avx;
            ts.add("arrow_y_over_d", "1").values = avy;
            ts.add("vx", "m/s").values = vx;
            ts.add("vy", "m/s").values = vy;
        }
        const double smax = pr.sigma_max;
        sig_max[k] = smax;
        // Half-length of a cross arm: |sigma| / sigma_max of the panel times 0.45 cell widths, so
        // that sigma_max has the same length in every panel (as in the paper's Fig. 5).
        const double cell = l / nc / d;
        std::vector<double> sx, sy, s1, s2, a1x, a1y, a2x, a2y, ncol, press;
        for (int iy = 0; iy < nc; ++iy)
            for (int ix = 0; ix < nc; ++ix) {
                const auto& c = pr.cells[static_cast<std::size_t>(ix + nc * iy)];
                const double h1 = smax > 0 ? 0.45 * cell * std::fabs(c.sigma_min) / smax : 0.0;
                const double h2 = smax > 0 ? 0.45 * cell * std::fabs(c.sigma_max) / smax : 0.0;
                sx.push_back((ix + 0.5) * cell);
                sy.push_back((iy + 0.5) * cell);
                s1.push_back(-c.sigma_min); // compressive principal stresses, positive
                s2.push_back(-c.sigma_max);
                a1x.push_back(h1 * c.axis_min.x());
                a1y.push_back(h1 * c.axis_min.y());
                a2x.push_back(h2 * c.axis_max.x());
                a2y.push_back(h2 * c.axis_max.y());
                ncol.push_back(static_cast<double>(c.collisions));
                press.push_back(c.pressure());
            }
        {
            Table& tst = res.table("fig5_stress_" + lb, "principal stresses of Eq. (9) per cell, stress window (seed 0)");
            tst.add("x_over_d", "1").values = sx;
            tst.add("y_over_d", "1").values = sy;
            tst.add("sigma_1", "N/m").values = s1;
            tst.add("sigma_2", "N/m").values = s2;
            tst.add("axis1_x_over_d", "1").values = a1x;
            tst.add("axis1_y_over_d", "1").values = a1y;
            tst.add("axis2_x_over_d", "1").values = a2x;
            tst.add("axis2_y_over_d", "1").values = a2y;
            tst.add("collisions", "1").values = ncol;
            tst.add("pressure", "N/m").values = press;
        }
        res.scalar("sigma_max_" + lb, smax, "N/m", "largest principal stress magnitude over the cells (Eq. 9, stress window)");
        res.scalar("v_rms_end_" + lb, v_rms[k], "m/s", "rms speed at t_end (seed 0)");
        res.scalar("arrow_tau_" + lb, taus[k], "s", "arrow length / velocity in the snapshot panel");
        res.scalar("K_end_over_K0_" + lb, 0.5 * m * v2 / pr.k0, "1",
                   "translational kinetic energy at t_end over K(0) (seed 0)");
        res.scalar("flow_fraction_end_" + lb, pr.flow_fraction, "1",
                   "K of the velocity field averaged over the stress cells, over K, at t_end (seed 0)");
        // Over all seeds: how typical the figure run is.
        double ff = 0.0, sm = 0.0;
        for (std::size_t s = 0; s < n_seeds; ++s) {
            ff += points[s * per_seed + k].flow_fraction;
            sm += points[s * per_seed + k].sigma_max;
        }
        res.scalar("flow_fraction_mean_" + lb, ff / static_cast<double>(n_seeds), "1", "flow_fraction_end averaged over seeds");
        res.scalar("sigma_max_mean_" + lb, sm / static_cast<double>(n_seeds), "N/m", "sigma_max averaged over seeds");
    }
    {
        Table& tm = res.table("fig5_meta", "per panel: r, box side, arrow scale, sigma_max, rms speed at t_end");
        tm.add("r", "1").values = rs;
        tm.add("box_over_d", "1").values = std::vector<double>(rs.size(), l / d);
        tm.add("sigma_max", "N/m").values = sig_max;
        tm.add("v_rms", "m/s").values = v_rms;
        tm.add("arrow_tau", "s").values = taus;
    }
    // Ordering of the panels' sigma_max; the paper's values are in arbitrary units, only ratios
    // are comparable: 0.894 / 0.568 = 1.57 (r = 0.8 over 0.9), 1.56 / 0.568 = 2.75 (0.95 over 0.9).
    auto find_r = [&](double r) -> long {
        for (std::size_t k = 0; k < rs.size(); ++k)
            if (std::fabs(rs[k] - r) < 1e-9) return static_cast<long>(k);
        return -1;
    };
    const long k8 = find_r(0.8), k9 = find_r(0.9), k95 = find_r(0.95);
    if (k8 >= 0 && k9 >= 0 && k95 >= 0) {
        res.scalar("sigma_max_ratio_080_over_090", sig_max[k8] / sig_max[k9], "1", "sigma_max(r=0.8)/sigma_max(r=0.9)");
        res.scalar("sigma_max_ratio_095_over_090", sig_max[k95] / sig_max[k9], "1", "sigma_max(r=0.95)/sigma_max(r=0.9)");
        res.scalar("v_rms_ratio_080_over_095", v_rms[k8] / v_rms[k95], "1", "rms speed at t_end, r=0.8 over r=0.95");
        // Seeds whose panels are ordered as the paper's (0.95 largest, then 0.8, then 0.9).
        double n_090_lowest = 0, n_095_highest = 0;
        for (std::size_t s = 0; s < n_seeds; ++s) {
            const double a = points[s * per_seed + static_cast<std::size_t>(k8)].sigma_max;
            const double b = points[s * per_seed + static_cast<std::size_t>(k9)].sigma_max;
            const double c = points[s * per_seed + static_cast<std::size_t>(k95)].sigma_max;
            n_090_lowest += (b < a && b < c);
            n_095_highest += (c > a && c > b);
        }
        res.scalar("seeds_sigma_max_090_lowest", n_090_lowest / static_cast<double>(n_seeds), "1",
                   "fraction of seeds where sigma_max(0.9) is the smallest of the three (as in the paper)");
        res.scalar("seeds_sigma_max_095_highest", n_095_highest / static_cast<double>(n_seeds), "1",
                   "fraction of seeds where sigma_max(0.95) is the largest of the three (as in the paper)");
    }

    // Fig. 5's arrows: the paper scales them by 1, 3, 7 (left to right), which, read as
    // arrow = velocity x factor drawn at a similar length, means v(0.8) > v(0.9) > v(0.95).
    if (k8 >= 0 && k9 >= 0 && k95 >= 0) {
        double ordered = 0, reversed = 0, stress_order = 0, r89 = 0, r895 = 0;
        for (std::size_t s = 0; s < n_seeds; ++s) {
            const double a = points[s * per_seed + static_cast<std::size_t>(k8)].v_rms;
            const double b = points[s * per_seed + static_cast<std::size_t>(k9)].v_rms;
            const double c = points[s * per_seed + static_cast<std::size_t>(k95)].v_rms;
            ordered += (a > b && b > c);
            reversed += (a < b && b < c);
            stress_order += (c > a && a > b);
            r89 += std::log(a / b) / static_cast<double>(n_seeds);
            r895 += std::log(a / c) / static_cast<double>(n_seeds);
        }
        res.scalar("seeds_v_rms_order_080_090_095", ordered / static_cast<double>(n_seeds), "1",
                   "fraction of seeds with v_rms(0.8) > v_rms(0.9) > v_rms(0.95) at t_end (the paper's arrow factors 1, 3, 7)");
        res.scalar("seeds_v_rms_order_reversed", reversed / static_cast<double>(n_seeds), "1",
                   "fraction of seeds with v_rms(0.8) < v_rms(0.9) < v_rms(0.95) (homogeneous cooling: v ~ 1/((1 - r^2) t))");
        res.scalar("seeds_v_rms_order_095_080_090", stress_order / static_cast<double>(n_seeds), "1",
                   "fraction of seeds with v_rms(0.95) > v_rms(0.8) > v_rms(0.9), the order of the paper's sigma_max values 1.56 > 0.894 > 0.568");
        res.scalar("v_rms_ratio_080_over_090_geomean", std::exp(r89), "1", "v_rms(0.8)/v_rms(0.9) at t_end, geometric mean over seeds (paper's factors: 3)");
        res.scalar("v_rms_ratio_080_over_095_geomean", std::exp(r895), "1", "v_rms(0.8)/v_rms(0.95) at t_end, geometric mean over seeds (paper's factors: 7)");
    }
    // Fig. 5 left: two co-rotating eddies with small stresses inside.
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const std::string lb = label("r", rs[k], "%.2f");
        const double need = p.real("eddy_significance");
        double found = 0, e_sum = 0;
        std::vector<double> ratios;
        for (std::size_t s = 0; s < n_seeds; ++s) {
            const PointResult& pr = points[s * per_seed + k];
            e_sum += pr.eddy_strength / static_cast<double>(n_seeds);
            if (pr.eddy_beats >= need) {
                found += 1;
                if (std::isfinite(pr.eddy_core_pressure_ratio)) ratios.push_back(pr.eddy_core_pressure_ratio);
            }
        }
        res.scalar("eddy_pair_fraction_" + lb, found / static_cast<double>(n_seeds), "1",
                   "fraction of seeds whose strongest co-rotating eddy pair at t_end beats at least eddy_significance of its velocity shuffles");
        res.scalar("eddy_strength_mean_" + lb, e_sum, "1", "eddy-pair strength E at t_end, mean over seeds");
        std::sort(ratios.begin(), ratios.end());
        const double med = ratios.empty() ? NAN
                         : ratios.size() % 2 ? ratios[ratios.size() / 2]
                                             : 0.5 * (ratios[ratios.size() / 2 - 1] + ratios[ratios.size() / 2]);
        res.scalar("eddy_core_pressure_ratio_median_" + lb, med, "1",
                   "mean Eq. (9) pressure (0.5-1 s) of the stress cells in the two eddy cores over that of the other cells, median over seeds with a significant pair");
        res.scalar("eddy_core_pressure_ratio_seeds_" + lb, static_cast<double>(ratios.size()), "1", "seeds entering that median");
        // The same for the strongest pair of every seed, significant or not (always defined).
        std::vector<double> all;
        for (std::size_t s = 0; s < n_seeds; ++s) all.push_back(points[s * per_seed + k].eddy_core_pressure_ratio);
        double mean = 0, m2 = 0, cnt = 0;
        for (double x : all)
            if (std::isfinite(x)) { mean += x; m2 += x * x; cnt += 1; }
        std::erase_if(all, [](double x) { return !std::isfinite(x); });
        std::sort(all.begin(), all.end());
        const double med_all = all.empty() ? NAN : all.size() % 2 ? all[all.size() / 2] : 0.5 * (all[all.size() / 2 - 1] + all[all.size() / 2]);
        res.scalar("eddy_core_pressure_ratio_median_all_" + lb, med_all, "1",
                   "the same ratio for every seed's strongest co-rotating pair, significant or not, median over seeds");
        if (cnt >= 2) {
            mean /= cnt;
            res.scalar("eddy_core_pressure_ratio_mean_all_" + lb, mean, "1", "its mean over seeds");
            res.scalar("eddy_core_pressure_ratio_sem_all_" + lb, std::sqrt(std::max(0.0, (m2 / cnt - mean * mean) * cnt / (cnt - 1)) / cnt), "1",
                       "standard error of that mean (seed scatter)");
        }
    }

    // Cooling curves of the figure runs, for reference (Eq. 18 with t0 of Eq. 19).
    std::vector<std::vector<double>> kcols;
    const double s_star = (1 - rho) * (1 - rho) / (1 - 7 * rho / 16);
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const std::string lb = label("r", rs[k], "%.2f");
        std::vector<double> kk, haff;
        const double t0h = std::sqrt(M_PI) * d * s_star / (2 * (1 - rs[k] * rs[k]) * rho * vbar);
        for (std::size_t s = 0; s < points[k].k_t.size(); ++s) {
            kk.push_back(points[k].k_val[s] / points[k].k0);
            haff.push_back(std::pow(1.0 + points[k].k_t[s] / t0h, -2.0));
        }
        kcols.push_back(kk);
        kcols.push_back(haff);
        res.scalar("haff_t0_" + lb, t0h, "s", "t0 of Eq. (19) at rho, r and vbar");
    }
    Table& tk = res.table("cooling", "K(t)/K(0) of the figure runs (seed 0) and Eq. (18) with t0 from Eq. (19)");
    tk.add("t", "s").values = points[0].k_t;
    for (std::size_t k = 0; k < rs.size(); ++k) {
        const std::string lb = label("r", rs[k], "%.2f");
        tk.add("K_over_K0_" + lb, "1").values = kcols[2 * k];
        tk.add("haff_" + lb, "1").values = kcols[2 * k + 1];
    }
    return res;
}

} // namespace

Experiment impact_parameter() { return {"impact-parameter", &validate, &run}; }

} // namespace granrepro::experiments
