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
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "analysis/eddy_pair.hpp"
#include "analysis/seed_stats.hpp"
#include "analysis/stress_shape.hpp"
#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "data/spec.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "observables/collisional_stress.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "scenarios/ed_gas.hpp"
#include "scenarios/hard_sphere_lattice.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro::experiments {

namespace {

struct ImpactSpec {
    long N = 0, seeds = 0, stress_snapshots = 0, eddy_shuffles = 0, elastic3d_n_side = 0;
    int n_bins = 0, stress_cells = 0;       // stress cells per side
    double rho = 0, d = 0, m = 0, vbar = 0; // area fraction, [m], [kg], [m/s]
    double t_c = 0, t_end = 0, stress_t_begin = 0;                            // [s]
    double mu = 0, beta0 = -1; // Coulomb friction and tangential restitution of the cooling runs (Eqs. 4-6)
    double equilibration_collisions = 0, elastic_collisions_per_particle = 0; // per particle
    double arrow_rms_length = 0;                                              // [d]
    double eddy_significance = 0, elastic3d_collisions = 0;
    std::vector<double> restitutions, elastic_densities, elastic3d_packing, window_edges; // window_edges [s]
    template <class V> void fields(V&& v) {
        v("N", N); v("seeds", seeds); v("stress_snapshots", stress_snapshots); v("eddy_shuffles", eddy_shuffles);
        v("elastic3d_n_side", elastic3d_n_side); v("n_bins", n_bins); v("stress_cells", stress_cells); v("rho", rho);
        v("d", d); v("m", m); v("vbar", vbar); v("t_c", t_c); v("mu", mu); v("beta0", beta0); v("t_end", t_end); v("stress_t_begin", stress_t_begin);
        v("equilibration_collisions", equilibration_collisions); v("arrow_rms_length", arrow_rms_length);
        v("elastic_collisions_per_particle", elastic_collisions_per_particle); v("eddy_significance", eddy_significance);
        v("elastic3d_collisions", elastic3d_collisions); v("restitutions", restitutions); v("window_edges", window_edges);
        v("elastic_densities", elastic_densities); v("elastic3d_packing", elastic3d_packing);
    }
    // Sweep points: seed s, run k (the cooling runs, then the elastic densities) is 2D point
    // s * per_seed() + k; the 3D packing fractions follow the 2D points.
    std::size_t n_r() const { return restitutions.size(); }
    std::size_t per_seed() const { return restitutions.size() + elastic_densities.size(); }
    std::size_t n_seeds() const { return static_cast<std::size_t>(seeds); }
    std::size_t n_2d() const { return per_seed() * n_seeds(); }
    std::size_t n_windows() const { return window_edges.size() - 1; }
};

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

// One sweep point; it travels as JSON. A 2D run gives b/d counts (seeds are merged by adding them)
// and measures of its end state; the figure run (seed 0 of each r) also keeps Fig. 5's panel and
// its cooling curve. A 3D point gives its counts as one window.
struct PointResult {
    std::vector<std::vector<std::uint64_t>> counts; // [window][bin]
    std::uint64_t pair_collisions = 0, elastic_by_tc = 0;
    std::vector<Vec2> pos, vel; // at t_end
    std::vector<CollisionalStress::Cell> cells; // stress window
    std::vector<double> k_t, k_val;   // K(t) [s], [J]
    double k0 = 0.0, k_end = 0.0;     // translational K at t = 0 and t_end [J]
    double sigma_max = NAN, flow_fraction = NAN, v_rms = NAN; // see sigma_max_of(), flow_fraction(); [m/s]
    double eddy_strength = NAN, eddy_beats = NAN, eddy_core_pressure_ratio = NAN; // see eddy_measures()
    double eddy_outside_anisotropy_ratio = NAN, stress_anisotropy = NAN, stress_axes_order = NAN; // see stress_shape()
    template <class V> void fields(V&& v) {
        v("counts", counts); v("pairs", pair_collisions); v("elastic_by_tc", elastic_by_tc); v("pos", pos);
        v("vel", vel); v("cells", cells); v("k_t", k_t); v("k_val", k_val); v("k0", k0); v("k_end", k_end);
        v("sigma_max", sigma_max); v("flow_fraction", flow_fraction); v("v_rms", v_rms);
        v("eddy_strength", eddy_strength); v("eddy_beats", eddy_beats); v("eddy_core_pressure_ratio", eddy_core_pressure_ratio);
        v("eddy_outside_anisotropy_ratio", eddy_outside_anisotropy_ratio); v("stress_anisotropy", stress_anisotropy);
        v("stress_axes_order", stress_axes_order);
    }
};

PointResult counts_only(const std::vector<std::uint64_t>& c) { PointResult r; r.counts = {c}; return r; }


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
    const auto s = read_spec<ImpactSpec>(p);
    const double t_end = s.t_end;
    // Pair collisions, bounded above at the initial Enskog rate (cooling only slows it):
    // t_end = 1e308 s printed nothing for minutes.
    const double nd = double(s.N), eq = s.equilibration_collisions;
    const double omega = theory::enskog_collision_rate_vbar(s.rho, s.d, s.vbar, theory::henderson_contact_value(s.rho));
    const double per_seed = double(s.restitutions.size()) * nd / 2 * (omega * t_end + eq) +
                            double(s.elastic_densities.size()) * nd / 2 * (s.elastic_collisions_per_particle + eq);
    p.limit_work({"t_end", "N", "seeds", "vbar", "rho", "d", "equilibration_collisions",
                  "elastic_collisions_per_particle", "restitutions", "elastic_densities"},
                 double(s.seeds) * per_seed, kMaxCollisions, "pair collisions");
    const auto& edges = s.window_edges;
    if (edges.size() < 2 || edges.front() != 0.0 || std::fabs(edges.back() - t_end) > 1e-12 * t_end)
        p.reject("window_edges", "must start at 0 s and end at t_end = " + number_text(t_end) + " s");
    for (std::size_t k = 1; k < edges.size(); ++k)
        if (!(edges[k] > edges[k - 1])) p.reject("window_edges", "must be strictly increasing");
    if (!(s.stress_t_begin < t_end)) p.reject("stress_t_begin", "must be below t_end = " + number_text(t_end) + " s");
    if (s.n_bins % 5 != 0) p.reject("n_bins", "must be a multiple of 5 so that bins end at b/d = 0.2 and 0.8");
    if (s.restitutions.empty()) p.reject("restitutions", "needs at least one value");
    // The periodic box must be 3 cells of one diameter wide for the minimum image, else the
    // engine refuses seconds into the run naming no parameter (N = 2). L/d depends on N and rho.
    const auto n = static_cast<std::size_t>(s.N);
    for (double rho : s.elastic_densities)
        if (EdCellGrid::cells_along(box_side(n, s.d, rho), 0.5 * s.d, EdConfig{}.cell_size_factor) < 3)
            p.reject(std::vector<std::string>{"N", "elastic_densities"},
                     "the periodic box at rho = " + number_text(rho) + " is below 3 diameters wide (N >= 36 rho / pi needed)");
    if (EdCellGrid::cells_along(box_side(n, s.d, s.rho), 0.5 * s.d, EdConfig{}.cell_size_factor) < 3)
        p.reject(std::vector<std::string>{"N", "rho"}, "the periodic box is below 3 diameters wide (N >= 36 rho / pi needed)");
    // The start lattice must fit (it throws InputError naming rho otherwise).
    staggered_lattice(n, box_side(n, s.d, s.rho), s.d);
    for (double rho : s.elastic_densities) {
        try {
            staggered_lattice(n, box_side(n, s.d, rho), s.d);
        } catch (const InputError& e) {
            p.reject("elastic_densities", std::string("at ") + number_text(rho) + ": " + e.what());
        }
    }
}

