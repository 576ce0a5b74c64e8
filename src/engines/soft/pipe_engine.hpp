// Many-body soft-sphere MD for a vertical pipe (Schäfer & Wolf 1995, Fig. 6): free grains between
// two rows of fixed wall grains at x = 0 and x = width, periodic along y, gravity along -y.
// Translation only, as in the paper.
//
// Integration: velocity Verlet (half kick, drift, forces, half kick). The dashpot and Coulomb
// forces depend on velocity; evaluating them at the half-step velocity, as LAMMPS' gran/hooke
// does, lags them by dt/2 and costs a first-order error in e_N (about gamma_N dt / 2, 1 % at
// e_N = 0.7 and dt = t_col/50). They are evaluated instead at the predicted full-step velocity
// v(t+dt/2) + a(t) dt/2 (the modified velocity Verlet of Groot & Warren 1997 with lambda = 1).
// dt = t_col/50 of the stiffest pair (Eq. 5). Neighbours: a Verlet list with skin, built from linked cells and rebuilt when any
// grain has moved more than skin/2 since the last build, so every step costs O(N). Wall grains
// are not stored: a grain near a wall tests the two or three wall grains at its height, found
// from the row's spacing.
//
// Template parameters: NormalLaw::normal_force(xi, xi_dot, m_red) -> NormalForce;
// ShearLaw::applied_normal(NormalForce) and ShearLaw::shear_force(NormalForce, v_S).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "models/normal_force.hpp"

namespace granrepro {

struct PipeGeometry {
    double width = 0.02;       // distance between the centre lines of the two wall rows [m]
    double length = 0.04;      // periodic length along y [m]; a multiple of wall_spacing
    double wall_radius = 0.33e-3;  // [m]
    double wall_spacing = 0.66e-3; // [m]
    double right_row_shift = 0.0;  // y offset of the right row's grains [m]
    double gravity = 10.0;     // [m/s^2], acting along -y
};

// Counts of what happened at the walls, accumulated until reset.
struct WallImpactStats {
    long impacts = 0;          // wall impacts begun (a grain starting to touch a wall after not touching any)
    double sum_dvy = 0;        // sum over completed impacts of the wall impulse along +y per mass [m/s]
    double sum_vy_in = 0;      // sum of |v_y| at the start of completed impacts [m/s]
    double sum_vx_in = 0;      // sum of |v_x| at the start of completed impacts [m/s]
    long completed = 0;
    double time = 0;           // time over which impacts were counted [s]
};

template <class NormalLaw, class ShearLaw>
class PipeEngine {
public:
    PipeEngine(NormalLaw normal, ShearLaw shear, PipeGeometry geo, double dt, double skin)
        : normal_(normal), shear_(shear), geo_(geo), dt_(dt), skin_(skin) {
        const double n = geo.length / geo.wall_spacing;
        if (std::abs(n - std::round(n)) > 1e-9 * n)
            throw std::invalid_argument("pipe length must be a multiple of the wall spacing");
    }

    void add_grain(double x, double y, double vx, double vy, double radius, double mass) {
        x_.push_back(x); y_.push_back(wrap(y)); vx_.push_back(vx); vy_.push_back(vy);
        ax_.push_back(0); ay_.push_back(0); rad_.push_back(radius); mass_.push_back(mass);
        inv_mass_.push_back(1.0 / mass);
        wall_touch_.push_back(0); vy_at_touch_.push_back(0); vx_at_touch_.push_back(0);
        need_build_ = true;
    }

    std::size_t size() const { return x_.size(); }
    double time() const { return t_; }
    double dt() const { return dt_; }
    long steps() const { return steps_; }
    long list_builds() const { return builds_; }
    const std::vector<double>& x() const { return x_; }
    const std::vector<double>& y() const { return y_; }
    const std::vector<double>& vx() const { return vx_; }
    const std::vector<double>& vy() const { return vy_; }
    const std::vector<double>& radius() const { return rad_; }
    const std::vector<double>& mass() const { return mass_; }
    const WallImpactStats& wall_stats() const { return wall_; }
    void reset_wall_stats() { wall_ = {}; }
    const std::vector<double>& ax() const { return ax_; }
    const std::vector<double>& ay() const { return ay_; }

