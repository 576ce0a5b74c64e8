// Statistics of a sample (over seeds, states or repeated timings): median, quantile, and mean,
// standard deviation and standard error of the mean.
//
// NaN policy, an argument of median, quantile and mean_sd:
//   NonFinite::skip (the default): NaN and +-inf are dropped first; what remains is the sample
//     (a value that could not be measured does not enter). Nothing left: the statistic is NaN.
//   NonFinite::censored: NaN means "did not happen before the end" and counts as +inf (so it
//     still ranks above every measured value); a statistic that lands on an infinite value is NaN.
// Small samples: n = 0 gives NaN for everything; n = 1 gives the value as median and mean, and
// NaN for sd and sem (no spread can be measured from one value).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <gsl/gsl_statistics_double.h>

namespace granrepro {

enum class NonFinite { skip, censored };

inline std::vector<double> sorted_sample(std::vector<double> v, NonFinite policy) {
    if (policy == NonFinite::skip) std::erase_if(v, [](double x) { return !std::isfinite(x); });
    else std::replace_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }, INFINITY);
    std::sort(v.begin(), v.end());
    return v;
}

// The middle value of the sorted sample; the mean of the two middle ones for even n.
inline double median(std::vector<double> v, NonFinite policy = NonFinite::skip) {
    v = sorted_sample(std::move(v), policy);
    if (v.empty()) return NAN;
    const std::size_t h = v.size() / 2;
    const double m = v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
    return policy == NonFinite::censored && std::isinf(m) ? NAN : m;
}

// The q-quantile (0 <= q <= 1), linear between the sorted values at floor and ceil of q (n - 1);
// NaN if either of those is infinite (only possible under `censored`).
inline double quantile(std::vector<double> v, double q, NonFinite policy = NonFinite::skip) {
    v = sorted_sample(std::move(v), policy);
    if (v.empty()) return NAN;
    const double pos = q * double(v.size() - 1);
    const std::size_t lo = std::size_t(std::floor(pos)), hi = std::size_t(std::ceil(pos));
    const double a = v[lo], b = v[hi];
    if (!std::isfinite(a) || !std::isfinite(b)) return std::isfinite(a) && lo == hi ? a : NAN;
    return a + (pos - double(lo)) * (b - a);
}

// n, mean, sample sd (1/(n - 1)) and sem = sd / sqrt(n), from GSL's gsl_stats_mean and
// gsl_stats_sd. `skip`: over the finite values. `censored`: a sample holding a non-finite value
// (a time that did not happen before the end) has no mean, so all but n are NaN.
struct MeanSd { double n = 0, mean = NAN, sd = NAN, sem = NAN; };
inline MeanSd mean_sd(std::vector<double> v, NonFinite policy = NonFinite::skip) {
    const auto non_finite = [](double x) { return !std::isfinite(x); };
    if (policy == NonFinite::censored && std::any_of(v.begin(), v.end(), non_finite)) return {double(v.size())};
    std::erase_if(v, non_finite);
    MeanSd m{double(v.size())};
    if (v.size() >= 1) m.mean = gsl_stats_mean(v.data(), 1, v.size());
    if (v.size() >= 2) m.sd = gsl_stats_sd(v.data(), 1, v.size()), m.sem = m.sd / std::sqrt(m.n);
    return m;
}

} // namespace granrepro
