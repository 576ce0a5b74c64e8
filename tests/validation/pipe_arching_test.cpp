// Validation for the pipe-arching experiment (Luding 1998 Sec. 5): the ED engine's frictional
// walls against the Walton-Braun operator (Sec. 2.1, Eqs. (1)-(6) with m_2 = infinity), and the
// momentum balance of a falling column between frictional side walls. (The smooth bouncing disk,
// height lost by r_w^2 per bounce, is tests/validation/ed_validation_test.cpp; here it is repeated
// only with friction on, which must not change the normal restitution.)
#include "gas.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace granrepro;
using namespace granrepro::test;

namespace {

constexpr double kA = 0.5 * kD;
constexpr double kQ = 0.4;  // I = q m a^2 (the paper's 2/7 = q/(1+q))

struct WallShot {
    CollisionRecord rec;
    Vec2 v_after;
    double w_after = 0;
};

// One disk hits the left wall (x = 0) with velocity (-un, vt) and no spin; no gravity.
WallShot shoot(double un, double vt, double rw, double mu, double beta0) {
    EdConfig cfg;
    cfg.lx = 20 * kD;
    cfg.ly = 20 * kD;
    cfg.periodic_x = false;
    cfg.law.q = kQ;
    cfg.walls = {EdWall{0, 0.0, +1, rw, mu, beta0}};
    EdEngine e(cfg, {{5 * kD, 10 * kD}}, {{-un, vt}}, {kA}, {kM});
    WallShot s;
    int hits = 0;
    e.run_until(6.0 * kD / un, [&](const CollisionRecord& c) {
        s.rec = c;
        ++hits;
    });
    EXPECT_EQ(hits, 1);
    s.v_after = e.velocity(0);
    s.w_after = e.spin(0);
    return s;
}

} // namespace

// Walton-Braun at a wall: the contact point's tangential velocity v_ct = v_t - a w (here w = 0
// before) is reversed to -beta0 v_ct while |dP_t| <= mu |dP_n| (sticking), and |dP_t| = mu |dP_n|
// beyond (sliding). The regimes meet at |v_ct|/|v_cn| = mu (1 + r)(1 + 1/q)/(1 + beta0), i.e.
// at the collision angle where beta_1 = beta0 (Sec. 2.1).
TEST(PipeArchingWall, StickingAndSlidingRegimesOfWaltonBraun) {
    const double rw = 0.9, mu = 0.5, beta0 = 0.2, un = 0.1;
    const double crit = mu * (1 + rw) * (1 + 1 / kQ) / (1 + beta0);
    for (double f : {0.1, 0.5, 0.9, 0.99, 1.01, 1.1, 2.0, 10.0}) {
        const double vt = f * crit * un;
        const WallShot s = shoot(un, vt, rw, mu, beta0);
        // Normal restitution is untouched by friction.
        EXPECT_NEAR(s.v_after.x, rw * un, 1e-12 * un) << f;
        const double pn = s.rec.dP.x, pt = s.rec.dP.y;
        EXPECT_NEAR(pn, kM * (1 + rw) * un, 1e-12 * kM * un) << f;
        // Spin from the tangential impulse at the contact point r - a n (Eq. (3)).
        EXPECT_NEAR(s.w_after, -pt / (kQ * kM * kA), 1e-9 * std::abs(pt / (kQ * kM * kA)) + 1e-12) << f;
        const double vct_before = vt, vct_after = s.v_after.y - kA * s.w_after;
        if (f < 1) {
            EXPECT_NEAR(vct_after, -beta0 * vct_before, 1e-9 * vt) << "sticking at " << f;
            EXPECT_LT(std::abs(pt), mu * pn) << f;
        } else {
            EXPECT_NEAR(std::abs(pt), mu * pn, 1e-9 * mu * pn) << "sliding at " << f;
            // beta_1 = -1 - mu (1 + r)(1 + 1/q) cot(gamma), cot(gamma) = -un/vt (approaching).
            const double beta1 = -1 + mu * (1 + rw) * (1 + 1 / kQ) * un / vt;
            EXPECT_NEAR(vct_after, -beta1 * vct_before, 1e-9 * vt) << f;
            EXPECT_LT(beta1, beta0 + 1e-12) << f;
        }
        EXPECT_LT(pt, 0.0) << "friction opposes the sliding direction, " << f;
    }
}