    // Reference for tests: accelerations from all N^2 pairs and all wall grains in range, without
    // the neighbour list, for the positions and the velocities the last force evaluation used.
    void brute_force_accelerations(std::vector<double>& ax, std::vector<double>& ay) const {
        const std::size_t n = x_.size();
        ax.assign(n, 0.0);
        ay.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                const double dx = x_[i] - x_[j], dy = min_image(y_[i] - y_[j]);
                const double rs = rad_[i] + rad_[j];
                const double d = std::sqrt(dx * dx + dy * dy);
                if (d >= rs) continue;
                double fx, fy;
                contact(dx / d, dy / d, rs - d, vpx_[i] - vpx_[j], vpy_[i] - vpy_[j],
                        mass_[i] * mass_[j] / (mass_[i] + mass_[j]), fx, fy);
                ax[i] += fx; ay[i] += fy; ax[j] -= fx; ay[j] -= fy;
            }
        const long nw = std::lround(geo_.length / geo_.wall_spacing);
        for (std::size_t i = 0; i < n; ++i) {
            for (int side = 0; side < 2; ++side) {
                const double xw = side ? geo_.width : 0.0, shift = side ? geo_.right_row_shift : 0.0;
                for (long k = 0; k < nw; ++k) {
                    const double dx = x_[i] - xw, dy = min_image(y_[i] - (shift + double(k) * geo_.wall_spacing));
                    const double rs = rad_[i] + geo_.wall_radius;
                    const double d = std::sqrt(dx * dx + dy * dy);
                    if (d >= rs) continue;
                    double fx, fy;
                    contact(dx / d, dy / d, rs - d, vpx_[i], vpy_[i], mass_[i], fx, fy);
                    ax[i] += fx; ay[i] += fy;
                }
            }
            ax[i] /= mass_[i];
            ay[i] = ay[i] / mass_[i] - geo_.gravity;
        }
    }

    // Largest overlap seen in the last force evaluation, relative to the smaller diameter.
    double max_overlap_ratio() const { return max_overlap_; }

    void step() {
        if (need_build_) throw std::logic_error("PipeEngine: call finalize() after adding grains");
        const double h = 0.5 * dt_;
        const std::size_t n = x_.size();
        for (std::size_t i = 0; i < n; ++i) {
            vx_[i] += h * ax_[i];
            vy_[i] += h * ay_[i];
            const double dx = dt_ * vx_[i], dy = dt_ * vy_[i];
            x_[i] += dx;
            y_[i] += dy;
            dispx_[i] += dx;
            dispy_[i] += dy;
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (y_[i] < 0) y_[i] += geo_.length;
            else if (y_[i] >= geo_.length) y_[i] -= geo_.length;
        }
        for (std::size_t i = 0; i < n; ++i) {
            vpx_[i] = vx_[i] + h * ax_[i];
            vpy_[i] = vy_[i] + h * ay_[i];
        }
        if (moved_too_far()) build_list();
        compute_forces();
        for (std::size_t i = 0; i < n; ++i) {
            vx_[i] += h * ax_[i];
            vy_[i] += h * ay_[i];
        }
        t_ += dt_;
        wall_.time += dt_;
        ++steps_;
        track_wall_impacts();
    }

private:
    double wrap(double y) const {
        y = std::fmod(y, geo_.length);
        return y < 0 ? y + geo_.length : y;
    }

    void compute_forces_after_build() {
        build_list();
        compute_forces();
        need_build_ = false;
    }

    // A pair's distance changes by at most |u_i - u_j| <= |u_i - c| + |u_j - c| for any common
    // c, u the displacements since the last build. Measuring from the mean displacement c keeps
    // a fast but nearly rigid flow (all grains falling at 10 m/s) from rebuilding every few steps;
    // wall contacts are found afresh every step and do not use the list.
    bool moved_too_far() const {
        const std::size_t n = x_.size();
        double cx = 0, cy = 0;
        for (std::size_t i = 0; i < n; ++i) {
            cx += dispx_[i];
            cy += dispy_[i];
        }
        cx /= double(n);
        cy /= double(n);
        const double lim = 0.25 * skin_ * skin_;
        for (std::size_t i = 0; i < n; ++i) {
            const double ux = dispx_[i] - cx, uy = dispy_[i] - cy;
            if (ux * ux + uy * uy > lim) return true;
        }
        return false;
    }

