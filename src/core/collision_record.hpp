// What an engine reports about one instantaneous collision (ED and DSMC). Observables
// (impact-parameter histograms, collisional stress, collision counts) consume only this, so they
// work for every hard-particle engine.
#pragma once
#include "core/vec2.hpp"

namespace granrepro {

struct CollisionRecord {
    double t = 0.0;        // time of the collision [s]
    int i = 0;             // first particle index
    int j = 0;             // partner index; a wall w is reported as j = -1 - w
    Vec2 ri;               // centre of i at contact [m]
    Vec2 rj;               // centre of j at contact [m] (unwrapped next to ri); for walls the contact point
    Vec2 n;                // unit normal pointing from j to i
    Vec2 dP;               // momentum change of particle i [kg m/s] (j receives -dP)
    double b_over_d = 0.0; // impact parameter |sin(gamma)|, gamma the angle between v_ij and r_ij
    bool elastic = false;  // true when the TC model (Luding Eq. 7) made the collision elastic
};

} // namespace granrepro
