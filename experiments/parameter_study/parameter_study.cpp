// parameter-study: Luding (1998) Section 4.1, Figs. 8 and 9. N = 784 disks on a square lattice
// in a periodic box of side L = 50 d are equilibrated elastically (about 10 collisions per
// particle); at t = 0 the restitution is switched to r and the TCED model (Eq. 7) with threshold
// t_c takes over. Each parameter set runs until C/N, the mean number of collisions per particle,
// reaches 1000. Measured: K(t), (K_x - K_y)/K, C/N and the TC-elastic collisions against t.
//
// C/N counts a pair collision for both partners: C/N = 2 (pair collisions) / N. The cluster-growth
// run checks this reading against the paper's t = 0.64 s at C/N = 39 (experiments/cluster_growth/).
//
// Why K ∝ exp(-c C/N) (text above Fig. 8): with Eq. (18), K = K0/(1 + t/t0)^2, and a collision
// rate per particle proportional to the mean speed, omega(t) = omega0 sqrt(K/K0) = omega0/(1+t/t0),
// C/N = omega0 t0 ln(1 + t/t0), so K/K0 = exp(-2 (C/N)/(omega0 t0)). Kinetic theory gives
// t0 = 4/((1 - r^2) omega0) (experiments/cooling/), hence c = (1 - r^2)/2 per collision per
// particle, independent of density and of v̄: each collision removes (1 - r^2)/2 of the mean
// normal-relative energy share. The paper writes exp(-C/N), i.e. up to this constant.
#include <chrono>
#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "data/spec.hpp"
#include "experiments/parameter_study/spec.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace {

using namespace parameter_study_detail;

// The points of the sweep; every point runs with `seeds` initial states.
Sweep make_sweep(const ParameterStudySpec& s) {
    Sweep sw;
    auto find_or_add = [&](Point q) {
        for (std::size_t k = 0; k < sw.points.size(); ++k)
            if (sw.points[k].r == q.r && sw.points[k].t_c == q.t_c) return k;
        sw.points.push_back(q);
        return sw.points.size() - 1;
    };
    for (double r : s.fig8_r) sw.fig8_idx.push_back(find_or_add({r, s.fig8_t_c}));
    for (double tc : s.fig9_t_c) sw.fig9_idx.push_back(find_or_add({s.fig9_r, tc}));
    sw.start = std::chrono::steady_clock::now();
    return sw;
}

// Figs. 8 and 9 as a protocol (harness/protocol.hpp): sweep point i is (point i / seeds, seed
// i % seeds) with random stream i.
struct ParameterStudy {
    static constexpr const char* name = outputs.experiment();
    using Spec = ParameterStudySpec;
    using Outcome = Trace;
    using Shared = Sweep;
    static void validate(const ParameterSet& p) {
        const auto s = read_spec<ParameterStudySpec>(p);
        validate_lattice_box(p, s.box_over_d, s.n_side);
        // Every run goes to C/N = cn_end: cn_end = 1e308 ended in "cannot create std::vector larger
        // than max_size()".
        const double n = double(s.n_side) * double(s.n_side);
        const double runs = double(s.seeds) * double(s.fig8_r.size() + s.fig9_t_c.size());
        p.limit_work({"cn_end", "n_side", "seeds", "equilibration", "fig8_r", "fig9_t_c"},
                     runs * n / 2 * (s.cn_end + s.equilibration), kMaxCollisions, "collisions");
        for (const auto& [name, v] : {std::pair{"zeta_fit_early", &s.zeta_fit_early}, std::pair{"zeta_fit_late", &s.zeta_fit_late}})
            if (v->size() != 2 || !((*v)[1] > (*v)[0])) p.reject(name, "must be [lo, hi] with hi > lo");
        if (s.fig8_r.empty()) p.reject("fig8_r", "needs at least one value");
        if (s.fig9_t_c.empty()) p.reject("fig9_t_c", "needs at least one value");
    }
    static Sweep prepare(const Spec& s, const RunContext&) { return make_sweep(s); }
    static std::vector<long> points(const Spec& s, const Sweep& sw) {
        return index_order(sw.points.size() * std::size_t(s.seeds));
    }
    static Trace compute(const Spec& s, const Sweep& sw, long i, const PointContext& ctx) {
        return run_point(s, sw.points[std::size_t(i / s.seeds)], ctx.seed, std::uint64_t(i));
    }
    static Result report(const Spec& s, const Sweep& shared, const Swept<Trace>& swept, const RunContext&) {
        Sweep sw = shared;
        sw.traces.assign(sw.points.size(), std::vector<Trace>(std::size_t(s.seeds)));
        for (std::size_t i = 0; i < swept.outcomes.size(); ++i)
            sw.traces[i / std::size_t(s.seeds)][i % std::size_t(s.seeds)] = swept.outcomes[i];
        sw.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - sw.start).count();
        Result res;
        report_totals(res, s, sw);
        const std::vector<double> cn_grid = log_space(0.1, s.cn_end, int(std::round(40 * std::log10(s.cn_end / 0.1))) + 1);
        report_points(res, sw, cn_grid);
        report_fig8(res, s, sw);
        report_fig9(res, s, sw, cn_grid);
        report_cn_jumps(res, s, sw);
        return res;
    }
};

} // namespace

Experiment parameter_study() { return protocol_experiment<ParameterStudy>(); }

} // namespace granrepro::experiments
