#include "observables/pair_correlation.hpp"

#include "observables/periodic_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granrepro {

PairCorrelation::PairCorrelation(double Lx, double Ly, double r_max, int n_bins)
    : Lx_(Lx), Ly_(Ly), r_max_(r_max), dr_(r_max / n_bins), n_bins_(n_bins),
      counts_(static_cast<std::size_t>(std::max(n_bins, 0)), 0) {
    if (!(Lx > 0.0) || !(Ly > 0.0)) throw std::invalid_argument("PairCorrelation: box sides <= 0");
    if (!(r_max > 0.0) || r_max > 0.5 * std::min(Lx, Ly))
        throw std::invalid_argument("PairCorrelation: need 0 < r_max <= min(Lx, Ly)/2");
    if (n_bins < 1) throw std::invalid_argument("PairCorrelation: n_bins < 1");
}

// Both accumulate functions call this with a = earlier index, b = later index, so that the
// rounding of dx, dy is identical in both and the histograms agree exactly.
void PairCorrelation::bin_pair(const Vec2& a, const Vec2& b) {
    double dx = b.x - a.x;
    double dy = b.y - a.y;
    dx -= Lx_ * std::round(dx / Lx_);
    dy -= Ly_ * std::round(dy / Ly_);
    const double r2 = dx * dx + dy * dy;
    if (r2 >= r_max_ * r_max_) return;
    const int k = std::min(n_bins_ - 1, static_cast<int>(std::sqrt(r2) / dr_));
    ++counts_[static_cast<std::size_t>(k)];
}

void PairCorrelation::finish_snapshot(std::size_t n) {
    const double nn = static_cast<double>(n);
    pair_norm_ += 0.5 * nn * (nn - 1.0) / (Lx_ * Ly_);
    ++snapshots_;
}

void PairCorrelation::accumulate_brute_force(std::span<const Vec2> pos) {
    for (std::size_t i = 0; i < pos.size(); ++i)
        for (std::size_t j = i + 1; j < pos.size(); ++j) bin_pair(pos[i], pos[j]);
    finish_snapshot(pos.size());
}

void PairCorrelation::accumulate(std::span<const Vec2> pos) {
    for_each_near_pair(Lx_, Ly_, r_max_, pos, [&](std::size_t i, std::size_t j) { bin_pair(pos[i], pos[j]); });
    finish_snapshot(pos.size());
}

std::vector<double> PairCorrelation::centres() const {
    std::vector<double> r(counts_.size());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = (static_cast<double>(k) + 0.5) * dr_;
    return r;
}

std::vector<double> PairCorrelation::g() const {
    std::vector<double> out(counts_.size(), 0.0);
    if (pair_norm_ <= 0.0) return out;
    for (std::size_t k = 0; k < out.size(); ++k) {
        const double r1 = static_cast<double>(k) * dr_, r2 = r1 + dr_;
        const double expected = pair_norm_ * std::numbers::pi * (r2 * r2 - r1 * r1);
        out[k] = static_cast<double>(counts_[k]) / expected;
    }
    return out;
}

std::vector<double> PairCorrelation::g_error() const {
    std::vector<double> out = g();
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k] = counts_[k] > 0 ? out[k] / std::sqrt(static_cast<double>(counts_[k])) : 0.0;
    return out;
}

void PairCorrelation::reset() {
    std::fill(counts_.begin(), counts_.end(), 0);
    pair_norm_ = 0.0;
    snapshots_ = 0;
}

} // namespace granrepro
