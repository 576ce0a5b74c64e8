// The ED engine's collision operator is open (EdCollisionOperator): a second operator defined
// here, smooth disks with a constant normal restitution e, runs through the engine with its own
// parameters in BasicEdConfig<C>::law, and each part the concept names (collide, against,
// elastic_version, validate, fields) is checked against the analytic result.
#include "engines/ed/ed_collision_operator.hpp"
#include "engines/ed/ed_engine.hpp"
#include "gas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;
using namespace granrepro::test;

namespace {

// Smooth disks, normal restitution e, no tangential impulse: dP = -m12 (1+e) (v_1-v_2).n n.
// A wall collides with the wall's r as its e; TC-elastic means e = 1.
struct ConstantRestitution {
    double e = 1.0; // normal restitution [-]
    double q = 0.5; // I = q m a^2 [-] (spins never change)

    template <class V>
    void fields(V&& v) { v("e", e), v("q", q); }
    void validate() const {
        if (!(e >= 0.0 && e <= 1.0) || !(q > 0.0)) throw InputError("ConstantRestitution: need 0<=e<=1, q>0");
    }
    ConstantRestitution elastic_version(bool) const { return {1.0, q}; }
    ConstantRestitution against(const EdWall& w) const { return {w.r, q}; }
    bool frictional() const { return false; }

    struct Result {
        Vec2 dP;
        double dw1 = 0.0, dw2 = 0.0;
    };
    template <bool kFrictional>
    Result collide(const Vec2& v1, double, double m1, double, const Vec2& v2, double, double m2, double,
                   const Vec2& n) const {
        const double inv2 = std::isinf(m2) ? 0.0 : 1.0 / m2;
        const double m12 = 1.0 / (1.0 / m1 + inv2);
        return {n * (-m12 * (1.0 + e) * dot(v1 - v2, n))};
    }
};

struct NoWalls { // everything but against(wall)
    double q = 0.5;
    template <class V>
    void fields(V&& v) { v("q", q); }
    void validate() const {}
    NoWalls elastic_version(bool) const { return *this; }
    bool frictional() const { return false; }
    template <bool kFrictional>
    ConstantRestitution::Result collide(const Vec2&, double, double, double, const Vec2&, double, double, double,
                                        const Vec2&) const { return {}; }
};

static_assert(EdCollisionOperator<RoughDiskCollision>);
static_assert(EdCollisionOperator<ConstantRestitution>);
static_assert(!EdCollisionOperator<NoWalls>);

using Engine = BasicEdEngine<BinaryHeapQueue, ConstantRestitution>;

double kinetic(const Engine& eng) { return eng.kinetic_energy().total(); }

// Two unequal disks on the line y = 5 kD of a periodic 10 kD box, approaching head on.
struct HeadOn {
    double e = 0.6;
    double m1 = kM, m2 = 3.0 * kM;
    double u1 = 1.5, u2 = -0.5; // x velocities before [m/s]
    BasicEdConfig<ConstantRestitution> cfg() const {
        BasicEdConfig<ConstantRestitution> c;
        c.lx = c.ly = 10 * kD;
        c.law.e = e;
        return c;
    }
    Engine engine(const BasicEdConfig<ConstantRestitution>& c) const {
        return Engine(c, {{3 * kD, 5 * kD}, {6 * kD, 5 * kD}}, {{u1, 0.0}, {u2, 0.0}}, {0.5 * kD, 0.7 * kD},
                      {m1, m2});
    }
};

} // namespace

// Momentum conservation and v_2' - v_1' = -e (v_2 - v_1) give
//   v_1' = v_1 - (1+e) m_2/(m_1+m_2) (v_1-v_2),  v_2' = v_2 + (1+e) m_1/(m_1+m_2) (v_1-v_2),
// and the kinetic energy drops by (1-e^2)/2 m12 v_n^2 with v_n = v_1 - v_2, 1/m12 = 1/m_1 + 1/m_2.
TEST(EdCollisionOperator, HeadOnPairFollowsRestitutionAndMomentum) {
    const HeadOn h;
    Engine eng = h.engine(h.cfg());
    const double k0 = kinetic(eng);
    eng.run_collisions(1);
    ASSERT_EQ(eng.total_collisions(), 1u);
    const double vn = h.u1 - h.u2, mt = h.m1 + h.m2, m12 = h.m1 * h.m2 / mt;
    const double v1 = h.u1 - (1.0 + h.e) * h.m2 / mt * vn;
    const double v2 = h.u2 + (1.0 + h.e) * h.m1 / mt * vn;
    EXPECT_NEAR(eng.velocity(0).x, v1, 1e-12);
    EXPECT_NEAR(eng.velocity(1).x, v2, 1e-12);
    EXPECT_EQ(eng.velocity(0).y, 0.0);
    EXPECT_EQ(eng.velocity(1).y, 0.0);
    EXPECT_EQ(eng.spin(0), 0.0);
    EXPECT_EQ(eng.spin(1), 0.0);
    EXPECT_NEAR(eng.total_momentum().x, h.m1 * h.u1 + h.m2 * h.u2, 1e-12 * mt);
    const double loss = 0.5 * (1.0 - h.e * h.e) * m12 * vn * vn;
    EXPECT_NEAR(k0 - kinetic(eng), loss, 1e-12 * k0);
    EXPECT_EQ(eng.elastic_collisions(), 0u);
}

