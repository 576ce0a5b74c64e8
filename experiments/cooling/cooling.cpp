// cooling: Luding (1998) Section 3. N disks at rho = 0.25 are equilibrated elastically by ED
// (Sec. 3: about 10 collisions per particle); at t = 0 dissipation r = 0.8 is switched on and the
// same state is evolved by ED and by DSMC. Measured: K(t) against Eq. (18) (Fig. 2), the Sonine
// coefficient a2 of the velocity distribution, P(b/d) in time windows (Fig. 3), g(r/d) (Fig. 6)
// and S(k) (Fig. 7) at snapshot times. With seeds > 1 the whole comparison (equilibration, ED,
// DSMC) is repeated from independent initial states; the figures show the first seed, the S(k)
// claims use all of them (mean and seed scatter).
//
// t0 of Eq. (18): Eq. (19) as printed has sqrt(pi); the Enskog collision rate of hard disks,
// omega_0 = 2 n d g(d) sqrt(pi T/m) with T = m v̄^2/2 and Henderson's g(d) = 1/s_*(rho), and the
// 2D cooling law dT/dt = -(1 - r^2) omega T / 2 give t0 = 4 / ((1 - r^2) omega_0)
// = sqrt(2 pi) d s_* / (2 (1 - r^2) rho v̄), i.e. sqrt(2 pi). The paper's number 23.24 1/s is
// the sqrt(2 pi) value; Fig. 2 is normalised by it (src/theory/kinetic_theory.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "data/spec.hpp"
#include "engines/dsmc/dsmc_rules.hpp"
#include "experiments/common/columns.hpp"
#include "experiments/cooling/spec.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace {

using namespace cooling_detail;

void validate(const ParameterSet& p) {
    const auto c = read_spec<CoolingSpec>(p);
    // Collisions of the ED and DSMC runs, bounded above at the initial Enskog rate (cooling only
    // slows it); vbar = 1e308 got as far as "all velocities are equal".
    const double n = double(c.n_side) * double(c.n_side);
    if (!c.run_ed && !c.run_dsmc) p.reject(std::vector<std::string>{"run_ed", "run_dsmc"}, "at least one must be true");
    const double runs = double(c.seeds) * (double(c.run_ed) + double(c.run_dsmc));
    p.limit_work({"t_end", "n_side", "seeds", "vbar", "rho", "d", "equilibration"},
                 runs * n / 2 * (c.omega_enskog() * c.t_end + c.equilibration), kMaxCollisions, "collisions");
    const auto& w = c.bd_windows;
    for (std::size_t i = 1; i < w.size(); ++i)
        if (!(w[i] > w[i - 1])) p.reject("bd_windows", "edges must increase");
    if (w.size() < 2) p.reject("bd_windows", "needs at least two edges");
    if (c.box() / double(c.n_side) < c.d * 1.0000001)
        p.reject("rho", "too dense for a square-lattice start (lattice spacing below d)");
    // g(r) is measured up to 5 d, at most half the box (rho = 0.7 at n_side = 8 failed inside the run).
    if (c.box() < 10 * c.d) p.reject(std::vector<std::string>{"n_side", "rho"}, "the box must be at least 10 d wide for g(r) up to r = 5 d");
    // A step far below the mean free time multiplies the DSMC steps (1e-300 never ended).
    if (c.dsmc_mft_fraction > 0 && c.dsmc_mft_fraction < 1e-3)
        p.reject("dsmc_mft_fraction", "must be 0 (off) or at least 1e-3 of the mean free time");
    // The DSMC cell count as the engine's constructor computes it (same sums, same order): a
    // free-volume block wider than the cells per side was refused seconds into the run, naming
    // no parameter (dsmc_free_volume_block = 99).
    if (c.run_dsmc) {
        if (c.dsmc_free_volume_block % 2 == 0) p.reject("dsmc_free_volume_block", "must be odd (a block centred on its cell)");
        const DsmcConfig cfg = dsmc_config(c, c.box());
        const double r = 0.5 * c.d, box = cfg.lx * cfg.ly;
        double asum = 0, area = 0;
        for (double i = 0; i < n; ++i) { asum += r; area += std::numbers::pi * r * r; }
        const double chi = cfg.free_volume == DsmcFreeVolume::off
                               ? 1.0
                               : 1.0 / std::max(1.0 - area / box / cfg.rcp_fraction, cfg.free_volume_floor);
        const double lambda = dsmc_mean_free_path(n / box, 2.0 * asum / n, chi);
        const std::size_t cells = dsmc_cells_per_side(cfg.lx, lambda, cfg.min_cell_diameters * 2.0 * r);
        if (std::size_t(c.dsmc_free_volume_block) > cells)
            p.reject(std::vector<std::string>{"dsmc_free_volume_block", "n_side", "rho", "dsmc_cell_diameters"},
                     "the block is wider than the " + std::to_string(cells) + " DSMC cells per side");
    }
    const auto& a2w = c.a2_window;
    if (a2w.size() != 2 || !(a2w[1] > a2w[0]) || !(a2w[0] > 0)) p.reject("a2_window", "two increasing positive times in units of t0");
    const auto& snaps = c.snapshot_times;
    if (snaps.empty() || snaps.front() != 0.0) p.reject("snapshot_times", "must start with 0 (the equilibrated state)");
    for (std::size_t i = 1; i < snaps.size(); ++i)
        if (!(snaps[i] > snaps[i - 1])) p.reject("snapshot_times", "must increase");
}

// Figs. 2, 3, 6 and 7 as a protocol (harness/protocol.hpp): ED and DSMC (run_ed = false: DSMC
// alone, for variant studies) from every seed's initial state, one sweep point per seed and
// method: points 0 .. n_ed-1 are ED of seed i, the rest DSMC of seed i - n_ed. Index order is cost
// order, ED first (quick scale: ED 0.46, DSMC 0.12 CPU s a seed). A point's random streams are its
// seed index's, whichever thread, rank or shard computes it.
struct Cooling {
    static constexpr const char* name = outputs.experiment();
    using Spec = CoolingSpec;
    using Outcome = Trace;
    using Shared = Setups;
    static void validate(const ParameterSet& p) { granrepro::experiments::validate(p); }
    static Setups prepare(const Spec& c, const RunContext& ctx) { return Setups(c, ctx.seed); }
    static long n_ed(const Spec& c) { return c.run_ed ? c.seeds : 0; }
    static std::vector<long> points(const Spec& c, const Setups&) {
        return index_order(std::size_t(n_ed(c) + (c.run_dsmc ? c.seeds : 0)));
    }
    static Trace compute(const Spec& c, const Setups& setups, long i, const PointContext& ctx) {
        const long k = i < n_ed(c) ? i : i - n_ed(c);
        return run_method(ctx, c, setups[k], k, i < n_ed(c));
    }
    static Result report(const Spec& c, const Setups& setups, const Swept<Trace>& swept, const RunContext& ctx) {
        std::vector<Trace> eds, dss;
        for (std::size_t i = 0; i < swept.outcomes.size(); ++i)
            (long(i) < n_ed(c) ? eds : dss).push_back(with_pbd(swept.outcomes[i], c));
        Result res = c.run_ed ? report_all(c, ctx.seed, setups, eds, dss) : report_dsmc_only(c, dss);
        return res;
    }
};

} // namespace

Experiment cooling() { return protocol_experiment<Cooling>(); }

} // namespace granrepro::experiments
