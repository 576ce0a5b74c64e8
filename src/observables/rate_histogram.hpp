// P(N_c) of Luding 1998 Figs 12 and 14: the probability density of the per-particle collision
// rate N_c [1/s]. Normalised over all particles, including those outside the binned range, so
// that sum P * width = 1 when the bins cover every rate: this matches Eqs (20)-(22), which are
// normalised densities in N_c. Fig. 12 is linear in N_c, Fig. 14(b) logarithmic; both binnings
// are available. A particle with N_c = 0 never lands in a log bin (it is counted in below).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace granrepro {

struct RateHistogram {
    enum class Binning { Linear, Log };

    std::vector<double> edges;           // n_bins + 1 increasing bin edges [1/s]
    std::vector<double> centres;         // arithmetic (linear) or geometric (log) centres [1/s]
    std::vector<std::uint64_t> counts;   // particles per bin [a, b)
    std::vector<double> density;         // P(N_c) = count / (total * width) [s]
    std::vector<double> error;           // sqrt(count) / (total * width) [s]
    std::uint64_t total = 0;             // all particles histogrammed
    std::uint64_t below = 0;             // rates < edges.front()
    std::uint64_t above = 0;             // rates >= edges.back()
    double window = 0.0;                 // the Dt the rates were counted over [s]; the Poisson
                                         // fit of Eq. (20) needs it

    // n_bins bins between lo and hi [1/s] (Log needs lo > 0). window [s] as above.
    // Throws std::invalid_argument on bad arguments.
    static RateHistogram make(std::span<const double> rates, double window, Binning binning,
                              int n_bins, double lo, double hi);
    // One bin per collision count C = 0 .. c_max: edges (C - 1/2)/Dt, so each bin holds exactly
    // the particles with C collisions and P = (fraction with C) * Dt, the paper's
    // P_o(N_c Dt, chi) Dt (text below Eq. 20).
    static RateHistogram per_count(std::span<const double> rates, double window, int c_max);
    // Bin index of a rate, -1 below, n_bins above; the single place deciding bin membership.
    int bin_of(double rate) const;
};

} // namespace granrepro
