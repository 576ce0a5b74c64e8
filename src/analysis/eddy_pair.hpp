// Two co-rotating eddies in a periodic square box, as in the left panel of Luding 1998 Fig. 5
// ("the two eddies (top left and bottom right) ... are rotating in the same sense").
//
// The rotation of a square region about its centre c is
//     rho = sum_i (r_i - c) x v_i / sum_i |r_i - c| |v_i|     in [-1, 1]
// over the particles inside (minimum image): +1 for a rigid counter-clockwise rotation, -1
// clockwise, ~0 for uncorrelated velocities (of order 1/sqrt(n)).
// The box is tiled into four quadrants, shifted over a grid of offsets. An eddy pair sits on a
// diagonal: both quadrants turn the same way, and the quadrants of the other diagonal do not
// (they may turn the other way, as the flow between two co-rotating eddies does). Its strength is
//     E = min(s rho_a, s rho_b) - max(0, s rho_c, s rho_d),   s = +-1 the sense,
// the weaker eddy's rotation less any rotation in the same sense on the other diagonal, maximised
// over offsets, the two diagonals and both senses. Two co-rotating eddies give E of order 1;
// shear layers give E <= 0 (one wavelength turns the two rows oppositely, two wavelengths turn
// all four quadrants alike); uncorrelated velocities give a small E, measured by shuffling the
// velocities among the particles (same speeds, no correlation).
#pragma once
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace granrepro {

struct EddyPair {
    double strength = 0;   // E above
    int sense = 0;         // +1 counter-clockwise, -1 clockwise
    Vec2 centre_a, centre_b; // centres of the two quadrants [length units of pos], in [0, box)
    double rotation_a = 0, rotation_b = 0; // their rho
};

// Rotation rho of the particles within the square of half-width `half` around `centre`.
double region_rotation(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box, Vec2 centre, double half);

// The strongest co-rotating diagonal pair; offsets on a shifts x shifts grid over [0, box/2)^2.
EddyPair find_eddy_pair(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box, int shifts = 16);

// Strengths of find_eddy_pair with the velocities shuffled among the particles, n_shuffles times
// (deterministic for a given seed): the null distribution of E.
std::vector<double> shuffled_eddy_strengths(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box,
                                            int n_shuffles, std::uint64_t seed, int shifts = 16);

} // namespace granrepro
