// Sample times for K(t) and friends. Luding 1998 Figs 2, 9(a), 10(a) are log-log plots over
// several decades, so equally spaced samples would waste almost all points on the last decade.
// Engines either poll due(t) after each step/event, or schedule an event at next().
#pragma once
#include <cstddef>
#include <vector>

namespace granrepro {

class LogTimeSampler {
public:
    // Times t_min * 10^(k/per_decade), k = 0, 1, ..., up to and including t_max (within a relative
    // 1e-9, so t_max itself is kept when it lies on the grid). t_min > 0 [s], t_max >= t_min [s],
    // per_decade >= 1. Throws std::invalid_argument otherwise.
    LogTimeSampler(double t_min, double t_max, int per_decade);

    const std::vector<double>& times() const { return times_; }
    std::size_t size() const { return times_.size(); }
    // Next sample time not yet consumed [s]; +infinity when all are consumed.
    double next() const;
    bool done() const { return next_ >= times_.size(); }
    // True when the time t [s] has reached the next sample time; consumes every sample time <= t
    // (an engine that jumps over several sample times takes one sample, not a burst of copies).
    bool due(double t);
    // Consumes exactly one sample time.
    void advance() { if (next_ < times_.size()) ++next_; }
    void reset() { next_ = 0; }

private:
    std::vector<double> times_;
    std::size_t next_ = 0;
};

} // namespace granrepro
