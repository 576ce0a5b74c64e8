// Parameters of an ED run (everything except the per-particle state), for the collision
// operator Collision (EdConfig: the default, RoughDiskCollision).
#pragma once
#include "data/fields.hpp"
#include "core/vec2.hpp"
#include "engines/ed/ed_collision_operator.hpp"
#include "engines/ed/ed_wall.hpp"
#include "models/rough_disk_collision.hpp"
#include <cstdint>
#include <vector>

namespace granrepro {

template <EdCollisionOperator Collision>
struct BasicEdConfig {
    double lx = 1.0;          // box width [m]; cells tile [0, lx)
    double ly = 1.0;          // box height [m]
    bool periodic_x = true;   // false: the x axis is closed by walls (or open: edge cells extend to infinity)
    bool periodic_y = true;
    Vec2 gravity{0.0, 0.0};   // uniform acceleration [m/s^2]
    Collision law;            // particle-particle operator; default: r, mu, beta0, q (Luding Eqs. (1)-(6))
    std::vector<EdWall> walls; // each collides by law.against(wall)
    // TC model, Luding Eq. (7): a collision is elastic when either partner's previous collision
    // happened at most t_c ago [s]; 0 = plain ED.
    double t_c = 0.0;
    // How Eq. (7) combines the partners of a pair collision, which the paper leaves open:
    // false (default): elastic when either partner collided within t_c; true: only when both did.
    bool tc_both = false;
    // What "elastic" means for rough disks under TC (law.elastic_version(tc_keep_friction)).
    // false (default): r = 1 and no tangential impulse, so the collision conserves energy
    // exactly, as the paper's wording ("assumed to be elastic") requires. true: r = 1 but
    // friction (mu, beta0) unchanged, which still dissipates.
    bool tc_keep_friction = false;
    // Cell edge = max(cell_size_factor * largest diameter, tile of the box) [-]; >= 1.
    double cell_size_factor = 1.0;
    // Inelastic-collapse guard: a particle taking part in more than collapse_limit collisions
    // within collapse_window [s] aborts the run with an exception. collapse_window = 0 picks
    // 1e-7 * (mean diameter / rms speed) when a run starts.
    std::uint32_t collapse_limit = 2000;
    double collapse_window = 0.0;

    // The one list of fields, walked by the state files (io/h5_fields.hpp).
    GRANREPRO_FIELDS(lx, ly, periodic_x, periodic_y, gravity, law, walls, t_c, tc_both, tc_keep_friction,
                     cell_size_factor, collapse_limit, collapse_window)
};

using EdConfig = BasicEdConfig<RoughDiskCollision>;

} // namespace granrepro
