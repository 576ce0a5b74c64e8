// A crack in a column of equal disks between two vertical walls (Luding 1998 Sec. 5: "a crack
// opens below the plug"; Ref. [83]: approximately V-shaped microcracks), of any shape.
//
// Definition: the column has a crack of opening w when a probe disk of diameter w can pass from
// one side wall to the other with at least `min_below` disks below its path and `min_above`
// above it. The opening is the largest such w, a surface-to-surface distance [m].
//
// How: by planar duality the probe is blocked exactly when a chain of disks, each closer than
// d + w to the next (centre to centre), links the lowest `min_below` disks to the highest
// `min_above`. So the opening is the bottleneck of the best chain: over all chains from the
// bottom set to the top set, the smallest possible largest surface gap. Adding neighbour pairs in
// order of increasing gap to a disjoint-set forest (Kruskal) finds it exactly; the pair that
// joins bottom and top is the crack's narrowest place. Horizontal, V-shaped, tilted or ragged
// cracks are all found the same way; a hole or a notch that does not reach both walls is not a
// crack (a chain passes around it).
//
// The crack's course: with the pairs narrower than the opening joined, the disks fall into the
// part connected to the bottom, the part connected to the top, and loose disks. Per slice of the
// pipe's width, the crack runs midway between the highest bottom-part disk and the lowest
// top-part disk above it.
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace granrepro {

struct CrackSearch {
    double diameter = 0;        // disk diameter d [m]
    double width = 0;           // pipe width: walls at x = 0 and x = width [m]
    std::size_t min_below = 1;  // disks that must lie below the crack (the lowest ones)
    std::size_t min_above = 1;  // disks that must lie above it (the highest ones)
    double max_opening = 0;     // openings are resolved up to this [m]; wider ones report it
    double slice = 0;           // width of a slice of the course [m] (0: one diameter)
};

struct Crack {
    double opening = 0;        // [m], <= max_opening
    bool wider = false;        // no chain with gaps below max_opening: opening >= max_opening
    int narrow_i = -1, narrow_j = -1; // the pair at the narrowest place (-1 if wider)
    std::vector<int> side;     // per disk: -1 bottom part, +1 top part, 0 loose
    std::vector<double> course_x, course_y; // slice centres and the crack's mid-height (NaN: none)
    double y_left = 0, y_right = 0; // course in the slices at the walls (NaN if undefined) [m]
    double y_mean = 0;              // mean of the defined course [m]
    double y_low = 0, y_high = 0;   // its lowest and highest point [m]
    double x_low = 0;               // where it is lowest [m]
};

// Throws std::invalid_argument when min_below + min_above exceeds the number of disks or a
// length is not positive.
Crack find_crack(const std::vector<Vec2>& pos, const CrackSearch& s);

} // namespace granrepro
