// One instantaneous picture of the particles, as every engine can produce it. Plain data, so the
// observables, the writers and the plotting code share it without depending on any engine.
#pragma once
#include "core/vec2.hpp"

#include <vector>

namespace granrepro {

struct Snapshot {
    double t = 0.0;                     // simulation time of the picture [s]
    double Lx = 0.0;                    // box width [m]
    double Ly = 0.0;                    // box height [m]
    std::vector<Vec2> positions;        // particle centres [m]
    std::vector<Vec2> velocities;       // particle velocities [m/s]
    std::vector<double> radii;          // particle radii [m]
    std::vector<double> collision_rate; // per-particle collision frequency N_c over the trailing
                                        // window (Luding 1998 Sec. 4.3, Figs 11, 13) [1/s]
};

} // namespace granrepro
