#include "observables/collision_counter.hpp"

#include <algorithm>
#include <stdexcept>

namespace granrepro {

CollisionCounter::CollisionCounter(std::size_t n_particles, bool count_walls)
    : n_(n_particles), count_walls_(count_walls) {}

void CollisionCounter::add(const CollisionRecord& c) {
    if (c.i < 0 || static_cast<std::size_t>(c.i) >= n_ || (c.j >= 0 && static_cast<std::size_t>(c.j) >= n_))
        throw std::out_of_range("CollisionCounter: particle index");
    const Event e{c.t, c.i, c.j};
    if (events_.empty() || events_.back().t <= c.t) {
        events_.push_back(e);
        return;
    }
    auto it = std::upper_bound(events_.begin(), events_.end(), c.t,
                               [](double t, const Event& ev) { return t < ev.t; });
    events_.insert(it, e);
}

void CollisionCounter::add(std::span<const CollisionRecord> cs) {
    for (const auto& c : cs) add(c);
}

std::vector<std::uint32_t> CollisionCounter::counts(double t, double dt) const {
    if (!(dt > 0.0)) throw std::invalid_argument("CollisionCounter: dt must be > 0");
    std::vector<std::uint32_t> n(n_, 0);
    const double t0 = t - dt;
    // First event with time > t0, i.e. the window is (t0, t].
    auto it = std::upper_bound(events_.begin(), events_.end(), t0,
                               [](double tt, const Event& ev) { return tt < ev.t; });
    for (; it != events_.end() && it->t <= t; ++it) {
        if (it->j < 0 && !count_walls_) continue;
        ++n[static_cast<std::size_t>(it->i)];
        if (it->j >= 0) ++n[static_cast<std::size_t>(it->j)];
    }
    return n;
}

std::vector<double> CollisionCounter::rates(double t, double dt) const {
    const auto c = counts(t, dt);
    std::vector<double> r(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) r[k] = static_cast<double>(c[k]) / dt;
    return r;
}

void CollisionCounter::discard_before(double t) {
    while (!events_.empty() && events_.front().t < t) events_.pop_front();
}

} // namespace granrepro
