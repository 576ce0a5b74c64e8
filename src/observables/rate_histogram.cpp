#include "observables/rate_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granrepro {

namespace {
void fill(RateHistogram& h, std::span<const double> rates) {
    const std::size_t nb = h.edges.size() - 1;
    h.counts.assign(nb, 0);
    for (double r : rates) {
        const int k = h.bin_of(r);
        if (k < 0) ++h.below;
        else if (static_cast<std::size_t>(k) >= nb) ++h.above;
        else ++h.counts[static_cast<std::size_t>(k)];
    }
    h.total = rates.size();
    h.density.assign(nb, 0.0);
    h.error.assign(nb, 0.0);
    if (h.total == 0) return;
    for (std::size_t k = 0; k < nb; ++k) {
        const double norm = static_cast<double>(h.total) * (h.edges[k + 1] - h.edges[k]);
        h.density[k] = static_cast<double>(h.counts[k]) / norm;
        h.error[k] = std::sqrt(static_cast<double>(h.counts[k])) / norm;
    }
}
} // namespace

int RateHistogram::bin_of(double rate) const {
    // Edges compared directly (not (x - lo)/width) so that a rate exactly on an edge always
    // goes to the bin starting there, whatever the rounding of the width.
    const auto it = std::upper_bound(edges.begin(), edges.end(), rate);
    return static_cast<int>(it - edges.begin()) - 1;
}

RateHistogram RateHistogram::make(std::span<const double> rates, double window, Binning binning,
                                  int n_bins, double lo, double hi) {
    if (n_bins < 1 || !(hi > lo)) throw std::invalid_argument("RateHistogram: need n_bins >= 1, hi > lo");
    if (binning == Binning::Log && !(lo > 0.0)) throw std::invalid_argument("RateHistogram: log bins need lo > 0");
    if (!(window > 0.0)) throw std::invalid_argument("RateHistogram: window must be > 0");
    RateHistogram h;
    h.window = window;
    for (int k = 0; k <= n_bins; ++k) {
        const double f = static_cast<double>(k) / n_bins;
        h.edges.push_back(binning == Binning::Linear ? lo + f * (hi - lo) : lo * std::pow(hi / lo, f));
    }
    h.edges.back() = hi;
    for (int k = 0; k < n_bins; ++k) {
        const double a = h.edges[static_cast<std::size_t>(k)], b = h.edges[static_cast<std::size_t>(k) + 1];
        h.centres.push_back(binning == Binning::Linear ? 0.5 * (a + b) : std::sqrt(a * b));
    }
    fill(h, rates);
    return h;
}

RateHistogram RateHistogram::per_count(std::span<const double> rates, double window, int c_max) {
    if (c_max < 0 || !(window > 0.0)) throw std::invalid_argument("RateHistogram: c_max >= 0, window > 0");
    RateHistogram h;
    h.window = window;
    for (int c = 0; c <= c_max + 1; ++c) h.edges.push_back((c - 0.5) / window);
    for (int c = 0; c <= c_max; ++c) h.centres.push_back(static_cast<double>(c) / window);
    fill(h, rates);
    return h;
}

} // namespace granrepro
