// Conservation laws of the soft-sphere engines with several free grains in free space:
// momentum is conserved by every contact law (forces are pairwise equal and opposite), energy
// by the undamped, frictionless linear law to the integrator's accuracy. The many-body pipe
// engine computes each pair force twice (once per grain, for thread-independent sums); the two
// must be exactly opposite, also across the periodic boundary.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng_stream.hpp"
#include "engines/soft/few_body_engine.hpp"
#include "engines/soft/pipe_engine.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

using namespace granrepro;

namespace {

template <class Engine>
void add_cluster(Engine& eng, std::uint64_t seed) {
    // Seven grains aimed at a common centre, slightly off-axis so that contacts are oblique.
    RngStream rng(seed, 0);
    for (int k = 0; k < 7; ++k) {
        const double a = 2 * M_PI * k / 7;
        const double R = 0.5e-3 * (1 + 0.1 * rng.uniform());
        const Vec2 r{2.5e-3 * std::cos(a), 2.5e-3 * std::sin(a)};
        const Vec2 v{-std::cos(a) + 0.2 * rng.uniform(-1, 1), -std::sin(a) + 0.2 * rng.uniform(-1, 1)};
        eng.add_free({r, v, R, 1e-6 * (1 + 0.2 * rng.uniform())});
    }
}

struct Totals {
    Vec2 p;
    double e;
};

Totals totals(const std::vector<SoftGrain>& g) {
    Totals t{{}, 0.0};
    for (const auto& x : g) {
        t.p += x.mass * x.v;
        t.e += 0.5 * x.mass * norm2(x.v);
    }
    return t;
}

// Runs the cluster with the linear law (k_N = 2000 N/m, gamma_N) and Coulomb mu for 4000 steps
// of t_col/50; returns the totals before and after and the number of contact events.
struct ClusterRun {
    Totals before, after;
    std::size_t events;
    std::size_t active_at_end;
};

ClusterRun run_cluster(double gamma_N, double mu, std::uint64_t seed) {
    const LinearSpringDashpot law{2000.0, gamma_N};
    const double dt = law.collision_time(0.5e-6) / 50;
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{mu}, dt);
    add_cluster(eng, seed);
    const Totals before = totals(eng.grains());
    for (int s = 0; s < 4000; ++s) eng.step();
    return {before, totals(eng.grains()), eng.events().size(), eng.active_contacts()};
}

TEST(SoftEngine, ElasticFrictionlessClusterConservesEnergyAndMomentum) {
    const ClusterRun run = run_cluster(0.0, 0.0, 3);
    ASSERT_GE(run.events, 10u); // the grains did collide, several times
    ASSERT_EQ(run.active_at_end, 0u);
    EXPECT_NEAR(run.after.p.x, run.before.p.x, 1e-15);
    EXPECT_NEAR(run.after.p.y, run.before.p.y, 1e-15);
    EXPECT_NEAR(run.after.e / run.before.e, 1.0, 1e-6);
}

TEST(SoftEngine, DampedFrictionalClusterConservesMomentumAndLosesEnergy) {
    const ClusterRun run = run_cluster(1e4, 0.5, 5);
    ASSERT_GE(run.events, 10u);
    EXPECT_NEAR(run.after.p.x, run.before.p.x, 1e-15);
    EXPECT_NEAR(run.after.p.y, run.before.p.y, 1e-15);
    EXPECT_LT(run.after.e, 0.9 * run.before.e);
}

// The same seven-grain cluster in the pipe engine, centred on the periodic boundary (y = 0) in
// the middle of a pipe whose walls it never reaches, gravity off.
struct PipeClusterRun {
    Vec2 p_before, p_after;
    double e_before, e_after, p_scale;
    long builds;
};

PipeClusterRun run_pipe_cluster(double gamma_N, double mu, std::uint64_t seed, int threads) {
    const LinearSpringDashpot law{2000.0, gamma_N};
    const double dt = law.collision_time(0.5e-6) / 50;
    PipeGeometry geo;
    geo.width = 0.03;
    geo.length = 0.02;
    geo.wall_spacing = 1e-3;
    geo.gravity = 0;
    PipeEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{mu}, geo, dt, 1e-4);
    RngStream rng(seed, 0);
    for (int k = 0; k < 7; ++k) {
        const double a = 2 * M_PI * k / 7;
        const double R = 0.5e-3 * (1 + 0.1 * rng.uniform());
        eng.add_grain(0.015 + 2.5e-3 * std::cos(a), 2.5e-3 * std::sin(a), -std::cos(a) + 0.2 * rng.uniform(-1, 1),
                      -std::sin(a) + 0.2 * rng.uniform(-1, 1), R, 1e-6 * (1 + 0.2 * rng.uniform()));
    }
    eng.set_threads(threads);
    eng.finalize();
    auto totals = [&](Vec2& p, double& e, double& scale) {
        p = {};
        e = scale = 0;
        for (std::size_t i = 0; i < eng.size(); ++i) {
            const Vec2 v{eng.vx()[i], eng.vy()[i]};
            p += eng.mass()[i] * v;
            e += 0.5 * eng.mass()[i] * norm2(v);
            scale += eng.mass()[i] * std::sqrt(norm2(v));
        }
    };
    PipeClusterRun r{};
    totals(r.p_before, r.e_before, r.p_scale);
    eng.advance(4000);
    double unused;
    totals(r.p_after, r.e_after, unused);
    r.builds = eng.list_builds();
    return r;
}

TEST(PipeEngine, DampedFrictionalClusterConservesMomentumAcrossThePeriodicBoundary) {
    for (int threads : {1, 2}) {
        const PipeClusterRun run = run_pipe_cluster(1e4, 0.5, 5, threads);
        ASSERT_GT(run.builds, 3); // the grains moved, the list was rebuilt
        EXPECT_LT(run.e_after, 0.9 * run.e_before); // they collided, dissipatively
        EXPECT_NEAR(run.p_after.x, run.p_before.x, 1e-14 * run.p_scale);
        EXPECT_NEAR(run.p_after.y, run.p_before.y, 1e-14 * run.p_scale);
    }
}

TEST(PipeEngine, ElasticFrictionlessClusterConservesEnergy) {
    const PipeClusterRun run = run_pipe_cluster(0.0, 0.0, 3, 1);
    EXPECT_NEAR(run.p_after.x, run.p_before.x, 1e-14 * run.p_scale);
    EXPECT_NEAR(run.p_after.y, run.p_before.y, 1e-14 * run.p_scale);
    EXPECT_NEAR(run.e_after / run.e_before, 1.0, 1e-3);
}

} // namespace