// Fig. 5's stress shape (src/analysis/stress_shape.hpp): mean cell anisotropy and the alignment
// of the principal axes over the cells.
void stress_shape(PointResult& out) {
    double sa = 0, na = 0;
    for (const auto& c : out.cells) {
        const double a = stress_anisotropy(c);
        if (std::isfinite(a)) { sa += a; na += 1; }
    }
    out.stress_anisotropy = na > 0 ? sa / na : NAN;
    out.stress_axes_order = stress_axes_alignment(out.cells);
}

// Fig. 5 left, "two co-rotating eddies with small stresses inside": the strongest co-rotating
// pair at t_end (src/analysis/eddy_pair.hpp), the share of n_sh velocity shuffles it beats, and
// the mean pressure of the stress cells in its two cores over that of the other cells.
void eddy_measures(PointResult& out, double l, int nc, long n_sh, std::uint64_t shuffle_seed) {
    const EddyPair ep = find_eddy_pair(out.pos, out.vel, l);
    const auto sh = shuffled_eddy_strengths(out.pos, out.vel, l, static_cast<int>(n_sh), shuffle_seed);
    out.eddy_strength = ep.strength;
    out.eddy_beats = static_cast<double>(std::count_if(sh.begin(), sh.end(), [&](double x) { return x < ep.strength; })) /
                     static_cast<double>(n_sh);
    // Cores: cells whose centre lies within a quarter box (the quadrant's inscribed circle) of
    // either eddy centre.
    double p_in = 0, n_in = 0, p_out = 0, n_out = 0, a_in = 0, a_out = 0;
    for (int iy = 0; iy < nc; ++iy)
        for (int ix = 0; ix < nc; ++ix) {
            const Vec2 c{(ix + 0.5) * l / nc, (iy + 0.5) * l / nc};
            auto dist = [&](Vec2 a) {
                const double dx = c.x - a.x - l * std::round((c.x - a.x) / l), dy = c.y - a.y - l * std::round((c.y - a.y) / l);
                return std::hypot(dx, dy);
            };
            const auto& cell = out.cells[static_cast<std::size_t>(ix + nc * iy)];
            const double pr = cell.pressure(), an = stress_anisotropy(cell);
            if (std::min(dist(ep.centre_a), dist(ep.centre_b)) < 0.25 * l) { p_in += pr; n_in += 1; a_in += an; }
            else { p_out += pr; n_out += 1; a_out += an; }
        }
    if (n_in > 0 && n_out > 0 && p_out > 0) out.eddy_core_pressure_ratio = (p_in / n_in) / (p_out / n_out);
    // Sec. 3.2: outside the eddies "the stress tensor typically has strongly different eigenvalues".
    if (n_in > 0 && n_out > 0 && a_in > 0) out.eddy_outside_anisotropy_ratio = (a_out / n_out) / (a_in / n_in);
}

