// ED engine: event search against brute force, conservation laws, TC model, walls, gravity,
// collapse detection and checkpoint/restart.
#include "calendar_queue.hpp"
#include "engines/ed/flight_roots.hpp"
#include "gas.hpp"
#include "saved_states.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace granrepro;
using namespace granrepro::test;

namespace {

// Brute-force O(N^2) earliest pair collision from time(), using the engine's public state and
// the same "last partners do not re-collide" rule.
template <class Engine>
typename Engine::PairEvent brute_force_next(const Engine& e) {
    typename Engine::PairEvent best;
    const auto& cfg = e.config();
    for (std::size_t i = 0; i < e.size(); ++i) {
        for (std::size_t j = i + 1; j < e.size(); ++j) {
            if (e.last_partner(i) == static_cast<int>(j) && e.last_partner(j) == static_cast<int>(i)) continue;
            Vec2 dr = e.position(i) - e.position(j);
            if (cfg.periodic_x) dr.x -= cfg.lx * std::round(dr.x / cfg.lx);
            if (cfg.periodic_y) dr.y -= cfg.ly * std::round(dr.y / cfg.ly);
            const Vec2 dv = e.velocity(i) - e.velocity(j);
            const double t = flight_roots::pair_contact_time(dr.x, dr.y, dv.x, dv.y, e.radius(i) + e.radius(j));
            if (e.time() + t < best.t) best = {e.time() + t, static_cast<int>(i), static_cast<int>(j)};
        }
    }
    return best;
}

// The engine's next executed particle-particle collision is the brute-force one.
template <class Engine>
void expect_next_collision_is(Engine& e, const typename Engine::PairEvent& ref) {
    CollisionRecord got;
    e.run_collisions(1, [&](const CollisionRecord& r) { if (r.j >= 0) got = r; });
    EXPECT_NEAR(got.t, ref.t, 1e-12 * (1 + ref.t));
    EXPECT_EQ(std::min(got.i, got.j), ref.i);
    EXPECT_EQ(std::max(got.i, got.j), ref.j);
}

// The run stops with an exception that names the inelastic collapse (instead of hanging).
template <class Run>
void expect_collapse(Run run) {
    try {
        run();
        FAIL() << "no exception";
    } catch (const std::runtime_error& ex) {
        EXPECT_NE(std::string(ex.what()).find("collapse"), std::string::npos) << ex.what();
    }
}

} // namespace

// The same test body runs against every engine implementation (event-queue variants) and
// both boundary types.
template <class E>
class EdEngineImpl : public ::testing::Test {};
using EngineTypes = ::testing::Types<BasicEdEngine<BinaryHeapQueue>, BasicEdEngine<CalendarQueue>>;
TYPED_TEST_SUITE(EdEngineImpl, EngineTypes);

TYPED_TEST(EdEngineImpl, CellSearchMatchesBruteForceAndEngineExecutesIt) {
    for (bool periodic : {true, false}) {
        EdConfig cfg;
        cfg.periodic_x = cfg.periodic_y = periodic;
        const double l = box_for(600, 0.35);
        if (!periodic) {
            cfg.walls = {EdWall{0, 0.0, +1}, EdWall{0, l, -1}, EdWall{1, 0.0, +1}, EdWall{1, l, -1}};
        }
        auto e = random_ed_gas<TypeParam>(600, 0.35, 42, cfg);
        int adjacent = 0;
        for (int round = 0; round < 40; ++round) {
            e.synchronize();
            ASSERT_LT(e.max_cell_excursion(), 1e-12 * kD) << "round " << round;
            const auto ref = brute_force_next(e);
            // The cell search sees only pairs in adjacent cells: never earlier than the brute
            // force, and identical whenever the brute-force pair is within one cell width now.
            const auto cells = e.next_pair_collision_cells();
            ASSERT_GE(cells.t, ref.t);
            Vec2 dr = e.position(ref.i) - e.position(ref.j);
            if (periodic) {
                dr.x -= l * std::round(dr.x / l);
                dr.y -= l * std::round(dr.y / l);
            }
            if (std::fabs(dr.x) < l / e.cells_x() && std::fabs(dr.y) < l / e.cells_y()) {
                ++adjacent;
                ASSERT_EQ(cells.t, ref.t) << "round " << round << " ref " << ref.i << "," << ref.j << " cells " << cells.i << "," << cells.j
                    << " pos " << e.position(ref.i).x / l * e.cells_x() << " " << e.position(ref.i).y / l * e.cells_y() << " / "
                    << e.position(ref.j).x / l * e.cells_x() << " " << e.position(ref.j).y / l * e.cells_y() << " t=" << e.time();
                ASSERT_EQ(cells.i, ref.i);
                ASSERT_EQ(cells.j, ref.j);
            }
            expect_next_collision_is(e, ref);
            e.run_collisions(37); // move on to a different state
        }
        EXPECT_GT(adjacent, 20);
    }
}

