// Many-body soft-sphere MD for a vertical pipe (Schäfer & Wolf 1995, Fig. 6): free grains between
// two rows of fixed wall grains at x = 0 and x = width, periodic along y, gravity along -y.
// Translation only, as in the paper.
//
// Integration: velocity Verlet (half kick, drift, forces, half kick). The dashpot and Coulomb
// forces depend on velocity; evaluating them at the half-step velocity, as LAMMPS' gran/hooke
// does, lags them by dt/2 and costs a first-order error in e_N (about gamma_N dt / 2, 1 % at
// e_N = 0.7 and dt = t_col/50). They are evaluated instead at the predicted full-step velocity
// v(t+dt/2) + a(t) dt/2 (the modified velocity Verlet of Groot & Warren 1997 with lambda = 1).
// dt = t_col/50 of the stiffest pair (Eq. 5). Wall grains are not stored: a grain near a wall
// tests the two or three wall grains at its height, found from the row's spacing.
//
// Neighbours: a full Verlet list (every pair in both grains' lists) from linked cells, rebuilt
// when any grain has moved more than skin/2 relative to the mean displacement since the last
// build, so every step costs O(N). At each build the grains are re-sorted into cell order, so
// that neighbours are near in memory.
// A step: (1) accelerations from the last force sums, the last step's closing half kick (kept
// pending so that it shares this pass), this step's half kick and drift of every grain, noting
// the grains near a wall; (2) contact test of each listed pair, once per pair, listing the
// entries of the pairs in contact (pipe_detect.hpp); (3) forces of those entries, grain by
// grain in list order; (4) the wall rows, for the grains near a wall; (5) the wall-impact meter
// (wall_impact_meter.hpp) notes the grains that touch or touched a wall.
// (1) runs several grains per instruction (pipe_drift.hpp); contacts and wall grains are the
// only scalar work per grain.
//
// Determinism. Grains keep the index they were added with ("id"); every accessor speaks ids.
// The force on grain I is summed in an order fixed by ids and by the cell grid at the last build,
// never by memory order: first its partners J < I in increasing J, then (a separate
// sum, added to the first) its partners J > I in the order of the cells (row below, same row, row
// above; left to right) and increasing J within a cell, then the wall grains. (This is the order
// of the half-list engine this one replaced, so its trajectories are reproduced bit for bit.)
// Each grain computes its own pair forces; a pair's force is computed twice, with bit-identical
// magnitude (the pair law is antisymmetric in floating point, see contact()). The rebuild test
// uses the mean displacement summed in id order, and wall-impact sums run in id order.
// (One thread: sharing a step between two threads was 0.72x as fast as one core on a 2-core
// machine, so the engine has none.)
//
// Template parameters: NormalLaw::normal_force(xi, xi_dot, m_red) -> NormalForce;
// ShearLaw::applied_normal(NormalForce) and ShearLaw::shear_force(NormalForce, v_S).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/interrupt.hpp"
#include "engines/soft/pipe_detect.hpp"
#include "engines/soft/pipe_drift.hpp"
#include "engines/soft/wall_impact_meter.hpp"
#include "models/normal_force.hpp"
#include "models/stateful_shear.hpp"

namespace granrepro {

struct PipeGeometry {
    double width = 0.02;       // distance between the centre lines of the two wall rows [m]
    double length = 0.04;      // periodic length along y [m]; a multiple of wall_spacing
    double wall_radius = 0.33e-3;  // [m]
    double wall_spacing = 0.66e-3; // [m]
    double right_row_shift = 0.0;  // y offset of the right row's grains [m]
    double gravity = 10.0;     // [m/s^2], acting along -y
};

template <class NormalLaw, class ShearLaw>
class PipeEngine {
    static_assert(!StatefulShear<ShearLaw>,
                  "PipeEngine does not carry per-contact shear state (yet): use FewBodyEngine");

public:
    PipeEngine(NormalLaw normal, ShearLaw shear, PipeGeometry geo, double dt, double skin)
        : normal_(normal), shear_(shear), geo_(geo), dt_(dt), dt_closing_(dt), skin_(skin) {
        if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
        const double n = geo.length / geo.wall_spacing;
        if (std::abs(n - std::round(n)) > 1e-9 * n)
            throw std::invalid_argument("pipe length must be a multiple of the wall spacing");
    }

    void add_grain(double x, double y, double vx, double vy, double radius, double mass) {
        id_.push_back(int(x_.size()));
        x_.push_back(x); y_.push_back(wrap(y)); vx_.push_back(vx); vy_.push_back(vy);
        fx_.push_back(0); fy_.push_back(0); rad_.push_back(radius); mass_.push_back(mass);
        inv_mass_.push_back(1.0 / mass);
        wall_meter_.add_grain();
        need_build_ = true;
        ++version_;
    }