// A cooling run from t0 = e.time() to t0 + t_end: b/d per time window, the Eq. (9) stresses of the
// stress window (kinetic term from stress_snapshots snapshots, the midpoints of equal slices) and
// the end state; the figure run also keeps its panel and K(t) at log-spaced times.
PointResult cooling_run(const ImpactSpec& s, EdEngine& e, double l, bool figure_run, std::uint64_t shuffle_seed) {
    const double t0 = e.time(), t_end = s.t_end, ts0 = s.stress_t_begin;
    const int nc = s.stress_cells;
    std::vector<double> w_edges(s.window_edges.size());
    for (std::size_t w = 0; w < w_edges.size(); ++w) w_edges[w] = t0 + s.window_edges[w];
    ImpactParameterHistogram hist(s.n_bins, w_edges);
    CollisionalStress stress(nc, nc, 0.0, 0.0, l, l, t0 + ts0, t0 + t_end, true);
    const std::uint64_t c_before = e.total_collisions(), el_before = e.elastic_collisions();
    auto observe = [&](const CollisionRecord& c) { hist.add(c); stress.add(c); };
    std::vector<double> stops, snaps;
    for (long k = 0; k < s.stress_snapshots; ++k)
        snaps.push_back(t0 + ts0 + (static_cast<double>(k) + 0.5) * (t_end - ts0) / static_cast<double>(s.stress_snapshots));
    stops = snaps;
    const int n_k = 61;
    for (int k = 0; k < n_k; ++k) stops.push_back(t0 + t_end * std::pow(10.0, -5.0 + 5.0 * k / (n_k - 1)));
    std::sort(stops.begin(), stops.end());
    PointResult out;
    out.k0 = e.kinetic_energy().kx + e.kinetic_energy().ky;
    const std::vector<double> mass(static_cast<std::size_t>(s.N), s.m);
    std::size_t next_snap = 0;
    for (double ts : stops) {
        e.run_until(ts, observe);
        if (next_snap < snaps.size() && ts == snaps[next_snap]) {
            stress.add_snapshot(e.positions(), e.velocities(), mass);
            ++next_snap;
        } else if (figure_run) {
            const auto k = e.kinetic_energy();
            out.k_t.push_back(ts - t0);
            out.k_val.push_back(k.kx + k.ky);
        }
    }
    e.run_until(t0 + t_end, observe);
    for (std::size_t w = 0; w < s.n_windows(); ++w) out.counts.push_back(hist.window(w).counts);
    out.pair_collisions = e.total_collisions() - c_before;
    out.elastic_by_tc = e.elastic_collisions() - el_before;
    out.pos = e.positions();
    out.vel = e.velocities();
    out.cells = stress.result();
    out.sigma_max = sigma_max_of(out.cells);
    out.flow_fraction = flow_fraction(out.pos, out.vel, l, nc);
    double v2 = 0.0;
    for (const auto& v : out.vel) v2 += norm2(v);
    out.v_rms = std::sqrt(v2 / static_cast<double>(s.N));
    out.k_end = 0.5 * s.m * v2;
    stress_shape(out);
    eddy_measures(out, l, nc, s.eddy_shuffles, shuffle_seed);
    if (!figure_run) { out.pos.clear(); out.vel.clear(); out.cells.clear(); }
    return out;
}

// Sec. 3.2 in 3D, "P(b/d) = 2b/d in 3D" for elastic spheres (src/engines/ed3d): n_side^3 spheres
// on a simple cubic lattice at packing fraction eta, Gaussian velocities of zero mean, about
// equilibration_collisions per sphere as in Sec. 3, then elastic3d_collisions binned by b/d.
PointResult run_3d(const ImpactSpec& s, std::uint64_t seed, std::size_t k) {
    const int nb = s.n_bins;
    RngStream rng3(seed, 1000000 + k);
    HardSphereGas3D g = simple_cubic_gas(s.elastic3d_n_side, s.elastic3d_packing[k], s.d, s.vbar, rng3);
    const auto n3 = static_cast<double>(g.positions().size());
    g.run_collisions(static_cast<std::uint64_t>(s.equilibration_collisions * n3 / 2.0 + 0.5));
    std::vector<std::uint64_t> counts(static_cast<std::size_t>(nb), 0);
    g.run_collisions(static_cast<std::uint64_t>(s.elastic3d_collisions), [&](double x) {
        counts[std::min(static_cast<std::size_t>(nb) - 1, static_cast<std::size_t>(x * nb))] += 1;
    });
    return counts_only(counts);
}

