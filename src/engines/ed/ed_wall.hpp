// A flat, axis-aligned, fixed wall for the ED engine (Luding 1998 Sec. 2.1: m_2 = infinity,
// with its own restitution r_w, friction mu_w and tangential restitution beta0_w).
#pragma once

namespace granrepro {

struct EdWall {
    int axis = 1;          // 0: the wall is the line x = position; 1: the line y = position
    double position = 0.0; // [m]
    int side = +1;         // +1: disks live at coordinates > position (normal along +axis), -1: below
    double r = 1.0;        // normal restitution r_w [-]
    double mu = 0.0;       // Coulomb friction mu_w [-]
    double beta0 = -1.0;   // maximal tangential restitution beta0_w [-]
    bool enabled = true;   // a disabled wall is ignored (e.g. the pipe's bottom removed at t = 0)

    // The one list of fields, walked by the state files (io/h5_fields.hpp).
    GRANREPRO_FIELDS(axis, position, side, r, mu, beta0, enabled)
};

} // namespace granrepro
