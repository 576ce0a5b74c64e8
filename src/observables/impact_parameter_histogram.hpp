// P(b/d) of Luding 1998 Sec. 3.2, Figs 3-4: the distribution of the impact parameter
// b/d = |sin gamma| of the collisions in given time windows. Molecular chaos predicts P = 1 in
// 2D; grazing collisions (b/d -> 1) become more frequent once shear develops.
// Normalisation as in the paper: integral_0^1 P(x) dx = 1 for every window.
#pragma once
#include "core/collision_record.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace granrepro {

class ImpactParameterHistogram {
public:
    struct Window {
        double t_begin = 0.0;              // [s], inclusive
        double t_end = 0.0;                // [s], exclusive
        std::uint64_t total = 0;           // collisions in the window
        std::vector<std::uint64_t> counts; // per bin
        std::vector<double> p;             // P(b/d) per bin, integral 1 (all 0 if total = 0)
        std::vector<double> error;         // Poisson error sqrt(count) propagated to p
    };

    // n_bins equal bins on [0, 1]; window_edges [s] strictly increasing, at least two, giving the
    // windows [e_0, e_1), [e_1, e_2), ... Collisions outside every window are ignored.
    // count_walls: whether particle-wall collisions (j < 0) enter; the paper's P(b/d) is for
    // particle pairs, so the default is false. Throws std::invalid_argument on bad arguments.
    ImpactParameterHistogram(int n_bins, std::vector<double> window_edges, bool count_walls = false);

    // Throws std::out_of_range if b_over_d is NaN or outside [0, 1] by more than 1e-9 (an engine
    // bug, not a rounding effect); values within the tolerance are clamped onto [0, 1].
    void add(const CollisionRecord& c);
    void add(std::span<const CollisionRecord> cs);

    int bins() const { return n_bins_; }
    std::size_t windows() const { return counts_.size(); }
    // Bin centres of b/d.
    std::vector<double> centres() const;
    // Normalised histogram of window w.
    Window window(std::size_t w) const;

    // The accumulated state, counts[window][bin], so that a checkpointed run can continue
    // accumulating where it stopped. set_counts throws std::invalid_argument unless the shape is
    // windows() x bins().
    const std::vector<std::vector<std::uint64_t>>& counts() const { return counts_; }
    void set_counts(std::vector<std::vector<std::uint64_t>> counts);

private:
    int n_bins_;
    bool count_walls_;
    std::vector<double> edges_;
    std::vector<std::vector<std::uint64_t>> counts_;
};

} // namespace granrepro
