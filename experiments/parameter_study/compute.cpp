// parameter-study: one run of the sweep, from the equilibrated lattice gas to C/N = cn_end.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/rng_stream.hpp"
#include "engines/ed/ed_engine.hpp"
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/parameter_study/spec.hpp"
#include "harness/sampled_run.hpp"
#include "scenarios/ed_gas.hpp"

namespace granrepro::experiments::parameter_study_detail {

Trace run_point(const ParameterStudySpec& s, const Point& pt, std::uint64_t seed, std::uint64_t stream) {
    const auto wall0 = std::chrono::steady_clock::now();
    const std::size_t n = std::size_t(s.n_side * s.n_side);
    const double L = s.box_over_d * s.d;
    const std::vector<double> rad(n, 0.5 * s.d), mass(n, s.mass);
    RngStream rng(seed, stream);
    const EquilibratedGas gas =
        equilibrated_lattice_gas(L, maxwellian_velocities(mass, s.vbar, rng), rad, mass, s.vbar, s.equilibration);
    EdEngine eng(rough_disk_box(L, pt.r, s.mu, pt.t_c), gas.pos, gas.vel, rad, mass); // t = 0: dissipation switched on

    // The sampling loop's clock here is the count of pair collisions.
    struct CollisionClock {
        EdEngine& eng;
        void run_until(double count, NoCollisionObserver) { eng.run_collisions(std::uint64_t(count) - eng.total_collisions()); }
    } collisions{eng};
    Trace tr;
    auto sample = [&] {
        const EdKineticEnergy k = eng.kinetic_energy();
        tr.t.push_back(eng.time());
        tr.cn.push_back(2.0 * double(eng.total_collisions()) / double(n));
        tr.elastic_cn.push_back(2.0 * double(eng.elastic_collisions()) / double(n));
        tr.kx.push_back(k.kx);
        tr.ky.push_back(k.ky);
        tr.krot.push_back(k.krot);
    };
    sample();
    const auto target = std::uint64_t(std::ceil(s.cn_end * double(n) / 2.0));
    // Samples every 0.2 collisions per particle early (Fig. 8(a) is linear in C/N) and every 1 %
    // of the collisions later (Fig. 9(b) is logarithmic in C/N): ~500 samples per run.
    auto next_count = [&](long) -> std::optional<double> {
        const std::uint64_t done = eng.total_collisions();
        if (done >= target) return std::nullopt;
        const std::uint64_t chunk = std::max<std::uint64_t>({1, n / 10, done / 100});
        return double(done + std::min(chunk, target - done)); // exact: counts stay far below 2^53
    };
    try {
        SampledRun<>().run(collisions, next_count, NoCollisionObserver{}, [&](long, double) { sample(); return false; }, NAN);
    } catch (const std::runtime_error& e) {
        // The collapse guard: keep what was measured and report the reason.
        tr.error = e.what();
        sample();
    }
    tr.events = double(eng.events_processed());
    tr.pairs = double(eng.total_collisions());
    tr.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return tr;
}

} // namespace granrepro::experiments::parameter_study_detail
