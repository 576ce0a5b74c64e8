// The many-body pipe engine: neighbour list against the O(N^2) reference on the same state, and
// two-grain collisions against Eq. (4).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenarios/pipe_setup.hpp"

using namespace granrepro;

namespace {

// A dense, hot pipe (many overlaps, fast relative motion) after some steps, so that the list has
// been rebuilt across the periodic boundary and against the walls.
PipeSpec hot_pipe() {
    PipeSpec s;
    s.geo.width = 0.012;
    s.geo.length = 0.012;
    s.geo.wall_spacing = 1.0e-3;
    s.phi = 0.6;
    s.agitation = 2.0;
    s.v0 = 3.0;
    return s;
}

TEST(PipeEngine, NeighbourListForcesEqualBruteForce) {
    const PipeSpec s = hot_pipe();
    auto eng = build_pipe(s);
    for (int k = 0; k < 3000; ++k) eng.step();
    ASSERT_GT(eng.list_builds(), 5);
    ASSERT_GT(eng.max_overlap_ratio(), 0.0); // there are contacts
    std::vector<double> bx, by;
    eng.brute_force_accelerations(bx, by);
    double scale = 0, worst = 0;
    for (std::size_t i = 0; i < eng.size(); ++i) {
        scale = std::max(scale, std::hypot(bx[i], by[i] + s.geo.gravity));
        worst = std::max(worst, std::hypot(eng.ax()[i] - bx[i], eng.ay()[i] - by[i]));
    }
    ASSERT_GT(scale, 100.0); // contact accelerations much larger than g
    EXPECT_LT(worst / scale, 1e-12);
}

// Head-on free-free collisions in the middle of the pipe (gravity off), with the contact starting
// at different phases of a time step: velocity Verlet with the dashpot at the predicted full-step
// velocity reproduces Eq. (4)'s restitution to a few 1e-3 at dt = t_col/50 and converges with dt.
double restitution_error(double e_N, double steps_per_contact) {
    double sum = 0;
    const double phases[] = {0.0, 0.13, 0.37, 0.71};
    for (double phase : phases) {
        const double m = 1e-6;
        PipeGeometry geo;
        geo.gravity = 0.0;
        geo.wall_spacing = 1.0e-3;
        const auto law = LinearSpringDashpot::from_restitution(2000.0, e_N, m / 2);
        const double dt = law.collision_time(m / 2) / steps_per_contact;
        PipeEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{0.5}, geo, dt, 1e-4);
        eng.add_grain(0.0095, 0.02, 0.5, 0.0, 0.5e-3, m);
        eng.add_grain(0.0105 + 1e-6 + phase * dt, 0.02, -0.5, 0.0, 0.5e-3, m);
        eng.finalize();
        for (int k = 0; k < 40 * int(steps_per_contact); ++k) eng.step();
        EXPECT_NEAR(eng.vx()[0] + eng.vx()[1], 0.0, 1e-14); // momentum
        sum += std::abs(eng.vx()[1] - eng.vx()[0] - e_N) / e_N;
    }
    return sum / 4;
}

#if defined(__GNUC__) && defined(__x86_64__)
// The drift pass gives the same bits four (AVX2), two (SSE2) or one grain at a time.
TEST(PipeEngine, VectorLanesGiveTheSameBits) {
    if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2 on this processor";
    PipeSpec s = hot_pipe();
    auto run = [&](bool avx2) {
        pipe_detail::use_avx2() = avx2;
        auto eng = build_pipe(s);
        eng.advance(2000);
        pipe_detail::use_avx2() = __builtin_cpu_supports("avx2");
        return std::vector<std::vector<double>>{eng.x(), eng.y(), eng.vx(), eng.vy(), eng.ax(), eng.ay()};
    };
    EXPECT_TRUE(run(true) == run(false));
}
#endif

TEST(PipeEngine, HeadOnRestitutionMatchesEq4AndConverges) {
    for (double e : {0.5, 0.7, 0.9}) {
        const double coarse = restitution_error(e, 50), fine = restitution_error(e, 400);
        EXPECT_LT(coarse, 5e-3) << "e_N = " << e;
        EXPECT_LT(fine, coarse / 8) << "e_N = " << e; // better than first order over a factor 8 in dt
    }
}

} // namespace

// A variable step (set_dt, the time_step = "wall" rule of bistable-pipe): velocity Verlet stays
// exact for a grain under gravity alone when dt changes between steps, because the last step's
// pending closing half kick keeps that step's dt/2. (Applying the new dt/2 to it instead shifts
// v by g (dt_new - dt_old) / 2 at each change: 5e-6 m/s here, far above the tolerance.)
TEST(PipeEngine, VariableTimeStepKeepsVelocityVerletExact) {
    const auto law = LinearSpringDashpot::from_restitution(2000.0, 0.9, 0.5e-6);
    PipeGeometry geo;
    geo.wall_spacing = 1.0e-3;
    const double dt0 = 1e-6, v0 = -3.0, y0 = 0.03;
    PipeEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{0.5}, geo, dt0, 1e-4);
    eng.add_grain(0.01, y0, 0.0, v0, 0.5e-3, 1e-6); // mid-pipe: no wall grain in reach
    eng.finalize();
    double t = 0;
    const double steps[] = {1e-6, 2e-7, 3e-6, 1e-6, 5e-7, 2.5e-6};
    for (int round = 0; round < 20; ++round)
        for (double dt : steps) {
            eng.set_dt(dt);
            for (int k = 0; k < 7; ++k) eng.step();
            t += 7 * dt;
        }
    EXPECT_NEAR(eng.time(), t, 1e-15);
    EXPECT_NEAR(eng.vy()[0], v0 - geo.gravity * t, 1e-12);
    double y = y0 + v0 * t - 0.5 * geo.gravity * t * t; // back into [0, length)
    y -= std::floor(y / geo.length) * geo.length;
    EXPECT_NEAR(eng.y()[0], y, 1e-12);
    EXPECT_THROW(eng.set_dt(0.0), std::invalid_argument);
}
