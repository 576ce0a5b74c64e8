#include "observables/collisional_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granrepro {

CollisionalStress::CollisionalStress(int nx, int ny, double x0, double y0, double Lx, double Ly,
                                     double t_begin, double t_end, bool periodic,
                                     bool subtract_mean_velocity)
    : nx_(nx), ny_(ny), x0_(x0), y0_(y0), Lx_(Lx), Ly_(Ly), t0_(t_begin), t1_(t_end),
      periodic_(periodic), subtract_mean_(subtract_mean_velocity) {
    if (nx < 1 || ny < 1) throw std::invalid_argument("CollisionalStress: need nx, ny >= 1");
    if (!(Lx > 0.0) || !(Ly > 0.0)) throw std::invalid_argument("CollisionalStress: box sides <= 0");
    if (!(t_end > t_begin)) throw std::invalid_argument("CollisionalStress: need t_end > t_begin");
    const auto n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
    coll_sum_.assign(n, Eigen::Matrix2d::Zero());
    kin_sum_.assign(n, Eigen::Matrix2d::Zero());
    n_coll_.assign(n, 0);
}

int CollisionalStress::cell_index(const Vec2& p) const {
    auto axis = [this](double x, double x0, double L, int nc) {
        double u = (x - x0) / L;
        if (periodic_) u -= std::floor(u);
        return std::clamp(static_cast<int>(std::floor(u * nc)), 0, nc - 1);
    };
    return axis(p.x, x0_, Lx_, nx_) + nx_ * axis(p.y, y0_, Ly_, ny_);
}

Vec2 CollisionalStress::cell_centre(int ix, int iy) const {
    return {x0_ + (ix + 0.5) * Lx_ / nx_, y0_ + (iy + 0.5) * Ly_ / ny_};
}

bool CollisionalStress::add(const CollisionRecord& c) {
    if (!(c.t >= t0_ && c.t < t1_)) return false;
    const Vec2 branch = c.rj - c.ri; // sum of both particles' branch terms, see header
    const Vec2 contact = c.j >= 0 ? 0.5 * (c.ri + c.rj) : c.rj;
    const auto k = static_cast<std::size_t>(cell_index(contact));
    Eigen::Matrix2d m;
    m << branch.x * c.dP.x, branch.x * c.dP.y, branch.y * c.dP.x, branch.y * c.dP.y;
    coll_sum_[k] += m;
    ++n_coll_[k];
    return true;
}

void CollisionalStress::add(std::span<const CollisionRecord> cs) {
    for (const auto& c : cs) add(c);
}

void CollisionalStress::add_snapshot(std::span<const Vec2> pos, std::span<const Vec2> vel,
                                     std::span<const double> mass) {
    if (vel.size() != pos.size() || mass.size() != pos.size())
        throw std::invalid_argument("CollisionalStress: positions/velocities/masses size");
    const std::size_t ncell = kin_sum_.size();
    std::vector<int> cell(pos.size());
    for (std::size_t i = 0; i < pos.size(); ++i) cell[i] = cell_index(pos[i]);
    std::vector<Vec2> mean(ncell);
    if (subtract_mean_) {
        std::vector<double> msum(ncell, 0.0);
        for (std::size_t i = 0; i < pos.size(); ++i) {
            mean[static_cast<std::size_t>(cell[i])] += mass[i] * vel[i];
            msum[static_cast<std::size_t>(cell[i])] += mass[i];
        }
        for (std::size_t k = 0; k < ncell; ++k)
            if (msum[k] > 0.0) mean[k] = mean[k] / msum[k];
    }
    for (std::size_t i = 0; i < pos.size(); ++i) {
        const auto k = static_cast<std::size_t>(cell[i]);
        const Vec2 v = vel[i] - mean[k];
        Eigen::Matrix2d m;
        m << v.x * v.x, v.x * v.y, v.y * v.x, v.y * v.y;
        kin_sum_[k] -= mass[i] * m;
    }
    ++snapshots_;
}

std::vector<CollisionalStress::Cell> CollisionalStress::result() const {
    const double area = (Lx_ / nx_) * (Ly_ / ny_);
    const double dt = t1_ - t0_;
    std::vector<Cell> out(coll_sum_.size());
    for (std::size_t k = 0; k < out.size(); ++k) {
        Cell& c = out[k];
        c.collisional = coll_sum_[k] / (area * dt);
        if (snapshots_ > 0) c.kinetic = kin_sum_[k] / (area * static_cast<double>(snapshots_));
        c.total = c.collisional + c.kinetic;
        c.collisions = n_coll_[k];
        const Eigen::Matrix2d sym = 0.5 * (c.total + c.total.transpose());
        // Eigenvalues come back in increasing order.
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(sym);
        c.sigma_min = es.eigenvalues()(0);
        c.sigma_max = es.eigenvalues()(1);
        c.axis_min = es.eigenvectors().col(0);
        c.axis_max = es.eigenvectors().col(1);
    }
    return out;
}

} // namespace granrepro
