// cluster-growth: Luding (1998) Sections 4.2 and 4.3, Figs. 10-12. N = 79524 disks in a periodic
// box of side L = 500 d (rho = 0.25) are equilibrated elastically; at t = 0 the TCED model
// (Eq. 7) with r = 0.8 and t_c = 1e-5 s takes over and the gas cools, clusters and the clusters
// grow. Measured: K(t), C/N(t) and the TC-elastic collisions per particle (Fig. 10); at
// t = t_base 2^k the per-particle collision frequency N_c over the last Δt = t/2 (Figs. 11, 12),
// its distribution P(N_c) and the fits of Eqs. (20)-(22).
//
// C/N = sum of per-particle collision counts / N = 2 (pair collisions) / N. Why this reading:
// Eq. (18) with the Enskog rate omega0 (experiments/cooling/) gives
// C/N = omega0 t0 ln(1 + t/t0) = 4/(1-r^2) ln(1 + t/t0) = 7.3 at t = 0.04 s, the paper's
// "C/N = 8, i.e. t = 0.04 s"; counting a pair collision once would give 3.7.
//
// TC-elastic share, three ways (Sec. 4.2 speaks of "the fraction of particles that have collisions
// with a collision frequency larger than 1/t_c"): (1) the engine's share of pair collisions made
// elastic by Eq. (7) under the pair rule in force ("either" or "both" partners); (2) per particle,
// Eq. (7) literally: the share of particle-collisions (each pair collision counts for both
// partners) that came within t_c of that particle's previous one; (3) the fraction of particles
// whose latest collision came within t_c of the one before (current collision frequency > 1/t_c).
// With tc_compare_until > 0 the other pair rule runs beside the main one from the same state.
//
// Why t = t_base 2^k: the paper's instants 0.04, 0.64 and 10.24 s are 0.01 s times powers of two,
// and with Δt = t/2 the window of one instant starts exactly at the previous instant, so storing
// the per-particle counts at every instant gives N_c = (count(t) - count(t/2)) / (t/2) with no
// per-collision bookkeeping (1e8 collisions at paper scale).
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "data/spec.hpp"
#include "experiments/cluster_growth/spec.hpp"
#include "experiments/work_limits.hpp"
#include "harness/progress.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace cluster_growth_detail {

// Figs. 10-12 as a protocol (harness/protocol.hpp). The main run (pair rule tc_both) to cn_end
// and, with tc_compare_until > 0, the other pair rule beside it up to that time, both from one
// equilibrated state: the sweep's points 0 and 1, the main run first (the longer one: 1.8 against
// 0.44 CPU s at quick scale).
struct ClusterGrowth {
    static constexpr const char* name = outputs.experiment();
    using Spec = ClusterSpec;
    using Outcome = RunOutcome;
    // The state both runs start from, made once, by the first point that needs it (not at all
    // where every point is resumed or gathered), and the main run's progress line.
    struct Shared {
        struct State {
            std::once_flag made;
            EquilibratedGas gas;
            std::optional<Progress> progress;
        };
        std::unique_ptr<State> state = std::make_unique<State>();
        const EquilibratedGas& gas(const ClusterSpec& s, std::uint64_t seed) const {
            std::call_once(state->made, [&] { state->gas = initial_gas(s, seed); });
            return state->gas;
        }
    };
    static void validate(const ParameterSet& p) {
        const auto s = read_spec<ClusterSpec>(p);
        validate_lattice_box(p, s.box_over_d, s.n_side);
        if (s.t_max <= s.t_base) p.reject("t_max", "must exceed t_base");
        if (s.paper_cn.empty()) p.reject("paper_cn", "needs at least one value");
        // The main run to C/N = cn_end (or t_max), the other pair rule beside it, the
        // equilibration: bounded by 2 (cn_end + equilibration) collisions per particle.
        const double n = double(s.n_side) * double(s.n_side);
        p.limit_work({"cn_end", "n_side", "equilibration"}, 2 * n / 2 * (s.cn_end + s.equilibration), kMaxCollisions, "collisions");
        // Samples at t_base 2^(j/m) up to t_max, each holding the N positions.
        const double samples = std::log2(s.t_max / s.t_base) * double(s.samples_per_octave);
        p.limit_work({"t_max", "t_base", "samples_per_octave"}, samples, 1e5, "samples");
    }
    static Shared prepare(const Spec& s, const RunContext& ctx) {
        Shared sh;
        sh.state->progress.emplace("cluster-growth", long(std::ceil(std::log2(s.t_max / s.t_base))) + 4, ctx.quiet);
        return sh;
    }
    static std::vector<long> points(const Spec& s, const Shared&) {
        return s.tc_compare_until > 0 ? std::vector<long>{0, 1} : std::vector<long>{0};
    }
    static RunOutcome compute(const Spec& s, const Shared& sh, long k, const PointContext& ctx) {
        const EquilibratedGas& gas = sh.gas(s, ctx.seed);
        if (k == 0) return trimmed(run_tced(ctx, s, gas, s.tc_both, s.cn_end, s.t_max, "ed", &*sh.state->progress), s, true);
        return trimmed(run_tced(ctx, s, gas, !s.tc_both, INFINITY, s.tc_compare_until, "ed_other_rule", nullptr), s, false);
    }
    static Result report(const Spec& s, const Shared&, const Swept<RunOutcome>& swept, const RunContext&) {
        std::vector<RunOutcome> runs = swept.outcomes;
        const RunOutcome& main_run = runs.front();
        const RunOutcome* other_run = runs.size() > 1 ? &runs[1] : nullptr;
        std::vector<Instant> instants;
        for (InstantRecord& rec : runs.front().st.instants) instants.push_back(make_instant(std::move(rec), s));

        Result res;
        const KineticTheory kin = kinetic_theory(s);
        report_run(res, s, kin, main_run, other_run);
        fig10(res, s, kin.t0, main_run.st, other_run ? &other_run->st : nullptr);
        fig12_instants_table(res, instants);
        report_poisson_falling(res, instants, s.poisson_until_cn);
        fig12_panels(res, instants, s.paper_cn);
        report_at_paper_cn(res, instants, s.paper_cn);
        report_clustered_B(res, instants);
        report_powerlaw_onset(res, instants);
        fig11(res, instants, s);
        return res;
    }
};

} // namespace cluster_growth_detail

Experiment cluster_growth() { return protocol_experiment<cluster_growth_detail::ClusterGrowth>(); }

} // namespace granrepro::experiments
