// Complete, plain-data snapshot of an ED engine: restoring it and running on reproduces an
// uninterrupted run bit for bit (the event queue is rebuilt from predicted_time, and its pop
// order is a total order on (time, id)). The engine has no random numbers, so no RNG state.
// EdState: the default operator, RoughDiskCollision.
#pragma once
#include "data/fields.hpp"
#include "engines/ed/ed_config.hpp"
#include <cstdint>
#include <vector>

namespace granrepro {

template <EdCollisionOperator Collision>
struct BasicEdState {
    BasicEdConfig<Collision> config;
    double time = 0.0; // global simulated time [s]

    // Per particle (size N). Positions/velocities are at each particle's own local_time.
    std::vector<double> x, y;                 // [m]
    std::vector<double> vx, vy;               // [m/s]
    std::vector<double> spin;                 // [1/s]
    std::vector<double> local_time;           // [s]
    std::vector<double> radius;               // [m]
    std::vector<double> mass;                 // [kg]
    std::vector<double> last_collision_time;  // [s], -inf before the first
    std::vector<double> burst_start;          // [s] collapse-guard window start
    std::vector<double> predicted_time;       // [s] pending event (queue key)
    std::vector<double> collision_time;       // [s] best predicted pair collision
    std::vector<std::uint64_t> collision_count;
    std::vector<std::uint64_t> partner_count; // partner's count when the pair was predicted
    std::vector<std::int32_t> last_partner;   // particle index, -1-w for wall w, INT32_MIN none
    std::vector<std::int32_t> partner;        // predicted partner, -1 none
    std::vector<std::uint8_t> event_kind;     // 0 collision, 1 wall, 2 cell crossing, 3 none
    std::vector<std::uint8_t> event_arg;      // wall index or crossing direction
    std::vector<std::uint32_t> burst_count;
    std::vector<std::int32_t> cell, cell_next, cell_prev;
    std::vector<std::int32_t> cell_head;      // size = number of cells

    std::uint64_t pair_collisions = 0;
    std::uint64_t wall_collisions = 0;
    std::uint64_t elastic_collisions = 0;
    std::uint64_t events = 0;
    std::uint64_t crossings = 0;
    std::uint64_t stale_events = 0;
    double max_overlap = 0.0;                 // [m]

    // The one list of fields, walked by the state files (io/h5_fields.hpp): a field left out
    // here is neither saved nor restored.
    GRANREPRO_FIELDS(config, time, x, y, vx, vy, spin, local_time, radius, mass, last_collision_time, burst_start,
                     predicted_time, collision_time, collision_count, partner_count, last_partner, partner,
                     event_kind, event_arg, burst_count, cell, cell_next, cell_prev, cell_head, pair_collisions,
                     wall_collisions, elastic_collisions, events, crossings, stale_events, max_overlap)
};

using EdState = BasicEdState<RoughDiskCollision>;

} // namespace granrepro
