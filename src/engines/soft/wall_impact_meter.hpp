// The wall-impact meter of the pipe (Schäfer & Wolf 1995, Fig. 6): per wall impact, the Δv_y
// of Eq. (9), the velocity change the wall gives a grain. It sits beside PipeEngine rather than
// in its force loop, so that the integrator holds only the dynamics and the meter can be tested
// on its own.
//
// A wall impact lasts from the first step a grain touches any wall grain to the first step it
// touches none. Its Δv_y, as in Eq. (9) and the impact studies, is the wall force's impulse along
// +y over the impact, divided by the mass: gravity and collisions with other free grains during
// the impact are no part of what the wall does, so they are not counted.
//
// State per grain is kept by id, because the engine re-sorts its grains (slots) at every list
// build while an impact may last across builds. The impacts completed in a step are added in id
// order (end_step()), so the sums do not depend on the slots.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace granrepro {

// Counts of what happened at the walls, accumulated until reset.
struct WallImpactStats {
    long impacts = 0;          // wall impacts begun (a grain starting to touch a wall after not touching any)
    double sum_dvy = 0;        // sum over completed impacts of the wall impulse along +y per mass [m/s]
    double sum_vy_in = 0;      // sum of |v_y| at the start of completed impacts [m/s]
    double sum_vx_in = 0;      // sum of |v_x| at the start of completed impacts [m/s]
    long completed = 0;
    double time = 0;           // time over which impacts were counted [s]
};

class WallImpactMeter {
public:
    struct Velocity {
        double x, y;
    };

    void add_grain() {
        touch_.push_back(0), vy_at_touch_.push_back(0), vx_at_touch_.push_back(0), impulse_y_.push_back(0);
    }
    // Before the engine's first force evaluation. (The impulse of that evaluation is kept: it
    // counts in the grain's first impact, as it always did.)
    void clear_impulses() { std::fill(impulse_y_.begin(), impulse_y_.end(), 0.0); }
    // Called for each wall grain a grain touches, from the force loop: the one piece of metering
    // that needs the single wall force rather than the grain's force sum.
    void add_impulse(std::size_t id, double fy_dt) { impulse_y_[id] += fy_dt; }

    // After the grains moved to other slots (a list build): the slots [0, n) that are inside an
    // impact or hold wall impulse, i.e. those that can end one without being near a wall. id[i]
    // is the id of slot i.
    void relist(std::size_t n, const int* id) {
        touching_.clear();
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t g = std::size_t(id[i]);
            if (touch_[g] || impulse_y_[g] != 0) touching_.push_back(int(i));
        }
    }

    // The engine's step, after its forces. near[0, count) are the slots near a wall; mark[i] is 2
    // for a slot that touched a wall grain this step, 1 for one near a wall only, 0 for one not
    // near. Only those and the slots touching after the last step can change state, so the rest
    // of the grains cost nothing. The meter is the marks' last reader: it sets them back to 0 for
    // the engine's next step (in its own last pass, saving the engine one). velocity_at_touch(i) is slot i's velocity after this step's
    // closing half kick; id[i] and inv_mass[i] are slot i's id and 1/m. With count false (the
    // engine's first force evaluation) no impact begins or ends: only the touching slots are noted.
    template <class VelocityAtTouch>
    void step(bool count, const int* near, std::size_t near_count, unsigned char* mark, const int* id,
              const double* inv_mass, VelocityAtTouch&& velocity_at_touch) {
        impacts_ = 0;
        completed_.clear();
        auto track = [&](std::size_t i, bool now) {
            const std::size_t g = std::size_t(id[i]);
            if (now && !touch_[g]) {
                ++impacts_;
                const Velocity v = velocity_at_touch(i);
                vy_at_touch_[g] = v.y;
                vx_at_touch_[g] = v.x;
            } else if (!now && touch_[g]) {
                completed_.push_back({id[i], impulse_y_[g] * inv_mass[i], std::abs(vy_at_touch_[g]), std::abs(vx_at_touch_[g])});
            }
            if (!now) impulse_y_[g] = 0;
            touch_[g] = now;
        };
        if (count) {
            for (int i : touching_)
                if (!mark[std::size_t(i)]) track(std::size_t(i), false);
            for (std::size_t a = 0; a < near_count; ++a) track(std::size_t(near[a]), mark[std::size_t(near[a])] == 2);
        }
        touching_.clear();
        for (std::size_t a = 0; a < near_count; ++a) {
            const std::size_t i = std::size_t(near[a]);
            if (mark[i] == 2) touching_.push_back(int(i));
            mark[i] = 0;
        }
    }

    // After step(): the step's impacts, and the impacts completed in it added in id order, so
    // that no sum depends on the order of the slots.
    void end_step(double dt) {
        stats_.impacts += impacts_;
        stats_.time += dt;
        if (completed_.empty()) return;
        std::sort(completed_.begin(), completed_.end(), [](const Completion& a, const Completion& b) { return a.id < b.id; });
        for (const Completion& c : completed_) {
            ++stats_.completed;
            stats_.sum_dvy += c.dvy;
            stats_.sum_vy_in += c.vy_in;
            stats_.sum_vx_in += c.vx_in;
        }
    }

    const WallImpactStats& stats() const { return stats_; }
    // Clears the counts only: impacts under way go on and are counted when they end.
    void reset_stats() { stats_ = {}; }

    // Bytes held by the per-grain state and the touching list (capacity, not just size).
    std::size_t bytes() const {
        std::size_t b = (vy_at_touch_.capacity() + vx_at_touch_.capacity() + impulse_y_.capacity()) * sizeof(double);
        b += touching_.capacity() * sizeof(int);
        return b + touch_.capacity();
    }

private:
    struct Completion {
        int id;
        double dvy, vy_in, vx_in;
    };

    std::vector<char> touch_;                          // by id: inside an impact
    std::vector<double> vy_at_touch_, vx_at_touch_;    // by id: velocity at the impact's start
    std::vector<double> impulse_y_;                    // by id: wall impulse along +y since the impact's start
    long impacts_ = 0;                                 // impacts begun in this step
    std::vector<Completion> completed_;                // impacts completed in this step
    std::vector<int> touching_; // slots touching a wall (or holding wall impulse) after the last step
    WallImpactStats stats_;
};

} // namespace granrepro
