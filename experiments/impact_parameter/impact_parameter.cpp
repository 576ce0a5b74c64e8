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
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "data/spec.hpp"
#include "engines/ed/ed_engine.hpp"
#include "experiments/impact_parameter/spec.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro::experiments {

namespace {

using namespace impact_parameter_detail;

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

// Costliest first, as measured at quick scale: the 3D points (every event moves all spheres), the
// cooling runs (mostly eddy shuffles), the elastic 2D runs; each group dilute first.
std::vector<long> cost_order(const ImpactSpec& s) {
    std::vector<long> order = index_order(s.n_2d() + s.elastic3d_packing.size());
    auto cost_rank = [&](long i) {
        const auto u = static_cast<std::size_t>(i), k = u % s.per_seed();
        if (u >= s.n_2d()) return std::pair{0, s.elastic3d_packing[u - s.n_2d()]};
        return k < s.n_r() ? std::pair{1, 0.0} : std::pair{2, s.elastic_densities[k - s.n_r()]};
    };
    std::stable_sort(order.begin(), order.end(), [&](long a, long b) { return cost_rank(a) < cost_rank(b); });
    return order;
}

const ScalarOut out_box_side = outputs.scalar("box_side", "m",
    "side of the periodic square box at rho (N pi d^2 / (4 L^2) = rho)");
const ScalarOut out_box_side_over_d = outputs.scalar("box_side_over_d", "1", "box side in diameters");

// Figs. 4 and 5 as a protocol (harness/protocol.hpp): one sweep point per 2D run (random stream
// i, see ImpactSpec::per_seed) or 3D packing.
struct ImpactParameter {
    static constexpr const char* name = outputs.experiment();
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
        const double l = box_side(static_cast<std::size_t>(s.N), s.d, s.rho);
        res.put(out_box_side, l);
        res.put(out_box_side_over_d, l / s.d);
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