// Sweep point i: the 2D run of random stream i (see ImpactSpec::per_seed) or a 3D point.
PointResult run_point(const ImpactSpec& s, std::uint64_t seed, std::size_t i) {
    if (i >= s.n_2d()) return run_3d(s, seed, i - s.n_2d());
    const auto n = static_cast<std::size_t>(s.N);
    const std::size_t k = i % s.per_seed();
    const bool inelastic = k < s.n_r();
    const double l = box_side(n, s.d, inelastic ? s.rho : s.elastic_densities[k - s.n_r()]);
    RngStream rng(seed, i);
    // Smooth disks by default (mu = 0, beta0 = -1): Sec. 2.4 says DSMC's collision scheme "is
    // identical to the event driven procedure" with the tangential velocity unchanged, beta0 = -1.
    // mu, beta0 make the cooling runs rough (Eqs. 4-6); equilibrate() runs smooth and elastic, so
    // the disks start without spin.
    EdConfig cfg = rough_disk_box(l, inelastic ? s.restitutions[k] : 1.0, 0.0, inelastic ? s.t_c : 0.0);
    if (inelastic) { cfg.law.mu = s.mu; cfg.law.beta0 = s.beta0; }
    const std::vector<double> rad(n, 0.5 * s.d), mass(n, s.m);
    EdEngine e(cfg, staggered_lattice(n, l, s.d), maxwellian_velocities(mass, s.vbar, rng), rad, mass);
    // Sec. 3: "first allowed to evolve with r = 1 for about 10 collisions per particle"; the
    // elastic run conserves K, so vbar is still the initial mean velocity at t = 0.
    equilibrate(e, s.equilibration_collisions);
    if (inelastic) return cooling_run(s, e, l, i < s.per_seed(), mix_seed(seed, i));
    ImpactParameterHistogram hist(s.n_bins, {e.time(), std::numeric_limits<double>::max()}); // Fig. 4's elastic check
    e.run_collisions(static_cast<std::uint64_t>(s.elastic_collisions_per_particle * static_cast<double>(n) / 2.0 + 0.5),
                     [&](const CollisionRecord& c) { hist.add(c); });
    return counts_only(hist.window(0).counts);
}

// Costliest first, as measured at quick scale: the 3D points (every event moves all spheres), the
// cooling runs (mostly eddy shuffles), the elastic 2D runs; each group dilute first.
std::vector<long> cost_order(const ImpactSpec& s) {
    std::vector<long> order(s.n_2d() + s.elastic3d_packing.size());
    std::iota(order.begin(), order.end(), 0L);
    auto cost_rank = [&](long i) {
        const auto u = static_cast<std::size_t>(i), k = u % s.per_seed();
        if (u >= s.n_2d()) return std::pair{0, s.elastic3d_packing[u - s.n_2d()]};
        return k < s.n_r() ? std::pair{1, 0.0} : std::pair{2, s.elastic_densities[k - s.n_r()]};
    };
    std::stable_sort(order.begin(), order.end(), [&](long a, long b) { return cost_rank(a) < cost_rank(b); });
    return order;
}

const PointResult& at(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t seed, std::size_t k) {
    return pts[seed * s.per_seed() + k];
}

// A field of run k summed over the seeds.
template <class T>
T seed_sum(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k, T PointResult::*field) {
    T sum{};
    for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) sum += at(s, pts, seed, k).*field;
    return sum;
}

// b/d counts of run k in windows [w0, w1), added over the seeds [seed0, seed1).
std::vector<std::uint64_t> merged(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k, std::size_t w0,
                                  std::size_t w1, std::size_t seed0 = 0, std::size_t seed1 = SIZE_MAX) {
    std::vector<std::uint64_t> c(static_cast<std::size_t>(s.n_bins), 0);
    for (std::size_t seed = seed0; seed < std::min(seed1, s.n_seeds()); ++seed)
        for (std::size_t w = w0; w < w1; ++w)
            for (std::size_t b = 0; b < c.size(); ++b) c[b] += at(s, pts, seed, k).counts[w][b];
    return c;
}

// Seed-to-seed scatter of the grazing ratio of run k: checks the Poisson errors, which assume
// independent collisions (correlated re-collisions would make them too small).
double grazing_ratio_seed_sem(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k) {
    double s1 = 0, s2 = 0;
    for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) {
        const double rr = grazing_ratio(merged(s, pts, k, 0, s.n_windows(), seed, seed + 1)).value;
        s1 += rr;
        s2 += rr * rr;
    }
    const double ns = static_cast<double>(s.n_seeds()), mean = s1 / ns;
    return std::sqrt(std::max(0.0, s2 / ns - mean * mean) / (ns - 1.0));
}

// Fig. 4, inelastic: whole run and the late window (the last of window_edges).
void fig4_inelastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    Table& t4 = res.table("fig4_inelastic", "P(b/d) at rho = 0.7495 per r: whole run 0 <= t < t_end and last window");
    t4.add("b_over_d", "1").values = centres;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = label("r", s.restitutions[k], "%.2f");
        for (const bool late : {false, true}) {
            const auto c = merged(s, pts, k, late ? s.n_windows() - 1 : 0, s.n_windows());
            const Histogram h = normalise(c);
            const Ratio ra = grazing_ratio(c);
            const std::string sfx = late ? "late_" : "", when = late ? "last window" : "whole run";
            t4.add({{"P_" + sfx + lb, "1", h.p}, {"err_" + sfx + lb, "1", h.err}});
            res.scalar("collisions_" + sfx + lb, static_cast<double>(h.total), "1",
                       late ? "pair collisions in the last window, all seeds" : "pair collisions 0 <= t < t_end, all seeds");
            res.scalar("chi2_dof_" + sfx + lb, chi2_per_dof(c), "1", "chi^2 per dof of P(b/d) against 1, " + when);
            res.scalar("grazing_ratio_" + sfx + lb, ra.value, "1", "P(b/d > 0.8) / P(b/d < 0.2), " + when);
            res.scalar("grazing_ratio_" + sfx + "err_" + lb, ra.err, "1", "its Poisson error");
            res.scalar("grazing_z_" + sfx + lb, ra.z, "1", "(ratio - 1) / error, " + when);
        }
        if (s.n_seeds() >= 2)
            res.scalar("grazing_ratio_seed_sem_" + lb, grazing_ratio_seed_sem(s, pts, k), "1",
                       "standard error of the mean of the per-seed ratios (compare grazing_ratio_err)");
        const std::uint64_t el = seed_sum(s, pts, k, &PointResult::elastic_by_tc);
        const std::uint64_t tot = seed_sum(s, pts, k, &PointResult::pair_collisions);
        res.scalar("tc_elastic_fraction_" + lb, tot ? static_cast<double>(el) / static_cast<double>(tot) : NAN, "1",
                   "fraction of collisions made elastic by the TC model (Eq. 7)");
    }
}

