// What a soft normal contact law hands to the shear law: the whole normal force of Eq. (1) or
// (3) and its elastic part alone (k_N xi, or k xi^(3/2) for Hertz-Kuwabara-Kono). Both are
// repulsive when positive [N]. The shear law needs both because the papers' Coulomb law, Eq. (2),
// can be read in several ways (src/models/coulomb_shear.hpp).
#pragma once

namespace granrepro {

struct NormalForce {
    double total = 0.0;   // elastic + dashpot [N]
    double elastic = 0.0; // elastic part [N]
};

} // namespace granrepro
