#include "core/rng_stream.hpp"
#include "observables/structure_factor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <thread>
#include <vector>

using namespace granrepro;

TEST(ObsStructureFactor, LatticeSizeIsPowerOfTwoClosestToOneDiameter) {
    // The paper's runs: L = 316 (Fig. 7), 500 and 50 (Sec. 4) diameters.
    EXPECT_EQ(StructureFactor::lattice_size(316.0, 1.0), 256); // cell 1.23 d vs 0.62 d
    EXPECT_EQ(StructureFactor::lattice_size(0.5, 0.001), 512); // cell 0.98 d
    EXPECT_EQ(StructureFactor::lattice_size(50.0, 1.0), 64);   // cell 0.78 d vs 1.56 d
    EXPECT_EQ(StructureFactor(316.0, 1.0).M(), 256);
}

TEST(ObsStructureFactor, SquareLatticeGivesBraggPeaksOnly) {
    // 16 x 16 particles, spacing 4 d in a box of 64 d: reciprocal lattice at n = 16 (m1, m2).
    const double l = 64.0;
    StructureFactor sf(l, 1.0);
    ASSERT_EQ(sf.M(), 64);
    std::vector<Vec2> p;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) p.push_back({4.0 * i + 0.5, 4.0 * j + 0.5});
    const double N = static_cast<double>(p.size());
    sf.accumulate(p);
    const auto& S = sf.last_spectrum();
    const int half = sf.M() / 2 + 1;
    for (int i = 0; i < sf.M(); ++i)
        for (int j = 0; j < half; ++j) {
            const bool bragg = sf.signed_mode(i) % 16 == 0 && j % 16 == 0;
            EXPECT_NEAR(S[static_cast<std::size_t>(i) * half + j], bragg ? N : 0.0, 1e-9 * N)
                << "mode " << sf.signed_mode(i) << "," << j;
        }
    const auto sh = sf.radial_average();
    // Shells holding reciprocal-lattice vectors: |n| = 16, 16 sqrt2 = 22.6 -> 23, 32.
    for (std::size_t s = 0; s < sh.k.size(); ++s) {
        const int k = static_cast<int>(sh.k[s]);
        if (k == 16 || k == 23 || k == 32) EXPECT_GT(sh.S[s], 1.0) << "k " << k;
        else EXPECT_NEAR(sh.S[s], 0.0, 1e-9) << "k " << k;
    }
    // Shell 16 holds the 4 modes (+-16, 0), (0, +-16) with S = N among all its modes.
    EXPECT_NEAR(sh.S[15], 4.0 * N / static_cast<double>(sh.modes[15]), 1e-9 * N);
}

TEST(ObsStructureFactor, UniformRandomPointsGiveOne) {
    const double l = 100.0;
    StructureFactor sf(l, 1.0);
    ASSERT_EQ(sf.M(), 128);
    RngStream rng(77, 2);
    for (int s = 0; s < 4; ++s) {
        std::vector<Vec2> p(5000);
        for (auto& x : p) x = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
        sf.accumulate(p);
    }
    const auto sh = sf.radial_average();
    double chi2 = 0.0;
    int n = 0;
    for (std::size_t s = 0; s < sh.k.size(); ++s) {
        if (sh.k[s] < 10) continue; // few modes at small k
        EXPECT_NEAR(sh.S[s], 1.0, 5.0 * sh.error[s]) << "k " << sh.k[s];
        chi2 += std::pow((sh.S[s] - 1.0) / sh.error[s], 2);
        ++n;
    }
    EXPECT_LT(chi2 / n, 2.0);
}

TEST(ObsStructureFactor, ParsevalAndZeroMode) {
    const double l = 32.0;
    StructureFactor sf(l, 1.0);
    RngStream rng(3, 9);
    std::vector<Vec2> p(700);
    for (auto& x : p) x = {rng.uniform(-l, 2.0 * l), rng.uniform(0.0, l)}; // wrapped into the box
    sf.accumulate(p);
    const auto& c = sf.last_density();
    const auto& S = sf.last_spectrum();
    const double N = static_cast<double>(p.size());
    EXPECT_DOUBLE_EQ(std::accumulate(c.begin(), c.end(), 0.0), N);
    EXPECT_NEAR(S[0], N, 1e-9 * N); // rho_0 = N
    const int M = sf.M(), half = M / 2 + 1;
    double lhs = 0.0, c2 = 0.0;
    for (int i = 0; i < M; ++i)
        for (int j = 0; j < half; ++j) lhs += sf.mode_weight(j) * S[static_cast<std::size_t>(i) * half + j];
    for (double x : c) c2 += x * x;
    // sum_n |rho_n|^2 = M^2 sum_x c(x)^2, divided by N on both sides.
    EXPECT_NEAR(lhs, static_cast<double>(M) * M * c2 / N, 1e-9 * lhs);
}

TEST(ObsStructureFactor, ParallelConstructionIsSafeAndDeterministic) {
    std::vector<Vec2> p;
    RngStream rng(1, 1);
    for (int k = 0; k < 300; ++k) p.push_back({rng.uniform(0.0, 20.0), rng.uniform(0.0, 20.0)});
    std::vector<std::vector<double>> res(4);
    std::vector<std::thread> th;
    for (int t = 0; t < 4; ++t)
        th.emplace_back([&, t] {
            for (int r = 0; r < 5; ++r) {
                StructureFactor sf(20.0, 1.0);
                sf.accumulate(p);
                res[t] = sf.radial_average().S;
            }
        });
    for (auto& x : th) x.join();
    for (int t = 1; t < 4; ++t) EXPECT_EQ(res[t], res[0]);
}