    std::size_t size() const { return x_.size(); }
    const NormalLaw& normal_law() const { return normal_; }
    const ShearLaw& shear_law() const { return shear_; }
    double time() const { return t_; }
    double dt() const { return dt_; }
    // The step of the following steps (velocity Verlet with a variable step: the pending closing
    // half kick of the last step keeps that step's dt/2, the next one opens with the new dt/2).
    // Unchanged steps give the same bits as before.
    void set_dt(double dt) {
        if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
        dt_ = dt;
    }
    long steps() const { return steps_; }
    long list_builds() const { return builds_; }
    // Per-grain arrays in id order (the order grains were added).
    // (A step ends with its closing half kick pending: the next step's drift applies it, and
    // these accessors add it, with the same operations.)
    const std::vector<double>& x() const { return by_id(out_[0], [&](std::size_t i) { return x_[i]; }); }
    const std::vector<double>& y() const { return by_id(out_[1], [&](std::size_t i) { return y_[i]; }); }
    const std::vector<double>& vx() const {
        return by_id(out_[2], [&](std::size_t i) { return kick_pending() ? vx_[i] + 0.5 * dt_closing_ * accel_x(i) : vx_[i]; });
    }
    const std::vector<double>& vy() const {
        return by_id(out_[3], [&](std::size_t i) { return kick_pending() ? vy_[i] + 0.5 * dt_closing_ * accel_y(i) : vy_[i]; });
    }
    const std::vector<double>& radius() const { return by_id(out_[4], [&](std::size_t i) { return rad_[i]; }); }
    const std::vector<double>& mass() const { return by_id(out_[5], [&](std::size_t i) { return mass_[i]; }); }
    const std::vector<double>& ax() const { return by_id(out_[6], [&](std::size_t i) { return accel_x(i); }); }
    const std::vector<double>& ay() const { return by_id(out_[7], [&](std::size_t i) { return accel_y(i); }); }
    const WallImpactStats& wall_stats() const { return wall_meter_.stats(); }
    void reset_wall_stats() { wall_meter_.reset_stats(); }
    // Bytes held per grain by the engine's arrays and lists (capacity, not just size).
    double bytes_per_grain() const {
        std::size_t b = 0;
        for (const auto* v : {&x_, &y_, &vx_, &vy_, &vpx_, &vpy_, &rad_, &mass_, &inv_mass_, &dispx_,
                              &dispy_})
            b += v->capacity() * sizeof(double);
        for (const auto& v : spare_) b += v.capacity() * sizeof(double);
        b += (id_.capacity() + slot_of_id_.capacity() + spare_id_.capacity() + nb_start_.capacity() + nb_owner_.capacity() +
              nb_j_.capacity() + cell_of_.capacity() + cell_x_.capacity() + cell_y_.capacity() + order_.capacity() +
              cell_col_.capacity() + cell_row_.capacity() + cell_start_.capacity()) * sizeof(int);
        b += nb_mirror_.capacity() * sizeof(int);
        {
            const Scratch& s = scratch_;
            b += (s.low.capacity() + s.high.capacity() + s.found.capacity() + s.cell_count.capacity() +
                  s.owners.capacity() + s.pi.capacity() + s.pj.capacity() + s.pk.capacity() +
                  s.pm.capacity()) * sizeof(int) +
                 (s.partners.capacity() + s.counts.capacity() + s.hits.capacity() + s.near.capacity()) * sizeof(int);
        }
        b += wall_meter_.bytes() + near_mark_.capacity();
        b += (fx_.capacity() + fy_.capacity()) * sizeof(double);
        for (const auto& o : out_) b += o.second.capacity() * sizeof(double);
        return x_.empty() ? 0.0 : double(b) / double(x_.size());
    }

