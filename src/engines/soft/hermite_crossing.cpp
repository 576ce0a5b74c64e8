#include "engines/soft/hermite_crossing.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <memory>

namespace granrepro {

double HermiteSegment::value(double t) const {
    const double s = t / h;
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * x1 +
           (s3 - s2) * h * v1;
}

double HermiteSegment::slope(double t) const {
    const double s = t / h;
    const double s2 = s * s;
    return ((6 * s2 - 6 * s) * x0 + (6 * s2 - 6 * s) * (-x1)) / h + (3 * s2 - 4 * s + 1) * v0 +
           (3 * s2 - 2 * s) * v1;
}

namespace {
double segment_value(double t, void* p) { return static_cast<const HermiteSegment*>(p)->value(t); }

double brent_root(const HermiteSegment& seg, double a, double b) {
    // GSL's error handler aborts by default; failures here are handled by falling back to the
    // bracket midpoint, so switch it off for the duration of the call.
    gsl_error_handler_t* old = gsl_set_error_handler_off();
    gsl_function f{&segment_value, const_cast<HermiteSegment*>(&seg)};
    std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    double root = 0.5 * (a + b);
    if (gsl_root_fsolver_set(solver.get(), &f, a, b) == GSL_SUCCESS) {
        for (int it = 0; it < 100; ++it) {
            if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
            root = gsl_root_fsolver_root(solver.get());
            const double lo = gsl_root_fsolver_x_lower(solver.get());
            const double hi = gsl_root_fsolver_x_upper(solver.get());
            if (gsl_root_test_interval(lo, hi, 0.0, 1e-14) == GSL_SUCCESS) break;
        }
    }
    gsl_set_error_handler(old);
    return root;
}
} // namespace

std::optional<double> first_crossing(const HermiteSegment& seg, CrossingDirection dir,
                                     int samples) {
    double ta = 0.0;
    double xa = seg.x0;
    for (int k = 1; k <= samples; ++k) {
        const double tb = seg.h * k / samples;
        const double xb = (k == samples) ? seg.x1 : seg.value(tb);
        const bool crosses = dir == CrossingDirection::Upward ? (xa <= 0.0 && xb > 0.0)
                                                              : (xa >= 0.0 && xb < 0.0);
        if (crosses) {
            // A root at the left end of the very first interval is the residue of a switch just
            // made; the sign test above already excludes it unless xa is exactly zero.
            return brent_root(seg, ta, tb);
        }
        ta = tb;
        xa = xb;
    }
    return std::nullopt;
}

} // namespace granrepro
