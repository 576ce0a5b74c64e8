// The one serialization (io/h5_fields.hpp) and the one sampling loop (harness/sampled_run.hpp):
// every field type round-trips bit for bit, and a sampled run killed after a checkpoint and
// resumed equals an uninterrupted one, for ED and DSMC alike (one test body, two engines).
#include "gas.hpp"
#include "harness/sampled_run.hpp"
#include "saved_states.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>

using namespace granrepro;
using namespace granrepro::test;
namespace fs = std::filesystem;

namespace {

enum class Colour { red, green, blue };

struct Inner {
    double a = 0;
    std::vector<std::uint32_t> counts;
    template <class V>
    void fields(V&& v) {
        v("a", a), v("counts", counts);
    }
};

struct Everything {
    double x = 0;
    long n = 0;
    int i = 0;
    std::uint64_t big = 0;
    bool flag = false;
    Colour colour = Colour::red;
    std::string text;
    Vec2 g;
    std::vector<double> values;
    std::vector<std::int32_t> ints;
    std::vector<std::uint8_t> bytes;
    std::vector<std::uint64_t> u64;
    std::vector<Vec2> points;
    Inner inner;
    std::vector<Inner> list;
    template <class V>
    void fields(V&& v) {
        v("x", x), v("n", n), v("i", i), v("big", big), v("flag", flag), v("colour", colour), v("text", text);
        v("g", g), v("values", values), v("ints", ints), v("bytes", bytes), v("u64", u64), v("points", points);
        v("inner", inner), v("list", list);
    }
};

// Reads Everything's "n" into a narrower type.
struct NarrowN {
    std::uint32_t n = 0;
    template <class V>
    void fields(V&& v) {
        v("n", n);
    }
};

} // namespace

TEST(H5Fields, EveryFieldTypeRoundTripsBitForBit) {
    TempDir dir;
    Everything e;
    e.x = -0.0;
    e.n = -123456789012;
    e.i = -7;
    e.big = std::numeric_limits<std::uint64_t>::max();
    e.flag = true;
    e.colour = Colour::blue;
    e.text = "Luding 1998";
    e.g = {0.1, -9.81};
    e.values = {std::nan(""), -INFINITY, 1e-310, 0.1 + 0.2};
    e.ints = {-1, std::numeric_limits<std::int32_t>::min()};
    e.bytes = {0, 255};
    e.u64 = {1, std::uint64_t(1) << 63};
    e.points = {{1.5, -2.5}, {3e300, 4e-300}};
    e.inner = {2.5, {7, 8}};
    e.list = {{1.0, {}}, {std::nextafter(1.0, 2.0), {3}}};
    Everything r;
    read_fields(written_h5(dir, [&](const H5File& f) { write_fields(f.group("e"), e); }).open_group("e"), r);
    expect_same_fields(r, e); // bit for bit: the sign of -0 and NaN included
}

TEST(H5Fields, AMissingFieldThrows) {
    TempDir dir;
    const H5File f = written_h5(dir, [](const H5File& w) { write_fields(w.group("e"), Inner{1.0, {2}}); });
    Everything r;
    EXPECT_ANY_THROW(read_fields(f.open_group("e"), r));
}

TEST(H5Fields, AnIntegerTheFieldCannotHoldThrows) {
    // A stored -1 must not wrap into a valid uint32 (a state reader's ">= 1" check would pass).
    TempDir dir;
    const H5File f = written_h5(dir, [](const H5File& w) {
        Everything e;
        write_fields(w.group("fits"), e);
        e.n = -1;
        write_fields(w.group("negative"), e);
        e.n = long(1) << 32;
        write_fields(w.group("too_big"), e);
    });
    NarrowN r;
    EXPECT_NO_THROW(read_fields(f.open_group("fits"), r));
    EXPECT_ANY_THROW(read_fields(f.open_group("negative"), r));
    EXPECT_ANY_THROW(read_fields(f.open_group("too_big"), r));
}

