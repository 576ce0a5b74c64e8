// Root finders of the ED event prediction against brute-force sampling.
#include "engines/ed/flight_roots.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace granrepro::flight_roots;

TEST(EdFlightRoots, PairContactTimeMatchesBruteForce) {
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    int hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const double sigma = 1.0;
        double drx = u(gen), dry = u(gen);
        if (drx * drx + dry * dry < 1.0) continue;
        const double dvx = u(gen), dvy = u(gen);
        const double t = pair_contact_time(drx, dry, dvx, dvy, sigma);
        auto dist = [&](double s) { return std::hypot(drx + dvx * s, dry + dvy * s); };
        // Brute force: first sample below sigma on a fine grid over [0, 10].
        double tb = kNever;
        const int m = 20000;
        for (int s = 0; s <= m; ++s) {
            const double ts = 10.0 * s / m;
            if (dist(ts) < sigma) { tb = ts; break; }
        }
        if (std::isinf(t)) {
            EXPECT_TRUE(std::isinf(tb) || dist(tb) > sigma - 1e-6) << k;
        } else if (t < 10.0) {
            ++hits;
            EXPECT_NEAR(dist(t), sigma, 1e-12);
            EXPECT_LE(t, tb + 1e-12);
            EXPECT_GE(t, tb - 10.0 / m - 1e-12);
        }
    }
    EXPECT_GT(hits, 200);
}

TEST(EdFlightRoots, PairOverlapApproachingIsImmediateRecedingIsNever) {
    EXPECT_EQ(pair_contact_time(0.99, 0.0, -1.0, 0.0, 1.0), 0.0);
    EXPECT_TRUE(std::isinf(pair_contact_time(0.99, 0.0, 1.0, 0.0, 1.0)));
    EXPECT_TRUE(std::isinf(pair_contact_time(2.0, 0.0, 0.0, 1.0, 1.0)));
}

TEST(EdFlightRoots, GapClosingTimeMatchesBruteForce) {
    std::mt19937_64 gen(9);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
        const double gap = k % 10 == 0 ? -1e-3 * std::fabs(u(gen)) : std::fabs(u(gen));
        const double v = u(gen), a = (k % 7 == 0) ? 0.0 : u(gen);
        const double t = gap_closing_time(gap, v, a);
        auto g = [&](double s) { return gap + v * s + 0.5 * a * s * s; };
        auto gd = [&](double s) { return v + a * s; };
        if (std::isinf(t)) {
            // Never reaches 0 while decreasing within a long horizon.
            for (int s = 1; s <= 4000; ++s) {
                const double ts = 20.0 * s / 4000;
                EXPECT_FALSE(g(ts) < -1e-9 && gd(ts) < 0 && gap > 0) << k;
            }
            continue;
        }
        ++hits;
        EXPECT_GE(t, 0.0);
        if (gap > 0) {
            EXPECT_NEAR(g(t), 0.0, 1e-11 * (1 + t * t));
            EXPECT_LE(gd(t), 1e-12);
            for (int s = 0; s < 1000; ++s) EXPECT_GT(g(t * s / 1000.0), -1e-12) << k;
        } else {
            // Already past the boundary: fires when the gap is <= 0 and not increasing.
            EXPECT_LE(g(t), 1e-11);
            EXPECT_LE(gd(t), 1e-12);
        }
    }
    EXPECT_GT(hits, 1000);
}
