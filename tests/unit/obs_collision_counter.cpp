#include "core/rng_stream.hpp"
#include "observables/collision_counter.hpp"
#include "observables/collision_rate_fit.hpp"
#include "observables/rate_histogram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;
using Model = CollisionRateFit::Model;

namespace {
CollisionRecord rec(double t, int i, int j) {
    CollisionRecord c;
    c.t = t;
    c.i = i;
    c.j = j;
    return c;
}

// Poisson deviate by inversion (RngStream exposes only uniforms and normals).
int poisson(RngStream& rng, double mean) {
    const double u = rng.uniform();
    double p = std::exp(-mean), cdf = p;
    int k = 0;
    while (u > cdf && k < 10000) {
        ++k;
        p *= mean / k;
        cdf += p;
    }
    return k;
}

// The fit of `model` over each range converges on `value` within 3 of its standard errors, each
// below max_error, with a reduced chi^2 below 2.
void expect_fit_recovers(const RateHistogram& h, Model model, double value,
                         std::initializer_list<std::pair<double, double>> ranges, double max_error = INFINITY) {
    for (auto [lo, hi] : ranges) {
        const auto f = CollisionRateFit::fit(h, model, lo, hi);
        EXPECT_TRUE(f.converged);
        EXPECT_NEAR(f.value, value, 3.0 * f.error) << "range " << lo << ".." << hi;
        EXPECT_LT(f.error, max_error);
        EXPECT_LT(f.chi2_reduced, 2.0);
    }
}
} // namespace

TEST(ObsCollisionCounter, TrailingWindowCounts) {
    CollisionCounter cc(3);
    cc.add(rec(0.1, 0, 1));
    cc.add(rec(0.3, 1, 2));
    cc.add(rec(0.2, 0, -1)); // out of order and a wall
    cc.add(rec(0.5, 2, 0));
    const auto n = cc.counts(0.5, 0.3); // window (0.2, 0.5]
    EXPECT_EQ(n, (std::vector<std::uint32_t>{1, 1, 2}));
    const auto all = cc.counts(1.0, 1.0);
    EXPECT_EQ(all, (std::vector<std::uint32_t>{3, 2, 2}));
    CollisionCounter nowall(3, false);
    nowall.add(rec(0.2, 0, -1));
    EXPECT_EQ(nowall.counts(1.0, 1.0)[0], 0u);
    const auto r = cc.rates(1.0, 0.5); // (0.5, 1.0]: nothing
    EXPECT_EQ(r, (std::vector<double>{0.0, 0.0, 0.0}));
    EXPECT_DOUBLE_EQ(cc.rates(0.5, 0.5)[2], 4.0); // 2 collisions / 0.5 s
    cc.discard_before(0.25);
    EXPECT_EQ(cc.stored(), 2u);
    EXPECT_THROW(cc.add(rec(0.6, 3, 0)), std::out_of_range);
}

TEST(ObsRateHistogram, NormalisedDensity) {
    const std::vector<double> r{0.0, 1.0, 1.0, 2.5, 9.0, 20.0};
    const auto h = RateHistogram::make(r, 1.0, RateHistogram::Binning::Linear, 5, 0.0, 10.0);
    EXPECT_EQ(h.total, 6u);
    EXPECT_EQ(h.above, 1u);
    EXPECT_EQ(h.counts, (std::vector<std::uint64_t>{3, 1, 0, 0, 1}));
    double integral = 0.0;
    for (std::size_t k = 0; k < 5; ++k) integral += h.density[k] * 2.0;
    EXPECT_NEAR(integral, 5.0 / 6.0, 1e-14); // the particle above the range is missing
    const auto lg = RateHistogram::make(r, 1.0, RateHistogram::Binning::Log, 4, 0.1, 1000.0);
    EXPECT_EQ(lg.below, 1u); // N_c = 0 has no log bin
    EXPECT_NEAR(lg.centres[0], std::sqrt(0.1 * 1.0), 1e-12);
}

TEST(ObsCollisionRateFit, RecoversExponentialEq21) {
    const double A = 19.0; // 1/s, the paper's Fig. 12(a) value
    RngStream rng(21, 0);
    std::vector<double> r(20000);
    for (auto& x : r) x = -A * std::log(1.0 - rng.uniform());
    const auto h = RateHistogram::make(r, 0.1, RateHistogram::Binning::Linear, 60, 0.0, 150.0);
    expect_fit_recovers(h, Model::Exponential, A, {{0.0, 150.0}, {25.0, 125.0}}, 0.05 * A);
    // The wrong model must be visibly worse.
    const auto bad = CollisionRateFit::fit(h, Model::PowerLaw, 0.0, 150.0);
    EXPECT_GT(bad.chi2_reduced, 10.0);
}

TEST(ObsCollisionRateFit, RecoversPowerLawEq22) {
    const double B = 8.0; // 1/s, Fig. 12(b)
    RngStream rng(22, 0);
    std::vector<double> r(20000);
    for (auto& x : r) {
        const double u = rng.uniform();
        x = B * u / (1.0 - u); // inverse of the CDF x / (B + x)
    }
    const auto h = RateHistogram::make(r, 0.1, RateHistogram::Binning::Log, 40, 0.1, 1e4);
    expect_fit_recovers(h, Model::PowerLaw, B, {{0.1, 1e4}, {10.0, 1e4}});
    const auto bad = CollisionRateFit::fit(h, Model::Exponential, 0.1, 1e4);
    EXPECT_GT(bad.chi2_reduced, 10.0);
}

TEST(ObsCollisionRateFit, RecoversPoissonEq20) {
    const double chi = 6.5, dt = 0.02; // the paper's Fig. 12(a) values
    RngStream rng(20, 0);
    std::vector<double> r(20000);
    for (auto& x : r) x = static_cast<double>(poisson(rng, chi)) / dt;
    const auto h = RateHistogram::per_count(r, dt, 30);
    // P here is the paper's P_o(N_c dt, chi) dt, bin by bin.
    EXPECT_NEAR(CollisionRateFit::density(Model::Poisson, chi, 5.0 / dt, dt),
                std::exp(-chi) * std::pow(chi, 5) / 120.0 * dt, 1e-15);
    expect_fit_recovers(h, Model::Poisson, chi, {{-25.0, 1525.0}, {275.0, 625.0}});
    // Full range: the ML estimate of a Poisson mean is the sample mean, SE sqrt(chi/N).
    double mean = 0.0;
    for (double x : r) mean += x * dt;
    mean /= static_cast<double>(r.size());
    const auto f = CollisionRateFit::fit(h, Model::Poisson, -25.0, 1525.0);
    EXPECT_NEAR(f.value, mean, 1e-4);
    EXPECT_NEAR(f.error, std::sqrt(chi / static_cast<double>(r.size())), 0.05 * f.error);
}