// Time-resolved P(b/d) (as Fig. 3 does for the large system): one table per r.
void fig4_windows(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    const auto& edges = s.window_edges;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = label("r", s.restitutions[k], "%.2f");
        Table& tw = res.table("windows_" + lb, "P(b/d) per time window (window_edges), all seeds");
        tw.add("b_over_d", "1").values = centres;
        for (std::size_t w = 0; w < s.n_windows(); ++w) {
            const auto c = merged(s, pts, k, w, w + 1);
            const Histogram h = normalise(c);
            const std::string wl = label("t", edges[w], "%g") + label("-", edges[w + 1], "%g");
            tw.add({{"P_" + wl, "1", h.p}, {"err_" + wl, "1", h.err}});
            res.scalar("grazing_ratio_" + lb + "_" + wl, grazing_ratio(c).value, "1",
                       "P(b/d > 0.8) / P(b/d < 0.2) in that window");
        }
    }
}

// Fig. 4, elastic check (Sec. 3.2, "P(b/d) is not sensitive to the density").
void fig4_elastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    Table& te = res.table("fig4_elastic", "P(b/d) at r = 1 for N = 240 and several densities");
    te.add("b_over_d", "1").values = centres;
    double worst_chi2 = 0.0;
    for (std::size_t j = 0; j < s.elastic_densities.size(); ++j) {
        const std::string lb = label("rho", s.elastic_densities[j], "%g");
        const auto c = merged(s, pts, s.n_r() + j, 0, 1);
        const Histogram h = normalise(c);
        te.add({{"P_" + lb, "1", h.p}, {"err_" + lb, "1", h.err}});
        const double chi = chi2_per_dof(c);
        worst_chi2 = std::max(worst_chi2, chi);
        res.scalar("elastic_chi2_dof_" + lb, chi, "1", "chi^2 per dof of P(b/d) against 1 at r = 1");
        const Ratio ra = grazing_ratio(c);
        res.scalar("elastic_grazing_z_" + lb, ra.z, "1", "(P(b/d > 0.8)/P(b/d < 0.2) - 1) / error at r = 1");
        res.scalar("elastic_collisions_" + lb, static_cast<double>(h.total), "1", "pair collisions counted, all seeds");
    }
    res.scalar("elastic_chi2_dof_worst", worst_chi2, "1", "largest chi^2 per dof over the elastic densities");
}

