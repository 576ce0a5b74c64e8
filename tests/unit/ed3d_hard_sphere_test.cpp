// The 3D elastic hard-sphere gas (src/engines/ed3d/hard_sphere_gas.hpp): a binary collision
// against the analytic result, conservation and no overlaps in a gas, the Enskog collision rate
// with the Carnahan-Starling contact value, and the impact-parameter moments of P(b/d) = 2 b/d.
#include "engines/ed3d/hard_sphere_gas.hpp"
#include "core/rng_stream.hpp"
#include "scenarios/hard_sphere_lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace granrepro;

namespace {

// n^3 spheres of diameter 1 on a simple cubic lattice at packing fraction eta, unit Gaussian
// velocity components with zero total momentum (src/scenarios/hard_sphere_lattice.hpp).
HardSphereGas3D gas(int n, double eta, std::uint64_t seed) {
    RngStream rng(seed, 0);
    return simple_cubic_gas(n, eta, 1.0, 1.0, rng);
}

} // namespace

TEST(HardSphereGas3D, BinaryCollisionSwapsNormalComponents) {
    // Sphere 0 at rest, sphere 1 comes along -x with impact parameter b = 0.6 d (offset in y).
    const double b = 0.6;
    HardSphereGas3D g({{5, 5, 5}, {8, 5 + b, 5}}, {{0, 0, 0}, {-1, 0, 0}}, 1.0, 20.0);
    double seen = -1;
    g.run_collisions(1, [&](double x) { seen = x; });
    EXPECT_NEAR(seen, b, 1e-12);
    // At contact n = (cos, sin) with sin = b: the normal part of v_1 goes to sphere 0.
    const double s = b, c = std::sqrt(1 - b * b), vn = -c; // v_1 . n
    const auto& v = g.velocities();
    EXPECT_NEAR(v[0].x, vn * c, 1e-12);
    EXPECT_NEAR(v[0].y, vn * s, 1e-12);
    EXPECT_NEAR(v[1].x, -1 - vn * c, 1e-12);
    EXPECT_NEAR(v[1].y, -vn * s, 1e-12);
    EXPECT_NEAR(g.time(), (3 - c) / 1.0, 1e-12);
}

TEST(HardSphereGas3D, GasConservesEnergyAndMomentumAndNeverOverlaps) {
    HardSphereGas3D g = gas(5, 0.3, 1);
    const double k0 = g.kinetic_energy_per_mass();
    g.run_collisions(20000);
    EXPECT_NEAR(g.kinetic_energy_per_mass(), k0, 1e-10 * k0);
    EXPECT_LT(norm(g.momentum_per_mass()), 1e-10 * std::sqrt(k0));
    EXPECT_GT(g.min_distance(), 1.0 - 1e-9);
}

// Enskog: omega = 4 sqrt(pi) n d^2 g(d) sqrt(T/m) per sphere, T/m = <v^2>/3, with the
// Carnahan-Starling contact value g(d) = (1 - eta/2)/(1 - eta)^3 (accurate to ~1 % at eta = 0.1).
// 20000 collisions after 10 per sphere of equilibration: Poisson error 0.7 %; tolerance 3 %.
TEST(HardSphereGas3D, EnskogCollisionRate) {
    const double eta = 0.1;
    HardSphereGas3D g = gas(5, eta, 2);
    g.run_collisions(625); // 10 collisions per sphere
    const double t0 = g.time();
    const std::uint64_t c = 20000;
    g.run_collisions(c);
    const double n_spheres = 125, box = std::cbrt(n_spheres * M_PI / 6 / eta);
    const double n = n_spheres / (box * box * box);
    const double t_over_m = 2 * g.kinetic_energy_per_mass() / (3 * n_spheres);
    const double gd = (1 - eta / 2) / std::pow(1 - eta, 3);
    const double omega = 4 * std::sqrt(M_PI) * n * gd * std::sqrt(t_over_m);
    const double measured = 2.0 * double(c) / (n_spheres * (g.time() - t0));
    EXPECT_NEAR(measured / omega, 1.0, 0.03);
}

// Molecular chaos in 3D: P(b/d) = 2 b/d, whose mean is 2/3 and second moment 1/2 (standard
// deviation of b/d: sqrt(1/18) = 0.236, so 20000 collisions give a standard error of 0.0017).
TEST(HardSphereGas3D, ImpactParameterMomentsOfTwoBOverD) {
    HardSphereGas3D g = gas(5, 0.1, 3);
    g.run_collisions(625);
    double s1 = 0, s2 = 0;
    const int c = 20000;
    g.run_collisions(c, [&](double x) { s1 += x; s2 += x * x; });
    EXPECT_NEAR(s1 / c, 2.0 / 3.0, 3 * 0.0017);
    EXPECT_NEAR(s2 / c, 0.5, 3 * std::sqrt((1.0 / 3 - 0.25) / c));
}

TEST(HardSphereGas3D, RejectsOverlapsAndSmallBoxes) {
    EXPECT_THROW(HardSphereGas3D({{1, 1, 1}, {1.5, 1, 1}}, {{0, 0, 0}, {0, 0, 0}}, 1.0, 10.0), std::invalid_argument);
    EXPECT_THROW(HardSphereGas3D({{1, 1, 1}}, {{0, 0, 0}}, 1.0, 2.0), std::invalid_argument);
}
