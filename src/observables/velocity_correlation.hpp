// Velocity correlations of pairs at distance r: how far a dense inelastic gas departs from
// molecular chaos (Luding 1998 Sec. 3.1; issue 27's study of the early offset from Eq. (18)).
//
// For each unordered pair at minimum-image distance r, n is the unit vector between the centres
// and t its normal; u = v - (mean velocity of the snapshot). Per bin of r,
//   C_n(r) = < (u_i.n)(u_j.n) > / T1,   C_t(r) = < (u_i.t)(u_j.t) > / T1,
// with T1 = < |u|^2 > / 2 the per-component variance of that snapshot (so each snapshot enters at
// its own temperature). Molecular chaos (Boltzmann, Enskog, Eq. (18)) has C_n = C_t = 0; an
// elastic equilibrium gas has them exactly 0 at every r. Pairs that move together (C_n > 0)
// approach each other more slowly: a pair's mean squared normal relative velocity is 2 T1 (1 - C_n).
// What a collision dissipates depends on the approaching pairs alone, so
//   A(r) = < g_n^2 | g_n < 0 > / (2 T1),   g_n = (v_j - v_i).n,
// is reported too: 1 under molecular chaos (g_n is then normal with variance 2 T1, symmetric), and
// the energy lost per collision falls short of (1 - r^2) T where A < 1 at contact.
// Errors are the standard errors of the mean products over pairs (pairs taken as independent).
#pragma once
#include "core/vec2.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace granrepro {

class VelocityCorrelation {
public:
    // Lx, Ly box sides [m]; bins of equal width on [r_min, r_max) with 0 <= r_min < r_max <=
    // min(Lx, Ly)/2. Throws std::invalid_argument.
    VelocityCorrelation(double Lx, double Ly, double r_min, double r_max, int n_bins);

    // Adds one snapshot (cell list, O(N)); positions [m] and velocities [m/s] of equal length.
    void accumulate(std::span<const Vec2> positions, std::span<const Vec2> velocities);
    // The same over all pairs, O(N^2): the reference for the cell list (same pairs and counts; the
    // sums differ only by the rounding of another summation order).
    void accumulate_brute_force(std::span<const Vec2> positions, std::span<const Vec2> velocities);

    std::vector<double> centres() const;  // bin centres [m]
    std::vector<double> normal() const;   // C_n per bin [-]; NaN in an empty bin
    std::vector<double> tangential() const;
    std::vector<double> normal_error() const;
    std::vector<double> tangential_error() const;
    std::vector<double> approach() const; // A per bin [-]; NaN in a bin without approaching pairs
    std::vector<double> approach_error() const;
    const std::vector<std::uint64_t>& counts() const { return count_; }
    const std::vector<std::uint64_t>& approaching_counts() const { return count_a_; }

private:
    struct Frame; // one snapshot's mean velocity and T1
    void add_pair(const Frame& f, const Vec2& a, const Vec2& b, const Vec2& va, const Vec2& vb);
    Frame frame(std::span<const Vec2> positions, std::span<const Vec2> velocities) const;

    double Lx_, Ly_, r_min_, r_max_, dr_;
    int n_bins_;
    std::vector<std::uint64_t> count_, count_a_;
    std::vector<double> sn_, sn2_, st_, st2_, sa_, sa2_; // sums of the normalised products and their squares
};

} // namespace granrepro
