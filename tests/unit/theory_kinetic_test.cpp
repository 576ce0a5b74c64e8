// The kinetic-theory formulas of src/theory/kinetic_theory.hpp against independent evaluations:
// the paper's quoted numbers, exact limits, and numerical derivatives.
#include "theory/kinetic_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace granrepro::theory;

TEST(KineticTheory, HendersonContactValueIsTheInverseOfLudingsSStar) {
    // Luding Sec. 3.1: s_*(0.25) = (1 - rho)^2 / (1 - 7 rho/16) ~ 0.63158.
    EXPECT_NEAR(1.0 / henderson_contact_value(0.25), 0.63158, 5e-6);
    EXPECT_DOUBLE_EQ(henderson_contact_value(0.0), 1.0);
}

TEST(KineticTheory, HendersonEquationOfStateIsTheVirialWithItsContactValue) {
    for (double rho : {0.05, 0.25, 0.5, 0.7})
        EXPECT_NEAR(henderson_compressibility(rho), 1.0 + 2.0 * rho * henderson_contact_value(rho), 1e-12);
}

TEST(KineticTheory, StructureFactorAtZeroIsTheInverseDerivativeOfTheDensityTimesZ) {
    for (double rho : {0.01, 0.25, 0.6}) {
        const double h = 1e-6;
        const double deriv = ((rho + h) * henderson_compressibility(rho + h) - (rho - h) * henderson_compressibility(rho - h)) / (2 * h);
        EXPECT_NEAR(hard_disk_structure_factor_zero(rho), 1.0 / deriv, 1e-7);
    }
    EXPECT_NEAR(hard_disk_structure_factor_zero(0.25), 0.3318, 1e-4);
    // Dilute limit: S(0) = 1 - 4 rho + O(rho^2) (second virial coefficient of disks, B2 = pi d^2/2).
    EXPECT_NEAR((1.0 - hard_disk_structure_factor_zero(1e-5)) / 1e-5, 4.0, 1e-3);
}

TEST(KineticTheory, HaffTimeScaleIsThePapersNumber) {
    // Luding Sec. 3.1: t0^-1 = 23.24 1/s for r = 0.8, rho = 0.25, d = 1 mm, vbar = 0.2047 m/s.
    const double omega0 = enskog_collision_rate_vbar(0.25, 1e-3, 0.2047, henderson_contact_value(0.25));
    EXPECT_NEAR(1.0 / haff_t0(0.8, omega0), 23.24, 0.005 * 23.24);
    // The two forms of the Enskog rate agree (T/m = vbar^2/2, n = 4 rho/(pi d^2)).
    const double n = 4 * 0.25 / (std::numbers::pi * 1e-6);
    EXPECT_NEAR(enskog_collision_rate(n, 1e-3, 0.2047 * 0.2047 / 2, 1.5), enskog_collision_rate_vbar(0.25, 1e-3, 0.2047, 1.5), 1e-9);
    // Haff's law: d(K/K0)/dt = -(1 - r^2) omega K/2 with omega = omega0 sqrt(K/K0).
    const double t0 = haff_t0(0.8, omega0), t = 0.7 * t0, h = 1e-7 * t0;
    const double dkdt = (haff_energy_ratio(t + h, t0) - haff_energy_ratio(t - h, t0)) / (2 * h);
    const double k = haff_energy_ratio(t, t0);
    EXPECT_NEAR(dkdt, -(1 - 0.64) * omega0 * std::sqrt(k) * k / 2, 1e-6 * std::fabs(dkdt));
    // C/N is the integral of omega = omega0 sqrt(K/K0).
    EXPECT_NEAR(haff_collisions_per_particle(t, t0, omega0), omega0 * t0 * std::log(1.7), 1e-9);
}

TEST(KineticTheory, VanNoijeErnstA2) {
    EXPECT_NEAR(van_noije_ernst_a2(0.8, 2), -0.0219, 5e-5); // the -0.022 of issue 16
    EXPECT_NEAR(van_noije_ernst_a2(0.8, 3), -0.0126, 5e-5);
    EXPECT_EQ(van_noije_ernst_a2(1.0, 2), 0.0);
    EXPECT_NEAR(van_noije_ernst_a2(1.0 / std::sqrt(2.0), 2), 0.0, 1e-15); // sign change at 1/sqrt(2)
    EXPECT_GT(van_noije_ernst_a2(0.3, 2), 0.0);
    // Independent evaluation at r = 0.5, d = 2: 16 * 0.5 * 0.5 / (9 + 48 - 12.5 + 3.75).
    EXPECT_NEAR(van_noije_ernst_a2(0.5, 2), 4.0 / 48.25, 1e-15);
}

TEST(KineticTheory, SonineA2OfAMaxwellianIsZero) {
    // 2D Maxwellian: v^2 exponential with mean mu, <v^4> = 2 mu^2.
    EXPECT_DOUBLE_EQ(sonine_a2_2d(0.3, 2 * 0.09), 0.0);
    // Equal speeds: <v^4> = <v^2>^2, a2 = -1/2.
    EXPECT_DOUBLE_EQ(sonine_a2_2d(1.0, 1.0), -0.5);
    EXPECT_NEAR(sonine_a2_2d_maxwell_error(1e5), 0.00707, 1e-5);
}

TEST(KineticTheory, FreeVolumeFactor) {
    EXPECT_NEAR(free_volume_factor(0.25, 0.82), 1.4386, 1e-4);
    // Luding's DSMC correction against Enskog at rho = 0.25: 0.909 of Enskog's rate.
    EXPECT_NEAR(free_volume_factor(0.25, 0.82) / henderson_contact_value(0.25), 0.9086, 1e-4);
}
