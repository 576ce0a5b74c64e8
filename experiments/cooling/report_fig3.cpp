// cooling, Fig. 3: P(b/d) of the ED run per time window and the trend of grazing collisions.
#include <cmath>
#include <string>
#include <vector>

#include "experiments/cooling/spec.hpp"

namespace granrepro::experiments::cooling_detail {

using Window = ImpactParameterHistogram::Window;

// Grazing over central collisions: mean P(b/d) over b/d > 0.8 against b/d < 0.2.
double grazing_ratio(const Window& w, const std::vector<double>& centres) {
    return mean_over(w.p, centres, 0.8, 1.0) / mean_over(w.p, centres, 0.0, 0.2);
}

namespace {

const TableOut out_impact_parameter_grazing = outputs.table("impact_parameter_grazing",
    "grazing ratio P(b/d>0.8)/P(b/d<0.2) of the ED run per window, with its counting error");
const ScalarOut out_pbd_grazing_rising_share = outputs.scalar("pbd_grazing_rising_share", "1",
    "share of successive P(b/d) windows whose grazing ratio does not fall by more than 3 combined standard errors");
const ScalarOut out_pbd_grazing_rising_pairs = outputs.scalar("pbd_grazing_rising_pairs", "1",
    "number of successive window pairs judged");
const ScalarOut out_pbd_grazing_step_min_z = outputs.scalar("pbd_grazing_step_min_z", "1",
    "smallest change of the grazing ratio between successive windows, in combined standard errors");
const ScalarOut out_pbd_grazing_ratio_last_over_first = outputs.scalar("pbd_grazing_ratio_last_over_first", "1",
    "grazing ratio of the last window over the first (from the counts)");

// Sec. 3.2, "more and more grazing collisions occur with increasing simulation time": the grazing
// ratio of every window with its counting error (Poisson: the relative error of a ratio of two
// bin-group counts is sqrt(1/C_hi + 1/C_lo); the window total cancels), and the share of
// successive window pairs in which it does not fall by more than 3 combined standard errors.
void add_grazing_trend(Result& res, const Trace& ed) {
    std::vector<double> ratio, err;
    for (const auto& w : ed.pbd) {
        double hi = 0, lo = 0, nhi = 0, nlo = 0;
        for (std::size_t b = 0; b < w.counts.size() && b < ed.pbd_centres.size(); ++b) {
            const double x = ed.pbd_centres[b];
            if (x >= 0.8 && x <= 1.0) { hi += double(w.counts[b]); ++nhi; }
            if (x >= 0.0 && x <= 0.2) { lo += double(w.counts[b]); ++nlo; }
        }
        const double r = (hi > 0 && lo > 0) ? (hi / nhi) / (lo / nlo) : NAN;
        ratio.push_back(r);
        err.push_back(r * std::sqrt(1 / hi + 1 / lo));
    }
    Table& t = res.table(out_impact_parameter_grazing);
    t.add({{"t_begin", "s", column(ed.pbd, &Window::t_begin)}, {"grazing_ratio", "1", ratio},
           {"grazing_ratio_err", "1", err}});
    int pairs = 0, rising = 0;
    double min_z = NAN;
    for (std::size_t k = 1; k < ratio.size(); ++k) {
        if (!std::isfinite(ratio[k]) || !std::isfinite(ratio[k - 1])) continue;
        const double z = (ratio[k] - ratio[k - 1]) / std::hypot(err[k], err[k - 1]);
        ++pairs;
        if (z >= -3) ++rising;
        min_z = std::isnan(min_z) ? z : std::min(min_z, z);
    }
    res.put(out_pbd_grazing_rising_share, pairs ? double(rising) / pairs : NAN);
    res.put(out_pbd_grazing_rising_pairs, double(pairs));
    res.put(out_pbd_grazing_step_min_z, min_z);
    res.put(out_pbd_grazing_ratio_last_over_first, ratio.empty() ? NAN : ratio.back() / ratio.front());
}

const TableOut out_impact_parameter_grazing_from_t0 = outputs.table("impact_parameter_grazing_from_t0",
    "grazing ratio P(b/d>0.8)/P(b/d<0.2) of the ED run over [0, t_end), with its counting error and the collisions");

// Sec. 3.2, "P(b/d) = 1 for short times only" (issue 43 §3, pbd_flat_early): the grazing ratio
// of every window that starts at t = 0, [0, t_end of window j), from the counts of windows 0..j
// summed, with its counting error. Molecular chaos holds at t = 0 (the elastic equilibration's
// end) and fades as the cooling builds velocity correlations (early_cooling_eq18), so a ratio above
// 1 that shrinks with the window's length is that build-up inside the window, not the start.
// Finer early edges (bd_windows) give the series its points.
void add_grazing_from_t0(Result& res, const Trace& ed) {
    std::vector<double> t_end, ratio, err, total;
    std::vector<double> sum;
    for (const auto& w : ed.pbd) {
        if (sum.empty()) sum.assign(w.counts.size(), 0.0);
        for (std::size_t b = 0; b < w.counts.size() && b < sum.size(); ++b) sum[b] += double(w.counts[b]);
        double hi = 0, lo = 0, nhi = 0, nlo = 0, all = 0;
        for (std::size_t b = 0; b < sum.size() && b < ed.pbd_centres.size(); ++b) {
            const double x = ed.pbd_centres[b];
            all += sum[b];
            if (x >= 0.8 && x <= 1.0) { hi += sum[b]; ++nhi; }
            if (x >= 0.0 && x <= 0.2) { lo += sum[b]; ++nlo; }
        }
        const double r = (hi > 0 && lo > 0) ? (hi / nhi) / (lo / nlo) : NAN;
        t_end.push_back(w.t_end), ratio.push_back(r), err.push_back(r * std::sqrt(1 / hi + 1 / lo)), total.push_back(all);
    }
    Table& t = res.table(out_impact_parameter_grazing_from_t0);
    t.add({{"t_end", "s", t_end}, {"grazing_ratio", "1", ratio}, {"grazing_ratio_err", "1", err}, {"collisions", "1", total}});
}

} // namespace

const TableOut out_impact_parameter_ed = outputs.table("impact_parameter_ed",
    "P(b/d) of the ED run per time window (columns by window start)");
const TableOut out_impact_parameter_windows = outputs.table("impact_parameter_windows",
    "time windows of P(b/d): [t_begin, t_end)");
const ScalarOut out_pbd_grazing_ratio_first = outputs.scalar("pbd_grazing_ratio_first", "1",
    "P(b/d>0.8)/P(b/d<0.2), first window, ED");
const ScalarOut out_pbd_grazing_ratio_last = outputs.scalar("pbd_grazing_ratio_last", "1",
    "P(b/d>0.8)/P(b/d<0.2), last window, ED");
const ScalarOut out_pbd_collisions_first = outputs.scalar("pbd_collisions_first", "1",
    "collisions in the first window");

// Fig. 3: P(b/d) of the ED run per time window, and grazing over central collisions in the first
// and last window.
void add_impact_parameter(Result& res, const Trace& ed) {
    {
        Table& t = res.table(out_impact_parameter_ed);
        t.add("b_over_d", "1").values = ed.pbd_centres;
        for (const auto& w : ed.pbd)
            t.add({{"P_t" + number_text(w.t_begin), "1", w.p}, {"err_t" + number_text(w.t_begin), "1", w.error}});
    }
    Table& wt = res.table(out_impact_parameter_windows);
    wt.add({{"t_begin", "s", column(ed.pbd, &Window::t_begin)}, {"t_end", "s", column(ed.pbd, &Window::t_end)}});
    res.put(out_pbd_grazing_ratio_first, grazing_ratio(ed.pbd.front(), ed.pbd_centres));
    res.put(out_pbd_grazing_ratio_last, grazing_ratio(ed.pbd.back(), ed.pbd_centres));
    res.put(out_pbd_collisions_first, double(ed.pbd.front().total));
    add_grazing_trend(res, ed);
    add_grazing_from_t0(res, ed);
}

} // namespace granrepro::experiments::cooling_detail
