#include "observables/column_bands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granrepro {

ColumnBands::ColumnBands(std::vector<double> y0, double band_height, double wall_reach, double width)
    : y0_(std::move(y0)), h_(band_height), reach_(wall_reach), width_(width) {
    if (y0_.empty() || !(h_ > 0) || !(reach_ >= 0) || !(width_ > 0))
        throw std::invalid_argument("ColumnBands: need disks, band_height > 0, wall_reach >= 0, width > 0");
    // Band edges at multiples of band_height.
    y0_min_ = std::floor(*std::min_element(y0_.begin(), y0_.end()) / h_) * h_;
    const double y0_max = *std::max_element(y0_.begin(), y0_.end());
    bands_ = std::size_t(std::floor((y0_max - y0_min_) / h_)) + 1;
    band_of_.resize(y0_.size());
    for (std::size_t i = 0; i < y0_.size(); ++i)
        band_of_[i] = std::min(bands_ - 1, std::size_t(std::floor((y0_[i] - y0_min_) / h_)));
}

void ColumnBands::add_frame(double t, const std::vector<Vec2>& pos, const std::vector<Vec2>& vel,
                            const std::vector<double>& wall_jy) {
    const std::size_t n = y0_.size();
    if (pos.size() != n || vel.size() != n || wall_jy.size() != n)
        throw std::invalid_argument("ColumnBands::add_frame: arrays differ from the number of disks");
    std::vector<Sums> s(bands_);
    for (std::size_t i = 0; i < n; ++i) {
        Sums& b = s[band_of_[i]];
        b.n += 1;
        b.y += pos[i].y;
        b.vy += vel[i].y;
        b.jy += wall_jy[i];
        if (pos[i].x <= reach_ || pos[i].x >= width_ - reach_) {
            b.nw += 1;
            b.vyw += vel[i].y;
        }
    }
    t_.push_back(t);
    s_.push_back(std::move(s));
}

ColumnBands::Group ColumnBands::group(std::size_t k, double y0_lo, double y0_hi) const {
    const std::vector<Sums>& s = s_.at(k);
    Sums a;
    for (std::size_t b = 0; b < bands_; ++b) {
        const double c = y0_min_ + (double(b) + 0.5) * h_;
        if (c < y0_lo || c >= y0_hi) continue;
        a.n += s[b].n;
        a.nw += s[b].nw;
        a.y += s[b].y;
        a.vy += s[b].vy;
        a.vyw += s[b].vyw;
        a.jy += s[b].jy;
    }
    Group g;
    g.n = a.n;
    g.n_wall = a.nw;
    g.jy = a.jy;
    g.y = a.n > 0 ? a.y / a.n : NAN;
    g.vy = a.n > 0 ? a.vy / a.n : NAN;
    g.vy_wall = a.nw > 0 ? a.vyw / a.nw : NAN;
    g.vy_inner = a.n > a.nw ? (a.vy - a.vyw) / (a.n - a.nw) : NAN;
    return g;
}

} // namespace granrepro