TYPED_TEST(EdEngineImpl, ElasticGasConservesEnergyAndMomentum) {
    auto e = random_ed_gas<TypeParam>(2000, 0.25, 7);
    const double k0 = e.kinetic_energy().total();
    const Vec2 p0 = e.total_momentum();
    const double pscale = kM * 1.0 * std::sqrt(2000.0);
    e.run_collisions(100 * 2000 / 2); // 100 collisions per particle
    const double k1 = e.kinetic_energy().total();
    const Vec2 p1 = e.total_momentum();
    EXPECT_NEAR(k1 / k0, 1.0, 1e-11);
    EXPECT_NEAR(p1.x, p0.x, 1e-12 * pscale);
    EXPECT_NEAR(p1.y, p0.y, 1e-12 * pscale);
    EXPECT_LT(e.max_overlap(), 1e-9 * kD);
    EXPECT_LT(e.current_max_overlap(), 1e-9 * kD);
    EXPECT_EQ(e.elastic_collisions(), 0u);
    std::uint64_t sum = 0;
    for (auto c : e.collision_counts()) sum += c;
    EXPECT_EQ(sum, 2 * e.total_collisions());
}

TEST(EdEngine, RoughElasticDisksConserveEnergyWithRotation) {
    // r = 1, beta0 = 1 and large mu: every contact sticks with beta = 1, which conserves
    // translational + rotational energy while exchanging them.
    EdConfig cfg;
    cfg.law = RoughDiskCollision{1.0, 1e6, 1.0, 0.5};
    auto e = random_ed_gas(1000, 0.3, 3, cfg);
    const double k0 = e.kinetic_energy().total();
    e.run_collisions(20000);
    const auto k = e.kinetic_energy();
    EXPECT_NEAR(k.total() / k0, 1.0, 1e-11);
    EXPECT_GT(k.krot / k0, 0.05); // rotation really got excited
    EXPECT_LT(e.max_overlap(), 1e-9 * kD);
}

TEST(EdEngine, InelasticPairLossMatchesOperator) {
    // Sum of analytic per-collision losses (smooth: (1-r^2)/2 m12 v_n^2) equals K0 - K.
    EdConfig cfg;
    cfg.law.r = 0.7;
    auto e = random_ed_gas(500, 0.2, 5, cfg);
    const double k0 = e.kinetic_energy().total();
    double loss = 0.0;
    e.run_collisions(3000, [&](const CollisionRecord& r) {
        // |dP| = m12 (1+r) |v_n|  =>  loss = (1-r)/(1+r) |dP|^2 / (2 m12), m12 = m/2
        const double dp2 = norm2(r.dP);
        loss += (1.0 - 0.7) / (1.0 + 0.7) * dp2 / (2.0 * 0.5 * kM);
    });
    EXPECT_NEAR((k0 - e.kinetic_energy().total()) / k0, loss / k0, 1e-10);
}

