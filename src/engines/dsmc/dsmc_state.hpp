// Complete, plain-data snapshot of a DSMC engine. Restoring it and stepping on reproduces an
// uninterrupted run bit for bit: the cell lists are rebuilt from the positions at every step, so
// positions, velocities, the step clock (time, tau, v_max, step counter) and the raw generator
// state are all the engine carries from one step to the next.
#pragma once
#include "data/fields.hpp"
#include "core/vec2.hpp"
#include "engines/dsmc/dsmc_config.hpp"
#include <cstdint>
#include <vector>

namespace granrepro {

inline constexpr std::uint32_t kNoPartner = 0xffffffffu;

struct DsmcState {
    DsmcConfig config;
    double time = 0.0;           // simulated time [s]
    double tau = 0.0;            // current time step [s]
    double v_max = 0.0;          // current bound on the relative speed, Eqs. (15)-(16) [m/s]
    std::uint64_t steps = 0;     // steps taken (drives the every-K resampling)

    std::vector<Vec2> position;  // [m], wrapped into [0,lx) x [0,ly)
    std::vector<Vec2> velocity;  // [m/s]
    std::vector<double> radius;  // [m]
    std::vector<double> mass;    // [kg]
    std::vector<double> last_collision_time;      // [s], -inf before the first (TC model)
    std::vector<std::uint64_t> collision_count;   // collisions per particle
    std::vector<std::uint32_t> last_partner;      // index of the last partner, kNoPartner before

    std::uint64_t collisions = 0;        // accepted pair collisions
    std::uint64_t elastic_collisions = 0; // of which made elastic by the TC model
    std::uint64_t candidates = 0;        // candidate pairs tested (sum of rounded M_c)
    std::uint64_t vmax_raises = 0;       // candidates whose sigma|v_ij| exceeded sigma v_max
    double exposure = 0.0;               // sum over steps and cells of N(N-1) tau / (2 V) [s/m^2]
    double resample_time = 0.0;          // time of the last resampling [s] (mft_fraction rule)
    std::uint64_t resample_collisions = 0; // collisions at the last resampling

    std::vector<unsigned char> rng_state; // RngStream::state()

    // The one list of fields, walked by the state files (io/h5_fields.hpp): a field left out
    // here is neither saved nor restored.
    GRANREPRO_FIELDS(config, time, tau, v_max, steps, position, velocity, radius, mass, last_collision_time,
                     collision_count, last_partner, collisions, elastic_collisions, candidates, vmax_raises, exposure,
                     resample_time, resample_collisions, rng_state)
};

} // namespace granrepro