// Under TC (t_c large) a collision of a disk that collided before uses law.elastic_version():
// e = 1, no loss. Three equal disks on a line: A hits B (both fresh: e), then B hits C (B's
// second: elastic, an equal-mass exchange). A state saved in between carries the operator's own
// parameters and continues bit for bit.
TEST(EdCollisionOperator, TcUsesTheElasticVersionAndStateKeepsTheLaw) {
    const double e = 0.6;
    BasicEdConfig<ConstantRestitution> cfg;
    cfg.lx = cfg.ly = 10 * kD;
    cfg.law.e = e;
    cfg.t_c = 1e30;
    Engine eng(cfg, {{2 * kD, 5 * kD}, {4 * kD, 5 * kD}, {6 * kD, 5 * kD}}, {{1.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}},
               std::vector<double>(3, 0.5 * kD), std::vector<double>(3, kM));
    eng.run_collisions(1);
    ASSERT_EQ(eng.last_partner(0), 1);
    EXPECT_EQ(eng.elastic_collisions(), 0u);
    EXPECT_NEAR(eng.velocity(0).x, 0.5 * (1.0 - e), 1e-12);
    EXPECT_NEAR(eng.velocity(1).x, 0.5 * (1.0 + e), 1e-12);
    const auto mid = eng.save_state();
    EXPECT_EQ(mid.config.law.e, e);
    const double k1 = kinetic(eng);
    eng.run_collisions(1);
    ASSERT_EQ(eng.total_collisions(), 2u);
    ASSERT_EQ(eng.last_partner(2), 1);
    EXPECT_EQ(eng.elastic_collisions(), 1u);
    EXPECT_NEAR(eng.velocity(1).x, 0.0, 1e-12);
    EXPECT_NEAR(eng.velocity(2).x, 0.5 * (1.0 + e), 1e-12);
    EXPECT_NEAR(kinetic(eng), k1, 1e-12 * k1);

    Engine again(mid);
    EXPECT_EQ(again.config().law.e, e);
    again.run_collisions(1);
    EXPECT_EQ(again.time(), eng.time());
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(again.velocity(i).x, eng.velocity(i).x);
}

// A wall collides through law.against(wall): here the wall's r is the restitution.
TEST(EdCollisionOperator, WallUsesAgainst) {
    BasicEdConfig<ConstantRestitution> cfg;
    cfg.lx = cfg.ly = 10 * kD;
    cfg.periodic_y = false;
    cfg.law.e = 0.9;
    EdWall floor;
    floor.axis = 1;
    floor.position = 0.0;
    floor.side = +1;
    floor.r = 0.3;
    cfg.walls = {floor};
    Engine eng(cfg, {{5 * kD, 2 * kD}}, {{0.0, -2.0}}, {0.5 * kD}, {kM});
    eng.run_until(1e-3);
    ASSERT_EQ(eng.wall_collisions(), 1u);
    EXPECT_NEAR(eng.velocity(0).y, 0.3 * 2.0, 1e-12);
    EXPECT_EQ(eng.velocity(0).x, 0.0);
}

// The engine refuses what the operator's validate() refuses, with its message.
TEST(EdCollisionOperator, EngineValidatesThroughTheOperator) {
    HeadOn h;
    h.e = 1.5;
    try {
        (void)h.engine(h.cfg());
        FAIL() << "e = 1.5 accepted";
    } catch (const InputError& ex) {
        EXPECT_NE(std::string(ex.what()).find("ConstantRestitution"), std::string::npos) << ex.what();
    }
    Engine eng = HeadOn{}.engine(HeadOn{}.cfg());
    ConstantRestitution bad;
    bad.e = -0.1;
    EXPECT_THROW(eng.set_law(bad), InputError);
}
