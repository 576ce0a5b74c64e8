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
//   crack = a gap from wall to wall through which a probe disk crack_opening wide passes, with
//           crack_min_particles disks below and crack_min_above above (any shape: horizontal,
//           V-shaped, ragged; src/analysis/crack_detector.hpp);
//   first hot wall disk of the arch = earliest frame within precursor_window before the arch with
//           a hot disk at a wall that started (t = 0) within precursor_band of the arch's height.
// P(N_c) over dist_dt (Fig. 14) is fitted with Eqs. (21) and (22) by binned maximum likelihood.
// One run's timing is random, so n_seeds runs are made (index k uses RngStream(seed, k)); run 0
// makes the figures, all runs make the distribution of the first-arch time.
//
// Momentum balance of the falling column (exact for hard disks: pair impulses cancel):
//   P_y(t) - P_y(0) = -M g t + J_y,  J_y = sum of the side walls' impulses (friction) since t = 0.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "data/spec.hpp"
#include "experiments/pipe_arching/spec.hpp"
#include "harness/protocol.hpp"

namespace granrepro::experiments {

namespace {

using namespace pipe_arching_detail;

const ScalarOut out_n_seeds = outputs.scalar("n_seeds", "1", "independent runs");
const ScalarOut out_layers = outputs.scalar("layers", "1", "rows of the initial lattice");

// Run 0's tables arrive named through the sweep point (spec.hpp: out_relaxation ... out_pnc); each
// is written through the handle that makes its name, which refuses any other.
void put_figure_table(Result& res, const FigureTable& f) {
    for (const TableOut* h : {&out_relaxation, &out_marks, &out_timeline, &out_snapshot, &out_crack, &out_pnc}) {
        if (!makes_name(h->pattern, h->words, f.name)) continue;
        Table& t = res.table_named(*h, f.name);
        for (std::size_t c = 0; c < f.columns.size(); ++c) t.add(f.columns[c], f.units[c]).values = f.values[c];
        return;
    }
    throw std::logic_error("pipe-arching: run 0's table " + f.name + " is made by no handle");
}

// Sec. 5 and Figs. 13-14 as a protocol (harness/protocol.hpp): one sweep point per seed run.
struct PipeArching {
    static constexpr const char* name = outputs.experiment();
    using Spec = PipeArchingSpec;
    using Outcome = SeedRun;
    using Shared = Pipe;
    static void validate(const ParameterSet& p) {
        const auto s = read_spec<PipeArchingSpec>(p);
        const double fdt = s.frame_dt;
        // N_c frames of every run (each holds per-particle counts); t_end = 1e308 would never end.
        p.limit_work({"t_end", "t_relax", "frame_dt"}, (s.t_relax + s.t_end) / fdt, 1e7, "frames");
        auto on_grid = [&](const char* name, const std::vector<double>& times, double window) {
            for (double t : times) {
                if (t > s.t_end) p.reject(name, "every time must be <= t_end");
                if (t < window)
                    p.reject(std::vector<std::string>{name, window == fdt ? "frame_dt" : "dist_dt"},
                             std::string(name) + ": every time must be >= its N_c window");
                if (std::abs(t / fdt - double(frame_of(t, fdt))) > 1e-6) p.reject(name, "times must be multiples of frame_dt");
            }
        };
        on_grid("snapshot_times", s.snapshot_times, fdt);
        on_grid("dist_times_before", s.dist_times_before, s.dist_dt);
        on_grid("dist_times_after", s.dist_times_after, s.dist_dt);
        // A frame of both lists is recorded once (compute.cpp) and its table pnc_<time> would be
        // one name: the Fig. 14 (b) times would shift against their list, or the run fail at its end.
        for (double b : s.dist_times_before)
            for (double a : s.dist_times_after)
                if (frame_of(a, fdt) == frame_of(b, fdt) || tlabel(a) == tlabel(b))
                    p.reject(std::vector<std::string>{"dist_times_before", "dist_times_after"},
                             "dist_times_before " + number_text(b) + " s and dist_times_after " + number_text(a) +
                                 " s are one frame or one name (" + tlabel(a) + "); the two lists must not share a time");
        if (s.dist_dt < fdt) p.reject("dist_dt", "must be >= frame_dt");
        // Each window becomes a frame count (long(ceil(t / frame_dt))): bounded by the run's frames
        // (limited above), it cannot overflow (t_detect_min = 1e308 crashed the run).
        for (const auto& [name, t] : {std::pair{"t_detect_min", s.t_detect_min}, std::pair{"precursor_window", s.precursor_window},
                                      std::pair{"arch_window", s.arch_window}, std::pair{"frame_dt", fdt}})
            if (!(t <= s.t_end))
                p.reject(std::vector<std::string>{name, "t_end"}, std::string(name) + " must be at most t_end");
        if (s.width < 2 * s.lattice) p.reject("width", "must hold at least two lattice sites");
        if (s.crack_min_particles + s.crack_min_above >= s.n_particles)
            p.reject("crack_min_above", "crack_min_particles + crack_min_above must be below n_particles");
    }
    static Pipe prepare(const Spec& spec, const RunContext&) { return Pipe(spec); }
    static std::vector<long> points(const Spec&, const Pipe& s) { return index_order(std::size_t(s.n_seeds)); }
    // Seed run k draws RngStream(seed, k) whatever n_seeds, rank or shard: any split of the seeds
    // (ranks, --points shards) reproduces the single run.
    static SeedRun compute(const Spec&, const Pipe& s, long k, const PointContext& ctx) { return run_seed(s, ctx.seed, k, k == 0); }
    static Result report(const Spec&, const Pipe& s, const Swept<SeedRun>& swept, const RunContext&) {
        const std::vector<SeedRun>& runs = swept.outcomes;
        Result res;
        res.put(out_n_seeds, double(s.n_seeds));
        res.put(out_layers, std::ceil(double(s.n_particles) / (std::floor((s.L - s.d) / s.a + 1e-9) + 0.5)));
        for (const FigureTable& f : runs.front().figure) put_figure_table(res, f);
        report_seeds(res, s, runs);
        return res;
    }
};

} // namespace

Experiment pipe_arching() { return protocol_experiment<PipeArching>(); }

} // namespace granrepro::experiments
