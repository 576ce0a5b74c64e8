// The stress tensor of Luding 1998 Eq. (9) on a coarse grid of cells (Fig. 5, lower panels):
//
//   sigma_ab = (1/V_c) [ sum_contacts r_a f_b  -  sum_particles m v_a v_b ],
//
// with, for hard spheres, f_b -> Delta P_b / Delta t summed over the collisions in the window
// [t_begin, t_end) (Sec. 2.2, below Eq. 9). In 2D the "volume" V_c is the cell area [m^2], so
// sigma is in [N/m].
//
// Sign convention: exactly Eq. (9) as printed. Check: for a collision the contact branch vector of
// particle i is r = c - r_i = -R_i n (n points from j to i) and Delta P_i = +|dP_n| n for a
// repulsive (compressive) contact, so r (x) dP = -R_i |dP_n| n(x)n is negative; the kinetic term
// -m v(x)v is negative too. Both terms are therefore negative under compression: Eq. (9) is the
// tension-positive (Cauchy, continuum-mechanics) stress, sigma = -p 1 for a gas, i.e. minus the
// usual virial pressure tensor. pressure() returns p = -tr(sigma)/2.
//
// Per collision the two particles contribute (c - r_i)(x)dP + (c - r_j)(x)(-dP) = (r_j - r_i)(x)dP:
// the contact point c drops out, so no radii are needed. For a wall collision (j < 0)
// CollisionRecord::rj is the contact point and the single particle term is again (r_j - r_i)(x)dP.
// The contribution goes to the cell holding the contact point, taken as the midpoint
// (r_i + r_j)/2 (exact for equal radii; for walls r_j itself).
//
// With friction dP has a tangential part and sigma is not symmetric (its antisymmetric part is
// the torque density, which Eq. (9) does not separate); principal stresses and axes are computed
// from the symmetric part (sigma + sigma^T)/2.
#pragma once
#include "core/collision_record.hpp"
#include "core/vec2.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <span>
#include <vector>

namespace granrepro {

class CollisionalStress {
public:
    struct Cell {
        Eigen::Matrix2d collisional = Eigen::Matrix2d::Zero(); // first term of Eq. (9) [N/m]
        Eigen::Matrix2d kinetic = Eigen::Matrix2d::Zero();     // second term of Eq. (9) [N/m]
        Eigen::Matrix2d total = Eigen::Matrix2d::Zero();       // their sum [N/m]
        double sigma_min = 0.0;  // smaller eigenvalue of sym(total) [N/m]
        double sigma_max = 0.0;  // larger eigenvalue of sym(total) [N/m]
        Eigen::Vector2d axis_min = Eigen::Vector2d::UnitX(); // unit eigenvector of sigma_min
        Eigen::Vector2d axis_max = Eigen::Vector2d::UnitY(); // unit eigenvector of sigma_max
        std::size_t collisions = 0; // collisions attributed to the cell
        double pressure() const { return -0.5 * total.trace(); } // [N/m]
        // What a sweep point keeps of a cell (Fig. 5 and the eddy cores): eigenvalues, axes,
        // collisions, the total stress (pressure).
        template <class V> void fields(V&& v) {
            v("sigma_min", sigma_min); v("sigma_max", sigma_max); v("collisions", collisions);
            v("axis_min_x", axis_min.x()); v("axis_min_y", axis_min.y()); v("axis_max_x", axis_max.x());
            v("axis_max_y", axis_max.y()); v("total_xx", total(0, 0)); v("total_xy", total(0, 1));
            v("total_yx", total(1, 0)); v("total_yy", total(1, 1));
        }
    };

    // Grid of nx * ny cells over [x0, x0+Lx) x [y0, y0+Ly) [m]; window [t_begin, t_end) [s].
    // periodic: positions outside the box are wrapped; otherwise clamped into the edge cells
    // (walls, pipe flow). subtract_mean_velocity: if true the kinetic term uses v minus the
    // mass-weighted mean velocity of the cell in that snapshot (the fluctuation, for flows with
    // a mean motion like the falling pile); the paper's Eq. (9) uses v itself (false).
    // Throws std::invalid_argument on bad arguments.
    CollisionalStress(int nx, int ny, double x0, double y0, double Lx, double Ly, double t_begin,
                      double t_end, bool periodic, bool subtract_mean_velocity = false);

    // Adds a collision if t_begin <= c.t < t_end; returns whether it was used.
    bool add(const CollisionRecord& c);
    void add(std::span<const CollisionRecord> cs);
    // Adds one particle snapshot taken inside the window: positions [m], velocities [m/s],
    // masses [kg]. The kinetic term is averaged over all snapshots added.
    void add_snapshot(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                      std::span<const double> masses);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    std::size_t snapshots() const { return snapshots_; }
    // Cell (ix, iy) is at index ix + nx * iy; its centre in cell_centre().
    std::vector<Cell> result() const;
    Vec2 cell_centre(int ix, int iy) const;
    int cell_index(const Vec2& p) const;

private:
    int nx_, ny_;
    double x0_, y0_, Lx_, Ly_, t0_, t1_;
    bool periodic_, subtract_mean_;
    std::vector<Eigen::Matrix2d> coll_sum_; // sum (r_j - r_i)(x)dP [kg m^2/s]
    std::vector<Eigen::Matrix2d> kin_sum_;  // sum over snapshots of -sum m v(x)v [J]
    std::vector<std::size_t> n_coll_;
    std::size_t snapshots_ = 0;
};

} // namespace granrepro