    // Linked cells of side >= the largest interaction range, then a half Verlet list.
    void build_list() {
        const std::size_t n = x_.size();
        dispx_.assign(n, 0.0);
        dispy_.assign(n, 0.0);
        double rmax = 0;
        for (double r : rad_) rmax = std::max(rmax, r);
        const double range = 2 * rmax + skin_;
        // Cells at least one interaction range wide, three or more along the periodic axis so
        // that the rows iy-1, iy, iy+1 are distinct and no pair is listed twice.
        if (geo_.length < 3 * range)
            throw std::invalid_argument("pipe length must be at least 3 interaction ranges (2 r_max + skin)");
        const int cx = std::max(1, int(geo_.width / range));
        const int cy = int(geo_.length / range);
        const double sx = geo_.width / cx, sy = geo_.length / cy;
        cell_start_.assign(std::size_t(cx * cy) + 1, 0);
        std::vector<int> cell_of(n);
        for (std::size_t i = 0; i < n; ++i) {
            const int ix = std::clamp(int(x_[i] / sx), 0, cx - 1);
            const int iy = std::clamp(int(y_[i] / sy), 0, cy - 1);
            cell_of[i] = iy * cx + ix;
            ++cell_start_[std::size_t(cell_of[i]) + 1];
        }
        for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
        cell_items_.resize(n);
        std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
        for (std::size_t i = 0; i < n; ++i) cell_items_[std::size_t(fill[std::size_t(cell_of[i])]++)] = int(i);

        nb_start_.assign(n + 1, 0);
        nb_.clear();
        const double range2 = range * range;
        for (std::size_t i = 0; i < n; ++i) {
            const int ix = cell_of[i] % cx, iy = cell_of[i] / cx;
            for (int ddy = -1; ddy <= 1; ++ddy) {
                const int jy = (iy + ddy + cy) % cy;
                for (int ddx = -1; ddx <= 1; ++ddx) {
                    const int jx = ix + ddx;
                    if (jx < 0 || jx >= cx) continue;
                    const int c = jy * cx + jx;
                    for (int k = cell_start_[std::size_t(c)]; k < cell_start_[std::size_t(c) + 1]; ++k) {
                        const int j = cell_items_[std::size_t(k)];
                        if (j <= int(i)) continue;
                        const double dx = x_[i] - x_[std::size_t(j)];
                        const double dy = min_image(y_[i] - y_[std::size_t(j)]);
                        if (dx * dx + dy * dy < range2) nb_.push_back(j);
                    }
                }
            }
            nb_start_[i + 1] = int(nb_.size());
        }
        ++builds_;
    }

    double min_image(double dy) const {
        if (dy > 0.5 * geo_.length) return dy - geo_.length;
        if (dy < -0.5 * geo_.length) return dy + geo_.length;
        return dy;
    }

    // Force of one contact on grain i with unit normal (nx, ny) from the partner to i, overlap
    // xi, relative velocity (rvx, rvy) = v_i - v_partner.
    inline void contact(double nx, double ny, double xi, double rvx, double rvy, double m_red, double& fx,
                        double& fy) const {
        const double xi_dot = -(rvx * nx + rvy * ny);
        const double vs = -rvx * ny + rvy * nx; // along perp(n) = (-ny, nx)
        const NormalForce f = normal_.normal_force(xi, xi_dot, m_red);
        const double fn = shear_.applied_normal(f);
        const double fs = shear_.shear_force(f, vs);
        fx = fn * nx - fs * ny;
        fy = fn * ny + fs * nx;
    }

