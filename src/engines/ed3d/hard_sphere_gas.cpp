#include "engines/ed3d/hard_sphere_gas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granrepro {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
double wrap(double x, double box) {
    x = std::fmod(x, box);
    if (x < 0) x += box;
    return x >= box ? 0.0 : x;
}
} // namespace

HardSphereGas3D::HardSphereGas3D(std::vector<Vec3> pos, std::vector<Vec3> vel, double diameter, double box)
    : r_(std::move(pos)), v_(std::move(vel)), d_(diameter), box_(box) {
    if (r_.empty() || r_.size() != v_.size()) throw std::invalid_argument("HardSphereGas3D: positions and velocities differ in size");
    if (!(d_ > 0) || !(box_ >= 3 * d_)) throw std::invalid_argument("HardSphereGas3D: need d > 0 and box >= 3 d");
    for (Vec3& x : r_) x = {wrap(x.x, box_), wrap(x.y, box_), wrap(x.z, box_)};
    if (min_distance() < d_ * (1 - 1e-12)) throw std::invalid_argument("HardSphereGas3D: overlapping spheres");
    t_ev_.assign(r_.size(), kInf);
    partner_.assign(r_.size(), -1);
    vmax_ = max_speed();
    for (std::size_t i = 0; i < r_.size(); ++i) predict(i);
}

Vec3 HardSphereGas3D::min_image(Vec3 d) const {
    d.x -= box_ * std::round(d.x / box_);
    d.y -= box_ * std::round(d.y / box_);
    d.z -= box_ * std::round(d.z / box_);
    return d;
}

double HardSphereGas3D::max_speed() const {
    double m = 0;
    for (const Vec3& v : v_) m = std::max(m, norm2(v));
    return std::sqrt(m);
}

void HardSphereGas3D::predict(std::size_t i) {
    const double horizon = vmax_ > 0 ? (0.5 * box_ - d_) / (2 * vmax_) : kInf;
    double best = horizon;
    int who = -1;
    for (std::size_t j = 0; j < r_.size(); ++j) {
        if (j == i) continue;
        const Vec3 dr = min_image(r_[i] - r_[j]), dv = v_[i] - v_[j];
        const double b = dot(dr, dv);
        if (b >= 0) continue; // receding
        const double c = norm2(dr) - d_ * d_;
        const double disc = b * b - norm2(dv) * c;
        if (disc <= 0) continue;
        const double tc = c <= 0 ? 0.0 : c / (-b + std::sqrt(disc)); // cancellation-free root
        if (tc < best) { best = tc; who = int(j); }
    }
    t_ev_[i] = t_ + best;
    partner_[i] = who;
}

bool HardSphereGas3D::step() {
    const std::size_t i = std::size_t(std::min_element(t_ev_.begin(), t_ev_.end()) - t_ev_.begin());
    const double dt = t_ev_[i] - t_;
    if (!std::isfinite(dt)) throw std::runtime_error("HardSphereGas3D: no event (all spheres at rest)");
    for (std::size_t k = 0; k < r_.size(); ++k) {
        r_[k] += v_[k] * dt;
        r_[k] = {wrap(r_[k].x, box_), wrap(r_[k].y, box_), wrap(r_[k].z, box_)};
    }
    t_ = t_ev_[i];
    const int j = partner_[i];
    if (j < 0) { // horizon reached
        predict(i);
        return false;
    }
    const Vec3 dr = min_image(r_[i] - r_[std::size_t(j)]);
    const Vec3 n = dr * (1.0 / norm(dr));
    const Vec3 dv = v_[i] - v_[std::size_t(j)];
    const double vn = dot(dv, n);
    last_b_ = norm(cross(dr, dv)) / (norm(dv) * d_);
    v_[i] -= vn * n;
    v_[std::size_t(j)] += vn * n;
    ++collisions_;
    // Re-predict the pair and every sphere that expected to meet one of them; everybody if a
    // sphere became faster than the speed the horizons were computed with.
    const double vmax = std::max(norm(v_[i]), norm(v_[std::size_t(j)]));
    const bool all = vmax > vmax_;
    if (all) vmax_ = vmax;
    for (std::size_t k = 0; k < r_.size(); ++k)
        if (all || k == i || int(k) == j || partner_[k] == int(i) || partner_[k] == j) predict(k);
    return true;
}

double HardSphereGas3D::kinetic_energy_per_mass() const {
    double s = 0;
    for (const Vec3& v : v_) s += 0.5 * norm2(v);
    return s;
}

Vec3 HardSphereGas3D::momentum_per_mass() const {
    Vec3 p;
    for (const Vec3& v : v_) p += v;
    return p;
}

double HardSphereGas3D::min_distance() const {
    double m = kInf;
    for (std::size_t i = 0; i < r_.size(); ++i)
        for (std::size_t j = i + 1; j < r_.size(); ++j) m = std::min(m, norm(min_image(r_[i] - r_[j])));
    return m;
}

} // namespace granrepro
