// drift_fit (src/analysis/curve_analysis.hpp) on an Ornstein-Uhlenbeck process, the model of a
// relaxing mean velocity near a steady state (issue 26: a steady state is accepted only when its
// drift is zero within its error over a span of several of the pipe's own relaxation times).
// The process is sampled exactly: x_{k+1} = a x_k + sqrt(1 - a^2) sigma xi, a = exp(-dt / tau).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/curve_analysis.hpp"
#include "core/rng_stream.hpp"

using namespace granrepro;

namespace {

constexpr double kTau = 0.05, kDt = 0.005, kSigma = 0.1; // [s], [s], [m/s]: 10 samples per tau
constexpr int kRealizations = 400;

// One realization over `span` (started in its stationary state) with a drift `slope` added.
void ou_series(RngStream& rng, double span, double slope, std::vector<double>& t, std::vector<double>& v) {
    const int n = int(std::lround(span / kDt)) + 1;
    const double a = std::exp(-kDt / kTau), kick = std::sqrt(1 - a * a) * kSigma;
    t.resize(std::size_t(n));
    v.resize(std::size_t(n));
    double x = kSigma * rng.normal();
    for (int k = 0; k < n; ++k) {
        t[std::size_t(k)] = k * kDt;
        v[std::size_t(k)] = x + slope * k * kDt;
        x = a * x + kick * rng.normal();
    }
}

struct Coverage {
    double tau_median = 0; // median estimated tau [s]
    double within = 0;     // fraction whose drift is zero within its error (95 %)
};

Coverage coverage(double span, double slope, std::uint64_t stream) {
    RngStream rng(7, stream);
    std::vector<double> t, v, taus;
    Coverage c;
    for (int r = 0; r < kRealizations; ++r) {
        ou_series(rng, span, slope, t, v);
        const DriftFit f = drift_fit(t, v, 0);
        taus.push_back(f.tau);
        c.within += (drift_within_error(f) ? 1.0 : 0.0) / kRealizations;
    }
    std::nth_element(taus.begin(), taus.begin() + kRealizations / 2, taus.end());
    c.tau_median = taus[kRealizations / 2];
    return c;
}

// Binomial error bar of a 95 % coverage over kRealizations, and 4 of them as the band.
const double kCoverageBand = 4 * std::sqrt(0.95 * 0.05 / kRealizations); // 0.044

} // namespace

TEST(DriftFit, RecoversTheRelaxationTimeOfAnOrnsteinUhlenbeckProcess) {
    // One estimate over 20 tau scatters by about 20 %; the median of 400 lies within a few %, and
    // 10 % leaves room for the bias correction's higher orders (a first-zero-crossing sum of the
    // autocorrelation, tried first, gave 0.64 tau here).
    const Coverage c = coverage(20 * kTau, 0.0, 1);
    EXPECT_NEAR(c.tau_median, kTau, 0.1 * kTau);
}

TEST(DriftFit, AStationarySeriesHasZeroDriftWithinItsError95PercentOfTheTime) {
    // The white-noise error (tau = dt/2) would be about sqrt(10) times too small here and pass about
    // a third of the series, 2 errors without the Student-t quantile 88 % at 20 tau: the coverage
    // tests the correlated-noise error bar and its degrees of freedom.
    for (double spans : {20.0, 50.0}) { // the spans the relaxation rule uses (M >= 20; 10 tau leaves 3 degrees of freedom)
        const Coverage c = coverage(spans * kTau, 0.0, 2 + std::uint64_t(spans));
        EXPECT_NEAR(c.within, 0.95, kCoverageBand) << "span " << spans << " tau";
    }
}

TEST(DriftFit, ADriftOfFiveErrorsIsSeen) {
    // The slope's error over 50 tau: sqrt(24 sigma^2 tau / T^3).
    const double span = 50 * kTau, error = std::sqrt(24 * kSigma * kSigma * kTau / (span * span * span));
    const Coverage c = coverage(span, 5 * error, 3);
    EXPECT_LT(c.within, 0.1);
}