    // Reference for tests: accelerations from all N^2 pairs and all wall grains in range, without
    // the neighbour list, for the positions and the velocities the last force evaluation used
    // (in id order).
    void brute_force_accelerations(std::vector<double>& ax, std::vector<double>& ay) const {
        const std::size_t n = x_.size();
        std::vector<double> bx(n, 0.0), by(n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                const double dx = x_[i] - x_[j], dy = min_image(y_[i] - y_[j]);
                const double rs = rad_[i] + rad_[j];
                const double d = std::sqrt(dx * dx + dy * dy);
                if (d >= rs) continue;
                double fx, fy;
                contact(dx / d, dy / d, rs - d, vpx_[i] - vpx_[j], vpy_[i] - vpy_[j],
                        mass_[i] * mass_[j] / (mass_[i] + mass_[j]), fx, fy);
                bx[i] += fx; by[i] += fy; bx[j] -= fx; by[j] -= fy;
            }
        const long nw = std::lround(geo_.length / geo_.wall_spacing);
        ax.assign(n, 0.0);
        ay.assign(n, 0.0);
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
                    bx[i] += fx; by[i] += fy;
                }
            }
            ax[std::size_t(id_[i])] = bx[i] / mass_[i];
            ay[std::size_t(id_[i])] = by[i] / mass_[i] - geo_.gravity;
        }
    }

    // Largest overlap seen in the last force evaluation, relative to the smaller diameter.
    double max_overlap_ratio() const { return max_overlap_; }

    void step() {
        if ((++pause_count_ & 1023) == 0) engine_pause_point();
        advance(1);
    }

    // `steps` time steps; the same as calling step() that often.
    void advance(long steps) {
        if (need_build_) throw std::logic_error("PipeEngine: call finalize() after adding grains");
        if (steps <= 0) return;
        ++version_;
        for (long s = 0; s < steps; ++s) one_step();
    }

    // Must be called once after all grains are added (sizes the per-grain scratch arrays).
    void finalize() {
        const std::size_t n = x_.size();
        wall_meter_.clear_impulses();
        vpx_ = vx_;
        vpy_ = vy_;
        dispx_.assign(n, 0.0);
        dispy_.assign(n, 0.0);
        fx_.assign(n, 0.0);
        fy_.assign(n, 0.0);
        near_mark_.assign(n, 0);
        double rmax = 0;
        for (double r : rad_) rmax = std::max(rmax, r);
        range_ = 2 * rmax + skin_;
        // Cells at least one interaction range wide, three or more along the periodic axis so
        // that the rows iy-1, iy, iy+1 are distinct and no pair is listed twice.
        if (geo_.length < 3 * range_)
            throw std::invalid_argument("pipe length must be at least 3 interaction ranges (2 r_max + skin)");
        cells_x_ = std::max(1, int(geo_.width / range_));
        cells_y_ = int(geo_.length / range_);
        cell_w_ = geo_.width / cells_x_;
        cell_h_ = geo_.length / cells_y_;
        const int ncell = cells_x_ * cells_y_;
        cell_start_.assign(std::size_t(ncell) + 1, 0);
        cell_col_.resize(std::size_t(ncell));
        cell_row_.resize(std::size_t(ncell));
        for (int c = 0; c < ncell; ++c) cell_col_[std::size_t(c)] = c % cells_x_, cell_row_[std::size_t(c)] = c / cells_x_;
        cell_of_.resize(n);
        order_.resize(n);
        for (auto& v : spare_) v.resize(n);
        spare_id_.resize(n);
        slot_of_id_.resize(n);
        cell_x_.resize(n);
        cell_y_.resize(n);
        nb_start_.resize(n + 1);
        scratch_ = Scratch{};
        need_build_ = false;
        ++version_;
        // The first list and forces, as a step would compute them, without kicks or wall impacts
        // begun or ended (the wall impulse of this evaluation is kept, as it always was).
        rebuild();
        find_near();
        detect();
        forces();
        meter_walls(false);
        finish_step_stats(false);
        wall_meter_.reset_stats();
    }

