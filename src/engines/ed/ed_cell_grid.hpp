// Linked cells of the ED engine. The box [0,lx) x [0,ly) is tiled by cells at least one largest
// diameter wide, so a disk can only touch disks in its own and the 8 surrounding cells.
// Periodic axes wrap (>= 3 cells needed for the minimum image); walled axes have edge cells that
// extend to +-infinity, so disks may leave the box (a pipe whose bottom was removed).
// Lists change only at cell-crossing events, so they are exact at every event time.
#pragma once
#include "core/input_error.hpp"
#include "core/vec2.hpp"
#include "engines/ed/ed_particles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace granrepro {

class EdCellGrid {
public:
    template <class Config> // a BasicEdConfig
    void setup(const Config& cfg, double max_rad) {
        if (!(cfg.lx > 0.0) || !(cfg.ly > 0.0)) throw InputError("ED: box sizes must be > 0");
        if (!(cfg.cell_size_factor >= 1.0)) throw InputError("ED: cell_size_factor must be >= 1");
        nx_ = cells_along(cfg.lx, max_rad, cfg.cell_size_factor);
        ny_ = cells_along(cfg.ly, max_rad, cfg.cell_size_factor);
        if ((cfg.periodic_x && nx_ < 3) || (cfg.periodic_y && ny_ < 3))
            throw InputError("ED: a periodic box must be at least 3 cell widths (> 3 diameters) wide");
        px_ = cfg.periodic_x; py_ = cfg.periodic_y; lx_ = cfg.lx; ly_ = cfg.ly;
        sx_ = lx_ / nx_; sy_ = ly_ / ny_; hx_ = 0.5 * lx_; hy_ = 0.5 * ly_;
    }
    // Cells along a box side l for disks up to max_rad; public so that a driver's validate() can
    // refuse a box too small for the minimum image (< 3 cells) before the run, by the same count.
    static int cells_along(double l, double max_rad, double cell_size_factor) {
        // A margin above the largest diameter keeps round-off excursions of a disk out of its
        // cell from hiding a contact across two cells.
        const double cmin = 2.0 * max_rad * cell_size_factor * (1.0 + 1e-9);
        return static_cast<int>(std::clamp(std::floor(l / cmin), 1.0, 1e9)); // 1e9: no overflow in the cast
    }
    int cells_x() const { return nx_; }
    int cells_y() const { return ny_; }
    std::size_t cells() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }

    // Minimum image of a separation on the periodic axes (|d| < l/2 + one cell, so once suffices).
    void min_image(double& dx, double& dy) const {
        if (px_) { if (dx > hx_) dx -= lx_; else if (dx < -hx_) dx += lx_; }
        if (py_) { if (dy > hy_) dy -= ly_; else if (dy < -hy_) dy += ly_; }
    }
    Vec2 wrap(Vec2 r) const {
        if (px_) r.x = wrap(r.x, lx_);
        if (py_) r.y = wrap(r.y, ly_);
        return r;
    }
    static double wrap(double v, double l) {
        v = std::fmod(v, l);
        if (v < 0.0) v += l;
        return v >= l ? 0.0 : v;
    }

    void build(EdParticles& ps) {
        head_.assign(cells(), -1);
        for (std::size_t i = 0; i < ps.size(); ++i) {
            const int cx = std::clamp(static_cast<int>(std::floor(ps.p[i].x / sx_)), 0, nx_ - 1);
            const int cy = std::clamp(static_cast<int>(std::floor(ps.p[i].y / sy_)), 0, ny_ - 1);
            link(ps, static_cast<int>(i), cy * nx_ + cx);
        }
    }
    // Moves i (advanced to its crossing time) into the cell beyond the face e[i].arg (0 -x, 1 +x,
    // 2 -y, 3 +y). Leaving a periodic box shifts i by one box length, so that its coordinates
    // stay inside [0, l) and the cell bounds stay monotone.
    void cross(EdParticles& ps, int i) {
        unlink(ps, i);
        int cx = ps.e[i].cell % nx_, cy = ps.e[i].cell / nx_;
        switch (ps.e[i].arg) {
        case 0: if (--cx < 0) { cx += nx_; ps.p[i].x += lx_; } break;
        case 1: if (++cx == nx_) { cx = 0; ps.p[i].x -= lx_; } break;
        case 2: if (--cy < 0) { cy += ny_; ps.p[i].y += ly_; } break;
        default: if (++cy == ny_) { cy = 0; ps.p[i].y -= ly_; } break;
        }
        link(ps, i, cy * nx_ + cx);
    }

    int head(int c) const { return head_[c]; }
    // f(cell) for the up to 9 cells around c (deduplicated: walled axes clip).
    template <class F>
    void for_neighbours(int c, F&& f) const { for_block<-1, 1, -1, 1>(c, f); }
    // f(cell) for the cells that became adjacent when a disk entered c across face dir: only
    // those can hold a partner that the disk's stored best pair collision has not seen.
    template <class F>
    void for_entered(int c, int dir, F&& f) const {
        switch (dir) {
        case 0: for_block<-1, -1, -1, 1>(c, f); break;
        case 1: for_block<1, 1, -1, 1>(c, f); break;
        case 2: for_block<-1, 1, -1, -1>(c, f); break;
        default: for_block<-1, 1, 1, 1>(c, f); break;
        }
    }
    // f(dir, axis, coordinate) for the faces of c a disk can leave through, in the order -x, +x,
    // -y, +y; the outer faces of walled edge cells do not exist.
    template <class F>
    void for_faces(int c, F&& f) const {
        const int cx = c % nx_, cy = c / nx_;
        if (px_ || cx > 0) f(0, 0, cx * sx_);
        if (px_ || cx < nx_ - 1) f(1, 0, cx + 1 == nx_ ? lx_ : (cx + 1) * sx_);
        if (py_ || cy > 0) f(2, 1, cy * sy_);
        if (py_ || cy < ny_ - 1) f(3, 1, cy + 1 == ny_ ? ly_ : (cy + 1) * sy_);
    }
    // How far [m] r lies outside cell c (<= 0 inside).
    double excursion(int c, Vec2 r) const {
        const int cx = c % nx_, cy = c / nx_;
        const double inf = EdParticles::kInf;
        const double lox = (cx == 0 && !px_) ? -inf : cx * sx_, hix = (cx == nx_ - 1 && !px_) ? inf : (cx + 1) * sx_;
        const double loy = (cy == 0 && !py_) ? -inf : cy * sy_, hiy = (cy == ny_ - 1 && !py_) ? inf : (cy + 1) * sy_;
        return std::max({lox - r.x, r.x - hix, loy - r.y, r.y - hiy});
    }

    std::size_t memory_bytes() const { return head_.capacity() * sizeof(std::int32_t); }
    template <class State> // a BasicEdState
    void save(State& s) const { s.cell_head.assign(head_.begin(), head_.end()); }
    template <class State>
    void restore(const State& s) {
        if (s.cell_head.size() != cells()) throw InputError("ED: EdState cell grid does not match its configuration");
        head_.assign(s.cell_head.begin(), s.cell_head.end());
    }

