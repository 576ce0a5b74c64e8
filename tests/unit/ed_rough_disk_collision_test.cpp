// Analytic two-body checks of the Walton-Braun operator (Luding 1998 Eqs. (1)-(6)).
#include "models/rough_disk_collision.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>

using granrepro::RoughDiskCollision;
using granrepro::Vec2;

namespace {

struct Body {
    Vec2 r, v;
    double w, m, a;
};

// Contact velocity of Eq. (1) with t = perp(n).
Vec2 contact_velocity(const Body& b1, const Body& b2, const Vec2& n) {
    return b1.v - b2.v - granrepro::perp(n) * (b1.a * b1.w + b2.a * b2.w);
}

double energy(const Body& b, double q) { return 0.5 * b.m * norm2(b.v) + 0.5 * q * b.m * b.a * b.a * b.w * b.w; }

void apply(const RoughDiskCollision::Result& res, Body& b1, Body& b2) {
    b1.v += res.dP / b1.m;
    b2.v -= res.dP / b2.m;
    b1.w += res.dw1;
    b2.w += res.dw2;
}

// Random approaching pair with unequal masses and radii.
std::pair<Body, Body> random_pair(std::mt19937_64& gen) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.5, 2.0);
    Body b1{{0, 0}, {u(gen), u(gen)}, 10 * u(gen), pos(gen), 0.5 * pos(gen)};
    Body b2{{0, 0}, {u(gen), u(gen)}, 10 * u(gen), pos(gen), 0.5 * pos(gen)};
    const double phi = 3.0 * u(gen);
    const Vec2 n{std::cos(phi), std::sin(phi)};
    b1.r = b2.r + n * (b1.a + b2.a);
    if (dot(contact_velocity(b1, b2, n), n) > 0) std::swap(b1.v, b2.v);
    return {b1, b2};
}

} // namespace

TEST(EdRoughDiskCollision, HeadOnSmoothGivesMinusRV) {
    for (double r : {0.0, 0.5, 0.8, 1.0}) {
        RoughDiskCollision law{r, 0.0, -1.0, 0.5};
        Body b1{{0, 0}, {1.0, 0}, 0, 1.0, 0.5}, b2{{1, 0}, {-1.0, 0}, 0, 1.0, 0.5};
        const Vec2 n{-1.0, 0.0}; // from 2 to 1
        apply(law.collide(b1.v, b1.w, b1.m, b1.a, b2.v, b2.w, b2.m, b2.a, n), b1, b2);
        EXPECT_DOUBLE_EQ(b1.v.x, -r);
        EXPECT_DOUBLE_EQ(b2.v.x, r);
        EXPECT_EQ(b1.v.y, 0.0);
        EXPECT_EQ(b1.w, 0.0);
    }
}

TEST(EdRoughDiskCollision, ConservesMomentumAndAngularMomentum) {
    std::mt19937_64 gen(7);
    const RoughDiskCollision law{0.7, 0.4, 0.3, 0.5};
    for (int k = 0; k < 1000; ++k) {
        auto [b1, b2] = random_pair(gen);
        const Vec2 n = (b1.r - b2.r) / norm(b1.r - b2.r);
        const Vec2 p0 = b1.m * b1.v + b2.m * b2.v;
        // Angular momentum about the origin: orbital + spin, I = q m a^2.
        auto ang = [&](const Body& a, const Body& b) {
            return a.m * cross(a.r, a.v) + b.m * cross(b.r, b.v) + law.q * a.m * a.a * a.a * a.w +
                   law.q * b.m * b.a * b.a * b.w;
        };
        const double l0 = ang(b1, b2);
        apply(law.collide(b1.v, b1.w, b1.m, b1.a, b2.v, b2.w, b2.m, b2.a, n), b1, b2);
        const Vec2 p1 = b1.m * b1.v + b2.m * b2.v;
        EXPECT_NEAR(p1.x, p0.x, 1e-14);
        EXPECT_NEAR(p1.y, p0.y, 1e-14);
        EXPECT_NEAR(ang(b1, b2), l0, 1e-13);
    }
}