// The 3D check per packing fraction: chi^2 of the bins against 2 b/d (and, to show the test's
// power, against 1).
void fig4_elastic_3d(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres) {
    const int nb = s.n_bins;
    Table& t3 = res.table("fig4_elastic_3d", "P(b/d) of elastic smooth hard spheres in 3D (periodic cube), per packing fraction, and 2 b/d");
    t3.add("b_over_d", "1").values = centres;
    std::vector<double> two_x;
    for (double x : centres) two_x.push_back(2 * x);
    t3.add("P_2bd", "1").values = two_x;
    for (std::size_t k = 0; k < s.elastic3d_packing.size(); ++k) {
        const std::string lb = label("eta", s.elastic3d_packing[k], "%g");
        const auto& c3 = pts[s.n_2d() + k].counts[0];
        const Histogram h = normalise(c3);
        t3.add({{"P_" + lb, "1", h.p}, {"err_" + lb, "1", h.err}});
        // chi^2 against a density f on [0, 1] with exact bin integrals; dof = bins - 1.
        auto chi2 = [&](auto cdf) {
            const double tot = static_cast<double>(h.total);
            double x2 = 0;
            for (int b = 0; b < nb; ++b) {
                const double e = tot * (cdf((b + 1.0) / nb) - cdf(static_cast<double>(b) / nb));
                const double o = static_cast<double>(c3[static_cast<std::size_t>(b)]);
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

// Appends a row to a table whose columns are all in place.
void add_row(Table& t, std::initializer_list<double> row) {
    auto col = t.columns.begin();
    for (double x : row) (col++)->values.push_back(x);
}

// Fig. 5 top: the particles of the figure run with arrows of length velocity x tau [d].
void fig5_snapshot(Result& res, const ImpactSpec& s, const PointResult& pr, const std::string& lb, double tau) {
    Table& t = res.table("fig5_snapshot_" + lb, "particles at t = t_end with velocity arrows (seed 0)");
    for (const char* c : {"x_over_d", "y_over_d", "arrow_x_over_d", "arrow_y_over_d"}) t.add(c, "1");
    t.add("vx", "m/s");
    t.add("vy", "m/s");
    for (std::size_t i = 0; i < pr.pos.size(); ++i) {
        const Vec2 x = pr.pos[i], v = pr.vel[i];
        add_row(t, {x.x / s.d, x.y / s.d, v.x * tau / s.d, v.y * tau / s.d, v.x, v.y});
    }
}

// Fig. 5 bottom: a cross per cell. Half-length of an arm: |sigma| / sigma_max of the panel times
// 0.45 cell widths, so that sigma_max has the same length in every panel (as in the paper).
void fig5_stress(Result& res, const ImpactSpec& s, const PointResult& pr, const std::string& lb, double l) {
    const int nc = s.stress_cells;
    const double smax = pr.sigma_max, cell = l / nc / s.d;
    Table& t = res.table("fig5_stress_" + lb, "principal stresses of Eq. (9) per cell, stress window (seed 0)");
    const char* const cols[][2] = {{"x_over_d", "1"}, {"y_over_d", "1"}, {"sigma_1", "N/m"}, {"sigma_2", "N/m"},
                                   {"axis1_x_over_d", "1"}, {"axis1_y_over_d", "1"}, {"axis2_x_over_d", "1"},
                                   {"axis2_y_over_d", "1"}, {"collisions", "1"}, {"pressure", "N/m"}};
    for (const auto& c : cols) t.add(c[0], c[1]);
    for (int iy = 0; iy < nc; ++iy)
        for (int ix = 0; ix < nc; ++ix) {
            const auto& c = pr.cells[static_cast<std::size_t>(ix + nc * iy)];
            const double h1 = smax > 0 ? 0.45 * cell * std::fabs(c.sigma_min) / smax : 0.0;
            const double h2 = smax > 0 ? 0.45 * cell * std::fabs(c.sigma_max) / smax : 0.0;
            // sigma_1, sigma_2: the compressive principal stresses, positive.
            add_row(t, {(ix + 0.5) * cell, (iy + 0.5) * cell, -c.sigma_min, -c.sigma_max, h1 * c.axis_min.x(), h1 * c.axis_min.y(),
                        h2 * c.axis_max.x(), h2 * c.axis_max.y(), static_cast<double>(c.collisions), c.pressure()});
        }
}

// One panel of Fig. 5 per r: the figure run (seed 0), and how typical it is over the seeds.
void fig5_panels(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, double l) {
    std::vector<double> sig_max, v_rms, taus;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const PointResult& pr = pts[k];
        const std::string lb = label("r", s.restitutions[k], "%.2f");
        // Arrows: a particle moving at the panel's rms speed gets an arrow of arrow_rms_length d;
        // tau [s] turns a velocity into an arrow length (the paper's factors 1, 3, 7 play this role).
        const double tau = pr.v_rms > 0 ? s.arrow_rms_length * s.d / pr.v_rms : 0.0;
        fig5_snapshot(res, s, pr, lb, tau);
        fig5_stress(res, s, pr, lb, l);
        sig_max.push_back(pr.sigma_max);
        v_rms.push_back(pr.v_rms);
        taus.push_back(tau);
        res.scalar("sigma_max_" + lb, pr.sigma_max, "N/m", "largest principal stress magnitude over the cells (Eq. 9, stress window)");
        res.scalar("v_rms_end_" + lb, pr.v_rms, "m/s", "rms speed at t_end (seed 0)");
        res.scalar("arrow_tau_" + lb, tau, "s", "arrow length / velocity in the snapshot panel");
        res.scalar("K_end_over_K0_" + lb, pr.k_end / pr.k0, "1", "translational kinetic energy at t_end over K(0) (seed 0)");
        res.scalar("flow_fraction_end_" + lb, pr.flow_fraction, "1",
                   "K of the velocity field averaged over the stress cells, over K, at t_end (seed 0)");
        const double ns = static_cast<double>(s.n_seeds());
        res.scalar("flow_fraction_mean_" + lb, seed_sum(s, pts, k, &PointResult::flow_fraction) / ns, "1", "flow_fraction_end averaged over seeds");
        res.scalar("sigma_max_mean_" + lb, seed_sum(s, pts, k, &PointResult::sigma_max) / ns, "N/m", "sigma_max averaged over seeds");
    }
    Table& tm = res.table("fig5_meta", "per panel: r, box side, arrow scale, sigma_max, rms speed at t_end");
    tm.add({{"r", "1", s.restitutions}, {"box_over_d", "1", std::vector<double>(s.n_r(), l / s.d)},
            {"sigma_max", "N/m", sig_max}, {"v_rms", "m/s", v_rms}, {"arrow_tau", "s", taus}});
}

long find_r(const std::vector<double>& rs, double r) {
    for (std::size_t k = 0; k < rs.size(); ++k)
        if (std::fabs(rs[k] - r) < 1e-9) return static_cast<long>(k);
    return -1;
}

// The ordering of Fig. 5's panels over seeds, when r = 0.8, 0.9 and 0.95 are all swept.
// sigma_max: the paper's values are in arbitrary units, only ratios are comparable: 0.894 / 0.568 =
// 1.57 (r = 0.8 over 0.9), 1.56 / 0.568 = 2.75 (0.95 over 0.9). Arrows: the paper scales them by
// 1, 3, 7 (left to right), which, read as arrow = velocity x factor drawn at a similar length,
// means v(0.8) > v(0.9) > v(0.95).
void fig5_orderings(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts) {
    const long k8 = find_r(s.restitutions, 0.8), k9 = find_r(s.restitutions, 0.9), k95 = find_r(s.restitutions, 0.95);
    if (k8 < 0 || k9 < 0 || k95 < 0) return;
    const PointResult &f8 = pts[std::size_t(k8)], &f9 = pts[std::size_t(k9)], &f95 = pts[std::size_t(k95)]; // seed 0
    res.scalar("sigma_max_ratio_080_over_090", f8.sigma_max / f9.sigma_max, "1", "sigma_max(r=0.8)/sigma_max(r=0.9)");
    res.scalar("sigma_max_ratio_095_over_090", f95.sigma_max / f9.sigma_max, "1", "sigma_max(r=0.95)/sigma_max(r=0.9)");
    res.scalar("v_rms_ratio_080_over_095", f8.v_rms / f95.v_rms, "1", "rms speed at t_end, r=0.8 over r=0.95");
    const double ns = static_cast<double>(s.n_seeds());
    double n_090_lowest = 0, n_095_highest = 0, ordered = 0, reversed = 0, stress_order = 0, r89 = 0, r895 = 0;
    for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) {
        const PointResult &p8 = at(s, pts, seed, std::size_t(k8)), &p9 = at(s, pts, seed, std::size_t(k9)),
                          &p95 = at(s, pts, seed, std::size_t(k95));
        // Seeds whose panels are ordered as the paper's (0.95 largest, then 0.8, then 0.9).
        n_090_lowest += (p9.sigma_max < p8.sigma_max && p9.sigma_max < p95.sigma_max);
        n_095_highest += (p95.sigma_max > p8.sigma_max && p95.sigma_max > p9.sigma_max);
        const double a = p8.v_rms, b = p9.v_rms, c = p95.v_rms;
        ordered += (a > b && b > c);
        reversed += (a < b && b < c);
        stress_order += (c > a && a > b);
        r89 += std::log(a / b) / ns;
        r895 += std::log(a / c) / ns;
    }
    res.scalar("seeds_sigma_max_090_lowest", n_090_lowest / ns, "1",
               "fraction of seeds where sigma_max(0.9) is the smallest of the three (as in the paper)");
    res.scalar("seeds_sigma_max_095_highest", n_095_highest / ns, "1",
               "fraction of seeds where sigma_max(0.95) is the largest of the three (as in the paper)");
    res.scalar("seeds_v_rms_order_080_090_095", ordered / ns, "1",
               "fraction of seeds with v_rms(0.8) > v_rms(0.9) > v_rms(0.95) at t_end (the paper's arrow factors 1, 3, 7)");
    res.scalar("seeds_v_rms_order_reversed", reversed / ns, "1",
               "fraction of seeds with v_rms(0.8) < v_rms(0.9) < v_rms(0.95) (homogeneous cooling: v ~ 1/((1 - r^2) t))");
    res.scalar("seeds_v_rms_order_095_080_090", stress_order / ns, "1",
               "fraction of seeds with v_rms(0.95) > v_rms(0.8) > v_rms(0.9), the order of the paper's sigma_max values 1.56 > 0.894 > 0.568");
    res.scalar("v_rms_ratio_080_over_090_geomean", std::exp(r89), "1", "v_rms(0.8)/v_rms(0.9) at t_end, geometric mean over seeds (paper's factors: 3)");
    res.scalar("v_rms_ratio_080_over_095_geomean", std::exp(r895), "1", "v_rms(0.8)/v_rms(0.95) at t_end, geometric mean over seeds (paper's factors: 7)");
}

// Fig. 5 left: two co-rotating eddies with small stresses inside.
void fig5_eddies(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts) {
    const double ns = static_cast<double>(s.n_seeds());
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = label("r", s.restitutions[k], "%.2f");
        double found = 0, e_sum = 0, mean = 0, m2 = 0, cnt = 0;
        std::vector<double> ratios, all; // significant pairs; every seed's strongest pair
        for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) {
            const PointResult& pr = at(s, pts, seed, k);
            e_sum += pr.eddy_strength / ns;
            if (pr.eddy_beats >= s.eddy_significance) {
                found += 1;
                if (std::isfinite(pr.eddy_core_pressure_ratio)) ratios.push_back(pr.eddy_core_pressure_ratio);
            }
            const double x = pr.eddy_core_pressure_ratio;
            if (std::isfinite(x)) { mean += x; m2 += x * x; cnt += 1; all.push_back(x); }
        }
        res.scalar("eddy_pair_fraction_" + lb, found / ns, "1",
                   "fraction of seeds whose strongest co-rotating eddy pair at t_end beats at least eddy_significance of its velocity shuffles");
        res.scalar("eddy_strength_mean_" + lb, e_sum, "1", "eddy-pair strength E at t_end, mean over seeds");
        res.scalar("eddy_core_pressure_ratio_median_" + lb, median(ratios), "1",
                   "mean Eq. (9) pressure (0.5-1 s) of the stress cells in the two eddy cores over that of the other cells, median over seeds with a significant pair");
        res.scalar("eddy_core_pressure_ratio_seeds_" + lb, static_cast<double>(ratios.size()), "1", "seeds entering that median");
        res.scalar("eddy_core_pressure_ratio_median_all_" + lb, median(all), "1",
                   "the same ratio for every seed's strongest co-rotating pair, significant or not, median over seeds");
        // Sec. 3.2's stress statements (Fig. 5 bottom): anisotropy outside the eddy cores over inside,
        // and whether the cells' principal axes look random (Rayleigh test at the 1 % level:
        // P(S > s) = exp(-n s^2) for n random axes, so s_1% = sqrt(ln(100) / n)).
        std::vector<double> aniso_ratio;
        double aniso = 0, order = 0, random_axes = 0, flow_thermal = 0;
        const double s_1pc = random_axes_level(static_cast<std::size_t>(s.stress_cells * s.stress_cells), 0.01);
        for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) {
            const PointResult& pr = at(s, pts, seed, k);
            if (std::isfinite(pr.eddy_outside_anisotropy_ratio)) aniso_ratio.push_back(pr.eddy_outside_anisotropy_ratio);
            aniso += pr.stress_anisotropy / ns;
            order += pr.stress_axes_order / ns;
            random_axes += (pr.stress_axes_order < s_1pc) / ns;
            flow_thermal += pr.flow_fraction / (1.0 - pr.flow_fraction) / ns;
        }
        res.scalar("eddy_outside_anisotropy_ratio_median_all_" + lb, median(aniso_ratio), "1",
                   "stress anisotropy (|s1| - |s2|)/(|s1| + |s2|) of the cells outside the strongest co-rotating pair's cores over that inside, median over seeds");
        res.scalar("stress_anisotropy_mean_" + lb, aniso, "1", "stress anisotropy (|s1| - |s2|)/(|s1| + |s2|) averaged over cells and seeds");
        res.scalar("stress_axes_order_mean_" + lb, order, "1",
                   "alignment |<exp(2 i theta)>| of the cells' major compressive axes, mean over seeds (random axes: sqrt(pi/(4 n_cells)))");
        res.scalar("stress_axes_random_fraction_" + lb, random_axes, "1",
                   "fraction of seeds whose principal axes pass as random (alignment below the Rayleigh 1 % level sqrt(ln 100 / n_cells))");
        res.scalar("flow_to_thermal_mean_" + lb, flow_thermal, "1",
                   "K of the cell-averaged flow over the rest of K (flow_fraction / (1 - flow_fraction)) at t_end, mean over seeds");
        if (cnt >= 2) {
            mean /= cnt;
            res.scalar("eddy_core_pressure_ratio_mean_all_" + lb, mean, "1", "its mean over seeds");
            res.scalar("eddy_core_pressure_ratio_sem_all_" + lb, std::sqrt(std::max(0.0, (m2 / cnt - mean * mean) * cnt / (cnt - 1)) / cnt), "1",
                       "standard error of that mean (seed scatter)");
        }
    }
}