private:
    // f(cell) for the cells (cx + dx, cy + dy), dx in [X0, X1], dy in [Y0, Y1], row by row.
    template <int X0, int X1, int Y0, int Y1, class F>
    void for_block(int c, F& f) const {
        const int cx = c % nx_, cy = c / nx_;
        for (int dy = Y0; dy <= Y1; ++dy) {
            int y = cy + dy;
            if (y < 0 || y >= ny_) {
                if (!py_) continue;
                y = y < 0 ? y + ny_ : y - ny_;
            }
            for (int dx = X0; dx <= X1; ++dx) {
                int x = cx + dx;
                if (x < 0 || x >= nx_) {
                    if (!px_) continue;
                    x = x < 0 ? x + nx_ : x - nx_;
                }
                f(y * nx_ + x);
            }
        }
    }
    void link(EdParticles& ps, int i, int c) {
        ps.e[i].cell = c;
        ps.e[i].prev = -1;
        ps.p[i].next = head_[c];
        if (head_[c] >= 0) ps.e[head_[c]].prev = i;
        head_[c] = i;
    }
    void unlink(EdParticles& ps, int i) {
        const int c = ps.e[i].cell;
        if (ps.e[i].prev >= 0) ps.p[ps.e[i].prev].next = ps.p[i].next; else head_[c] = ps.p[i].next;
        if (ps.p[i].next >= 0) ps.e[ps.p[i].next].prev = ps.e[i].prev;
    }

    int nx_ = 1, ny_ = 1;
    bool px_ = true, py_ = true;
    double lx_ = 1.0, ly_ = 1.0, sx_ = 1.0, sy_ = 1.0, hx_ = 0.5, hy_ = 0.5;
    HugeVector<std::int32_t> head_;
};

} // namespace granrepro