TEST(EdEngine, TcModelMakesQuickRepeatCollisionsElastic) {
    EdConfig cfg;
    cfg.law.r = 0.5;
    cfg.t_c = 1e30; // every collision after a particle's first one is elastic (Eq. 7)
    auto e = random_ed_gas(400, 0.3, 9, cfg);
    std::vector<int> seen(400, 0);
    std::uint64_t expected_elastic = 0;
    double inelastic_loss = 0.0;
    const double k_before = e.kinetic_energy().total();
    e.run_collisions(4000, [&](const CollisionRecord& r) {
        const bool el = seen[r.i] > 0 || seen[r.j] > 0;
        EXPECT_EQ(r.elastic, el);
        if (el) {
            ++expected_elastic;
        } else {
            // Smooth disks: loss = (1-r)/(1+r) |dP|^2 / (2 m12), m12 = m/2 (see InelasticPairLoss...).
            inelastic_loss += (1.0 - 0.5) / (1.0 + 0.5) * norm2(r.dP) / (2.0 * 0.5 * kM);
        }
        ++seen[r.i];
        ++seen[r.j];
    });
    EXPECT_EQ(e.elastic_collisions(), expected_elastic);
    EXPECT_GT(expected_elastic, 3000u);
    // Only the first collisions dissipated: the energy lost is exactly their loss (Eq. (7) makes
    // every later collision elastic, r = 1, which conserves energy).
    EXPECT_GT(inelastic_loss, 0.0);
    EXPECT_NEAR((k_before - e.kinetic_energy().total()) / k_before, inelastic_loss / k_before, 1e-10);
    // t_c = 0 is plain ED: no elastic collisions.
    EdConfig plain;
    plain.law.r = 0.5;
    auto f = random_ed_gas(400, 0.3, 9, plain);
    f.run_collisions(2000);
    EXPECT_EQ(f.elastic_collisions(), 0u);
}

TEST(EdEngine, InelasticCollapseThrowsClearMessage) {
    // A disk bouncing on an inelastic floor under gravity performs infinitely many bounces in
    // finite time (t_c = 0): the engine must stop with an exception, not hang.
    EdConfig cfg;
    cfg.lx = 10 * kD;
    cfg.ly = 100 * kD;
    cfg.periodic_y = false;
    cfg.gravity = {0.0, -9.81};
    cfg.walls = {EdWall{1, 0.0, +1, 0.5}};
    EdEngine e(cfg, {{5 * kD, 10 * kD}}, {{0.0, 0.0}}, {0.5 * kD}, {kM});
    expect_collapse([&] { e.run_until(10.0); });
    // With the TC model the same setup runs on.
    cfg.t_c = 1e-4;
    EdEngine f(cfg, {{5 * kD, 10 * kD}}, {{0.0, 0.0}}, {0.5 * kD}, {kM});
    EXPECT_NO_THROW(f.run_until(2.0));
    EXPECT_GT(f.elastic_collisions(), 0u);
}

TEST(EdEngine, DenseInelasticGasCollapseThrows) {
    EdConfig cfg;
    cfg.law.r = 0.1;
    auto e = random_ed_gas(300, 0.45, 21, cfg);
    expect_collapse([&] { e.run_collisions(50'000'000); });
}

TEST(EdEngine, RemovingTheFloorLetsDisksFall) {
    EdConfig cfg;
    cfg.lx = 12 * kD;
    cfg.ly = 60 * kD;
    cfg.periodic_x = false;
    cfg.periodic_y = false;
    cfg.gravity = {0.0, -9.81};
    cfg.walls = {EdWall{0, 0.0, +1}, EdWall{0, 12 * kD, -1}, EdWall{1, 0.0, +1}};
    const auto pos = triangular_lattice_positions(60, 0.5 * kD, 11.5 * kD, 0.6 * kD, 1.01 * kD);
    RngStream rng(1, 0);
    const std::vector<double> rad(pos.size(), 0.5 * kD), mass(pos.size(), kM);
    auto vel = uniform_velocities(pos.size(), 0.05, rng);
    EdEngine e(cfg, pos, vel, rad, mass);
    e.run_until(0.02);
    for (const Vec2& p : e.positions()) EXPECT_GT(p.y, 0.5 * kD * (1 - 1e-9));
    e.set_wall_enabled(2, false);
    e.run_until(0.2); // free fall 0.5 g t^2 ~ 0.16 m >> pile
    for (const Vec2& p : e.positions()) EXPECT_LT(p.y, 0.0);
    EXPECT_LT(e.max_overlap(), 1e-9 * kD);
}