// Cooling curves of the figure runs, for reference: Eq. (18) with t0 of Eq. (19) as printed.
void cooling_curves(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts) {
    Table& tk = res.table("cooling", "K(t)/K(0) of the figure runs (seed 0) and Eq. (18) with t0 from Eq. (19)");
    tk.add("t", "s").values = pts[0].k_t;
    for (std::size_t k = 0; k < s.n_r(); ++k) {
        const std::string lb = label("r", s.restitutions[k], "%.2f");
        const double t0h = theory::luding_eq19_t0_printed(s.restitutions[k], s.rho, s.d, s.vbar);
        std::vector<double> kk, haff;
        for (std::size_t i = 0; i < pts[k].k_t.size(); ++i) {
            kk.push_back(pts[k].k_val[i] / pts[k].k0);
            haff.push_back(std::pow(1.0 + pts[k].k_t[i] / t0h, -2.0));
        }
        tk.add({{"K_over_K0_" + lb, "1", kk}, {"haff_" + lb, "1", haff}});
        res.scalar("haff_t0_" + lb, t0h, "s", "t0 of Eq. (19) at rho, r and vbar");
    }
}

// Figs. 4 and 5 as a protocol (harness/protocol.hpp): one sweep point per 2D run (random stream
// i, see ImpactSpec::per_seed) or 3D packing.
struct ImpactParameter {
    static constexpr const char* name = "impact-parameter";
    using Spec = ImpactSpec;
    using Outcome = PointResult;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static std::vector<long> points(const Spec& s) { return cost_order(s); }
    static PointResult compute(const Spec& s, long i, const PointContext& ctx) {
        return run_point(s, ctx.seed, static_cast<std::size_t>(i));
    }
    static Result report(const Spec& s, const Swept<PointResult>& swept, const RunContext&) {
        const std::vector<PointResult>& pts = swept.outcomes;
        Result res;
        res.scalar("resumed_points", double(swept.resumed), "1", "sweep points loaded from a checkpoint");
        const double l = box_side(static_cast<std::size_t>(s.N), s.d, s.rho);
        res.scalar("box_side", l, "m", "side of the periodic square box at rho (N pi d^2 / (4 L^2) = rho)");
        res.scalar("box_side_over_d", l / s.d, "1", "box side in diameters");
        std::vector<double> centres(static_cast<std::size_t>(s.n_bins));
        for (int b = 0; b < s.n_bins; ++b) centres[static_cast<std::size_t>(b)] = (b + 0.5) / s.n_bins;
        fig4_inelastic(res, s, pts, centres);
        fig4_windows(res, s, pts, centres);
        fig4_elastic(res, s, pts, centres);
        fig4_elastic_3d(res, s, pts, centres);
        fig5_panels(res, s, pts, l);
        fig5_orderings(res, s, pts);
        fig5_eddies(res, s, pts);
        cooling_curves(res, s, pts);
        return res;
    }
};

} // namespace

Experiment impact_parameter() { return protocol_experiment<ImpactParameter>(); }

} // namespace granrepro::experiments
