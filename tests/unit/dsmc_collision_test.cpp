// Per-collision physics of the DSMC engine (Luding 1998 Sec. 2.4, Eqs. (15)-(17)): acceptance
// probability, impact parameter, conservation, restitution of the normal component only, the TC
// model and the two dense-gas corrections. Every collision is checked against the velocities the
// pair had just before it, kept independently of the engine's report.
#include "gas.hpp"

#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace granrepro;
using namespace granrepro::test;

namespace {

// Random positions, Gaussian velocities (T/m = 1 m^2/s^2); masses alternate between kM and
// mass_ratio * kM, radii between d/2 and radius_ratio * d/2 when asked for.
DsmcEngine gas(std::size_t n, double rho, DsmcConfig cfg, double mass_ratio = 1.0, double radius_ratio = 1.0,
               std::uint64_t seed = 3) {
    const double l = box_for(n, rho);
    cfg.lx = cfg.ly = l;
    RngStream rng(seed, 17);
    std::vector<Vec2> pos(n), vel(n);
    std::vector<double> rad(n), mass(n);
    for (std::size_t i = 0; i < n; ++i) {
        pos[i] = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
        vel[i] = {rng.normal(), rng.normal()};
        mass[i] = i % 2 ? mass_ratio * kM : kM;
        rad[i] = i % 2 ? radius_ratio * 0.5 * kD : 0.5 * kD;
    }
    return DsmcEngine(cfg, pos, vel, rad, mass);
}

Vec2 min_image(Vec2 d, double lx, double ly) {
    d.x -= lx * std::round(d.x / lx);
    d.y -= ly * std::round(d.y / ly);
    return d;
}

// Compares each collision with the pair's velocities just before it.
struct Tracker {
    const DsmcEngine* e = nullptr;
    double r = 1.0;      // restitution of an inelastic collision
    bool tc_huge = false; // t_c so large that any particle that collided before is elastic
    std::vector<Vec2> prev;
    Vec2 p0;
    double p_scale = 0.0; // sum m |v| [kg m/s]
    std::uint64_t seen = 0, elastic = 0, tc_mismatch = 0, not_approaching = 0;
    double err_momentum_pair = 0.0, err_momentum_total = 0.0, err_normal = 0.0, err_tangent = 0.0;
    double err_energy = 0.0, err_geometry = 0.0, err_b = 0.0, err_unit = 0.0, err_displacement = 0.0;
    std::vector<double> b;

    void start() {
        prev = e->velocities();
        p0 = e->total_momentum();
        p_scale = 0.0;
        for (std::size_t i = 0; i < prev.size(); ++i) p_scale += e->masses()[i] * norm(prev[i]);
    }
    void operator()(const CollisionRecord& c) {
        ++seen;
        const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
        const double mi = e->masses()[i], mj = e->masses()[j];
        const double dij = e->radii()[i] + e->radii()[j];
        const Vec2 vi = prev[i], vj = prev[j];
        const Vec2 wi = e->velocities()[i], wj = e->velocities()[j];
        const Vec2 g = vi - vj, gp = wi - wj;
        const Vec2 t = perp(c.n);
        const double gn = dot(g, c.n), gs = norm(g);
        err_unit = std::max(err_unit, std::fabs(norm(c.n) - 1.0));
        if (!(gn < 0.0)) ++not_approaching;
        // Eq. (17): b = |(r_i - r_j) x v_ij/|v_ij||, with r_i - r_j = d_ij n at the virtual contact.
        err_geometry = std::max(err_geometry, norm(c.ri - c.rj - dij * c.n) / dij);
        err_b = std::max(err_b, std::fabs(std::fabs(cross(c.ri - c.rj, g / gs)) / dij - c.b_over_d));
        b.push_back(c.b_over_d);
        const double re = c.elastic ? 1.0 : r;
        if (c.elastic) ++elastic;
        if (tc_huge) {
            const bool had = e->collision_counts()[i] > 1 || e->collision_counts()[j] > 1;
            if (had != c.elastic) ++tc_mismatch;
        }
        // Round-off scale: the velocities the differences were formed from, not |v_ij|.
        const double vs = norm(vi) + norm(vj);
        err_normal = std::max(err_normal, std::fabs(dot(gp, c.n) + re * gn) / vs);
        err_tangent = std::max(err_tangent, std::fabs(dot(gp, t) - dot(g, t)) / vs);
        const Vec2 dp = (mi * wi + mj * wj) - (mi * vi + mj * vj);
        err_momentum_pair = std::max(err_momentum_pair, norm(dp) / (mi * norm(vi) + mj * norm(vj)));
        err_momentum_total = std::max(err_momentum_total, norm(e->total_momentum() - p0) / p_scale);
        const double m12 = mi * mj / (mi + mj);
        const double e_before = 0.5 * (mi * norm2(vi) + mj * norm2(vj));
        const double e_after = 0.5 * (mi * norm2(wi) + mj * norm2(wj));
        const double loss = 0.5 * (1.0 - re * re) * m12 * gn * gn; // Walton-Braun, beta0 = -1
        err_energy = std::max(err_energy, std::fabs(e_before - e_after - loss) / e_before);
        if (e->config().displacement) {
            const Vec2 moved = min_image(e->positions()[i] - c.ri, e->config().lx, e->config().ly);
            err_displacement = std::max(err_displacement, norm(moved - (mj / (mi + mj) * dij) * c.n) / dij);
        }
        prev[i] = wi;
        prev[j] = wj;
    }
};

// `steps` steps of e with every collision checked; r and tc_huge as in Tracker.
Tracker run_tracked(DsmcEngine& e, int steps, double r = 1.0, bool tc_huge = false) {
    Tracker tr;
    tr.e = &e;
    tr.r = r;
    tr.tc_huge = tc_huge;
    tr.start();
    for (int k = 0; k < steps; ++k) e.step(tr);
    return tr;
}

} // namespace

