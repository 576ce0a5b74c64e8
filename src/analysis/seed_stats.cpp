#include "analysis/seed_stats.hpp"

#include <algorithm>
#include <cmath>

#include <gsl/gsl_statistics_double.h>

namespace granrepro {

namespace {

// The sample under the policy, sorted.
std::vector<double> sorted(std::vector<double> v, NonFinite policy) {
    if (policy == NonFinite::skip) std::erase_if(v, [](double x) { return !std::isfinite(x); });
    else
        for (double& x : v)
            if (std::isnan(x)) x = INFINITY;
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

double median(std::vector<double> v, NonFinite policy) {
    v = sorted(std::move(v), policy);
    if (v.empty()) return NAN;
    const std::size_t h = v.size() / 2;
    const double m = v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
    return policy == NonFinite::censored && std::isinf(m) ? NAN : m;
}

double quantile(std::vector<double> v, double q, NonFinite policy) {
    v = sorted(std::move(v), policy);
    if (v.empty()) return NAN;
    const double pos = q * double(v.size() - 1);
    const std::size_t lo = std::size_t(std::floor(pos)), hi = std::size_t(std::ceil(pos));
    const double a = v[lo], b = v[hi];
    if (!std::isfinite(a) || !std::isfinite(b)) return std::isfinite(a) && lo == hi ? a : NAN;
    return a + (pos - double(lo)) * (b - a);
}

MeanSd mean_sd(std::vector<double> v) {
    std::erase_if(v, [](double x) { return !std::isfinite(x); });
    const std::size_t n = v.size();
    MeanSd m{double(n), NAN, NAN, NAN};
    if (n < 1) return m;
    m.mean = gsl_stats_mean(v.data(), 1, n);
    if (n < 2) return m;
    m.sd = gsl_stats_sd(v.data(), 1, n);
    m.sem = m.sd / std::sqrt(double(n));
    return m;
}

} // namespace granrepro
