#include "observables/velocity_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "observables/periodic_pairs.hpp"

namespace granrepro {

struct VelocityCorrelation::Frame {
    Vec2 mean;
    double t1 = 0; // [m^2/s^2]
};

VelocityCorrelation::VelocityCorrelation(double Lx, double Ly, double r_min, double r_max, int n_bins)
    : Lx_(Lx), Ly_(Ly), r_min_(r_min), r_max_(r_max), dr_((r_max - r_min) / n_bins), n_bins_(n_bins) {
    if (!(Lx > 0.0) || !(Ly > 0.0)) throw std::invalid_argument("VelocityCorrelation: box sides <= 0");
    if (!(r_min >= 0.0) || !(r_max > r_min) || r_max > 0.5 * std::min(Lx, Ly))
        throw std::invalid_argument("VelocityCorrelation: need 0 <= r_min < r_max <= min(Lx, Ly)/2");
    if (n_bins < 1) throw std::invalid_argument("VelocityCorrelation: n_bins < 1");
    const auto nb = static_cast<std::size_t>(n_bins);
    count_.assign(nb, 0), count_a_.assign(nb, 0);
    for (auto* v : {&sn_, &sn2_, &st_, &st2_, &sa_, &sa2_}) v->assign(nb, 0.0);
}

VelocityCorrelation::Frame VelocityCorrelation::frame(std::span<const Vec2> pos, std::span<const Vec2> vel) const {
    if (pos.size() != vel.size() || pos.size() < 2)
        throw std::invalid_argument("VelocityCorrelation: need as many velocities as positions, at least 2");
    Frame f;
    for (const Vec2& v : vel) f.mean += v;
    f.mean = f.mean / double(vel.size());
    for (const Vec2& v : vel) f.t1 += norm2(v - f.mean);
    f.t1 /= 2.0 * double(vel.size());
    if (!(f.t1 > 0.0)) throw std::invalid_argument("VelocityCorrelation: all velocities equal");
    return f;
}

// Both accumulate functions call this with a = earlier index, b = later index, so that each pair's
// products are computed with the same arithmetic.
void VelocityCorrelation::add_pair(const Frame& f, const Vec2& a, const Vec2& b, const Vec2& va, const Vec2& vb) {
    double dx = b.x - a.x;
    double dy = b.y - a.y;
    dx -= Lx_ * std::round(dx / Lx_);
    dy -= Ly_ * std::round(dy / Ly_);
    const double r2 = dx * dx + dy * dy;
    if (r2 >= r_max_ * r_max_ || r2 < r_min_ * r_min_) return;
    const double r = std::sqrt(r2);
    const auto k = static_cast<std::size_t>(std::min(n_bins_ - 1, static_cast<int>((r - r_min_) / dr_)));
    const Vec2 n{dx / r, dy / r}, t{-n.y, n.x};
    const Vec2 ua = va - f.mean, ub = vb - f.mean;
    const double cn = dot(ua, n) * dot(ub, n) / f.t1, ct = dot(ua, t) * dot(ub, t) / f.t1;
    ++count_[k];
    sn_[k] += cn, sn2_[k] += cn * cn, st_[k] += ct, st2_[k] += ct * ct;
    const double gn = dot(vb - va, n);
    if (gn < 0) {
        const double a = gn * gn / (2 * f.t1);
        ++count_a_[k];
        sa_[k] += a, sa2_[k] += a * a;
    }
}

void VelocityCorrelation::accumulate(std::span<const Vec2> pos, std::span<const Vec2> vel) {
    const Frame f = frame(pos, vel);
    for_each_near_pair(Lx_, Ly_, r_max_, pos, [&](std::size_t i, std::size_t j) { add_pair(f, pos[i], pos[j], vel[i], vel[j]); });
}

void VelocityCorrelation::accumulate_brute_force(std::span<const Vec2> pos, std::span<const Vec2> vel) {
    const Frame f = frame(pos, vel);
    for (std::size_t i = 0; i < pos.size(); ++i)
        for (std::size_t j = i + 1; j < pos.size(); ++j) add_pair(f, pos[i], pos[j], vel[i], vel[j]);
}

std::vector<double> VelocityCorrelation::centres() const {
    std::vector<double> r(count_.size());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = r_min_ + (static_cast<double>(k) + 0.5) * dr_;
    return r;
}

namespace {
std::vector<double> means(const std::vector<double>& sum, const std::vector<std::uint64_t>& n) {
    std::vector<double> out(sum.size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = n[k] ? sum[k] / double(n[k]) : NAN;
    return out;
}
std::vector<double> errors(const std::vector<double>& sum, const std::vector<double>& sum2, const std::vector<std::uint64_t>& n) {
    std::vector<double> out(sum.size());
    for (std::size_t k = 0; k < out.size(); ++k) {
        const double c = double(n[k]);
        out[k] = n[k] > 1 ? std::sqrt(std::max(0.0, sum2[k] / c - (sum[k] / c) * (sum[k] / c)) / (c - 1)) : NAN;
    }
    return out;
}
} // namespace

std::vector<double> VelocityCorrelation::normal() const { return means(sn_, count_); }
std::vector<double> VelocityCorrelation::tangential() const { return means(st_, count_); }
std::vector<double> VelocityCorrelation::normal_error() const { return errors(sn_, sn2_, count_); }
std::vector<double> VelocityCorrelation::tangential_error() const { return errors(st_, st2_, count_); }
std::vector<double> VelocityCorrelation::approach() const { return means(sa_, count_a_); }
std::vector<double> VelocityCorrelation::approach_error() const { return errors(sa_, sa2_, count_a_); }

} // namespace granrepro
