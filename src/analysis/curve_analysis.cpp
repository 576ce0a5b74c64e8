#include "analysis/curve_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <limits>

namespace granrepro {

std::vector<double> log_space(double lo, double hi, int n) {
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i)
        v[i] = n == 1 ? lo : std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n - 1));
    return v;
}

Peak find_peak(const std::vector<double>& x, const std::vector<double>& y) {
    Peak p;
    if (x.empty()) return p;
    const auto it = std::max_element(y.begin(), y.end());
    p.index = int(it - y.begin());
    p.x = x[p.index];
    p.y = *it;
    if (p.index > 0 && p.index + 1 < int(x.size())) {
        // Parabola through three points in u = log x.
        const double u0 = std::log(x[p.index - 1]), u1 = std::log(x[p.index]), u2 = std::log(x[p.index + 1]);
        const double y0 = y[p.index - 1], y1 = y[p.index], y2 = y[p.index + 1];
        const double d1 = (y1 - y0) / (u1 - u0), d2 = (y2 - y1) / (u2 - u1);
        const double a = (d2 - d1) / (u2 - u0);
        if (a < 0) {
            const double b = d1 - a * (u0 + u1);
            const double u = -b / (2 * a);
            if (u > u0 && u < u2) {
                p.x = std::exp(u);
                p.y = y0 + d1 * (u - u0) + a * (u - u0) * (u - u1);
            }
        }
    }
    return p;
}

Peak first_maximum(const std::vector<double>& x, const std::vector<double>& y, double rel_drop) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < y.size(); ++i) {
        if (y[i] > y[best]) best = i;
        else if (y[i] < (1 - rel_drop) * y[best]) break;
    }
    // Refine on the neighbourhood of the found maximum only.
    const std::size_t lo = best > 0 ? best - 1 : 0, hi = std::min(y.size(), best + 2);
    Peak p = find_peak(std::vector<double>(x.begin() + long(lo), x.begin() + long(hi)),
                       std::vector<double>(y.begin() + long(lo), y.begin() + long(hi)));
    p.index += int(lo);
    return p;
}

int count_maxima(const std::vector<double>& x, const std::vector<double>& y, double rel_prominence) {
    (void)x;
    if (y.size() < 3) return 0;
    const double scale = *std::max_element(y.begin(), y.end());
    const double tol = rel_prominence * std::abs(scale);
    // Walk the curve as a sequence of significant rises and falls.
    int maxima = 0;
    int trend = 0; // +1 rising, -1 falling
    double ref = y[0];
    std::size_t ref_i = 0;
    for (std::size_t i = 1; i < y.size(); ++i) {
        if (trend >= 0) {
            if (y[i] > ref) {
                ref = y[i];
                ref_i = i;
            } else if (ref - y[i] > tol) {
                if (ref_i > 0) ++maxima; // a fall from the first sample is no interior maximum
                trend = -1;
                ref = y[i];
            }
        } else {
            if (y[i] < ref) ref = y[i];
            else if (y[i] - ref > tol) {
                trend = 1;
                ref = y[i];
            }
        }
    }
    return maxima;
}

PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y, double x_lo, double x_hi) {
    std::vector<double> lx, ly;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] >= x_lo * (1 - 1e-12) && x[i] <= x_hi * (1 + 1e-12) && y[i] > 0) {
            lx.push_back(std::log(x[i]));
            ly.push_back(std::log(y[i]));
        }
    PowerLawFit f;
    f.points = int(lx.size());
    if (f.points < 3) {
        f.exponent = f.exponent_err = std::numeric_limits<double>::quiet_NaN();
        return f;
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    gsl_fit_linear(lx.data(), 1, ly.data(), 1, lx.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
    // cov11 from gsl_fit_linear is scaled by the residual variance, i.e. the standard error.
    f.exponent = c1;
    f.exponent_err = std::sqrt(cov11);
    return f;
}

double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double scale = 0, worst = 0;
    for (double v : b) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return scale > 0 ? worst / scale : worst;
}

double first_upward_crossing(const std::vector<double>& x, const std::vector<double>& y, double level) {
    for (std::size_t i = 1; i < x.size(); ++i)
        if (y[i - 1] < level && y[i] >= level) {
            const double f = (level - y[i - 1]) / (y[i] - y[i - 1]);
            return std::exp(std::log(x[i - 1]) + f * (std::log(x[i]) - std::log(x[i - 1])));
        }
    if (!y.empty() && y[0] >= level) return x[0];
    return std::numeric_limits<double>::quiet_NaN();
}

double fit_haff_inv_t0(const std::vector<double>& t, const std::vector<double>& k_over_k0, double t0) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] > 0 && t[i] <= t0) {
            x.push_back(t[i]);
            y.push_back(1 / std::sqrt(k_over_k0[i]) - 1);
        }
    double c1 = NAN, cov = 0, ss = 0;
    if (x.size() >= 2) gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &c1, &cov, &ss);
    return c1;
}

} // namespace granrepro