// A disk bouncing on a frictional floor with a horizontal velocity: after the first bounce the
// contact slides or sticks, but the apex height still drops by r_w^2 per bounce.
TEST(PipeArchingWall, FrictionLeavesNormalRestitutionAlone) {
    EdConfig cfg;
    cfg.lx = 1.0;
    cfg.ly = 0.1;
    cfg.periodic_y = false;
    cfg.gravity = {0.0, -9.81};
    cfg.law.q = kQ;
    const double rw = 0.9;
    cfg.walls = {EdWall{1, 0.0, +1, rw, 0.5, 0.2}};
    const double h = 5 * kD;
    EdEngine e(cfg, {{0.5, h + kA}}, {{0.05, 0.0}}, {kA}, {kM});
    std::vector<double> un;
    const double t1 = std::sqrt(2 * h / 9.81), u1 = 9.81 * t1;
    e.run_until(t1 + 0.9 * 2 * rw * u1 / (9.81 * (1 - rw)),
                [&](const CollisionRecord& c) { un.push_back(c.dP.y / (kM * (1.0 + rw))); });
    ASSERT_GE(un.size(), 10u);
    for (std::size_t k = 1; k < 10; ++k) EXPECT_NEAR(un[k] * un[k] / (un[k - 1] * un[k - 1]), rw * rw, 1e-9) << k;
}

// The falling column of Sec. 5 in small: relaxed on a floor, then released between frictional
// side walls with dissipation and TC. Pair collisions conserve momentum, so at every time
//   P_y(t) - P_y(0) = -M g t + J_y(t),   J_y = summed side-wall impulses since t = 0,
// and J_y > 0: wall friction can only brake a column that falls past the walls.
TEST(PipeArchingColumn, MomentumBalanceOfTheFallingColumn) {
    const std::size_t n = 300;
    const double L = 10.1 * kD, g = 9.81, yf = 0.02;
    RngStream rng(7, 0);
    EdConfig cfg;
    cfg.lx = L;
    cfg.ly = 0.06;
    cfg.periodic_x = cfg.periodic_y = false;
    cfg.gravity = {0.0, -g};
    cfg.law = RoughDiskCollision{1.0, 0.0, -1.0, kQ};
    cfg.walls = {EdWall{0, 0.0, +1}, EdWall{0, L, -1}, EdWall{1, yf, +1}};
    EdEngine e(cfg, triangular_lattice_positions(n, kA, L - kA, yf + kA, 1.01 * kD), uniform_velocities(n, 0.05, rng),
               std::vector<double>(n, kA), std::vector<double>(n, kM), {}, -0.05);
    e.run_until(0.0);
    e.set_law(RoughDiskCollision{0.9, 0.5, 0.2, kQ});
    e.set_wall_law(0, 0.9, 0.5, 0.2);
    e.set_wall_law(1, 0.9, 0.5, 0.2);
    e.set_tc(1e-6);
    e.set_wall_enabled(2, false);
    const double M = double(n) * kM, p0 = e.total_momentum().y;
    double jy = 0, jx = 0;
    std::size_t wall_hits = 0;
    auto obs = [&](const CollisionRecord& c) {
        if (c.j < 0) {
            ASSERT_NE(c.j, -3) << "the floor was removed";
            jy += c.dP.y;
            jx += c.dP.x;
            ++wall_hits;
        }
    };
    double px0 = e.total_momentum().x;
    for (int k = 1; k <= 20; ++k) {
        const double t = 0.002 * k;
        e.run_until(t, obs);
        const double dpy = e.total_momentum().y - p0;
        EXPECT_NEAR(dpy, -M * g * t + jy, 1e-9 * M * g * t) << "t = " << t;
        EXPECT_NEAR(e.total_momentum().x - px0, jx, 1e-9 * M * g * t) << "t = " << t;
    }
    EXPECT_GT(wall_hits, 100u);
    EXPECT_GT(jy, 0.0) << "wall friction must brake the fall";
    EXPECT_LT(jy, M * g * 0.04) << "the walls cannot carry more than the weight";
}