namespace {

// What the sampled run carries: the samples and an observer's running count.
struct Carry {
    std::vector<double> t, k;
    std::uint64_t observed = 0;
    template <class V>
    void fields(V&& v) {
        v("t", t), v("K", k), v("observed", observed);
    }
};

EdEngine small_ed_gas() {
    EdConfig cfg;
    cfg.law = RoughDiskCollision{0.9, 0.0, -1.0, 0.5};
    return random_ed_gas(200, 0.25, 5, cfg);
}

DsmcEngine small_dsmc_gas() {
    DsmcConfig cfg;
    cfg.lx = cfg.ly = box_for(400, 0.25);
    cfg.r = 0.9;
    cfg.seed = 5;
    const Disks d = random_disks(400, cfg.lx, true, true, 5);
    return DsmcEngine(cfg, d.pos, d.vel, d.rad, d.mass);
}

// Samples K at 40 times; `stop_after_saves` > 0 kills the run (as a SIGKILL would) once that many
// checkpoints are on disk. Returns the carry, resumed from the checkpoint if there is one.
template <class Make>
Carry sampled(Make make, const fs::path& dir, long stop_after_saves) {
    ParameterSet params;
    const RunContext ctx{params, Scale::Quick, 1, 1, true, dir, 0.0}; // interval 0: save at every sample
    RunCheckpoint checkpoint(ctx, "test");
    SampledRun<Carry> run(checkpoint, "granrepro-test-run", 1);
    auto engine = make();
    Carry carry;
    decltype(engine.save_state()) saved;
    if (run.resume(saved, carry)) engine.restore_state(saved);
    const auto trigger = [](long i) { return i < 40 ? std::optional<double>(5e-4 * double(i + 1)) : std::nullopt; };
    run.run(engine, carry, trigger, [&](const CollisionRecord&) { ++carry.observed; },
            [&](long i, double t) {
                carry.t.push_back(t);
                carry.k.push_back(total_kinetic_energy(engine));
                if (stop_after_saves > 0 && checkpoint.saves() >= stop_after_saves) throw std::runtime_error("killed");
                return i == 35; // the sampler may end the run early
            },
            40 * 5e-4);
    return carry;
}

template <class Make>
void expect_resume_is_bit_identical(Make make) {
    TempDir whole_dir("-whole"), parts_dir("-parts");
    const Carry whole = sampled(make, whole_dir.path, 0);
    EXPECT_THROW(sampled(make, parts_dir.path, 12), std::runtime_error);
    const Carry resumed = sampled(make, parts_dir.path, 0);
    ASSERT_EQ(whole.t.size(), 36u); // stopped by the sampler after sample 35
    EXPECT_GT(whole.observed, 1000u);
    expect_same_fields(resumed, whole);
    EXPECT_LT(whole.k.back(), 0.5 * whole.k.front()); // it cooled: the samples are not all one value
}

} // namespace

TEST(SampledRun, KilledAndResumedEqualsUninterruptedEd) { expect_resume_is_bit_identical(small_ed_gas); }
TEST(SampledRun, KilledAndResumedEqualsUninterruptedDsmc) { expect_resume_is_bit_identical(small_dsmc_gas); }

// Without a checkpoint the same loop serves a run redone whole: it advances the engine to each
// trigger time before sampling there, and stops at the trigger's end or when the sample asks.
TEST(SampledRun, WithoutCheckpointSamplesAtEachTriggerUntilTheEndOrAStop) {
    struct Clock {
        double t = 0;
        std::vector<double> stops;
        void run_until(double to, NoCollisionObserver) { stops.push_back(t = to); }
    };
    Clock clock;
    std::vector<double> seen;
    auto at = [](long i) { return i < 4 ? std::optional(0.5 * double(i + 1)) : std::nullopt; };
    auto record = [&](long, double t) { seen.push_back(clock.t - t); return false; };
    SampledRun<>().run(clock, at, NoCollisionObserver{}, record, 2.0);
    EXPECT_EQ(clock.stops, (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
    EXPECT_EQ(seen, std::vector<double>(4, 0.0)); // each sample sees the engine at its time

    Clock stopped;
    long samples = 0;
    SampledRun<>().run(stopped, at, NoCollisionObserver{}, [&](long i, double) { ++samples; return i == 1; }, NAN);
    EXPECT_EQ(samples, 2);
    EXPECT_EQ(stopped.stops.size(), 2u);
}
