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

TEST(SoftEngine, ElasticFrictionlessClusterConservesEnergyAndMomentum) {
    const LinearSpringDashpot law{2000.0, 0.0};
    const double dt = law.collision_time(0.5e-6) / 50;
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{0.0}, dt);
    add_cluster(eng, 3);
    const Totals before = totals(eng.grains());
    for (int s = 0; s < 4000; ++s) eng.step();
    ASSERT_GE(eng.events().size(), 10u); // the grains did collide, several times
    ASSERT_EQ(eng.active_contacts(), 0u);
    const Totals after = totals(eng.grains());
    EXPECT_NEAR(after.p.x, before.p.x, 1e-15);
    EXPECT_NEAR(after.p.y, before.p.y, 1e-15);
    EXPECT_NEAR(after.e / before.e, 1.0, 1e-6);
}

TEST(SoftEngine, DampedFrictionalClusterConservesMomentumAndLosesEnergy) {
    const LinearSpringDashpot law{2000.0, 1e4};
    const double dt = law.collision_time(0.5e-6) / 50;
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{0.5}, dt);
    add_cluster(eng, 5);
    const Totals before = totals(eng.grains());
    for (int s = 0; s < 4000; ++s) eng.step();
    ASSERT_GE(eng.events().size(), 10u);
    const Totals after = totals(eng.grains());
    EXPECT_NEAR(after.p.x, before.p.x, 1e-15);
    EXPECT_NEAR(after.p.y, before.p.y, 1e-15);
    EXPECT_LT(after.e, 0.9 * before.e);
}

} // namespace
