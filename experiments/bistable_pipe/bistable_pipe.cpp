// bistable-pipe: Schäfer & Wolf (1995) Fig. 6. Grains fall through a vertical 2D pipe between two
// rows of fixed wall grains; the steady-state mean velocity is recorded against e_N for three
// k_N, from a slow start and from a fast start.
//
// Run control. A steady state is detected from the data (the drift of the mean velocity over a
// trailing window), never assumed, and a run stops as soon as it is confirmed. Each run has a time
// budget in units of its own contact duration t_col(k_N, e_N) (Eq. 4), so every k_N gets the same
// number of time steps; a run also stops when it falls freely (accelerating at g with no wall
// impact over a whole window: a plug that no longer touches the walls never brakes again) or
// passes v_abort. Every run ends with one of three outcomes (steady, free fall, unsettled) and its
// last speed, and the figure marks the runs that did not settle instead of omitting them.
//
// In steady states the braking balance of Eq. (9), g = ṅ Δv_y, is measured, and the paper's
// construction is repeated: the steady speed predicted by the impact curve Δv_y(v_y^i) of the
// pipe's own wall at the measured v_x^i, where it equals g/ṅ. Over windows of every run, ṅ is set
// against σ_vx and ṅ Δv_y against Δv_y (the crude estimates below Eq. 9).
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "data/spec.hpp"
#include "experiments/bistable_pipe/spec.hpp"
#include "experiments/work_limits.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace bistable_pipe_detail {

std::vector<Task> make_tasks(const BistablePipeSpec& b) {
    const auto &ks = b.kN_list, &es = b.eN_list;
    const double ws = b.time_step == "wall" ? b.wall_steps : 0.0;
    std::vector<Task> tasks;
    for (double k : ks)
        for (double e : es)
            for (bool fast : {false, true}) tasks.push_back({k, e, fast, b.length, ws, kFig6});
    // The length check: the second k_N at its largest e_N, slow start, at a second pipe length.
    const double k_check = ks.size() > 1 ? ks[1] : ks[0];
    if (b.length_check > 0) tasks.push_back({k_check, es.back(), false, b.length_check, ws, kLengthCheck});
    // Beside the resolved fast starts, the same starts at Eq. (5)'s step (the paper's), where the
    // wall rule can take over before the plug reaches v_abort; elsewhere the two runs are one.
    if (ws > 0) {
        const PipeSpec s = pipe_spec(b, 0);
        for (double k : ks)
            for (double e : es)
                if (b.wall_spacing / (ws * pipe_time_step(s, pipe_law(k, e, b.m_mean))) < b.v_abort)
                    tasks.push_back({k, e, true, b.length, 0.0, kEq5});
    }
    // Convergence: one fast start again with every step halved (Eq. 5's and the wall rule's).
    if (b.dt_check_eN > 0) tasks.push_back({k_check, b.dt_check_eN, true, b.length, 2 * ws, kDtCheck, 2.0});
    return tasks;
}

long find_task(const std::vector<Task>& tasks, int role, double k, double e, bool fast) {
    for (std::size_t i = 0; i < tasks.size(); ++i)
        if (tasks[i].role == role && tasks[i].k == k && tasks[i].e == e && tasks[i].fast == fast) return long(i);
    return -1;
}

std::string series_word(bool fast, int role) {
    static const char* const suffix[] = {"", "_length_check", "_eq5", "_dt_check"};
    return (fast ? "fast" : "slow") + std::string(suffix[role]);
}

// A family (claims may name any k_N and e_N), written here once; e_N keeps two decimals ("e0.70").
const ScalarOut out_t_col = outputs.scalar("t_col_k<n>_e<n>", "s",
    "free-wall contact duration at k_N = 2e5 N/m, e_N = 0.70 (Eq. 4)");
const ScalarOut out_grains = outputs.scalar("grains", "1", "free grains in the pipe (first run)");

