// The bodies of the soft-sphere engines: free grains, fixed (infinite-mass) wall grains, and
// infinite straight rows of fixed wall grains (a corrugated wall).
#pragma once
#include <cmath>
#include "core/vec2.hpp"

namespace granrepro {

struct SoftGrain {
    Vec2 r;            // centre [m]
    Vec2 v;            // velocity [m/s]
    double radius = 0; // [m]
    double mass = 0;   // [kg]
};

struct FixedGrain {
    Vec2 r;            // centre [m]
    double radius = 0; // [m]
};

// Wall grains of radius `radius` centred at (x, y0 + k * spacing) for every integer k: the
// corrugated wall of Schäfer & Wolf's Figs. 4-6, along the y axis.
struct GrainRow {
    double x = 0;       // [m]
    double y0 = 0;      // [m]
    double spacing = 0; // wall "wavelength" [m]
    double radius = 0;  // [m]
    Vec2 centre(long k) const { return {x, y0 + static_cast<double>(k) * spacing}; }
};

} // namespace granrepro
