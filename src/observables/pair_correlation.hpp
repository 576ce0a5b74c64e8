// The pair-correlation function g(r) of Luding 1998 Sec. 3.3, Fig. 6 (plotted against r/d:
// divide centres() by the diameter). Periodic rectangular box, minimum-image distances.
//
// Normalisation: the ideal-gas pair density in 2D. For N particles in area A a bin [r1, r2)
// expects N(N-1)/2 * pi (r2^2 - r1^2) / A unordered pairs (pi (r2^2 - r1^2) = 2 pi r dr exactly,
// r the bin centre), so g = 1 for uniform random points; N(N-1), not N^2, so that this holds
// exactly at finite N. Several snapshots are averaged by summing counts and expectations.
#pragma once
#include "core/vec2.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace granrepro {

class PairCorrelation {
public:
    // Lx, Ly box sides [m]; r_max [m] with 0 < r_max <= min(Lx, Ly)/2, so each pair has one
    // image within r_max; n_bins >= 1 equal bins on [0, r_max). Throws std::invalid_argument.
    PairCorrelation(double Lx, double Ly, double r_max, int n_bins);

    // Adds one snapshot using a cell list (cell side >= r_max): O(N).
    void accumulate(std::span<const Vec2> positions);
    // Adds one snapshot by looping over all pairs: O(N^2). Reference for the cell list; both give
    // the same counts bit for bit, since they compute each distance with the same arithmetic.
    void accumulate_brute_force(std::span<const Vec2> positions);

    // Unordered-pair counts per bin, summed over the snapshots.
    const std::vector<std::uint64_t>& counts() const { return counts_; }
    std::size_t snapshots() const { return snapshots_; }
    std::vector<double> centres() const; // bin centres [m]
    std::vector<double> g() const;       // all zero before any snapshot
    // Poisson error of g from the pair counts (ignores correlations between pairs).
    std::vector<double> g_error() const;
    void reset();

private:
    void bin_pair(const Vec2& a, const Vec2& b);
    void finish_snapshot(std::size_t n);

    double Lx_, Ly_, r_max_, dr_;
    int n_bins_;
    std::vector<std::uint64_t> counts_;
    double pair_norm_ = 0.0; // sum over snapshots of N(N-1)/(2A) [1/m^2]
    std::size_t snapshots_ = 0;
};

} // namespace granrepro
