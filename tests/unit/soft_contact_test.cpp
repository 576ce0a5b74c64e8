// Two-grain analytic tests of the soft-sphere contact laws (Schäfer & Wolf 1995, Eqs. 1, 2, 4, 5).
#include <gtest/gtest.h>

#include <cmath>

#include "engines/soft/few_body_engine.hpp"
#include "models/coulomb_shear.hpp"
#include "models/hertz_kuwabara_kono.hpp"
#include "models/linear_spring_dashpot.hpp"

using namespace granrepro;

namespace {

struct HeadOn {
    double t_col;   // measured contact duration [s]
    double e_N;     // measured -v_N(end)/v_N(start)
    double xi_max;  // largest overlap seen at step ends [m]
};

// Head-on collision of a 1 mg, 1 mm grain with a free twin or with a fixed wall grain.
template <class Law>
HeadOn head_on(const Law& law, double dt, bool wall, double v0 = 1.0) {
    FewBodyEngine<Law, CoulombShear> eng(law, CoulombShear{0.5}, dt);
    const double R = 0.5e-3, m = 1e-6;
    eng.add_free({{0.0, 0.0}, {v0, 0.0}, R, m});
    if (wall) eng.add_fixed({{R + 0.33e-3 + 1e-6, 0.0}, 0.33e-3});
    else eng.add_free({{2 * R + 1e-6, 0.0}, {0.0, 0.0}, R, m});
    double xi_max = 0;
    for (int s = 0; s < 100000 && eng.events().size() < 2; ++s) {
        eng.step();
        const auto& g = eng.grains();
        const double other_x = wall ? R + 0.33e-3 + 1e-6 : g[1].r.x;
        const double other_r = wall ? 0.33e-3 : R;
        xi_max = std::max(xi_max, R + other_r - std::abs(other_x - g[0].r.x));
    }
    const auto& ev = eng.events();
    EXPECT_EQ(ev.size(), 2u);
    if (ev.size() < 2) return {0, 0, 0};
    EXPECT_TRUE(ev[0].begins);
    EXPECT_FALSE(ev[1].begins);
    return {ev[1].t - ev[0].t, -ev[1].xi_dot / ev[0].xi_dot, xi_max};
}

class LinearLawRestitution : public ::testing::TestWithParam<std::tuple<double, bool>> {};

TEST_P(LinearLawRestitution, MatchesEq4AtTcolOver50) {
    const auto [e_N, wall] = GetParam();
    const double m = 1e-6;
    const double m_red = wall ? m : m / 2;
    const auto law = LinearSpringDashpot::from_restitution(2000.0, e_N, m_red);
    ASSERT_NEAR(law.restitution(m_red), e_N, 1e-12);
    const double t_col = law.collision_time(m_red);
    const HeadOn h = head_on(law, t_col / 50, wall);
    EXPECT_NEAR(h.t_col / t_col, 1.0, 1e-4);
    EXPECT_NEAR(h.e_N / e_N, 1.0, 1e-4);
    RecordProperty("rel_err_t_col", std::to_string(h.t_col / t_col - 1.0));
    RecordProperty("rel_err_e_N", std::to_string(h.e_N / e_N - 1.0));
}

INSTANTIATE_TEST_SUITE_P(FreeFreeAndFreeWall, LinearLawRestitution,
                         ::testing::Combine(::testing::Values(0.3, 0.5, 0.7, 0.9, 0.99),
                                            ::testing::Bool()),
                         [](const auto& info) { // e.g. eN_0_99_wall
                             std::string e = std::to_string(std::get<0>(info.param)).substr(0, 4);
                             e[1] = '_';
                             return "eN_" + e + (std::get<1>(info.param) ? "_wall" : "_free");
                         });

TEST(LinearLaw, PaperValuesOfFig3) {
    // k_N = 2000 N/m, gamma_N = 1e4 1/s, free grain of 1 mg against a wall grain:
    // the paper quotes e_N = 0.70 and t_col = 7.07e-5 s.
    const LinearSpringDashpot law{2000.0, 1e4};
    EXPECT_NEAR(law.collision_time(1e-6), 7.07e-5, 0.005e-5);
    EXPECT_NEAR(law.restitution(1e-6), 0.70, 0.005);
}

TEST(LinearLaw, ElasticMaxOverlapEqualsVtcolOverPi) {
    // For gamma_N = 0, xi_max = v_N t_col / pi exactly (text below Eq. 4).
    const LinearSpringDashpot law{2000.0, 0.0};
    const double t_col = law.collision_time(1e-6);
    const HeadOn h = head_on(law, t_col / 500, true, 0.5);
    EXPECT_NEAR(h.xi_max / (0.5 * t_col / M_PI), 1.0, 1e-4);
    EXPECT_NEAR(h.e_N, 1.0, 1e-8);
}

TEST(LinearLaw, CoarseStepIsLessAccurate) {
    // Eq. (5) is a requirement, not a formality: at dt = t_col/5 the error is far above 1e-4.
    const auto law = LinearSpringDashpot::from_restitution(2000.0, 0.7, 1e-6);
    const double t_col = law.collision_time(1e-6);
    const HeadOn h = head_on(law, t_col / 5, true);
    EXPECT_GT(std::abs(h.e_N / 0.7 - 1.0) + std::abs(h.t_col / t_col - 1.0), 1e-4);
}

TEST(HertzKuwabaraKono, ElasticLimitConservesEnergyAndRestitutionFallsWithSpeed) {
    const auto law = HertzKuwabaraKono::matched_at(2000.0, 0.0, 1e-5);
    const HeadOn h = head_on(law, 1e-7, true, 1.0);
    EXPECT_NEAR(h.e_N, 1.0, 1e-6);
    // With the xi^(1/2) dashpot the restitution decreases with impact speed (Kuwabara & Kono).
    const auto damped = HertzKuwabaraKono::matched_at(2000.0, 1e4, 1e-5);
    const HeadOn slow = head_on(damped, 1e-7, true, 0.1);
    const HeadOn fast = head_on(damped, 1e-7, true, 2.0);
    EXPECT_LT(fast.e_N, slow.e_N);
    EXPECT_GT(slow.e_N, 0.0);
}

TEST(CoulombShear, OpposesSlidingWithMuTimesNormalForce) {
    const CoulombShear s{0.5};
    EXPECT_DOUBLE_EQ(s.shear_force({2.0, 1.5}, 3.0), -1.0);
    EXPECT_DOUBLE_EQ(s.shear_force({2.0, 1.5}, -3.0), 1.0);
    EXPECT_DOUBLE_EQ(s.shear_force({-2.0, 1.5}, 3.0), -1.0);
    EXPECT_DOUBLE_EQ(s.shear_force({2.0, 1.5}, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(s.applied_normal({-2.0, 1.5}), -2.0);
}

// The four readings of Eq. (2) on a pressed contact (F_N = 2 N, elastic part 1.5 N) and on the
// attractive end of a contact (F_N = -0.4 N, elastic part 0.1 N), sliding with v_S > 0.
TEST(CoulombShear, ReadingsOfTheNormalForce) {
    const NormalForce pressed{2.0, 1.5}, pulling{-0.4, 0.1};
    auto with = [](FrictionNormal r) { return CoulombShear{0.5, r}; };
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Magnitude).shear_force(pressed, 1.0), -1.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Magnitude).shear_force(pulling, 1.0), -0.2);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Clipped).shear_force(pressed, 1.0), -1.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Clipped).shear_force(pulling, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Clipped).applied_normal(pulling), 0.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Clipped).applied_normal(pressed), 2.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Elastic).shear_force(pressed, 1.0), -0.75);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Elastic).shear_force(pulling, 1.0), -0.05);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Signed).shear_force(pressed, 1.0), -1.0);
    EXPECT_DOUBLE_EQ(with(FrictionNormal::Signed).shear_force(pulling, 1.0), 0.2);
    for (auto r : {FrictionNormal::Magnitude, FrictionNormal::Clipped, FrictionNormal::Elastic, FrictionNormal::Signed})
        EXPECT_EQ(parse_friction_normal(to_string(r)), r);
    EXPECT_FALSE(parse_friction_normal("bogus"));
}

