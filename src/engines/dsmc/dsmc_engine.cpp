#include "engines/dsmc/dsmc_engine.hpp"

#include "core/input_error.hpp"
#include "engines/dsmc/dsmc_rules.hpp"
#include <algorithm>
#include <numbers>

namespace granrepro {

template <DsmcCollisionOperator Collision>
BasicDsmcEngine<Collision>::BasicDsmcEngine(const DsmcConfig& config, std::vector<Vec2> position,
                                            std::vector<Vec2> velocity, std::vector<double> radius,
                                            std::vector<double> mass)
    : cfg_(config), rng_(config.seed, config.stream), pos_(std::move(position)), vel_(std::move(velocity)),
      rad_(std::move(radius)), mass_(std::move(mass)) {
    const std::size_t n = pos_.size();
    if (vel_.size() != n || rad_.size() != n || mass_.size() != n)
        throw InputError("DSMC: positions, velocities, radii and masses must have one length");
    last_.assign(n, -std::numeric_limits<double>::infinity());
    count_.assign(n, 0);
    partner_.assign(n, kNoPartner);
    validate_and_setup();
    for (auto& p : pos_) p = {wrap(p.x, cfg_.lx), wrap(p.y, cfg_.ly)};
}

template <DsmcCollisionOperator Collision>
BasicDsmcEngine<Collision>::BasicDsmcEngine(const DsmcState& s)
    : cfg_(s.config), rng_(s.config.seed, s.config.stream) {
    restore_state(s);
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::validate_and_setup() {
    const std::size_t n = pos_.size();
    if (n < 2) throw InputError("DSMC: need at least two particles");
    if (n > std::numeric_limits<std::uint32_t>::max()) throw InputError("DSMC: too many particles");
    if (!(cfg_.lx > 0.0) || !(cfg_.ly > 0.0)) throw InputError("DSMC: box lengths must be positive");
    if (!(cfg_.r >= 0.0 && cfg_.r <= 1.0)) throw InputError("DSMC: restitution r must be in [0, 1]");
    if (!(cfg_.t_c >= 0.0)) throw InputError("DSMC: t_c must be >= 0");
    if (!(cfg_.step_factor > 0.0)) throw InputError("DSMC: step_factor must be > 0");
    if (cfg_.resample_interval < 1) throw InputError("DSMC: resample_interval must be >= 1");
    if (!(cfg_.min_cell_diameters >= 0.0)) throw InputError("DSMC: min_cell_diameters must be >= 0");
    if (!(cfg_.rcp_fraction > 0.0 && cfg_.rcp_fraction <= 1.0)) throw InputError("DSMC: rcp_fraction must be in (0, 1]");
    if (!(cfg_.free_volume_floor > 0.0 && cfg_.free_volume_floor <= 1.0))
        throw InputError("DSMC: free_volume_floor must be in (0, 1]");
    if (cfg_.free_volume_block < 1 || cfg_.free_volume_block % 2 == 0)
        throw InputError("DSMC: free_volume_block must be odd and >= 1");
    if (!(cfg_.mft_fraction >= 0.0) || !std::isfinite(cfg_.mft_fraction))
        throw InputError("DSMC: mft_fraction must be >= 0 (0 = off)");
    if (cfg_.partner != DsmcPartner::uniform && cfg_.partner != DsmcPartner::nearest)
        throw InputError("DSMC: partner must be uniform or nearest");
    double amax = 0.0, asum = 0.0, area = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!(rad_[i] > 0.0) || !(mass_[i] > 0.0)) throw InputError("DSMC: radii and masses must be positive");
        if (!std::isfinite(vel_[i].x) || !std::isfinite(vel_[i].y) || !std::isfinite(pos_[i].x) || !std::isfinite(pos_[i].y))
            throw InputError("DSMC: non-finite position or velocity");
        amax = std::max(amax, rad_[i]);
        asum += rad_[i];
        area += std::numbers::pi * rad_[i] * rad_[i];
    }
    const double box = cfg_.lx * cfg_.ly;
    area_fraction_ = area / box;
    sigma_max_ = 4.0 * amax; // 2 d_max
    // The cells are sized with the mean free path of the collision rule actually used, so that
    // "half the mean free path" means the same thing for the plain and the corrected rule.
    const double chi = cfg_.free_volume == DsmcFreeVolume::off ? 1.0 : mean_free_volume_factor();
    lambda_ = dsmc_mean_free_path(static_cast<double>(n) / box, 2.0 * asum / static_cast<double>(n), chi);
    const double min_side = cfg_.min_cell_diameters * 2.0 * amax;
    nx_ = dsmc_cells_per_side(cfg_.lx, lambda_, min_side);
    ny_ = dsmc_cells_per_side(cfg_.ly, lambda_, min_side);
    if (nx_ * ny_ > std::numeric_limits<std::uint32_t>::max() / 2) throw InputError("DSMC: too many cells");
    wx_ = cfg_.lx / static_cast<double>(nx_);
    wy_ = cfg_.ly / static_cast<double>(ny_);
    inv_wx_ = static_cast<double>(nx_) / cfg_.lx;
    inv_wy_ = static_cast<double>(ny_) / cfg_.ly;
    cell_area_ = wx_ * wy_;
    law_ = smooth_law(cfg_.r);
    elastic_law_ = smooth_law(1.0);
    if (cfg_.free_volume_block > std::min(nx_, ny_))
        throw InputError("DSMC: free_volume_block exceeds the number of cells per side");
    cell_of_.assign(n, 0);
    order_.assign(n, 0);
    start_.assign(nx_ * ny_ + 1, 0);
    cell_r2_.clear();
    block_area_.clear();
}

