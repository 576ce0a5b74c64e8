#include "core/rng_stream.hpp"
#include "observables/impact_parameter_histogram.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace granrepro;

TEST(ObsImpactParameter, UniformSamplesGiveFlatUnitDensity) {
    ImpactParameterHistogram h(20, {0.0, 1.0, 2.0});
    RngStream rng(2024, 3);
    for (int k = 0; k < 200000; ++k) {
        CollisionRecord c;
        c.t = rng.uniform(0.0, 2.0);
        c.i = 0;
        c.j = 1;
        c.b_over_d = rng.uniform();
        h.add(c);
    }
    for (std::size_t w = 0; w < 2; ++w) {
        const auto win = h.window(w);
        EXPECT_GT(win.total, 90000u);
        double integral = 0.0, chi2 = 0.0;
        for (int b = 0; b < h.bins(); ++b) {
            EXPECT_NEAR(win.p[b], 1.0, 4.0 * win.error[b]);
            chi2 += std::pow((win.p[b] - 1.0) / win.error[b], 2);
            integral += win.p[b] / h.bins();
        }
        EXPECT_NEAR(integral, 1.0, 1e-12);
        EXPECT_LT(chi2 / h.bins(), 2.0);
    }
}

TEST(ObsImpactParameter, NonUniformIsDetectedAndStillNormalised) {
    // P(x) = 2x (the 3D molecular-chaos law): the 2D flat hypothesis must fail.
    ImpactParameterHistogram h(10, {0.0, 1.0});
    RngStream rng(5, 5);
    for (int k = 0; k < 50000; ++k) {
        CollisionRecord c;
        c.t = 0.5;
        c.j = 2;
        c.b_over_d = std::sqrt(rng.uniform());
        h.add(c);
    }
    const auto win = h.window(0);
    double integral = 0.0;
    for (int b = 0; b < 10; ++b) {
        integral += win.p[b] * 0.1;
        EXPECT_NEAR(win.p[b], 2.0 * (b + 0.5) / 10.0, 4.0 * win.error[b] + 1e-3);
    }
    EXPECT_NEAR(integral, 1.0, 1e-12);
    EXPECT_GT(std::abs(win.p[0] - 1.0), 10.0 * win.error[0]);
}

TEST(ObsImpactParameter, WindowsWallsAndEdges) {
    ImpactParameterHistogram h(4, {1.0, 2.0, 3.0});
    CollisionRecord c;
    c.j = 0;
    c.t = 0.5; c.b_over_d = 0.5; h.add(c);  // before the first window: ignored
    c.t = 3.0; h.add(c);                    // windows are half-open: ignored
    c.t = 2.0; c.b_over_d = 1.0; h.add(c);  // b/d = 1 goes to the last bin of window 1
    c.t = 1.0; c.b_over_d = 0.0; h.add(c);  // window 0, bin 0
    c.j = -1; c.t = 1.5; h.add(c);          // wall collision: ignored by default
    EXPECT_EQ(h.window(0).total, 1u);
    EXPECT_EQ(h.window(0).counts[0], 1u);
    EXPECT_EQ(h.window(1).counts[3], 1u);
    EXPECT_DOUBLE_EQ(h.window(1).p[3], 4.0);
    c.j = 0; c.b_over_d = 1.5;
    EXPECT_THROW(h.add(c), std::out_of_range);
    EXPECT_THROW(ImpactParameterHistogram(4, {1.0, 1.0}), std::invalid_argument);
}