TEST(FewBodyEngine, GrazingFrictionBrakesTangentialMotion) {
    // Oblique impact on a fixed grain: the free grain must lose tangential speed by at most
    // mu times the normal impulse per unit mass (Coulomb), and lose some.
    const LinearSpringDashpot law{2000.0, 1e4};
    const double dt = law.collision_time(1e-6) / 50;
    FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{0.5}, dt);
    eng.add_free({{0.82e-3, -0.2e-3}, {0.0, 1.0}, 0.5e-3, 1e-6});
    eng.add_fixed({{0.0, 0.0}, 0.33e-3});
    for (int s = 0; s < 20000 && !(eng.events().size() >= 2 && eng.active_contacts() == 0); ++s)
        eng.step();
    const Vec2 v = eng.grains()[0].v;
    EXPECT_GT(v.x, 0.0);          // pushed away from the wall grain
    EXPECT_LT(v.y, 1.0);          // braked
}

// The shear/normal split of the velocity change adds up, with gravity, to the whole change (RK4
// weights and contact switching included), and the shear part vanishes without friction.
TEST(FewBodyEngine, ShearAndNormalVelocityChangesAddUp) {
    const LinearSpringDashpot law{2000.0, 1e4};
    const double dt = law.collision_time(1e-6) / 50;
    for (double mu : {0.0, 0.5}) {
        FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{mu}, dt, Vec2{0.0, -10.0});
        const Vec2 v0{-0.3, 2.0};
        eng.add_free({{0.9e-3, -0.2e-3}, v0, 0.5e-3, 1e-6});
        eng.add_row({0.0, 0.0, 0.66e-3, 0.33e-3});
        for (int s = 0; s < 3000; ++s) eng.step();
        ASSERT_GE(eng.events().size(), 2u);
        const Vec2 dv = eng.grains()[0].v - v0;
        const Vec2 sum = eng.shear_dv(0) + eng.normal_dv(0) + Vec2{0.0, -10.0} * eng.time();
        EXPECT_NEAR(sum.x, dv.x, 1e-12);
        EXPECT_NEAR(sum.y, dv.y, 1e-12);
        if (mu == 0.0) EXPECT_EQ(norm(eng.shear_dv(0)), 0.0);
        else EXPECT_LT(eng.shear_dv(0).y, -1e-3); // friction brakes the motion along the wall
    }
}

} // namespace
