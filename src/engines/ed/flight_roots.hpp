// Event prediction for ballistic (possibly parabolic) flights: the only place where contact and
// crossing times are computed. Everything returns a time interval from "now" [s], or +infinity.
//
// Round-off policy (why the engine's overlaps cannot grow): a pair or a wall that is already at
// or inside contact and approaching collides *immediately* (t = 0) instead of being ignored, and
// a receding pair is never reported. Roots are taken with the cancellation-free forms
// t = c / (-b + sqrt(D)) (Numerical Recipes' "q" form), so grazing roots do not lose digits.
#pragma once
#include <cmath>
#include <limits>

namespace granrepro::flight_roots {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// Two disks with relative position dr = r_i - r_j [m] and relative velocity dv [m/s] move
// apart linearly (uniform gravity cancels in relative motion). First t >= 0 with |dr + dv t| =
// sigma [m] while approaching.
inline double pair_contact_time(double drx, double dry, double dvx, double dvy, double sigma) {
    const double b = drx * dvx + dry * dvy;
    if (b >= 0.0) return kNever;
    const double c = drx * drx + dry * dry - sigma * sigma;
    if (c <= 0.0) return 0.0;
    const double v2 = dvx * dvx + dvy * dvy;
    const double disc = b * b - v2 * c;
    if (disc <= 0.0) return kNever;
    return c / (-b + std::sqrt(disc));
}

// A gap G(t) = gap + u t + acc t^2/2 [m] (u [m/s], acc [m/s^2]) to a wall or cell boundary.
// Returns the first t >= 0 at which G reaches 0 while decreasing. A gap that is already <= 0
// (round-off put the disk on the far side) and decreasing fires at t = 0; one that is <= 0 but
// currently increasing fires when it next decreases through 0, or at its apex if it never gets
// back to positive values (then it is on the far side for good, by round-off only).
inline double gap_closing_time(double gap, double u, double acc) {
    if (gap <= 0.0) {
        if (u < 0.0 || (u == 0.0 && acc < 0.0)) return 0.0;
        if (acc >= 0.0) return kNever;
        const double disc = u * u - 2.0 * acc * gap; // = u^2 - 2|acc||gap| here
        if (disc <= 0.0) return u / -acc;            // apex
        return (u + std::sqrt(disc)) / -acc;         // later root: G decreasing
    }
    if (acc == 0.0) return u < 0.0 ? gap / -u : kNever;
    const double disc = u * u - 2.0 * acc * gap;
    if (disc < 0.0) return kNever; // only possible for acc > 0: turns before reaching 0
    const double sq = std::sqrt(disc);
    if (acc < 0.0) {
        // Exactly one positive root; pick the form without cancellation.
        return u >= 0.0 ? (u + sq) / -acc : 2.0 * gap / (sq - u);
    }
    // acc > 0: both roots share a sign, positive only while moving towards the boundary.
    if (u >= 0.0) return kNever;
    return 2.0 * gap / (sq - u); // smaller root
}

} // namespace granrepro::flight_roots
