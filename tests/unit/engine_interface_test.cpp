// The engine interface (HardParticleEngine): ED and DSMC run through one generic function, and
// the ED engine uses the collision operator it is instantiated with.
#include "engines/hard_particle_engine.hpp"
#include "gas.hpp"

#include <gtest/gtest.h>

using namespace granrepro;
using namespace granrepro::test;

namespace {

static_assert(HardParticleEngine<EdEngine>);
static_assert(HardParticleEngine<DsmcEngine>);

// Written once against the interface: elastic runs keep their energy, every collision reaches
// the observer, and a restored state continues bit for bit.
template <HardParticleEngine E>
void check_contract(E& e, double dt) {
    const double k0 = total_kinetic_energy(e);
    std::uint64_t seen = 0;
    auto count = [&seen](const CollisionRecord&) { ++seen; };
    const double t1 = e.time() + dt;
    e.run_until(t1, count);
    EXPECT_EQ(e.time(), t1);
    EXPECT_GT(seen, 100u);
    EXPECT_EQ(seen, e.total_collisions());
    EXPECT_NEAR(total_kinetic_energy(e), k0, 1e-12 * k0);
    const auto saved = e.save_state();
    e.run_until(t1 + dt, count);
    const double k2 = total_kinetic_energy(e);
    e.restore_state(saved);
    EXPECT_EQ(e.time(), t1);
    e.run_until(t1 + dt, count);
    EXPECT_EQ(total_kinetic_energy(e), k2);
}

// Smooth and perfectly plastic (r = 0), against walls and under TC alike.
struct PlasticCollision {
    double q = 0.4;
    template <class V>
    void fields(V&& v) { v("q", q); }
    void validate() const {}
    PlasticCollision elastic_version(bool) const { return *this; }
    PlasticCollision against(const EdWall&) const { return *this; }
    bool frictional() const { return false; }
    template <bool kFrictional>
    RoughDiskCollision::Result collide(const Vec2& v1, double w1, double m1, double a1, const Vec2& v2, double w2,
                                       double m2, double a2, const Vec2& n) const {
        return RoughDiskCollision{0.0, 0.0, -1.0, q}.collide<kFrictional>(v1, w1, m1, a1, v2, w2, m2, a2, n);
    }
};
static_assert(EdCollisionOperator<PlasticCollision>);

} // namespace

TEST(EngineInterface, EdAndDsmcMeetTheContract) {
    const double l = box_for(400, 0.25);
    const Disks g = random_disks(400, l, true, true, 7);
    EdConfig ed;
    ed.lx = ed.ly = l;
    EdEngine e(ed, g.pos, g.vel, g.rad, g.mass);
    check_contract(e, 5e-3);
    DsmcConfig ds;
    ds.lx = ds.ly = l;
    DsmcEngine d(ds, g.pos, g.vel, g.rad, g.mass);
    check_contract(d, 5e-3);
}

// A head-on pair of equal disks, configured elastic for the default operator: it exchanges
// their velocities, the plastic one stops both (momentum zero, r = 0).
TEST(EngineInterface, EdEngineUsesItsCollisionOperator) {
    EdConfig cfg;
    cfg.lx = cfg.ly = 10 * kD;
    const std::vector<Vec2> pos{{3 * kD, 5 * kD}, {6 * kD, 5 * kD}}, vel{{1.0, 0.0}, {-1.0, 0.0}};
    const std::vector<double> rad(2, 0.5 * kD), mass(2, kM);
    EdEngine elastic(cfg, pos, vel, rad, mass);
    elastic.run_collisions(1);
    EXPECT_NEAR(elastic.velocity(0).x, -1.0, 1e-12);
    BasicEdConfig<PlasticCollision> pcfg;
    pcfg.lx = pcfg.ly = cfg.lx;
    BasicEdEngine<BinaryHeapQueue, PlasticCollision> plastic(pcfg, pos, vel, rad, mass);
    plastic.run_collisions(1);
    ASSERT_EQ(plastic.total_collisions(), 1u);
    EXPECT_NEAR(plastic.velocity(0).x, 0.0, 1e-12);
    EXPECT_NEAR(plastic.velocity(1).x, 0.0, 1e-12);
    EXPECT_NEAR(total_kinetic_energy(plastic), 0.0, 1e-12 * kM);
}
