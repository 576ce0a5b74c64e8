// parameter-study (Figs. 8 and 9): the spec, one run's trace, the sweep and what the files share.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"

// Not granrepro::experiments::parameter_study: that name is the experiment's function (registry.cpp).
namespace granrepro::experiments::parameter_study_detail {

// The catalog every output handle of parameter-study registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"parameter-study"};
// The summaries of Figs. 8 and 9 (report_fig8.cpp, report_fig9.cpp): one family, as the TOML
// declared it, each figure's own description passed where it is written.
inline const TableOut out_fig_summary = outputs.table("fig<n>_summary", "");

// Units and ranges: experiments/parameter-study.toml.
struct ParameterStudySpec {
    long n_side = 0, seeds = 0;
    double box_over_d = 0, d = 0, mass = 0, vbar = 0, mu = 0; // L/d, [m], [kg], mean speed at t = 0 [m/s]
    double equilibration = 0, cn_end = 0;                    // collisions per particle
    std::vector<double> fig8_r, fig9_t_c;                    // fig9_t_c [s]
    double fig8_t_c = 0, fig9_r = 0;                         // fig8_t_c [s]
    double exp_fit_efolds = 0, line_check_efolds = 0, aniso_threshold = 0;
    std::vector<double> zeta_fit_early, zeta_fit_late, zeta_fit_tail; // C/N ranges [lo, hi]
    double tc_compare_time = 0, tc_small_max = 0;                      // [s]
    GRANREPRO_FIELDS(n_side, seeds, box_over_d, d, mass, vbar, mu, equilibration, cn_end, fig8_r, fig9_t_c, fig8_t_c,
                     fig9_r, exp_fit_efolds, aniso_threshold, line_check_efolds, zeta_fit_early, zeta_fit_late,
                     zeta_fit_tail, tc_compare_time, tc_small_max)
};

// One sweep point and what it produced.
struct Point { double r = 0, t_c = 0; };

struct Trace {
    std::vector<double> t, cn, elastic_cn, kx, ky, krot;
    double wall_seconds = 0, events = 0, pairs = 0;
    std::string error; // the engine's message if it stopped the run (collapse guard)
    double k(std::size_t i) const { return kx[i] + ky[i] + krot[i]; }
    GRANREPRO_FIELDS(t, cn, elastic_cn, kx, ky, krot, wall_seconds, events, pairs, error)
};

// One run: seed `seed`, random stream `stream` (compute.cpp).
Trace run_point(const ParameterStudySpec& s, const Point& pt, std::uint64_t seed, std::uint64_t stream);

// A curve averaged over the seeds of one parameter set: mean and standard error of
// log10(K/K0) on a grid (of C/N or of t). Geometric means, because K spans many decades and
// the seeds differ by factors, not by amounts.
struct MeanCurve {
    std::vector<double> x, mean, sem;
};
MeanCurve mean_curve(const std::vector<Trace>& seeds, const std::vector<double>& grid, double (*lnk)(const Trace&, double));
double ln_k_at_cn(const Trace& tr, double x); // ln(K/K0) at C/N = x (report.cpp)

// The sweep: Fig. 8's r values at fig8_t_c, then Fig. 9's t_c values at fig9_r, sharing the point
// (fig9_r, fig8_t_c) when both figures contain it; every point with `seeds` initial states.
struct Sweep {
    std::vector<Point> points;
    std::vector<std::size_t> fig8_idx, fig9_idx; // the point of each fig8_r, of each fig9_t_c
    std::vector<std::vector<Trace>> traces;       // [point][seed]
    std::vector<MeanCurve> mean_cn, mean_t;       // seed means per point, against C/N and t
    double wall = 0; // [s]
    std::chrono::steady_clock::time_point start; // of the sweep
};

// The report (report.cpp, report_fig8.cpp, report_fig9.cpp), in the order the protocol calls it.
void report_totals(Result& res, const ParameterStudySpec& s, const Sweep& sw);
void report_points(Result& res, Sweep& sw, const std::vector<double>& cn_grid);
void report_fig8(Result& res, const ParameterStudySpec& s, const Sweep& sw);
void report_fig9(Result& res, const ParameterStudySpec& s, const Sweep& sw, const std::vector<double>& cn_grid);
void report_cn_jumps(Result& res, const ParameterStudySpec& s, const Sweep& sw);

} // namespace granrepro::experiments::parameter_study_detail
