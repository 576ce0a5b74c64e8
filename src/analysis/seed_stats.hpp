// Statistics of a sample (over seeds, states or repeated timings): median, quantile, mean,
// standard deviation and standard error of the mean.
//
// NaN policy, an argument of median and quantile (mean_sd always skips):
//   NonFinite::skip (the default): NaN and +-inf are dropped first; what remains is the sample
//     (a value that could not be measured does not enter). Nothing left: every statistic is NaN.
//   NonFinite::censored: NaN means "did not happen before the end" and counts as +inf (so it
//     still ranks above every measured value); a statistic that lands on an infinite value is
//     NaN. For times of events that some seeds never reach.
// Small samples: n = 0 gives NaN for everything; n = 1 gives the value as median and mean, and
// NaN for sd and sem (no spread can be measured from one value).
#pragma once
#include <vector>

namespace granrepro {

enum class NonFinite { skip, censored };

// The middle value of the sorted sample; the mean of the two middle ones for even n.
double median(std::vector<double> v, NonFinite policy = NonFinite::skip);

// The q-quantile (0 <= q <= 1) interpolated linearly between the sorted values at
// positions floor and ceil of q (n - 1). Under `censored`, NaN if either of those is infinite.
double quantile(std::vector<double> v, double q, NonFinite policy = NonFinite::skip);

struct MeanSd {
    double n = 0;      // values that entered
    double mean = 0;   // arithmetic mean (NaN if n = 0)
    double sd = 0;     // sample standard deviation, 1/(n - 1) (NaN if n < 2)
    double sem = 0;    // standard error of the mean, sd / sqrt(n) (NaN if n < 2)
};
// Mean, sd and sem (GSL's gsl_stats_mean and gsl_stats_sd), always under NonFinite::skip: the
// mean of a censored sample (+inf in it) is not a number.
MeanSd mean_sd(std::vector<double> v);

} // namespace granrepro
