// Per-particle collision counts over a trailing time window, the input of Luding 1998 Sec. 4.3
// and Sec. 5: N_c = (collisions of the particle in (t - Dt, t]) / Dt [1/s], with Dt = t/2 in
// Fig. 12 and Dt = 0.001 s / 0.005 s in Figs 13-14. The colour of Figs 11 and 13 is this rate.
#pragma once
#include "core/collision_record.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

namespace granrepro {

class CollisionCounter {
public:
    // n_particles: particle indices run over [0, n_particles). count_walls: whether a wall
    // collision counts for its particle (Sec. 5: "collisions ... in which a particle
    // participates", walls included); a pair collision always counts for both partners.
    explicit CollisionCounter(std::size_t n_particles, bool count_walls = true);

    // Records may arrive slightly out of time order (DSMC steps); they are kept sorted.
    // Throws std::out_of_range for a particle index outside [0, n_particles).
    void add(const CollisionRecord& c);
    void add(std::span<const CollisionRecord> cs);

    // Collisions per particle in (t - dt, t]; t [s], dt > 0 [s].
    std::vector<std::uint32_t> counts(double t, double dt) const;
    // N_c = counts / dt [1/s]; computed as double(count) / dt so that RateHistogram and the
    // Poisson fit (which rebuilds C / dt the same way) agree on bin membership exactly.
    std::vector<double> rates(double t, double dt) const;
    // Forgets collisions at times < t [s] to bound memory; later windows must start at >= t.
    void discard_before(double t);
    std::size_t stored() const { return events_.size(); }
    std::size_t particles() const { return n_; }

private:
    struct Event {
        double t;
        int i;
        int j;
    };
    std::size_t n_;
    bool count_walls_;
    std::deque<Event> events_;
};

} // namespace granrepro
