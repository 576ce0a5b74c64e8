#include "observables/log_time_sampler.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace granrepro {

LogTimeSampler::LogTimeSampler(double t_min, double t_max, int per_decade) {
    if (!(t_min > 0.0) || !(t_max >= t_min) || per_decade < 1 || !std::isfinite(t_max))
        throw std::invalid_argument("LogTimeSampler: need 0 < t_min <= t_max and per_decade >= 1");
    // Each time from its own exponent, not by repeated multiplication, so no rounding drifts.
    for (int k = 0;; ++k) {
        const double t = t_min * std::pow(10.0, static_cast<double>(k) / per_decade);
        if (t > t_max * (1.0 + 1e-9)) break;
        times_.push_back(t);
    }
}

double LogTimeSampler::next() const {
    return done() ? std::numeric_limits<double>::infinity() : times_[next_];
}

bool LogTimeSampler::due(double t) {
    bool hit = false;
    while (next_ < times_.size() && times_[next_] <= t) {
        ++next_;
        hit = true;
    }
    return hit;
}

} // namespace granrepro