TEST(DsmcCollision, ElasticCollisionsConserveMomentumAndEnergyExactly) {
    auto e = gas(3000, 0.1, {}, 3.0); // unequal masses: the split of dP must still be exact
    const Tracker tr = run_tracked(e, 150);
    ASSERT_GT(tr.seen, 2000u);
    EXPECT_EQ(tr.not_approaching, 0u);
    EXPECT_LT(tr.err_unit, 1e-15);
    EXPECT_LT(tr.err_momentum_pair, 1e-15);
    EXPECT_LT(tr.err_momentum_total, 1e-14);
    EXPECT_LT(tr.err_energy, 1e-14);
    EXPECT_LT(tr.err_normal, 1e-14);
    EXPECT_LT(tr.err_tangent, 1e-14);
    EXPECT_LT(tr.err_geometry, 1e-11); // positions ~100 d: round-off of r_i - d n
    EXPECT_LT(tr.err_b, 1e-12);
}

TEST(DsmcCollision, RestitutionActsOnTheNormalComponentOnly) {
    DsmcConfig cfg;
    cfg.r = 0.7;
    auto e = gas(3000, 0.1, cfg, 2.0, 1.5); // polydisperse: sigma_ij, d_ij per pair
    const Tracker tr = run_tracked(e, 150, 0.7);
    ASSERT_GT(tr.seen, 1000u);
    EXPECT_EQ(tr.elastic, 0u);
    EXPECT_EQ(tr.not_approaching, 0u);
    EXPECT_LT(tr.err_normal, 1e-14);  // v_n' = -r v_n
    EXPECT_LT(tr.err_tangent, 1e-14); // v_t' = v_t
    EXPECT_LT(tr.err_energy, 1e-13);  // loss (1-r^2)/2 m12 v_n^2 and nothing else
    EXPECT_LT(tr.err_momentum_pair, 1e-15);
    EXPECT_LT(tr.err_momentum_total, 1e-14);
    EXPECT_LT(tr.err_b, 1e-12);
}

TEST(DsmcCollision, TcModelMakesRepeatedCollisionsElastic) {
    DsmcConfig cfg;
    cfg.r = 0.5;
    cfg.t_c = 1e9; // [s]: every particle's second collision comes within t_c
    auto e = gas(2000, 0.1, cfg);
    const Tracker tr = run_tracked(e, 200, 0.5, true);
    ASSERT_GT(tr.elastic, 100u);
    EXPECT_LT(tr.elastic, tr.seen);
    EXPECT_EQ(tr.tc_mismatch, 0u);
    EXPECT_EQ(tr.elastic, e.elastic_collisions());
    EXPECT_LT(tr.err_energy, 1e-13); // elastic ones conserve energy, the others lose exactly their share
}