private:
    // ---- per-step state and scratch ----------------------------------------------------------
    struct Scratch {
        double sum_x = 0, sum_y = 0, max_q = 0; // rebuild-test partials of this step
        double cprev_x = 0, cprev_y = 0;        // mean displacement of the last step
        bool kick_pending = false;              // the last step's closing half kick is still to come
        bool band_valid = false;                // band was made at the last build
        bool band_holds = false;                // near_from_band() is exact this step
        double worst = 0;
        std::vector<int> low, high, found; // list-build scratch
        std::vector<int> cell_count;       // grains per cell, then where they go
        std::vector<int> partners, owners, counts; // the list entries (partner, owner slots) and the
                                                   // entries before each grain
        // The pairs tested: slots pi < pj, list entries pk = pi -> pj and pm = pj -> pi.
        std::vector<int> pi, pj, pk, pm;
        std::vector<int> hits;             // list entries in contact this step (nhits of them)
        std::size_t nhits = 0;
        std::vector<int> near;             // slots near a wall this step (near_count of them)
        std::vector<int> band;             // slots that can come near a wall before the next build
        std::size_t near_count = 0;
    };

    double wrap(double y) const {
        y = std::fmod(y, geo_.length);
        return y < 0 ? y + geo_.length : y;
    }

    double min_image(double dy) const {
        if (dy > 0.5 * geo_.length) return dy - geo_.length;
        if (dy < -0.5 * geo_.length) return dy + geo_.length;
        return dy;
    }

    template <class Value>
    const std::vector<double>& by_id(std::pair<long, std::vector<double>>& out, Value value) const {
        const std::size_t n = x_.size();
        if (out.first != version_ || out.second.size() != n) {
            out.second.resize(n);
            for (std::size_t i = 0; i < n; ++i) out.second[std::size_t(id_[i])] = value(i);
            out.first = version_;
        }
        return out.second;
    }
    bool kick_pending() const { return scratch_.kick_pending; }
    double accel_x(std::size_t i) const { return fx_[i] * inv_mass_[i]; }
    double accel_y(std::size_t i) const { return fy_[i] * inv_mass_[i] - geo_.gravity; }

    // ---- one step --------------------------------------------------------------------------
    void one_step() {
        drift();
        if (must_rebuild()) {
            rebuild();
            find_near();
        } else if (scratch_.band_holds) {
            near_from_band();
        } else {
            find_near();
        }
        detect();
        forces();
        meter_walls(true);
        finish_step_stats(true);
        t_ += dt_;
        dt_closing_ = dt_;
        ++steps_;
    }

    // Accelerations from the last force sums (clearing them), the last step's closing half kick,
    // this step's half kick, drift, periodic wrap, predicted velocity; partial sums for the
    // rebuild test (pipe_drift.hpp: several grains per instruction, bit-identical).
    void drift() {
        Scratch& s = scratch_;
        const pipe_detail::DriftArrays a{x_.data(), y_.data(), vx_.data(), vy_.data(), vpx_.data(), vpy_.data(),
                                         dispx_.data(), dispy_.data(), fx_.data(), fy_.data(), inv_mass_.data(),
                                         0.5 * dt_, dt_, geo_.length, geo_.gravity, 0.5 * dt_closing_, s.cprev_x, s.cprev_y};
        const pipe_detail::DriftSums sums = s.kick_pending ? pipe_detail::drift<true>(a, 0, x_.size())
                                                           : pipe_detail::drift<false>(a, 0, x_.size());
        s.sum_x = sums.sx;
        s.sum_y = sums.sy;
        s.max_q = sums.qmax;
        s.kick_pending = true; // at the end of this step
    }

    // The grains near a wall, from the band of grains that were near enough at the last build:
    // no grain has moved more than skin/2 from the mean displacement c since then, so a grain
    // outside the band is farther than its reach from both walls while |c_x| stays below the
    // band's margin (must_rebuild() checks).
    void near_from_band() {
        Scratch& s = scratch_;
        std::size_t nn = 0;
        for (int k : s.band) {
            const std::size_t i = std::size_t(k);
            const double reach = rad_[i] + geo_.wall_radius;
            if (x_[i] < reach || x_[i] > geo_.width - reach) s.near[nn++] = int(i);
        }
        s.near_count = nn;
    }
    double band_margin() const { return skin_; }

    // The grains near a wall, by a scan.
    void find_near() {
        Scratch& s = scratch_;
        std::size_t nn = 0;
        for (std::size_t i = 0, e = x_.size(); i < e; ++i) {
            const double reach = rad_[i] + geo_.wall_radius;
            if (x_[i] < reach || x_[i] > geo_.width - reach) s.near[nn++] = int(i);
        }
        s.near_count = nn;
    }

    // A pair's distance changes by at most |u_i - u_j| <= |u_i - c| + |u_j - c| for any common
    // c, u the displacements since the last build. Measuring from the mean displacement c keeps
    // a fast but nearly rigid flow (all grains falling at 10 m/s) from rebuilding every few steps;
    // wall contacts are found afresh every step and do not use the list.
    //
    // The decision is that of the rule evaluated with c summed in id order (as the engine always
    // did; a different rounding of c could move a rebuild by a step and change the force sums'
    // order). It is mostly settled from the drift's sums (in slot order): with c' their mean,
    // c_prev the previous step's c' and Q = max_i |u_i - c_prev|^2, every |u_i - c| lies within
    // sqrt(Q) + |c' - c_prev| + delta, where delta bounds |c - c'| from summation rounding
    // (2 n eps max|u| per component, max|u| <= sqrt(Q) + |c_prev|). Only when lim falls inside
    // that bracket (in practice the step before a rebuild, or never) is the rule evaluated
    // exactly, in id order.
    bool must_rebuild() {
        const std::size_t n = x_.size();
        if (n == 0) return false;
        Scratch& mine = scratch_;
        double sx = 0, sy = 0, qmax = 0; // (0 + sum and max(0, q): the same bits as ever)
        sx += mine.sum_x;
        sy += mine.sum_y;
        qmax = std::max(qmax, mine.max_q);
        const double cx = sx / double(n), cy = sy / double(n);
        const double lim = 0.25 * skin_ * skin_;
        const double shift = std::sqrt((cx - mine.cprev_x) * (cx - mine.cprev_x) + (cy - mine.cprev_y) * (cy - mine.cprev_y));
        const double r = std::sqrt(qmax), slack = 1e-12;
        const double umax = 2 * (r + std::abs(mine.cprev_x) + std::abs(mine.cprev_y));
        const double delta = 4.0 * double(n + 1) * std::numeric_limits<double>::epsilon() * umax;
        const double hi = (r + shift) * (1 + slack) + delta;
        const double lo = std::max(0.0, r * (1 - slack) - shift * (1 + slack) - delta);
        bool rebuild_now;
        if (std::isfinite(cx) && std::isfinite(cy) && std::isfinite(hi) && hi * hi * (1 + slack) <= lim)
            rebuild_now = false;
        else if (std::isfinite(cx) && std::isfinite(cy) && std::isfinite(hi) && lo * lo * (1 - slack) > lim)
            rebuild_now = true;
        else {
            // Undecided (or not finite): the exact rule.
            rebuild_now = moved_too_far_exact();
        }
        mine.cprev_x = rebuild_now ? 0.0 : cx;
        mine.cprev_y = rebuild_now ? 0.0 : cy;
        mine.band_holds = mine.band_valid && std::abs(cx) + delta + 1e-9 * geo_.width < band_margin();
        return rebuild_now;
    }

    bool moved_too_far_exact() const {
        const std::size_t n = x_.size();
        double cx = 0, cy = 0;
        for (std::size_t k = 0; k < n; ++k) {
            cx += dispx_[std::size_t(slot_of_id_[k])];
            cy += dispy_[std::size_t(slot_of_id_[k])];
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

    // ---- neighbour list ------------------------------------------------------------------
    // Re-sorts the grains into cell order, then lists each grain's partners within
    // r_i + r_j + skin: partners with smaller id first, in increasing id, then those with larger
    // id in cell order (see the header comment). The cells are those of range = 2 r_max + skin,
    // as always; the cut-off per pair is tighter (a pair farther apart than r_i + r_j + skin
    // cannot touch before the next build).
    void rebuild() {
        const std::size_t n = x_.size();
        const std::size_t ncell = std::size_t(cells_x_) * std::size_t(cells_y_);
        Scratch& s = scratch_;
        ++builds_;
        // A counting sort by cell (stable), then by id within a cell.
        s.cell_count.assign(ncell, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const int ix = std::clamp(int(x_[i] / cell_w_), 0, cells_x_ - 1);
            const int iy = std::clamp(int(y_[i] / cell_h_), 0, cells_y_ - 1);
            cell_of_[i] = iy * cells_x_ + ix;
            ++s.cell_count[std::size_t(cell_of_[i])];
        }
        int total = 0;
        for (std::size_t c = 0; c < ncell; ++c) {
            cell_start_[c] = total;
            const int count = s.cell_count[c];
            s.cell_count[c] = total;
            total += count;
        }
        cell_start_[ncell] = total;
        for (std::size_t i = 0; i < n; ++i) order_[std::size_t(s.cell_count[std::size_t(cell_of_[i])]++)] = int(i);
        // Within a cell by id (the cells were sorted at the last build, so this is nearly so).
        for (std::size_t c = 0; c < ncell; ++c)
            for (int a = cell_start_[c] + 1; a < cell_start_[c + 1]; ++a) {
                const int k = order_[std::size_t(a)];
                int b2 = a;
                for (; b2 > cell_start_[c] && id_[std::size_t(order_[std::size_t(b2 - 1)])] > id_[std::size_t(k)]; --b2)
                    order_[std::size_t(b2)] = order_[std::size_t(b2 - 1)];
                order_[std::size_t(b2)] = k;
            }
        // Move the grains into the new order.
        {
            std::vector<double>* cur[] = {&x_, &y_, &vx_, &vy_, &vpx_, &vpy_, &rad_, &mass_, &inv_mass_};
            const int* __restrict order = order_.data();
            for (std::size_t a = 0; a < kMoved; ++a) {
                const double* __restrict src = cur[a]->data();
                double* __restrict dst = spare_[a].data();
                for (std::size_t i = 0; i < n; ++i) dst[i] = src[order[i]];
            }
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t o = std::size_t(order[i]);
                const int c = cell_of_[o];
                spare_id_[i] = id_[o];
                cell_x_[i] = cell_col_[std::size_t(c)];
                cell_y_[i] = cell_row_[std::size_t(c)];
                slot_of_id_[std::size_t(id_[o])] = int(i);
            }
            std::fill(dispx_.begin(), dispx_.end(), 0.0);
            std::fill(dispy_.begin(), dispy_.end(), 0.0);
            for (std::size_t a = 0; a < kMoved; ++a) cur[a]->swap(spare_[a]);
            id_.swap(spare_id_);
        }
        list_partners();
        const std::size_t entries = s.partners.size();
        if (nb_j_.size() < entries + 8) { // (+8: the mirror scan reads up to 8 entries past a start)
            const std::size_t cap = entries + entries / 4 + 8;
            nb_j_.resize(cap);
            nb_owner_.resize(cap);
            nb_mirror_.resize(cap);
        }
        std::copy(s.partners.begin(), s.partners.end(), nb_j_.begin());
        std::copy(s.owners.begin(), s.owners.end(), nb_owner_.begin());
        for (std::size_t i = 0; i < n; ++i) nb_start_[i] = s.counts[i];
        nb_start_[n] = int(entries);
        // Each entry i -> j finds its mirror j -> i among j's entries: a fixed, branch-free scan
        // of the first eight (more only for a grain with more partners).
        {
            const int* __restrict start = nb_start_.data();
            const int* __restrict nbj = nb_j_.data();
            const int* __restrict own = nb_owner_.data();
            int* __restrict mirror = nb_mirror_.data();
            for (std::size_t k = 0; k < entries; ++k) {
                const int i = own[k], j = nbj[k];
                const int s0 = start[j], count = start[j + 1] - s0;
                int m = 0; // (exactly one q matches: m = the sum of (s0 + q) [match])
                if (count <= 8) {
                    for (int q = 0; q < 8; ++q) m += (s0 + q) * int((nbj[s0 + q] == i) & (q < count));
                } else {
                    for (int q = 0; q < count; ++q) m += (s0 + q) * int(nbj[s0 + q] == i);
                }
                mirror[k] = m;
            }
        }
        pair_lists();
    }

    // What the step derives from the list at a build: the pairs to test (each once, yielding
    // both entries), and the grains that touch a wall or can come near one.
    void pair_lists() {
        Scratch& s = scratch_;
        const std::size_t n = x_.size();
        const std::size_t k1 = std::size_t(nb_start_[n]);
        const std::size_t most = k1 + 1;
        s.pi.resize(most), s.pj.resize(most), s.pk.resize(most), s.pm.resize(most);
        std::size_t np = 0;
        for (std::size_t k = 0; k < k1; ++k) {
            const std::size_t j = std::size_t(nb_j_[k]);
            s.pi[np] = nb_owner_[k];
            s.pj[np] = int(j);
            s.pk[np] = int(k);
            s.pm[np] = nb_mirror_[k];
            np += j > std::size_t(nb_owner_[k]);
        }
        s.pi.resize(np), s.pj.resize(np), s.pk.resize(np), s.pm.resize(np);
        s.hits.resize(2 * np + 1);
        s.near.resize(n + 2);
        double rmax = 0;
        for (double r : rad_) rmax = std::max(rmax, r);
        const double band = rmax + geo_.wall_radius + 0.5 * skin_ + band_margin();
        s.band.clear();
        for (std::size_t i = 0; i < n; ++i)
            if (x_[i] < band || x_[i] > geo_.width - band) s.band.push_back(int(i));
        s.band_valid = true; // (the band is measured from the positions at the build)
        wall_meter_.relist(n, id_.data());
    }

    // Lists the partners of the grains into the scratch (partners, counts). The cells
    // are slot ranges, in a row left to right, each sorted by id (rebuild() sees to that), so
    // the partners with larger id come out of the scan of rows below / same / above in the
    // required order; those with smaller id are sorted by id (a handful).
    void list_partners() {
        Scratch& s = scratch_;
        const std::size_t n = x_.size();
        s.counts.resize(n);
        const double* __restrict x = x_.data();
        const double* __restrict y = y_.data();
        const double* __restrict r = rad_.data();
        const int* __restrict id = id_.data();
        const double len = geo_.length, skin = skin_;
        std::size_t used = 0; // entries written to s.partners / s.owners
        for (std::size_t i = 0; i < n; ++i) {
            const int ix = cell_x_[i], iy = cell_y_[i];
            const int jx0 = std::max(ix - 1, 0), jx1 = std::min(ix + 1, cells_x_ - 1);
            int lo[3], hi[3];
            double shift[3]; // the image of the row nearest to grain i (L >= 3 ranges: unique)
            std::size_t candidates = 0;
            for (int row = 0; row < 3; ++row) {
                const int jy = iy + row - 1;
                const int wy = (jy + cells_y_) % cells_y_;
                shift[row] = jy < 0 ? -len : (jy >= cells_y_ ? len : 0.0);
                lo[row] = cell_start_[std::size_t(wy * cells_x_ + jx0)];
                hi[row] = cell_start_[std::size_t(wy * cells_x_ + jx1 + 1)];
                candidates += std::size_t(hi[row] - lo[row]);
            }
            if (s.found.size() < candidates + 1) {
                s.low.resize(2 * candidates + 8);
                s.high.resize(2 * candidates + 8);
                s.found.resize(2 * candidates + 8);
            }
            if (s.partners.size() < used + candidates) {
                s.partners.resize(2 * (used + candidates) + 64);
                s.owners.resize(2 * (used + candidates) + 64);
            }
            int* __restrict low = s.low.data();
            int* __restrict high = s.high.data();
            int* __restrict found = s.found.data();
            const int me = id[i];
            const double xi = x[i], yi = y[i], ri = r[i] + skin;
            std::size_t nf = 0; // candidates within reach, grain i itself among them
            for (int row = 0; row < 3; ++row) {
                const double yr = yi - shift[row];
                for (int j = lo[row]; j < hi[row]; ++j) {
                    const double dx = xi - x[j], dy = yr - y[j], cut = ri + r[j];
                    found[nf] = j;
                    nf += dx * dx + dy * dy < cut * cut;
                }
            }
            std::size_t nl = 0, nh = 0;
            for (std::size_t a = 0; a < nf; ++a) {
                const int j = found[a];
                const bool other = std::size_t(j) != i, below = id[j] < me;
                low[nl] = j;
                nl += other & below;
                high[nh] = j;
                nh += other & !below;
            }
            for (std::size_t a = 1; a < nl; ++a) { // insertion sort by id
                const int k = low[a];
                std::size_t c = a;
                for (; c > 0 && id[low[c - 1]] > id[k]; --c) low[c] = low[c - 1];
                low[c] = k;
            }
            s.counts[i] = int(used);
            int* __restrict out = s.partners.data() + used;
            int* __restrict own = s.owners.data() + used;
            for (std::size_t a = 0; a < nl; ++a) out[a] = low[a], own[a] = int(i);
            for (std::size_t a = 0; a < nh; ++a) out[nl + a] = high[a], own[nl + a] = int(i);
            used += nl + nh;
        }
        s.partners.resize(used);
        s.owners.resize(used);
    }

    // ---- forces ----------------------------------------------------------------------------
    // Force of one contact on grain i with unit normal (nx, ny) from the partner to i, overlap
    // xi, relative velocity (rvx, rvy) = v_i - v_partner. Swapping the grains negates n and the
    // relative velocity exactly, leaves xi_dot and v_S unchanged ((-a)(-b) = ab and (-a)b = -(ab)
    // in floating point), and so negates (fx, fy) exactly.
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

    // Contact test of the listed pairs (pipe_detect.hpp): the list entries in contact (not
    // d^2 >= (r_i + r_j)^2, the same in either direction), sorted into list order.
    void detect() {
        Scratch& s = scratch_;
        s.nhits = pipe_detail::detect({s.pi.data(), s.pj.data(), s.pk.data(), s.pm.data(), s.pi.size()},
                                      {x_.data(), y_.data(), rad_.data(), geo_.length}, s.hits.data());
        std::sort(s.hits.begin(), s.hits.begin() + std::ptrdiff_t(s.nhits)); // list order
    }

    // Force sums of the grains; near_mark_ tells meter_walls() which touched a wall.
    void forces() {
        Scratch& s = scratch_;
        const int* __restrict hits = s.hits.data();
        const std::size_t nh = s.nhits;

        // Contact forces, grain by grain: partners with smaller id, then larger id, then both.
        const double len = geo_.length, half = 0.5 * geo_.length;
        const double* __restrict x = x_.data();
        const double* __restrict y = y_.data();
        const double* __restrict r = rad_.data();
        const double* __restrict m = mass_.data();
        const double* __restrict vpx = vpx_.data();
        const double* __restrict vpy = vpy_.data();
        const int* __restrict own = nb_owner_.data();
        const int* __restrict nb = nb_j_.data();
        const int* __restrict id = id_.data();
        double* __restrict fxs = fx_.data();
        double* __restrict fys = fy_.data();
        double worst = 0;
        for (std::size_t a = 0; a < nh;) {
            const std::size_t i = std::size_t(own[hits[a]]);
            double low_x = 0, low_y = 0, high_x = 0, high_y = 0;
            for (; a < nh && std::size_t(own[hits[a]]) == i; ++a) {
                const std::size_t j = std::size_t(nb[hits[a]]);
                const double dx = x[i] - x[j];
                double dy = y[i] - y[j];
                if (dy > half) dy -= len;
                else if (dy < -half) dy += len;
                const double rs = r[i] + r[j];
                const double d = std::sqrt(dx * dx + dy * dy);
                const double xi = rs - d;
                worst = std::max(worst, xi / (2 * std::min(r[i], r[j])));
                const double m_red = m[i] * m[j] / (m[i] + m[j]);
                double fx, fy;
                contact(dx / d, dy / d, xi, vpx[i] - vpx[j], vpy[i] - vpy[j], m_red, fx, fy);
                // Branch-free: the sums start at +0 and so are never -0, and x + 0 = x otherwise.
                const bool below = id[j] < id[i];
                low_x += below ? fx : 0.0;
                low_y += below ? fy : 0.0;
                high_x += below ? 0.0 : fx;
                high_y += below ? 0.0 : fy;
            }
            fxs[i] = low_x + high_x;
            fys[i] = low_y + high_y;
        }

        // Wall rows, added after the pair forces.
        const int* near = s.near.data();
        const std::size_t nn = s.near_count;
        for (std::size_t a = 0; a < nn; ++a) {
            const std::size_t i = std::size_t(near[a]);
            const double reach = r[i] + geo_.wall_radius;
            bool touched = false;
            if (x[i] < reach) touched |= wall_row(i, 0.0, 0.0, fxs[i], fys[i], worst);
            if (x[i] > geo_.width - reach) touched |= wall_row(i, geo_.width, geo_.right_row_shift, fxs[i], fys[i], worst);
            near_mark_[i] = 1 + touched;
        }
        s.worst = worst;
    }

    // The wall-impact meter's part of the step (count false: finalize()'s force evaluation); it
    // clears the near marks for the next step.
    void meter_walls(bool count) {
        const Scratch& s = scratch_;
        const int* near = s.near.data();
        const std::size_t nn = s.near_count;
        const double h = 0.5 * dt_;
        wall_meter_.step(count, near, nn, near_mark_.data(), id_.data(), inv_mass_.data(), [&](std::size_t i) {
            // the velocities after this step's closing half kick (applied by the next drift)
            return WallImpactMeter::Velocity{vx_[i] + h * accel_x(i), vy_[i] + h * accel_y(i)};
        });
    }

    bool wall_row(std::size_t i, double xw, double shift, double& fx_sum, double& fy_sum, double& worst) {
        const double reach = rad_[i] + geo_.wall_radius;
        const double lam = geo_.wall_spacing;
        const double f0 = std::floor((y_[i] - shift - reach) / lam), f1 = std::ceil((y_[i] - shift + reach) / lam);
        // y is wrapped into [0, length), so the rows are within the pipe's count unless a grain
        // blew up (NaN): then the casts would be undefined. The step does not throw halfway, so
        // the grain gets no wall force and max_overlap_ratio() says inf.
        if (!(std::fabs(f0) < 1e15 && std::fabs(f1) < 1e15)) {
            worst = std::numeric_limits<double>::infinity();
            return false;
        }
        const long k0 = long(f0), k1 = long(f1);
        bool touched = false;
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
            fx_sum += fx;
            fy_sum += fy;
            wall_meter_.add_impulse(std::size_t(id_[i]), fy * dt_);
            touched = true;
        }
        return touched;
    }

    // After the forces of a step: the largest overlap, and (count) the meter's step, which adds
    // the wall impacts completed in it in id order.
    void finish_step_stats(bool count) {
        double worst = 0; // (max(0, worst): the same bits as ever)
        worst = std::max(worst, scratch_.worst);
        max_overlap_ = worst;
        if (count) wall_meter_.end_step(dt_);
    }

    // Per-grain double arrays moved by a re-sort (the force sums are zero at that point; the
    // wall-impact state is kept by id).
    static constexpr std::size_t kMoved = 9;

    NormalLaw normal_;
    ShearLaw shear_;
    PipeGeometry geo_;
    double dt_, dt_closing_, skin_; // this step's, and the last step's (its closing half kick pending) [s]
    double t_ = 0;
    long steps_ = 0, builds_ = 0;
    bool need_build_ = true;
    double max_overlap_ = 0;
    double range_ = 0, cell_w_ = 0, cell_h_ = 0;
    int cells_x_ = 1, cells_y_ = 1;
    // Per grain, in memory (cell) order; id_ maps a slot to the grain's id, slot_of_id_ back.
    std::vector<double> x_, y_, vx_, vy_, vpx_, vpy_, rad_, mass_, inv_mass_, dispx_, dispy_;
    std::vector<int> id_, slot_of_id_;
    std::vector<double> spare_[kMoved];
    std::vector<int> spare_id_;
    // Cells (by slot after a build) and the list: the partners of slot i are the entries
    // nb_start_[i] .. nb_start_[i+1]-1, entry k pairing nb_owner_[k] (= i) with nb_j_[k].
    std::vector<int> cell_start_, cell_of_, cell_x_, cell_y_, order_, cell_col_, cell_row_;
    // nb_mirror_[k] is the entry j -> i of entry k = i -> j.
    std::vector<int> nb_start_, nb_owner_, nb_j_, nb_mirror_;
    std::vector<double> fx_, fy_;        // force sums of the last force evaluation (cleared by drift)
    std::vector<unsigned char> near_mark_; // 1: near a wall this step, 2: and touching; else 0
    WallImpactMeter wall_meter_;
    Scratch scratch_;
    long version_ = 0;
    unsigned long pause_count_ = 0; // step() calls, for the pause point
    mutable std::pair<long, std::vector<double>> out_[8];
};

} // namespace granrepro
