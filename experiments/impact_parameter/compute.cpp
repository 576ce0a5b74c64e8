// impact-parameter: one sweep point, a 2D cooling or elastic run by ED or a 3D elastic run, and
// the measures of its end state.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/eddy_pair.hpp"
#include "analysis/stress_shape.hpp"
#include "core/input_error.hpp"
#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/impact_parameter/spec.hpp"
#include "harness/sampled_run.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "scenarios/ed_gas.hpp"
#include "scenarios/hard_sphere_lattice.hpp"

namespace granrepro::experiments::impact_parameter_detail {

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

namespace {

PointResult counts_only(const std::vector<std::uint64_t>& c) { PointResult r; r.counts = {c}; return r; }

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
    stops.push_back(t0 + t_end); // the end, not sampled
    std::size_t next_snap = 0;
    auto stop_at = [&](long i) { return std::size_t(i) < stops.size() ? std::optional(stops[std::size_t(i)]) : std::nullopt; };
    SampledRun<>().run(e, stop_at, observe, [&](long i, double ts) {
        if (std::size_t(i) + 1 == stops.size()) return true;
        if (next_snap < snaps.size() && ts == snaps[next_snap]) {
            stress.add_snapshot(e.positions(), e.velocities(), mass);
            ++next_snap;
        } else if (figure_run) {
            const auto k = e.kinetic_energy();
            out.k_t.push_back(ts - t0);
            out.k_val.push_back(k.kx + k.ky);
        }
        return false;
    }, t0 + t_end);
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

} // namespace

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

} // namespace granrepro::experiments::impact_parameter_detail
