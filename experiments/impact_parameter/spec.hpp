// impact-parameter (Figs. 4 and 5): the spec, one sweep point's outcome, and what the files share.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "core/vec2.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"
#include "observables/collisional_stress.hpp"

// Not granrepro::experiments::impact_parameter: that name is the experiment's function (registry.cpp).
namespace granrepro::experiments::impact_parameter_detail {

// The catalog every output handle of impact-parameter registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"impact-parameter"};

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
    GRANREPRO_FIELDS(N, seeds, stress_snapshots, eddy_shuffles, elastic3d_n_side, n_bins, stress_cells, rho, d, m,
                     vbar, t_c, mu, beta0, t_end, stress_t_begin, equilibration_collisions, arrow_rms_length,
                     elastic_collisions_per_particle, eddy_significance, elastic3d_collisions, restitutions,
                     window_edges, elastic_densities, elastic3d_packing)
    // Sweep points: seed s, run k (the cooling runs, then the elastic densities) is 2D point
    // s * per_seed() + k; the 3D packing fractions follow the 2D points.
    std::size_t n_r() const { return restitutions.size(); }
    std::size_t per_seed() const { return restitutions.size() + elastic_densities.size(); }
    std::size_t n_seeds() const { return static_cast<std::size_t>(seeds); }
    std::size_t n_2d() const { return per_seed() * n_seeds(); }
    std::size_t n_windows() const { return window_edges.size() - 1; }
};

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

// compute.cpp: the box, the start lattice (validate checks that it fits) and one sweep point.
double box_side(std::size_t n, double d, double rho);
std::vector<Vec2> staggered_lattice(std::size_t n, double l, double d);
PointResult run_point(const ImpactSpec& s, std::uint64_t seed, std::size_t i);

// What the report files share.
inline std::string label(const char* prefix, double x, const char* fmt) {
    char buf[48];
    std::snprintf(buf, sizeof buf, fmt, x);
    return std::string(prefix) + buf;
}

// The label of cooling run k: r and its restitution.
inline std::string r_label(const ImpactSpec& s, std::size_t k) { return label("r", s.restitutions[k], "%.2f"); }
// Its number as the outputs' names write it ("0.80", not number_text's "0.8"): the part for <n>
// in "..._r<n>".
inline std::string r_text(const ImpactSpec& s, std::size_t k) { return label("", s.restitutions[k], "%.2f"); }

// The outcome of run k of seed `seed`.
inline const PointResult& at(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t seed, std::size_t k) {
    return pts[seed * s.per_seed() + k];
}

// A field of run k summed over the seeds.
template <class T>
T seed_sum(const ImpactSpec& s, const std::vector<PointResult>& pts, std::size_t k, T PointResult::*field) {
    T sum{};
    for (std::size_t seed = 0; seed < s.n_seeds(); ++seed) sum += at(s, pts, seed, k).*field;
    return sum;
}

// report_fig4.cpp: P(b/d), per bin of b/d centres.
void fig4_inelastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres);
void fig4_windows(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres);
void fig4_elastic(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres);
void fig4_elastic_3d(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, const std::vector<double>& centres);

// report_fig5.cpp: the panels (box side l [m]), their ordering over r, the eddies, the cooling curves.
void fig5_panels(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts, double l);
void fig5_orderings(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts);
void fig5_eddies(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts);
void cooling_curves(Result& res, const ImpactSpec& s, const std::vector<PointResult>& pts);

} // namespace granrepro::experiments::impact_parameter_detail
