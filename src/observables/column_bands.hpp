// A falling column followed in Lagrangian bands (Luding 1998 Sec. 5): every disk belongs for good
// to the band of its initial height y0, so a band is the same material at every frame. Per frame
// and band (edges at multiples of the band height): mean height and vertical velocity, split into disks at a side wall and inside, and
// the vertical impulse the side walls gave the band's disks during the frame. From these:
// how much of the weight the walls carry, how a plug decelerates against the material below it,
// and how far the two move apart (a crack opening below the plug).
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace granrepro {

class ColumnBands {
public:
    // y0: initial heights [m]; band_height > 0 [m]; a disk is at a wall when its centre is within
    // wall_reach [m] of x = 0 or x = width [m].
    ColumnBands(std::vector<double> y0, double band_height, double wall_reach, double width);

    // One frame at time t [s]: positions [m], velocities [m/s], and per disk the vertical impulse
    // [kg m/s] the side walls gave it since the previous frame.
    void add_frame(double t, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                   const std::vector<double>& wall_jy);

    struct Group {
        double n = 0, n_wall = 0;  // disks, of which at a wall
        double y = 0, vy = 0;      // mean height [m] and vertical velocity [m/s]
        double vy_wall = 0, vy_inner = 0; // the same for the disks at a wall and the others (NaN if none)
        double jy = 0;             // wall impulse received during the frame [kg m/s]
    };
    // The disks whose initial height lies in [y0_lo, y0_hi) (whole bands: a band counts when its
    // centre does), at frame k (0-based, in the order added). Means are NaN for an empty group.
    Group group(std::size_t k, double y0_lo, double y0_hi) const;

    std::size_t frames() const { return t_.size(); }
    double time(std::size_t k) const { return t_.at(k); }

private:
    struct Sums {
        double n = 0, nw = 0, y = 0, vy = 0, vyw = 0, jy = 0;
    };
    std::vector<double> y0_;
    double h_, reach_, width_, y0_min_;
    std::size_t bands_;
    std::vector<std::size_t> band_of_;
    std::vector<double> t_;
    std::vector<std::vector<Sums>> s_; // [frame][band]
};

} // namespace granrepro
