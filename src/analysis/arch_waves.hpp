// Successive arches of the falling column as "momentum waves" (Luding 1998, Sec. 5, after
// Ref. [7]): cracks "develop in the lower part of the pile and ascend progressively", and the
// material from above hits the decelerated plug and "causes a new, possibly stronger momentum
// wave". Our columns open no crack (expected/pipe-arching.toml, crack_visible), so the arches are
// the waves we can follow.
//
// Input: one sighting per frame from the first arch's frame on: whether the frame has an arch,
// its mean initial (t = 0, Lagrangian) height and its number of hot disks. An arch is a new wave
// when its initial height differs from the previous sighting's by more than `separation`
// (jitter of one arch between frames is not a wave); each such step rises or falls. A wave's
// strength is its largest number of hot disks in one frame; the first arch's strength is taken
// over its first `settle` frames within `separation` of its height, a later wave's from frame
// `settle` on, farther than `separation` from the first arch (so the first arch growing in
// place is not a new wave).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace granrepro {

struct ArchSighting {
    bool found = false;
    double y0 = NAN;  // mean initial height of the arch's disks
    double size = 0;  // its hot disks
};

struct ArchWaves {
    double steps = 0, steps_up = 0;        // jumps between successive waves, and those that rose
    double first_peak = 0, later_peak = 0; // strengths of the first arch and of the strongest later wave
    bool stronger() const { return later_peak > first_peak; }
};

inline ArchWaves follow_arch_waves(const std::vector<ArchSighting>& frames, std::size_t settle, double separation) {
    ArchWaves w;
    if (frames.empty() || !frames.front().found) return w;
    const double y_first = frames.front().y0;
    double y_prev = y_first;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const ArchSighting& b = frames[k];
        if (!b.found) continue;
        const bool near_first = std::abs(b.y0 - y_first) <= separation;
        if (near_first && k < settle) w.first_peak = std::max(w.first_peak, b.size);
        if (!near_first && k >= settle) w.later_peak = std::max(w.later_peak, b.size);
        if (std::abs(b.y0 - y_prev) > separation) {
            w.steps += 1;
            w.steps_up += b.y0 > y_prev ? 1 : 0;
        }
        y_prev = b.y0;
    }
    return w;
}

} // namespace granrepro
