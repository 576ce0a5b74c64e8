// pipe-arching (Sec. 5, Figs. 13 and 14): the spec, one seed run's outcome, the fall's frames and what the files share.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "analysis/crack_detector.hpp"
#include "core/vec2.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"
#include "observables/column_bands.hpp"
#include "observables/rate_histogram.hpp"

// Not granrepro::experiments::pipe_arching: that name is the experiment's function (registry.cpp).
namespace granrepro::experiments::pipe_arching_detail {

// The catalog every output handle of pipe-arching registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"pipe-arching"};

enum class TcRule { either, both };    // Eq. (7) for a pair: elastic if either or both partners collided within t_c
enum class TcFriction { drop, keep }; // what a TC-elastic collision does to mu and beta0
// Where the lattice's free room (L - d minus the widest row's span) sits: all at the right wall
// (the leftmost disk touches the left wall), split evenly, or a uniform random share per seed.
enum class Registration { left, centred, random };
enum class RelaxGravity { on, off }; // gravity during the relaxation t = -t_r .. 0 (always on after t = 0)
inline void parse_choice(const std::string& s, TcRule& x) { x = s == "both" ? TcRule::both : TcRule::either; }
inline void parse_choice(const std::string& s, TcFriction& x) { x = s == "keep" ? TcFriction::keep : TcFriction::drop; }
inline void parse_choice(const std::string& s, Registration& x) {
    x = s == "centred" ? Registration::centred : s == "random" ? Registration::random : Registration::left;
}
inline void parse_choice(const std::string& s, RelaxGravity& x) { x = s == "off" ? RelaxGravity::off : RelaxGravity::on; }
// Read once from experiments/pipe-arching.toml, which holds every parameter's unit, range and source.
struct PipeArchingSpec {
    long n_particles = 0, n_seeds = 0, crack_min_particles = 0, crack_min_above = 0;
    double width = 0, lattice = 0;                            // [d]
    double d = 0, mass = 0, g = 0, v0 = 0;                    // [m], [kg], [m/s^2], [m/s]
    double t_relax = 0, t_end = 0, frame_dt = 0, dist_dt = 0; // [s]
    double epsilon = 0, mu = 0, beta0 = 0, q = 0, t_c = 0;    // t_c [s]
    double epsilon_w = 0, mu_w = 0, beta0_w = 0;
    TcRule tc_rule = TcRule::either;
    TcFriction tc_friction = TcFriction::drop;
    double wall_jitter = 0;                                   // [d]
    Registration registration = Registration::left;
    RelaxGravity relax_gravity = RelaxGravity::on;
    double t_arch_paper = 0;                                  // [s]
    std::vector<double> snapshot_times, dist_times_before, dist_times_after; // [s]
    double hot_rate = 0;                                      // [1/s]
    double link = 0, wall_reach = 0, pressure_band = 0, crack_opening = 0; // [d]
    double precursor_band = 0, plug_half_height = 0, below_depth = 0, arch_separation = 0; // [d]
    double arch_pressure_factor = 0;
    double t_detect_min = 0, precursor_window = 0, arch_window = 0; // [s]
    GRANREPRO_FIELDS(n_particles, n_seeds, crack_min_particles, crack_min_above, width, lattice, d, mass, g, v0,
                     t_relax, t_end, frame_dt, dist_dt, epsilon, mu, beta0, q, t_c, epsilon_w, mu_w, beta0_w, tc_rule,
                     tc_friction, wall_jitter, registration, relax_gravity, t_arch_paper, snapshot_times,
                     dist_times_before, dist_times_after, hot_rate, link, wall_reach, pressure_band, crack_opening,
                     precursor_band, plug_half_height, below_depth, arch_separation, arch_pressure_factor,
                     t_detect_min, precursor_window, arch_window)
};

constexpr int kLeft = 0, kRight = 1, kFloor = 2; // wall indices

inline long frame_of(double t, double frame_dt) { return std::lround(t / frame_dt); }

// The spec and what it implies: lengths [m] (pipe width L, lattice constant a, the removed
// floor's height, the box height), the frames (frame f ends at t = f frame_dt; arches, hot wall
// disks and cracks are searched from frame detect_from on) and the crack search.
struct Pipe : PipeArchingSpec {
    double L = 0, a = 0, y_floor = 0, ly = 0;
    long n_frames = 0, detect_from = 0;
    CrackSearch cs;
    explicit Pipe(const PipeArchingSpec& spec);
    double t(long f) const { return double(f) * frame_dt; }
    long frames(double dt) const { return long(std::lround(dt / frame_dt)); }
    bool at(const std::vector<double>& times, long f) const {
        return std::any_of(times.begin(), times.end(), [&](double x) { return frame_of(x, frame_dt) == f; });
    }
};

// A time as names write it, with three decimals ("0.050": the <n> of "A_t<n>"); tlabel puts the t
// in front ("t0.050").
inline std::string ttext(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", t);
    return buf;
}
inline std::string tlabel(double t) { return "t" + ttext(t); }

// Run 0's figure tables, named in compute (compute_figures.cpp: fill_pattern with the frame's
// time) and carried by name through the sweep point (FigureTable) to the report, which writes
// each through the handle that makes its name (Result::table_named).
inline const TableOut out_relaxation = outputs.table("relaxation", "v̄ = sqrt(<v^2>) during the elastic relaxation, run 0");
inline const TableOut out_marks =
    outputs.table("marks", "run 0 per Fig. 13 snapshot: initiating disk (x, y), arch height, crack opening");
inline const TableOut out_timeline = outputs.table("timeline",
    "run 0 per frame: hot disks, mean N_c, widest wall-to-wall crack, mean v_y, wall collisions, share of the weight carried by the walls, arch height");
inline const TableOut out_snapshot = outputs.table("snapshot_t<n>",
    "disk centres (x, y above the removed floor), N_c over the last frame_dt, member of the frame's arch, side of the crack (-1 below, +1 above, 0 loose), run 0");
inline const TableOut out_crack =
    outputs.table("crack_t<n>", "course of the widest wall-to-wall crack (mid-height per slice of one diameter), run 0");
inline const TableOut out_pnc = outputs.table("pnc_t<n>", "P(N_c) over the last dist_dt, run 0");

// Eq. (21) (a Fig. 14(a) time) or Eq. (22) (a (b) time) fitted at one time alone (NaN: no fit).
struct TimeFit {
    double t = NAN, value = NAN, error = NAN; // [s], [1/s], [1/s]
    GRANREPRO_FIELDS(t, value, error)
};

// One of run 0's tables (relaxation, Figs. 13 and 14), built by the run and carried through the
// sweep's JSON into the result as it is.
struct FigureTable {
    std::string name, description;
    std::vector<std::string> columns = {}, units = {};
    std::vector<std::vector<double>> values = {};
    void add(const char* column, const char* unit, std::vector<double> v) {
        columns.push_back(column);
        units.push_back(unit);
        values.push_back(std::move(v));
    }
    GRANREPRO_FIELDS(name, description, columns, units, values)
};

// One run (one seed). Times in s, heights in d above the removed floor unless named otherwise.
// Its JSON (the sweep's checkpoint format) names every field as below; NaN is null.
struct SeedRun {
    double vbar0 = NAN, vbar_relax_late = NAN;
    double fluid_layers = NAN, lattice_broken_below = NAN; // state at t = 0 (Sec. 5: lattice intact but the top)
    double t_hot_wall = NAN;                        // first hot disk at a wall (any)
    double t_arch = NAN, y_arch = NAN, y0_arch = NAN; // first arch: time, lab and initial height
    double arch_size = NAN, arch_pL = NAN, arch_pR = NAN;
    double t_precursor = NAN, react_lag = NAN;
    double arch_left_4ms = NAN, arch_above_later = NAN, arch_below_later = NAN;
    double wave_steps = NAN, wave_steps_up = NAN;  // successive distinct arches ("momentum waves") and how many rose
    double wave_stronger = NAN;                     // 1 if a later wave elsewhere had more hot disks than the first arch
    double plug_wall_load = NAN, arch_brake = NAN, opening_below = NAN;
    double wall_slowdown_arch = NAN, wall_slowdown_before = NAN;
    double t_crack = NAN, y_crack = NAN, y0_crack = NAN, crack_opening = NAN;
    double crack_below_arch = NAN, crack_at_initiator = NAN;
    double opening_max_before = NAN, opening_max_after = NAN, opening_max_all = NAN;
    double t_local_crack = NAN, local_opening_after = NAN; // at the initiating disk (local_crack)
    double A = NAN, A_err = NAN, A_chi2 = NAN, B = NAN, B_err = NAN, B_chi2 = NAN;
    double B_rel = NAN, times_rel = NAN;          // Eq. (22) at the Fig. 14(b) times shifted by t_arch - t_arch_paper
    double wall_left = NAN, wall_right = NAN, lattice_shift = NAN; // [d] the side walls' outward displacements, the lattice's offset
    double times_before = NAN, times_after = NAN; // Fig. 14 times pooled into A and B
    double dev_exp_early = NAN, dev_pow_early = NAN, dev_exp_late = NAN, dev_pow_late = NAN;
    double mean_rate_early = NAN;
    double momentum_residual = NAN, friction_share = NAN, wall_load_peak = NAN;
    double wall_seconds = NAN, collisions = NAN, elastic_share = NAN;
    std::vector<TimeFit> per_time;    // every run: at each Fig. 14 time
    std::vector<FigureTable> figure;  // run 0 only
    GRANREPRO_FIELDS(vbar0, vbar_relax_late, fluid_layers, lattice_broken_below, t_hot_wall, t_arch, y_arch, y0_arch,
                     arch_size, arch_pL, arch_pR, t_precursor, react_lag, arch_left_4ms, arch_above_later, wave_steps,
                     wave_steps_up, wave_stronger, arch_below_later, plug_wall_load, arch_brake, opening_below,
                     wall_slowdown_arch, wall_slowdown_before, t_crack, y_crack, y0_crack, crack_opening,
                     crack_below_arch, crack_at_initiator, opening_max_before, opening_max_after, opening_max_all,
                     t_local_crack, local_opening_after, A, A_err, A_chi2, B, B_err, B_chi2, B_rel, times_rel,
                     wall_left, wall_right, lattice_shift, times_before, times_after, dev_exp_early, dev_pow_early,
                     dev_exp_late, dev_pow_late, mean_rate_early, momentum_residual, friction_share, wall_load_peak,
                     wall_seconds, collisions, elastic_share, per_time, figure)
};

struct WallHit { // a side-wall collision
    double t, y;
    int wall;
};

struct ArchFound {
    bool found = false;
    double y = NAN, y0 = NAN, size = 0, pL = NAN, pR = NAN;
    std::vector<int> members;
};

// v̄ = sqrt(<v^2>) sampled over the relaxation, t = -t_r .. 0.
struct Relaxation {
    std::vector<double> t, vbar;
};

// One frame of the fall, at its end.
struct Frame {
    std::vector<Vec2> pos;
    std::vector<double> rate;          // N_c over the last frame_dt [1/s]
    std::vector<int> hot;              // disks with N_c >= hot_rate, ascending
    std::vector<int> hot_wall;         // those at a side wall
    ArchFound arch;
    Crack crack;
    double t = 0, vy = 0, wall_rate = 0; // [s]; mean v_y [m/s]; side-wall collisions per disk and unit time [1/s]
    double wall_load = 0;         // side-wall impulse over M g frame_dt
};

// One run from the release on: the column at t = 0, frames 1 .. n_frames (frame 0 stays empty),
// the Lagrangian bands of 1 d of initial height, and N_c over dist_dt at the Fig. 14 times.
struct Fall {
    std::vector<Vec2> pos0; // [m]
    std::vector<double> y0; // initial heights above the removed floor [d]
    std::vector<Frame> frames;
    ColumnBands bands;
    std::vector<std::vector<double>> dist_rates = {};
    std::vector<double> dist_t = {};
    double jy = 0; // side-wall impulse on the column since t = 0 [kg m/s]
    const Frame& at(long f) const { return frames[std::size_t(f)]; }
    template <class F> std::vector<double> per_frame(F x) const { // frames 1 .. n_frames
        return column(std::span(frames).subspan(1), x);
    }
};

// One seed run (compute.cpp); run 0 (figure) also makes the figures' tables.
SeedRun run_seed(const Pipe& s, std::uint64_t seed, long index, bool figure);
// What the fall shows (compute_arches.cpp): the first arch (frame fa) and its initiating disk (returned),
// what follows it, its plug, the cracks.
int first_arch(SeedRun& out, const Pipe& s, const Fall& fl, long fa);
void arch_aftermath(SeedRun& out, const Pipe& s, const Fall& fl, long fa);
void plug_motion(SeedRun& out, const Pipe& s, const Fall& fl, long fa);
void cracks(SeedRun& out, const Pipe& s, const Fall& fl, long fa, int i_prec);
void local_crack(SeedRun& out, const Pipe& s, const Fall& fl, long fa, int i_prec);
// Fig. 14's fits and run 0's tables (compute_figures.cpp).
std::vector<RateHistogram> fit_fig14(SeedRun& out, const PipeArchingSpec& s, const Fall& fl);
std::vector<FigureTable> figure_tables(const Pipe& s, const Fall& fl, const Relaxation& rel,
                                       const std::vector<RateHistogram>& hs, int i_prec);
// The scalars and tables over the seeds (report.cpp).
void report_seeds(Result& res, const PipeArchingSpec& s, const std::vector<SeedRun>& runs);

} // namespace granrepro::experiments::pipe_arching_detail
