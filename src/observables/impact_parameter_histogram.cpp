#include "observables/impact_parameter_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace granrepro {

ImpactParameterHistogram::ImpactParameterHistogram(int n_bins, std::vector<double> window_edges,
                                                   bool count_walls)
    : n_bins_(n_bins), count_walls_(count_walls), edges_(std::move(window_edges)) {
    if (n_bins_ < 1) throw std::invalid_argument("ImpactParameterHistogram: n_bins < 1");
    if (edges_.size() < 2) throw std::invalid_argument("ImpactParameterHistogram: < 2 window edges");
    for (std::size_t k = 1; k < edges_.size(); ++k)
        if (!(edges_[k] > edges_[k - 1]))
            throw std::invalid_argument("ImpactParameterHistogram: window edges not increasing");
    counts_.assign(edges_.size() - 1, std::vector<std::uint64_t>(static_cast<std::size_t>(n_bins_), 0));
}

void ImpactParameterHistogram::add(const CollisionRecord& c) {
    if (c.j < 0 && !count_walls_) return;
    double b = c.b_over_d;
    if (!(b >= -1e-9 && b <= 1.0 + 1e-9))
        throw std::out_of_range("ImpactParameterHistogram: b/d outside [0, 1]");
    b = std::clamp(b, 0.0, 1.0);
    // Windows are [e_k, e_k+1): upper_bound finds the first edge beyond t.
    const auto it = std::upper_bound(edges_.begin(), edges_.end(), c.t);
    if (it == edges_.begin() || it == edges_.end()) return;
    const auto w = static_cast<std::size_t>(it - edges_.begin() - 1);
    // b/d = 1 exactly (a perfectly grazing collision) belongs to the last bin, not past it.
    const int bin = std::min(n_bins_ - 1, static_cast<int>(b * n_bins_));
    ++counts_[w][static_cast<std::size_t>(bin)];
}

void ImpactParameterHistogram::add(std::span<const CollisionRecord> cs) {
    for (const auto& c : cs) add(c);
}

std::vector<double> ImpactParameterHistogram::centres() const {
    std::vector<double> x(static_cast<std::size_t>(n_bins_));
    for (int k = 0; k < n_bins_; ++k) x[static_cast<std::size_t>(k)] = (k + 0.5) / n_bins_;
    return x;
}

ImpactParameterHistogram::Window ImpactParameterHistogram::window(std::size_t w) const {
    if (w >= counts_.size()) throw std::out_of_range("ImpactParameterHistogram: window index");
    Window out;
    out.t_begin = edges_[w];
    out.t_end = edges_[w + 1];
    out.counts = counts_[w];
    for (auto n : out.counts) out.total += n;
    const auto nb = static_cast<std::size_t>(n_bins_);
    out.p.assign(nb, 0.0);
    out.error.assign(nb, 0.0);
    if (out.total == 0) return out;
    // Density over x = b/d with bin width 1/n_bins: P = n / (total * dx), so sum P dx = 1.
    const double scale = static_cast<double>(n_bins_) / static_cast<double>(out.total);
    for (std::size_t k = 0; k < nb; ++k) {
        out.p[k] = scale * static_cast<double>(out.counts[k]);
        out.error[k] = scale * std::sqrt(static_cast<double>(out.counts[k]));
    }
    return out;
}

void ImpactParameterHistogram::set_counts(std::vector<std::vector<std::uint64_t>> counts) {
    if (counts.size() != counts_.size())
        throw std::invalid_argument(
            "ImpactParameterHistogram: counts for a different number of windows");
    for (const auto& c : counts)
        if (c.size() != static_cast<std::size_t>(n_bins_))
            throw std::invalid_argument(
                "ImpactParameterHistogram: counts for a different number of bins");
    counts_ = std::move(counts);
}

} // namespace granrepro