TEST(DsmcCollision, ImpactParameterIsUniform) {
    auto e = gas(4000, 0.1, {});
    const Tracker tr = run_tracked(e, 400);
    ASSERT_GT(tr.b.size(), 20000u);
    constexpr int kBins = 20;
    std::vector<double> h(kBins, 0.0);
    for (double x : tr.b) h[std::min(kBins - 1, static_cast<int>(x * kBins))] += 1.0;
    const double expect = static_cast<double>(tr.b.size()) / kBins;
    double chi2 = 0.0;
    for (double c : h) chi2 += (c - expect) * (c - expect) / expect;
    EXPECT_GT(gsl_cdf_chisq_Q(chi2, kBins - 1), 1e-4) << "chi2 = " << chi2;
    double mean = 0.0;
    for (double x : tr.b) mean += x;
    mean /= static_cast<double>(tr.b.size());
    EXPECT_NEAR(mean, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / static_cast<double>(tr.b.size())));
}

TEST(DsmcCollision, AcceptedFractionIsMeanRelativeSpeedOverVmax) {
    // v_max frozen (no re-sampling), elastic gas: the velocity distribution stays Maxwellian with
    // the sample's T exactly, and candidates are uniform pairs independent of velocity, so
    // P(accept) = <|v_ij|>/v_max with <|v_ij|> = sqrt(pi T/m) (2D, equal masses).
    DsmcConfig cfg;
    cfg.resample_interval = 1u << 30;
    auto e = gas(20000, 0.1, cfg);
    e.run_steps(300);
    ASSERT_EQ(e.vmax_raises(), 0u);
    const double t_over_m = e.kinetic_energy() / (static_cast<double>(e.size()) * kM); // 2D: K = N T
    const double p = std::sqrt(std::numbers::pi * t_over_m) / e.v_max();
    const double c = static_cast<double>(e.candidates());
    const double measured = static_cast<double>(e.total_collisions()) / c;
    ASSERT_GT(c, 1e5);
    EXPECT_NEAR(measured, p, 5.0 * std::sqrt(p * (1.0 - p) / c)) << "p = " << p;
    // And the number of candidates is Eq. (15): sum of N(N-1) sigma v_max tau / (2 V_c).
    const double mc = e.exposure() * e.cross_section() * e.v_max();
    EXPECT_NEAR(c, mc, 5.0 * std::sqrt(mc));
}

TEST(DsmcCollision, FreeVolumeOfOneCellIsVcMinusV0) {
    // One cell holding all particles: V_0 = N pi a^2 / 0.82, so exposure per step =
    // N(N-1) tau / (2 (V_c - V_0)) for both the cell and the mean mode.
    for (auto mode : {DsmcFreeVolume::off, DsmcFreeVolume::cell, DsmcFreeVolume::mean}) {
        DsmcConfig cfg;
        cfg.min_cell_diameters = 1e9;
        cfg.free_volume = mode;
        const std::size_t n = 400;
        auto e = gas(n, 0.3, cfg);
        ASSERT_EQ(e.cells_x() * e.cells_y(), 1u);
        e.step();
        const double vc = e.config().lx * e.config().ly;
        const double v0 = static_cast<double>(n) * std::numbers::pi * 0.25 * kD * kD / 0.82;
        const double v = mode == DsmcFreeVolume::off ? vc : vc - v0;
        EXPECT_NEAR(e.exposure(), 0.5 * n * (n - 1.0) * e.tau() / v, 1e-12 * e.exposure());
    }
    // Over-full (area fraction 0.9 > 0.82): guarded at free_volume_floor V_c.
    DsmcConfig cfg;
    cfg.min_cell_diameters = 1e9;
    cfg.free_volume = DsmcFreeVolume::cell;
    auto e = gas(100, 0.9, cfg);
    e.step();
    const double vc = e.config().lx * e.config().ly;
    EXPECT_NEAR(e.exposure(), 0.5 * 100.0 * 99.0 * e.tau() / (0.05 * vc), 1e-12 * e.exposure());
}

TEST(DsmcCollision, DisplacementMovesThePairApartByTheContactDistanceAlongDp) {
    DsmcConfig cfg;
    cfg.displacement = true;
    cfg.r = 0.9;
    auto e = gas(3000, 0.2, cfg, 2.0);
    const Tracker tr = run_tracked(e, 100, 0.9);
    ASSERT_GT(tr.seen, 1000u);
    EXPECT_LT(tr.err_displacement, 1e-9);
    EXPECT_LT(tr.err_momentum_total, 1e-14);
    EXPECT_LT(tr.err_energy, 1e-13);
    // Positions stay in the box.
    for (const auto& p : e.positions()) {
        ASSERT_GE(p.x, 0.0);
        ASSERT_LT(p.x, e.config().lx);
        ASSERT_GE(p.y, 0.0);
        ASSERT_LT(p.y, e.config().ly);
    }
}
