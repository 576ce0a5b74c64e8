// Shape measures of a sampled curve y(x) on a log-spaced grid, used to turn a figure's
// qualitative claims into numbers: where the maximum is, how many maxima there are, the
// power-law exponent of a tail, whether the start is linear.
#pragma once
#include <cstddef>
#include <limits>
#include <vector>

namespace granrepro {

std::vector<double> log_space(double lo, double hi, int n);

struct Peak {
    double x = 0;     // location, refined by a parabola through the top three points in log x
    double y = 0;     // height (of the parabola)
    int index = -1;   // grid index of the largest sample
};
Peak find_peak(const std::vector<double>& x, const std::vector<double>& y);

// The first maximum of y that is followed by a fall below (1 - rel_drop) of it (so sampling noise
// is not taken for the maximum); refined like find_peak. The global maximum if there is no fall.
Peak first_maximum(const std::vector<double>& x, const std::vector<double>& y, double rel_drop = 0.05);

// Local maxima that stand out by more than `rel_prominence` of the global maximum on both sides
// (so sampling noise does not count as a maximum).
int count_maxima(const std::vector<double>& x, const std::vector<double>& y, double rel_prominence = 0.02);

struct PowerLawFit {
    double exponent = 0, exponent_err = 0; // y ∝ x^exponent
    int points = 0;
};
// Least-squares line through (log x, log y) for x in [x_lo, x_hi] (GSL gsl_fit_linear).
PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y, double x_lo, double x_hi);

// Largest |a_i - b_i| / max(|b|) over the samples: distance between two curves on one grid,
// relative to the curve's scale (floor: the maximum of |b|).
double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b);

// Haff's law (Luding Eq. 18) fitted to the start of a cooling curve: the line through the origin
// 1/sqrt(K/K0) - 1 = t/t0 over 0 < t <= t0 (GSL gsl_fit_mul). Returns the fitted 1/t0 [1/s]; NaN
// below two samples.
double fit_haff_inv_t0(const std::vector<double>& t, const std::vector<double>& k_over_k0, double t0);

// First x at which y crosses `level` upwards (linear interpolation in log x); NaN if never.
double first_upward_crossing(const std::vector<double>& x, const std::vector<double>& y, double level);

} // namespace granrepro