    void compute_forces() {
        const std::size_t n = x_.size();
        std::fill(ax_.begin(), ax_.end(), 0.0);
        std::fill(ay_.begin(), ay_.end(), 0.0);
        double worst = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double xi_ = x_[i], yi = y_[i], ri = rad_[i], mi = mass_[i];
            const double vxi = vpx_[i], vyi = vpy_[i];
            double fxi = 0, fyi = 0;
            for (int k = nb_start_[i]; k < nb_start_[i + 1]; ++k) {
                const std::size_t j = std::size_t(nb_[std::size_t(k)]);
                const double dx = xi_ - x_[j];
                const double dy = min_image(yi - y_[j]);
                const double rs = ri + rad_[j];
                const double d2 = dx * dx + dy * dy;
                if (d2 >= rs * rs) continue;
                const double d = std::sqrt(d2);
                const double xi = rs - d;
                worst = std::max(worst, xi / (2 * std::min(ri, rad_[j])));
                const double m_red = mi * mass_[j] / (mi + mass_[j]);
                double fx, fy;
                contact(dx / d, dy / d, xi, vxi - vpx_[j], vyi - vpy_[j], m_red, fx, fy);
                fxi += fx;
                fyi += fy;
                ax_[j] -= fx;
                ay_[j] -= fy;
            }
            ax_[i] += fxi;
            ay_[i] += fyi;
        }
        // Wall grains.
        for (std::size_t i = 0; i < n; ++i) {
            const double reach = rad_[i] + geo_.wall_radius;
            if (x_[i] < reach) wall_row(i, 0.0, 0.0, worst);
            if (x_[i] > geo_.width - reach) wall_row(i, geo_.width, geo_.right_row_shift, worst);
        }
        for (std::size_t i = 0; i < n; ++i) {
            ax_[i] *= inv_mass_[i];
            ay_[i] = ay_[i] * inv_mass_[i] - geo_.gravity;
        }
        max_overlap_ = worst;
    }

    void wall_row(std::size_t i, double xw, double shift, double& worst) {
        const double reach = rad_[i] + geo_.wall_radius;
        const double lam = geo_.wall_spacing;
        const long k0 = long(std::floor((y_[i] - shift - reach) / lam));
        const long k1 = long(std::ceil((y_[i] - shift + reach) / lam));
        for (long k = k0; k <= k1; ++k) {
            const double dx = x_[i] - xw;
            const double dy = y_[i] - (shift + double(k) * lam);
            const double d2 = dx * dx + dy * dy;
            if (d2 >= reach * reach) continue;
            const double d = std::sqrt(d2);
            const double xi = reach - d;
            worst = std::max(worst, xi / (2 * std::min(rad_[i], geo_.wall_radius)));
            double fx, fy;
            contact(dx / d, dy / d, xi, vpx_[i], vpy_[i], mass_[i], fx, fy);
            ax_[i] += fx;
            ay_[i] += fy;
            wall_impulse_y_[i] += fy * dt_;
            touch_flag_[i] = 1;
        }
    }

    // A wall impact lasts from the first step a grain touches any wall grain to the first step it
    // touches none. Its Δv_y, as in Eq. (9) and the impact studies, is the velocity change caused
    // by the wall: the wall force's impulse along +y over the impact, divided by the mass (gravity
    // and collisions with other free grains during the impact are not counted).
    void track_wall_impacts() {
        const std::size_t n = x_.size();
        for (std::size_t i = 0; i < n; ++i) {
            const bool now = touch_flag_.size() == n && touch_flag_[i];
            if (now && !wall_touch_[i]) {
                ++wall_.impacts;
                vy_at_touch_[i] = vy_[i];
                vx_at_touch_[i] = vx_[i];
            } else if (!now && wall_touch_[i]) {
                ++wall_.completed;
                wall_.sum_dvy += wall_impulse_y_[i] * inv_mass_[i];
                wall_.sum_vy_in += std::abs(vy_at_touch_[i]);
                wall_.sum_vx_in += std::abs(vx_at_touch_[i]);
            }
            if (!now) wall_impulse_y_[i] = 0;
            wall_touch_[i] = now;
        }
        std::fill(touch_flag_.begin(), touch_flag_.end(), 0);
    }

public:
    // Must be called once after all grains are added (sizes the per-grain scratch arrays).
    void finalize() {
        touch_flag_.assign(x_.size(), 0);
        wall_impulse_y_.assign(x_.size(), 0.0);
        vpx_ = vx_;
        vpy_ = vy_;
        dispx_.assign(x_.size(), 0.0);
        dispy_.assign(x_.size(), 0.0);
        compute_forces_after_build();
        std::fill(touch_flag_.begin(), touch_flag_.end(), 0);
        wall_ = {};
    }

private:
    NormalLaw normal_;
    ShearLaw shear_;
    PipeGeometry geo_;
    double dt_, skin_;
    double t_ = 0;
    long steps_ = 0, builds_ = 0;
    bool need_build_ = true;
    double max_overlap_ = 0;
    std::vector<double> x_, y_, vx_, vy_, vpx_, vpy_, ax_, ay_, rad_, mass_, inv_mass_, dispx_, dispy_;
    std::vector<double> vy_at_touch_, vx_at_touch_, wall_impulse_y_;
    std::vector<char> wall_touch_, touch_flag_;
    std::vector<int> cell_start_, cell_items_, nb_start_, nb_;
    WallImpactStats wall_;
};

} // namespace granrepro
