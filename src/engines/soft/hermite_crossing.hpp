// Geometric primitive for the soft-sphere engines: where, inside one time step, does the overlap
// xi(t) of a pair change sign? xi and dxi/dt are known at both ends of the step, so xi is
// interpolated by the cubic Hermite polynomial (error O(h^4)) and the root is polished with GSL's
// Brent solver. Only the crossing in the requested direction counts, so a pair whose contact was
// just switched on or off at a round-off distance from xi = 0 is not switched straight back.
#pragma once
#include <optional>

namespace granrepro {

enum class CrossingDirection { Upward, Downward }; // xi from <= 0 to > 0 (contact starts) or back

struct HermiteSegment {
    double h;           // step length [s]
    double x0, v0;      // xi and dxi/dt at the start of the step
    double x1, v1;      // ... and at the end
    double value(double t) const;
    double slope(double t) const;
};

// First time in (0, h] at which the interpolated xi crosses zero in the given direction, if any.
// The segment is scanned on `samples` sub-intervals (a double crossing inside one of them,
// i.e. a contact shorter than h/samples, is missed).
std::optional<double> first_crossing(const HermiteSegment& seg, CrossingDirection dir,
                                     int samples = 16);

} // namespace granrepro