TYPED_TEST(EdEngineImpl, CheckpointRestartIsBitIdentical) {
    // Rough, inelastic with TC, gravity and walls: all code paths.
    EdConfig cfg;
    cfg.periodic_y = false;
    cfg.gravity = {0.0, -9.81};
    cfg.law = RoughDiskCollision{0.8, 0.5, 0.2, 0.5};
    cfg.t_c = 1e-5;
    const double l = box_for(400, 0.3);
    cfg.walls = {EdWall{1, 0.0, +1, 0.9, 0.5, 0.2}, EdWall{1, l, -1}};
    auto a = random_ed_gas<TypeParam>(400, 0.3, 11, cfg);
    a.run_until(0.01);
    const EdState mid = a.save_state();
    a.run_until(0.03);
    a.synchronize();
    TypeParam b(mid);
    b.run_until(0.03);
    b.synchronize();
    EXPECT_GT(a.save_state().pair_collisions, mid.pair_collisions + 1000);
    expect_same_fields(a.save_state(), b.save_state());
}

TEST(EdEngine, InitialStatesAndVelocityScaling) {
    RngStream rng(5, 1);
    const std::vector<double> mass(1000, kM);
    auto v = maxwellian_velocities(mass, 0.2047, rng);
    Vec2 p;
    double k = 0;
    for (const auto& u : v) { p += kM * u; k += 0.5 * kM * norm2(u); }
    EXPECT_NEAR(p.x, 0.0, 1e-18);
    EXPECT_NEAR(p.y, 0.0, 1e-18);
    EXPECT_NEAR(std::sqrt(2 * k / (1000 * kM)), 0.2047, 1e-12);
    const auto sq = square_lattice_positions(784, 50 * kD, 50 * kD);
    EXPECT_EQ(sq.size(), 784u);
    EXPECT_NEAR(sq[1].x - sq[0].x, 50 * kD / 28, 1e-15);
    const auto tri = triangular_lattice_positions(1562, 0.5 * kD, 19.7 * kD, 0.5 * kD, 1.01 * kD);
    EXPECT_EQ(tri.size(), 1562u);
    EXPECT_NEAR(tri[20].y - tri[0].y, 1.01 * kD * std::sqrt(3.0) / 2, 1e-15);
    EXPECT_THROW(random_positions(std::vector<double>(100, 0.5), 5.0, 5.0, true, true, rng, 1000), InputError);
}

TEST(EdEngine, RejectsBadInput) {
    EdConfig cfg;
    cfg.lx = cfg.ly = 2 * kD; // fewer than 3 cells in a periodic box
    EXPECT_THROW(EdEngine(cfg, {{0.001, 0.001}}, {{0, 0}}, {0.5 * kD}, {kM}), InputError);
    cfg.lx = cfg.ly = 10 * kD;
    EXPECT_THROW(EdEngine(cfg, {{0.001, 0.001}, {0.0015, 0.001}}, {{0, 0}, {0, 0}}, {0.5 * kD, 0.5 * kD}, {kM, kM}), InputError);
    cfg.law.r = 1.5;
    EXPECT_THROW(EdEngine(cfg, {{0.001, 0.001}}, {{0, 0}}, {0.5 * kD}, {kM}), InputError);
}

TEST(EdEngine, PolydisperseGasMatchesBruteForceAndConserves) {
    // Bidisperse disks (d and 0.7 d, masses ~ area) in a box with walls on x, periodic in y.
    const std::size_t n = 500;
    std::vector<double> rad(n), mass(n);
    for (std::size_t i = 0; i < n; ++i) {
        rad[i] = (i % 2 ? 0.35 : 0.5) * kD;
        mass[i] = kM * (rad[i] / (0.5 * kD)) * (rad[i] / (0.5 * kD));
    }
    const double l = 30 * kD;
    EdConfig cfg;
    cfg.lx = cfg.ly = l;
    cfg.periodic_x = false;
    cfg.walls = {EdWall{0, 0.0, +1}, EdWall{0, l, -1}};
    RngStream rng(8, 8);
    const auto pos = random_positions(rad, l, l, false, true, rng);
    EdEngine e(cfg, pos, maxwellian_velocities(mass, 1.0, rng), rad, mass);
    const double k0 = e.kinetic_energy().total();
    for (int round = 0; round < 10; ++round) {
        e.synchronize();
        const auto ref = brute_force_next(e);
        expect_next_collision_is(e, ref);
        e.run_collisions(500);
    }
    EXPECT_NEAR(e.kinetic_energy().total() / k0, 1.0, 1e-11);
    EXPECT_GT(e.wall_collisions(), 0u);
    EXPECT_LT(e.max_overlap(), 1e-9 * kD);
    EXPECT_LT(e.current_max_overlap(), 1e-9 * kD);
}