template <DsmcCollisionOperator Collision>
double BasicDsmcEngine<Collision>::mean_free_volume_factor() const {
    return 1.0 / std::max(1.0 - area_fraction_ / cfg_.rcp_fraction, cfg_.free_volume_floor);
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::set_restitution(double r) {
    if (!(r >= 0.0 && r <= 1.0)) throw InputError("DSMC: restitution r must be in [0, 1]");
    cfg_.r = r;
    law_ = smooth_law(r);
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::set_tc(double t_c) {
    if (!(t_c >= 0.0)) throw InputError("DSMC: t_c must be >= 0");
    cfg_.t_c = t_c;
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::resample() {
    double v2 = 0.0;
    for (const auto& v : vel_) v2 = std::max(v2, norm2(v));
    const double v_fast = std::sqrt(v2);
    v_max_ = 2.0 * v_fast; // Sec. 2.4: "twice the maximum particle velocity found"
    tau_ = dsmc_time_step(std::min(wx_, wy_), v_fast, cfg_.step_factor);
    if (cfg_.mft_fraction > 0.0) {
        const double n = static_cast<double>(pos_.size());
        const double dt = time_ - resample_time_;
        const std::uint64_t dc = collisions_ - resample_collisions_;
        double omega = 0.0;
        if (dt > 0.0 && dc > 0) {
            omega = 2.0 * static_cast<double>(dc) / (n * dt);
        } else {
            // Nothing measured yet: the Boltzmann rate (n - 1/A) sigma sqrt(pi T/m) times the
            // mean free-volume factor, T/m = sum m v^2 / (2 sum m) (dsmc_kinetic_theory_test).
            double mv2 = 0.0, m = 0.0;
            for (std::size_t i = 0; i < vel_.size(); ++i) {
                mv2 += mass_[i] * norm2(vel_[i]);
                m += mass_[i];
            }
            const double chi = cfg_.free_volume == DsmcFreeVolume::off ? 1.0 : mean_free_volume_factor();
            omega = (n - 1.0) / (cfg_.lx * cfg_.ly) * sigma_max_ * std::sqrt(std::numbers::pi * mv2 / (2.0 * m)) * chi;
        }
        if (omega > 0.0) tau_ = std::min(tau_, cfg_.mft_fraction / omega);
    }
    resample_time_ = time_;
    resample_collisions_ = collisions_;
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::move_and_sort(double dt) {
    const std::size_t n = pos_.size(), ncell = nx_ * ny_;
    std::fill(start_.begin(), start_.end(), 0u);
    for (std::size_t i = 0; i < n; ++i) {
        Vec2& p = pos_[i];
        p = {wrap_near(p.x + vel_[i].x * dt, cfg_.lx), wrap_near(p.y + vel_[i].y * dt, cfg_.ly)};
        const auto ix = std::min(static_cast<std::size_t>(p.x * inv_wx_), nx_ - 1);
        const auto iy = std::min(static_cast<std::size_t>(p.y * inv_wy_), ny_ - 1);
        const auto c = static_cast<std::uint32_t>(iy * nx_ + ix);
        cell_of_[i] = c;
        ++start_[c + 1];
    }
    for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
    // Stable counting sort: within a cell particles keep index order, so the pair draws depend
    // only on the state, never on earlier scratch contents.
    std::vector<std::uint32_t>& fill = scratch_fill_;
    fill.assign(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::block_areas() {
    const std::size_t ncell = nx_ * ny_;
    cell_r2_.assign(ncell, 0.0);
    for (std::size_t c = 0; c < ncell; ++c)
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) cell_r2_[c] += rad_[order_[k]] * rad_[order_[k]];
    // Block sums, periodic: first along x into block_area_, then along y from there.
    const auto h = static_cast<std::ptrdiff_t>(cfg_.free_volume_block / 2);
    const auto nx = static_cast<std::ptrdiff_t>(nx_), ny = static_cast<std::ptrdiff_t>(ny_);
    std::vector<double>& row = scratch_r2_;
    row.assign(ncell, 0.0);
    for (std::ptrdiff_t y = 0; y < ny; ++y)
        for (std::ptrdiff_t x = 0; x < nx; ++x) {
            double s = 0.0;
            for (std::ptrdiff_t dx = -h; dx <= h; ++dx) s += cell_r2_[static_cast<std::size_t>(y * nx + (x + dx + nx) % nx)];
            row[static_cast<std::size_t>(y * nx + x)] = s;
        }
    block_area_.assign(ncell, 0.0);
    for (std::ptrdiff_t y = 0; y < ny; ++y)
        for (std::ptrdiff_t x = 0; x < nx; ++x) {
            double s = 0.0;
            for (std::ptrdiff_t dy = -h; dy <= h; ++dy) s += row[static_cast<std::size_t>(((y + dy + ny) % ny) * nx + x)];
            block_area_[static_cast<std::size_t>(y * nx + x)] = std::numbers::pi * s;
        }
}

template <DsmcCollisionOperator Collision>
double BasicDsmcEngine<Collision>::free_volume(std::size_t cell, std::size_t begin, std::size_t cnt) const {
    switch (cfg_.free_volume) {
    case DsmcFreeVolume::off:
        return cell_area_;
    case DsmcFreeVolume::mean:
        return cell_area_ / mean_free_volume_factor();
    case DsmcFreeVolume::cell: {
        if (cfg_.free_volume_block > 1) {
            // V_c (1 - V_0/V_block): the block's free-area fraction applied to the cell.
            const double block = static_cast<double>(cfg_.free_volume_block) * static_cast<double>(cfg_.free_volume_block) * cell_area_;
            const double free = 1.0 - block_area_[cell] / (cfg_.rcp_fraction * block);
            return cell_area_ * std::max(free, cfg_.free_volume_floor);
        }
        double area = 0.0;
        for (std::size_t k = begin; k < begin + cnt; ++k) area += rad_[order_[k]] * rad_[order_[k]];
        const double v0 = std::numbers::pi * area / cfg_.rcp_fraction;
        return std::max(cell_area_ - v0, cfg_.free_volume_floor * cell_area_);
    }
    }
    return cell_area_;
}

template <DsmcCollisionOperator Collision>
double BasicDsmcEngine<Collision>::kinetic_energy() const {
    double k = 0.0;
    for (std::size_t i = 0; i < vel_.size(); ++i) k += mass_[i] * norm2(vel_[i]);
    return 0.5 * k;
}

template <DsmcCollisionOperator Collision>
Vec2 BasicDsmcEngine<Collision>::total_momentum() const {
    Vec2 p;
    for (std::size_t i = 0; i < vel_.size(); ++i) p += mass_[i] * vel_[i];
    return p;
}

template <DsmcCollisionOperator Collision>
std::size_t BasicDsmcEngine<Collision>::memory_bytes() const {
    return pos_.capacity() * sizeof(Vec2) + vel_.capacity() * sizeof(Vec2) +
           (rad_.capacity() + mass_.capacity() + last_.capacity()) * sizeof(double) +
           count_.capacity() * sizeof(std::uint64_t) + (cell_r2_.capacity() + block_area_.capacity() + scratch_r2_.capacity()) * sizeof(double) +
           (partner_.capacity() + cell_of_.capacity() + order_.capacity() + start_.capacity() + scratch_fill_.capacity()) *
               sizeof(std::uint32_t) +
           sizeof(*this);
}

template <DsmcCollisionOperator Collision>
DsmcState BasicDsmcEngine<Collision>::save_state() const {
    DsmcState s;
    s.config = cfg_;
    s.time = time_;
    s.tau = tau_;
    s.v_max = v_max_;
    s.steps = steps_;
    s.position = pos_;
    s.velocity = vel_;
    s.radius = rad_;
    s.mass = mass_;
    s.last_collision_time = last_;
    s.collision_count = count_;
    s.collisions = collisions_;
    s.elastic_collisions = elastic_collisions_;
    s.candidates = candidates_;
    s.vmax_raises = vmax_raises_;
    s.exposure = exposure_;
    s.last_partner = partner_;
    s.resample_time = resample_time_;
    s.resample_collisions = resample_collisions_;
    s.rng_state = rng_.state();
    return s;
}

template <DsmcCollisionOperator Collision>
void BasicDsmcEngine<Collision>::restore_state(const DsmcState& s) {
    const std::size_t n = s.position.size();
    if (s.velocity.size() != n || s.radius.size() != n || s.mass.size() != n ||
        s.last_collision_time.size() != n || s.collision_count.size() != n || s.last_partner.size() != n)
        throw InputError("DSMC restore: per-particle arrays differ in length");
    cfg_ = s.config;
    pos_ = s.position;
    vel_ = s.velocity;
    rad_ = s.radius;
    mass_ = s.mass;
    last_ = s.last_collision_time;
    count_ = s.collision_count;
    partner_ = s.last_partner;
    for (const std::uint32_t j : partner_)
        if (j != kNoPartner && j >= n) throw InputError("DSMC restore: last partner index out of range");
    validate_and_setup();
    rng_.set_state(s.rng_state);
    time_ = s.time;
    tau_ = s.tau;
    v_max_ = s.v_max;
    steps_ = s.steps;
    collisions_ = s.collisions;
    elastic_collisions_ = s.elastic_collisions;
    candidates_ = s.candidates;
    vmax_raises_ = s.vmax_raises;
    exposure_ = s.exposure;
    resample_time_ = s.resample_time;
    resample_collisions_ = s.resample_collisions;
}

template class BasicDsmcEngine<RoughDiskCollision>; // DsmcEngine

} // namespace granrepro
