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

// Momentum, kinetic energy and sum of m |v| (the round-off scale of the momentum) of the grains.
struct Totals {
    Vec2 p;
    double e = 0, scale = 0;
    void add(double m, Vec2 v) {
        p += m * v;
        e += 0.5 * m * norm2(v);
        scale += m * norm(v);
    }
};

Totals totals(const std::vector<SoftGrain>& g) {
    Totals t;
    for (const auto& x : g) t.add(x.mass, x.v);
    return t;
}

// The totals before and after a run of the cluster, and what happened in it.
struct ClusterRun {
    Totals before, after;
    std::size_t events = 0, active_at_end = 0; // contact events; contacts open at the end
    long builds = 0;                           // neighbour-list builds (pipe engine)
};

// Runs the cluster with the linear law (k_N = 2000 N/m, gamma_N) and Coulomb mu for 4000 steps
// of t_col/50.
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
ClusterRun run_pipe_cluster(double gamma_N, double mu, std::uint64_t seed) {
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
    eng.finalize();
    auto pipe_totals = [&] {
        Totals t;
        for (std::size_t i = 0; i < eng.size(); ++i) t.add(eng.mass()[i], {eng.vx()[i], eng.vy()[i]});
        return t;
    };
    ClusterRun r;
    r.before = pipe_totals();
    eng.advance(4000);
    r.after = pipe_totals();
    r.builds = eng.list_builds();
    return r;
}

TEST(PipeEngine, DampedFrictionalClusterConservesMomentumAcrossThePeriodicBoundary) {
    const ClusterRun run = run_pipe_cluster(1e4, 0.5, 5);
    ASSERT_GT(run.builds, 3); // the grains moved, the list was rebuilt
    EXPECT_LT(run.after.e, 0.9 * run.before.e); // they collided, dissipatively
    EXPECT_NEAR(run.after.p.x, run.before.p.x, 1e-14 * run.before.scale);
    EXPECT_NEAR(run.after.p.y, run.before.p.y, 1e-14 * run.before.scale);
}

TEST(PipeEngine, ElasticFrictionlessClusterConservesEnergy) {
    const ClusterRun run = run_pipe_cluster(0.0, 0.0, 3);
    EXPECT_NEAR(run.after.p.x, run.before.p.x, 1e-14 * run.before.scale);
    EXPECT_NEAR(run.after.p.y, run.before.p.y, 1e-14 * run.before.scale);
    EXPECT_NEAR(run.after.e / run.before.e, 1.0, 1e-3);
}

} // namespace