// Fig. 6 as a protocol (harness/protocol.hpp): one sweep point per pipe run (Task).
struct BistablePipe {
    static constexpr const char* name = outputs.experiment();
    using Spec = BistablePipeSpec;
    using Outcome = RunResult;
    using Shared = std::vector<Task>;
    static void validate(const ParameterSet& p) {
        const auto b = read_spec<BistablePipeSpec>(p);
        for (double e : b.eN_list)
            if (!(e > 0 && e < 1)) p.reject("eN_list", "each e_N must be in (0, 1): e_N = 1 has no dashpot and Eq. (4) no solution");
        // The report finds a run by its k_N, e_N, start and role: a value listed twice would be two
        // runs with one name.
        for (const auto* list : {&b.kN_list, &b.eN_list})
            for (std::size_t i = 0; i < list->size(); ++i)
                if (std::find(list->begin(), list->begin() + long(i), (*list)[i]) != list->begin() + long(i))
                    p.reject(list == &b.kN_list ? "kN_list" : "eN_list", "values must be distinct: " + number_text((*list)[i]) + " is listed twice");
        double longest_budget = 0;
        for (double k : b.kN_list)
            for (double e : b.eN_list) {
                longest_budget = std::max(longest_budget, time_budget(b, k, e));
                if (time_budget(b, k, e) < b.window + b.t_average)
                    p.reject(std::vector<std::string>{"budget_tcol", "budget_min", "m_mean", "kN_list", "eN_list", "window", "t_average"},
                             "the budget of k_N = " + number_text(k) + " N/m, e_N = " + number_text(e) +
                                                " is shorter than window + t_average: no steady state could be detected");
            }
        // The start: phi of the channel as grains on a lattice (phi = 0.79 failed late with "area
        // fraction too high for a lattice start"), then every run's cost in grain-steps.
        const PipeSpec s = pipe_spec(b, 0);
        const std::vector<std::string> geometry{"phi", "width", "length", "wall_spacing", "d_mean", "polydispersity", "d_wall"};
        const long n = pipe_grain_count(s);
        p.limit_work(geometry, double(n), 1e7, "grains");
        if (n < 1) p.reject(geometry, "the channel holds no grain at this area fraction");
        if (!pipe_lattice_fits(s))
            p.reject(geometry, "the " + std::to_string(n) +
                                   " grains do not fit on a triangular lattice of spacing >= d_mean (1 + polydispersity) "
                                   "between the wall crests; lower phi");
        for (double k : b.kN_list)
            for (double e : b.eN_list) {
                const double dt = pipe_time_step(s, pipe_law(k, e, s.m_mean)); // build_pipe's step
                p.limit_work({"budget_tcol", "budget_min", "steps_per_contact", "time_step", "wall_steps", "v_abort", "dt_check_eN",
                              "kN_list", "eN_list", "phi", "width", "length", "d_mean"},
                             double(n) * time_budget(b, k, e) / smallest_time_step(b, dt) * (b.dt_check_eN > 0 ? 2 : 1),
                             kMaxGrainSteps, "grain-steps in one run");
                // One sample per step at most: sample_dt = 1e-300 overflowed window/sample_dt and
                // crashed the drift fit.
                if (!(b.sample_dt >= dt))
                    p.reject(std::vector<std::string>{"sample_dt", "m_mean", "kN_list", "eN_list", "steps_per_contact"},
                             "sample_dt must be at least the time step dt = " + number_text(dt) + " s (k_N = " +
                                 number_text(k) + " N/m, e_N = " + number_text(e) + "): one sample per step");
            }
        if (b.dt_check_eN > 0 && std::find(b.eN_list.begin(), b.eN_list.end(), b.dt_check_eN) == b.eN_list.end())
            p.reject(std::vector<std::string>{"dt_check_eN", "eN_list"},
                     "dt_check_eN must be 0 (off) or one of eN_list: its run is compared with that Fig. 6 run");
        if (b.wall_spacing - b.d_wall >= b.d_mean * (1 - b.polydispersity))
            p.reject(std::vector<std::string>{"wall_spacing", "d_wall", "d_mean", "polydispersity"},
                     "the gaps between wall grains (wall_spacing - d_wall) must be narrower than the smallest grain, "
                     "or grains fall through the wall");
        if (b.sample_dt > b.window / 3) p.reject("sample_dt", "must be at most window / 3 so that a drift can be fitted");
        if (b.eq9_window < b.sample_dt) p.reject("eq9_window", "must be at least sample_dt");
        // Windows become sample counts (size_t(eq9_window / sample_dt)): bounded by the budget's
        // samples, they cannot overflow (eq9_window = 1e308 hung).
        if (!(b.eq9_window <= longest_budget))
            p.reject(std::vector<std::string>{"eq9_window", "budget_tcol"},
                     "eq9_window must be at most the longest run's time budget, " + number_text(longest_budget) + " s");
        // The check pipe's grains, like the main pipe's (length_check = 1e308 aborted in GSL).
        // Estimated in double: pipe_grain_count's lround has no defined result beyond a long.
        if (b.length_check > 0)
            p.limit_work({"length_check", "phi", "width", "d_mean"}, double(n) * b.length_check / s.geo.length, 1e7, "grains");
        const double range = b.d_mean * (1 + b.polydispersity) + b.skin;
        if (b.length < 4 * range)
            p.reject(std::vector<std::string>{"length", "d_mean", "polydispersity", "skin"},
                     "length must be at least 4 interaction ranges d_mean (1 + polydispersity) + skin");
        if (b.length_check > 0 && b.length_check < 4 * range)
            p.reject("length_check", "must be 0 (off) or at least 4 interaction ranges");
        if (b.wall_spacing < b.d_wall * (1 - 1e-12)) p.reject("wall_spacing", "wall grains would overlap; must be at least d_wall");
        if (b.width < 10 * b.d_mean) p.reject("width", "must be at least 10 grain diameters");
    }
    static std::vector<Task> prepare(const Spec& b, const RunContext&) { return make_tasks(b); }
    // Every budget is the same number of time steps, but runs that settle stop early: start the
    // likely long ones first (fast starts, then nearly elastic grains, then longer pipes), so that
    // the last point to start is a short one.
    static std::vector<long> points(const Spec&, const std::vector<Task>& tasks) {
        std::vector<long> order = index_order(tasks.size());
        auto key = [&](long i) {
            const Task& t = tasks[std::size_t(i)];
            return std::make_tuple(t.fast, t.length, t.e, t.k, t.role);
        };
        std::stable_sort(order.begin(), order.end(), [&](long x, long y) { return key(x) > key(y); });
        return order;
    }
    static RunResult compute(const Spec& b, const std::vector<Task>& tasks, long i, const PointContext& ctx) {
        const Task& t = tasks[std::size_t(i)];
        PipeSpec s = pipe_spec(b, ctx.seed);
        s.k_N = t.k;
        s.e_N = t.e;
        s.geo.length = std::round(t.length / s.geo.wall_spacing) * s.geo.wall_spacing;
        s.v0 = t.fast ? b.fast_v0 : b.slow_v0;
        s.agitation = std::min(b.agitation, b.agitation_vcrit * v_crit(b, t.k));
        s.wall_steps = t.wall_steps;
        s.steps_per_contact *= t.refine;
        // Each point's random stream is its grid index; a comparison run (Eq. 5, half the step)
        // takes the stream of the Fig. 6 run it repeats, so that the two start alike.
        const long same = find_task(tasks, kFig6, t.k, t.e, t.fast);
        s.stream = std::uint64_t(t.role >= kEq5 && same >= 0 ? same : i);
        RunResult rr = run_pipe(s, time_budget(b, t.k, t.e), b.eq9_window, b.hold_distance);
        rr.k_N = t.k, rr.e_N = t.e, rr.fast = t.fast, rr.role = t.role;
        // The paper's construction (text below Eq. 9) for Fig. 6's states, on the wall of the base
        // pipe (the run's seed, not its length or step).
        if (t.role == kFig6) rr.construction = construct(pipe_spec(b, ctx.seed), t.k, t.e, rr);
        return rr;
    }
    static Result report(const Spec& b, const std::vector<Task>&, const Swept<RunResult>& swept, const RunContext& ctx) {
        const std::vector<RunResult>& results = swept.outcomes;
        Result r;
        // The paper's t_col at k_N = 200000 N/m refers to e_N = 0.70 (gamma scaled with sqrt(k_N)).
        r.put(out_t_col, pipe_law(200000.0, 0.70, b.m_mean).collision_time(b.m_mean), {200000.0, "0.70"});
        report_fig6(r, b, pipe_spec(b, ctx.seed), results);
        report_eq9_windows(r, results);
        report_series(r, results);
        r.put(out_grains, double(results.front().grains));
        return r;
    }
};

} // namespace bistable_pipe_detail

Experiment bistable_pipe() { return protocol_experiment<bistable_pipe_detail::BistablePipe>(); }

} // namespace granrepro::experiments