TEST(EdRoughDiskCollision, ContactVelocityRestitutionAndEnergyLoss) {
    std::mt19937_64 gen(11);
    for (double q : {0.4, 0.5}) {
        const RoughDiskCollision law{0.8, 0.3, 0.4, q};
        int n_slide = 0, n_stick = 0;
        for (int k = 0; k < 2000; ++k) {
            auto [b1, b2] = random_pair(gen);
            const Vec2 n = (b1.r - b2.r) / norm(b1.r - b2.r);
            const Vec2 t = granrepro::perp(n);
            const Vec2 vc = contact_velocity(b1, b2, n);
            const double vcn = dot(vc, n), vct = dot(vc, t);
            const double e0 = energy(b1, q) + energy(b2, q);
            const auto res = law.collide(b1.v, b1.w, b1.m, b1.a, b2.v, b2.w, b2.m, b2.a, n);
            // Independent beta = min(beta0, beta1), beta1 = -1 - mu(1+r) cot(gamma)(1+1/q),
            // cot(gamma) = vcn/|vct| (the paper's formula, valid for any masses).
            const double beta1 = -1.0 - law.mu * (1 + law.r) * (vcn / std::fabs(vct)) * (1 + 1 / q);
            const double beta = std::min(law.beta0, beta1);
            EXPECT_NEAR(res.beta, beta, 1e-12);
            EXPECT_EQ(res.sliding, beta1 < law.beta0);
            (res.sliding ? n_slide : n_stick)++;
            apply(res, b1, b2);
            const Vec2 vc1 = contact_velocity(b1, b2, n);
            EXPECT_NEAR(dot(vc1, n), -law.r * vcn, 1e-13);
            EXPECT_NEAR(dot(vc1, t), -beta * vct, 1e-12);
            const double m12 = 1 / (1 / b1.m + 1 / b2.m);
            const double mt = m12 * q / (1 + q);
            const double de = -0.5 * (1 - law.r * law.r) * m12 * vcn * vcn - 0.5 * (1 - beta * beta) * mt * vct * vct;
            EXPECT_NEAR(energy(b1, q) + energy(b2, q) - e0, de, 1e-12);
            // Coulomb: |dP_t| <= mu |dP_n|, with equality when sliding.
            const double pn = std::fabs(dot(res.dP, n)), pt = std::fabs(dot(res.dP, t));
            if (res.sliding) EXPECT_NEAR(pt, law.mu * pn, 1e-13);
            else EXPECT_LE(pt, law.mu * pn * (1 + 1e-12));
        }
        EXPECT_GT(n_slide, 100);
        EXPECT_GT(n_stick, 100);
    }
}

TEST(EdRoughDiskCollision, PaperFactorTwoSeventhsForSpheresQ) {
    // Sticking, equal masses, q = 2/5: dP_t = -(2/7) m12 (1+beta0) vct as printed in Eq. (6).
    const RoughDiskCollision law{0.9, 100.0, 0.5, 0.4};
    const Vec2 n{1, 0};
    const Vec2 v1{-1.0, 0.3}, v2{0, 0};
    const auto res = law.collide(v1, 0.0, 2.0, 0.5, v2, 0.0, 2.0, 0.5, n);
    EXPECT_FALSE(res.sliding);
    EXPECT_NEAR(res.dP.y, -(2.0 / 7.0) * 1.0 * 1.5 * 0.3, 1e-15);
    EXPECT_NEAR(res.dP.x, 1.0 * 1.9 * 1.0, 1e-15);
}

TEST(EdRoughDiskCollision, SmoothLimitIsExact) {
    std::mt19937_64 gen(3);
    for (int k = 0; k < 200; ++k) {
        auto [b1, b2] = random_pair(gen);
        b1.w = b2.w = 0.0;
        const Vec2 n = (b1.r - b2.r) / norm(b1.r - b2.r);
        const RoughDiskCollision smooth{0.8, 0.0, -1.0, 0.5};
        const auto ref = smooth.collide<false>(b1.v, 0, b1.m, b1.a, b2.v, 0, b2.m, b2.a, n);
        for (const RoughDiskCollision& law : {RoughDiskCollision{0.8, 0.0, 0.6, 0.5}, RoughDiskCollision{0.8, 0.7, -1.0, 0.5}}) {
            const auto res = law.collide<true>(b1.v, 0, b1.m, b1.a, b2.v, 0, b2.m, b2.a, n);
            EXPECT_EQ(res.dP, ref.dP);
            EXPECT_EQ(res.dw1, 0.0);
            EXPECT_EQ(res.dw2, 0.0);
        }
    }
}

TEST(EdRoughDiskCollision, WallHasInfiniteMass) {
    const double inf = std::numeric_limits<double>::infinity();
    const Vec2 n{0, 1}; // floor below the disk
    // Smooth wall: normal component reversed and scaled, tangential untouched.
    const RoughDiskCollision smooth{0.6, 0.0, -1.0, 0.5};
    const auto s = smooth.collide(Vec2{0.3, -2.0}, 5.0, 1.5, 0.1, Vec2{}, 0.0, inf, 0.0, n);
    EXPECT_DOUBLE_EQ(s.dP.y / 1.5, 2.0 * 1.6);
    EXPECT_EQ(s.dP.x, 0.0);
    EXPECT_EQ(s.dw1, 0.0);
    EXPECT_EQ(s.dw2, 0.0);
    // Rough sticking wall: contact-point velocity v - a w t restituted with -beta0.
    const RoughDiskCollision rough{0.6, 10.0, 0.2, 0.5};
    const Vec2 v{0.3, -2.0};
    const double w = 5.0, a = 0.1, m = 1.5;
    const auto res = rough.collide(v, w, m, a, Vec2{}, 0.0, inf, 0.0, n);
    const Vec2 t = granrepro::perp(n);
    const double vct = dot(v - t * (a * w), t);
    const Vec2 v1 = v + res.dP / m;
    const double w1 = w + res.dw1;
    EXPECT_NEAR(dot(v1 - t * (a * w1), t), -0.2 * vct, 1e-14);
    EXPECT_NEAR(v1.y, 0.6 * 2.0, 1e-14);
    EXPECT_EQ(res.dw2, 0.0);
}