TEST(EdEngine, TcElasticMeansEnergyConservingUnlessFrictionKept) {
    for (bool keep : {false, true}) {
        EdConfig cfg;
        cfg.law = RoughDiskCollision{0.5, 0.5, 0.3, 0.5};
        cfg.t_c = 1e30;
        cfg.tc_keep_friction = keep;
        auto e = random_ed_gas(100, 0.3, 13, cfg);
        double k_prev = e.kinetic_energy().total();
        int elastic = 0, lossy_elastic = 0;
        e.run_collisions(300, [&](const CollisionRecord& r) {
            const double k = e.kinetic_energy().total();
            if (r.elastic) {
                ++elastic;
                if (k < k_prev * (1 - 1e-9)) ++lossy_elastic;
                EXPECT_LE(k, k_prev * (1 + 1e-12)); // never gains energy
            }
            k_prev = k;
        });
        EXPECT_GT(elastic, 200);
        if (keep) EXPECT_GT(lossy_elastic, 10); // r = 1 but friction still dissipates
        else EXPECT_EQ(lossy_elastic, 0);       // r = 1, no tangential impulse: exactly elastic
    }
}

// Eq. (7) with either rule: a pair collision is elastic when one partner (tc_both = false) or
// both partners (true) collided at most t_c before. Checked against our own bookkeeping of the
// records; a particle's first collision is skipped (its earlier history is unknown here).
TEST(EdEngine, TcRuleEitherOrBothPartners) {
    for (bool both : {false, true}) {
        EdConfig cfg;
        cfg.law = RoughDiskCollision{0.5, 0.0, -1.0, 0.5};
        auto probe = random_ed_gas(200, 0.3, 21, cfg);
        probe.run_collisions(2000);
        // t_c = the mean time between a particle's collisions, so that both outcomes are common.
        const double tc = probe.time() / 2000.0 * 100.0;
        cfg.tc_both = both;
        cfg.t_c = tc;
        auto f = random_ed_gas(200, 0.3, 21, cfg);
        std::vector<double> last(200, -1.0);
        int checked = 0, elastic = 0, mixed = 0;
        f.run_collisions(20000, [&](const CollisionRecord& r) {
            if (r.j < 0) return;
            const auto i = std::size_t(r.i), j = std::size_t(r.j);
            if (last[i] >= 0 && last[j] >= 0) {
                const bool ti = r.t - last[i] <= tc, tj = r.t - last[j] <= tc;
                EXPECT_EQ(r.elastic, both ? (ti && tj) : (ti || tj));
                ++checked;
                elastic += r.elastic;
                mixed += ti != tj;
            }
            last[i] = last[j] = r.t;
        });
        EXPECT_GT(checked, 10000);
        EXPECT_GT(elastic, 100);
        EXPECT_GT(mixed, 100); // the two rules differ on these
    }
}

TEST(EdEngine, CollisionRecordGeometry) {
    EdConfig cfg;
    cfg.law = RoughDiskCollision{0.9, 0.3, 0.2, 0.5};
    auto e = random_ed_gas(400, 0.3, 17, cfg);
    int n = 0;
    e.run_collisions(2000, [&](const CollisionRecord& r) {
        ASSERT_GE(r.j, 0);
        ++n;
        const Vec2 d = r.ri - r.rj;
        EXPECT_NEAR(norm(d), kD, 1e-12 * kD);            // contact: |r_i - r_j| = (d_i + d_j)/2
        EXPECT_NEAR(norm(r.n), 1.0, 1e-14);
        EXPECT_NEAR(cross(d, r.n), 0.0, 1e-15 * kD);      // n along r_i - r_j ...
        EXPECT_GT(dot(d, r.n), 0.0);                      // ... pointing from j to i
        EXPECT_GT(dot(r.dP, r.n), 0.0);                   // repulsive normal impulse on i
        EXPECT_GE(r.b_over_d, 0.0);
        EXPECT_LE(r.b_over_d, 1.0);
        EXPECT_NEAR(r.t, e.time(), 0.0);
    });
    EXPECT_EQ(n, 2000);
}
