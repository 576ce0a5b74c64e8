#include "core/rng_stream.hpp"
#include "observables/pair_correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace granrepro;

namespace {

enum class Method { CellList, BruteForce };

void add(PairCorrelation& pc, const std::vector<Vec2>& p, Method m) {
    if (m == Method::CellList) pc.accumulate(p);
    else pc.accumulate_brute_force(p);
}

// Triangular lattice with lattice constant a that tiles the periodic box exactly:
// nx columns, ny (even) rows at height a*sqrt(3)/2.
std::vector<Vec2> triangular(int nx, int ny, double a, double& Lx, double& Ly) {
    const double h = a * std::sqrt(3.0) / 2.0;
    Lx = nx * a;
    Ly = ny * h;
    std::vector<Vec2> p;
    for (int r = 0; r < ny; ++r)
        for (int c = 0; c < nx; ++c) p.push_back({(c + 0.5 * (r % 2) + 0.25) * a, (r + 0.5) * h});
    return p;
}

class PairCorrelationBoth : public ::testing::TestWithParam<Method> {};

} // namespace

TEST_P(PairCorrelationBoth, IdealGasIsOne) {
    const double Lx = 40.0, Ly = 25.0; // m, rectangular on purpose
    const int n = 2000, snaps = 5, bins = 20;
    PairCorrelation pc(Lx, Ly, 5.0, bins);
    RngStream rng(12345, 7);
    for (int s = 0; s < snaps; ++s) {
        std::vector<Vec2> p(n);
        for (auto& x : p) x = {rng.uniform(0.0, Lx), rng.uniform(0.0, Ly)};
        add(pc, p, GetParam());
    }
    const auto g = pc.g();
    const auto err = pc.g_error();
    double chi2 = 0.0;
    for (int k = 0; k < bins; ++k) {
        // Each bin is Poisson in its pair count; 4 sigma per bin, and the bins together as chi^2.
        EXPECT_NEAR(g[k], 1.0, 4.0 * err[k]) << "bin " << k;
        chi2 += (g[k] - 1.0) * (g[k] - 1.0) / (err[k] * err[k]);
    }
    EXPECT_LT(chi2 / bins, 2.0);
}

TEST_P(PairCorrelationBoth, TriangularLatticePeaksAtOneSqrt3Two) {
    const double a = 1.3; // lattice constant [m]
    double Lx = 0.0, Ly = 0.0;
    const auto p = triangular(12, 14, a, Lx, Ly);
    const int bins = 80;
    const double r_max = 2.4 * a; // bin width 0.03 a keeps 1, sqrt3, 2 off the bin edges
    PairCorrelation pc(Lx, Ly, r_max, bins);
    add(pc, p, GetParam());
    const auto& c = pc.counts();
    const double dr = r_max / bins;
    auto bin_of = [&](double r) { return static_cast<int>(r * a / dr); };
    const std::size_t N = p.size();
    // Each shell of the triangular lattice at 1, sqrt3, 2 has 6 neighbours: 3N unordered pairs.
    for (double r : {1.0, std::sqrt(3.0), 2.0}) EXPECT_EQ(c[bin_of(r)], 3 * N) << "shell " << r;
    for (int k = 0; k < bins; ++k) {
        if (k == bin_of(1.0) || k == bin_of(std::sqrt(3.0)) || k == bin_of(2.0)) continue;
        EXPECT_EQ(c[k], 0u) << "bin " << k;
    }
    EXPECT_GT(pc.g()[bin_of(1.0)], 1.0);
}

INSTANTIATE_TEST_SUITE_P(Obs, PairCorrelationBoth, ::testing::Values(Method::CellList, Method::BruteForce),
                         [](const auto& info) {
                             return std::string(info.param == Method::CellList ? "CellList" : "BruteForce");
                         });

TEST(ObsPairCorrelation, CellListEqualsBruteForceExactly) {
    RngStream rng(99, 1);
    // Several box shapes, including ones with only 2 cells along an axis (neighbour aliasing)
    // and positions outside the primary box.
    for (auto [Lx, Ly, rmax] : {std::tuple{10.0, 10.0, 5.0}, std::tuple{30.0, 12.0, 6.0},
                                std::tuple{50.0, 50.0, 2.5}, std::tuple{9.0, 20.0, 3.0}}) {
        std::vector<Vec2> p(700);
        for (auto& x : p) x = {rng.uniform(-Lx, 2.0 * Lx), rng.uniform(0.0, Ly)};
        PairCorrelation a(Lx, Ly, rmax, 37), b(Lx, Ly, rmax, 37);
        a.accumulate(p);
        b.accumulate_brute_force(p);
        EXPECT_EQ(a.counts(), b.counts()) << Lx << "x" << Ly << " rmax " << rmax;
        std::uint64_t tot = 0;
        for (auto c : a.counts()) tot += c;
        EXPECT_GT(tot, 0u);
    }
}

TEST(ObsPairCorrelation, RejectsRmaxBeyondHalfBox) {
    EXPECT_THROW(PairCorrelation(10.0, 4.0, 2.5, 10), std::invalid_argument);
    EXPECT_NO_THROW(PairCorrelation(10.0, 4.0, 2.0, 10));
}
