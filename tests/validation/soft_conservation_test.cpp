// Conservation laws of the soft-sphere engine with several free grains in free space:
// momentum is conserved by every contact law (forces are pairwise equal and opposite), energy
// by the undamped, frictionless linear law to the integrator's accuracy.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng_stream.hpp"
#include "engines/soft/few_body_engine.hpp"
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

} // namespace
