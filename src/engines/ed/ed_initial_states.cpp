#include "engines/ed/ed_initial_states.hpp"

#include "core/input_error.hpp"
#include <algorithm>
#include <cmath>

namespace granrepro {

std::vector<Vec2> square_lattice_positions(std::size_t n, double lx, double ly) {
    if (n == 0 || !(lx > 0.0) || !(ly > 0.0)) throw InputError("square lattice: need n > 0 and a box");
    // Columns kx and rows ky with kx/ky ~ lx/ly and kx ky >= n.
    auto kx = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n) * lx / ly)));
    kx = std::max<std::size_t>(kx, 1);
    const std::size_t ky = (n + kx - 1) / kx;
    const double sx = lx / static_cast<double>(kx), sy = ly / static_cast<double>(ky);
    std::vector<Vec2> out;
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t ix = k % kx, iy = k / kx;
        out.push_back({(static_cast<double>(ix) + 0.5) * sx, (static_cast<double>(iy) + 0.5) * sy});
    }
    return out;
}

std::vector<Vec2> triangular_lattice_positions(std::size_t n, double x_min, double x_max, double y0,
                                               double spacing) {
    if (!(spacing > 0.0) || x_max < x_min) throw InputError("triangular lattice: bad spacing or width");
    std::vector<Vec2> out;
    out.reserve(n);
    const double dy = spacing * std::sqrt(3.0) / 2.0;
    for (std::size_t row = 0; out.size() < n; ++row) {
        const double off = (row % 2 == 1) ? 0.5 * spacing : 0.0;
        const std::size_t before = out.size();
        for (std::size_t m = 0; out.size() < n; ++m) {
            const double x = x_min + off + static_cast<double>(m) * spacing;
            if (x > x_max) break;
            out.push_back({x, y0 + static_cast<double>(row) * dy});
        }
        if (out.size() == before && row > 1) throw InputError("triangular lattice: no room in a row");
    }
    return out;
}

std::vector<Vec2> random_positions(const std::vector<double>& radius, double lx, double ly,
                                   bool periodic_x, bool periodic_y, RngStream& rng,
                                   std::size_t max_attempts) {
    const std::size_t n = radius.size();
    double amax = 0.0;
    for (double a : radius) amax = std::max(amax, a);
    // Grid of cells >= one largest diameter: candidates only need the 3x3 neighbourhood.
    const int ncx = std::max(1, static_cast<int>(lx / (2.0 * amax)));
    const int ncy = std::max(1, static_cast<int>(ly / (2.0 * amax)));
    const double cx = lx / ncx, cy = ly / ncy;
    std::vector<std::vector<int>> cells(static_cast<std::size_t>(ncx) * static_cast<std::size_t>(ncy));
    std::vector<Vec2> out(n);
    // Largest disks first: the classic way to keep polydisperse RSA from jamming early.
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });
    for (std::size_t k : order) {
        const double a = radius[k];
        bool placed = false;
        for (std::size_t attempt = 0; attempt < max_attempts && !placed; ++attempt) {
            const double px = periodic_x ? rng.uniform(0.0, lx) : rng.uniform(a, lx - a);
            const double py = periodic_y ? rng.uniform(0.0, ly) : rng.uniform(a, ly - a);
            const int ix = std::clamp(static_cast<int>(px / cx), 0, ncx - 1);
            const int iy = std::clamp(static_cast<int>(py / cy), 0, ncy - 1);
            bool ok = true;
            for (int dy = -1; dy <= 1 && ok; ++dy) {
                for (int dx = -1; dx <= 1 && ok; ++dx) {
                    int nx = ix + dx, ny = iy + dy;
                    if (nx < 0 || nx >= ncx) { if (!periodic_x) continue; nx = (nx + ncx) % ncx; }
                    if (ny < 0 || ny >= ncy) { if (!periodic_y) continue; ny = (ny + ncy) % ncy; }
                    for (int j : cells[static_cast<std::size_t>(ny * ncx + nx)]) {
                        double ddx = px - out[j].x, ddy = py - out[j].y;
                        if (periodic_x) ddx -= lx * std::round(ddx / lx);
                        if (periodic_y) ddy -= ly * std::round(ddy / ly);
                        const double s = a + radius[j];
                        if (ddx * ddx + ddy * ddy < s * s * (1.0 + 1e-12)) ok = false;
                    }
                }
            }
            if (ok) {
                out[k] = {px, py};
                cells[static_cast<std::size_t>(iy * ncx + ix)].push_back(static_cast<int>(k));
                placed = true;
            }
        }
        if (!placed) throw InputError("random_positions: could not place a disk; density too high for random "
                                      "sequential addition (use a lattice and equilibrate)");
    }
    return out;
}

void zero_momentum_and_scale(std::vector<Vec2>& vel, const std::vector<double>& mass, double vbar) {
    const std::size_t n = vel.size();
    if (n == 0 || mass.size() != n) throw InputError("velocity scaling: size mismatch");
    Vec2 p;
    double mtot = 0.0;
    for (std::size_t i = 0; i < n; ++i) { p += mass[i] * vel[i]; mtot += mass[i]; }
    const Vec2 vcm = p / mtot;
    double twice_k = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        vel[i] -= vcm;
        twice_k += mass[i] * norm2(vel[i]);
    }
    const double mbar = mtot / static_cast<double>(n);
    const double now = std::sqrt(twice_k / (static_cast<double>(n) * mbar));
    if (!(now > 0.0)) throw InputError("velocity scaling: all velocities are equal");
    for (auto& v : vel) v *= vbar / now;
}

std::vector<Vec2> maxwellian_velocities(const std::vector<double>& mass, double vbar, RngStream& rng) {
    std::vector<Vec2> v(mass.size());
    // Components ~ N(0, kT/m_i): equal temperature for every species.
    double mbar = 0.0;
    for (double m : mass) mbar += m;
    mbar /= static_cast<double>(mass.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double s = std::sqrt(mbar / mass[i]);
        v[i] = {s * rng.normal(), s * rng.normal()};
    }
    zero_momentum_and_scale(v, mass, vbar);
    return v;
}

std::vector<Vec2> uniform_velocities(std::size_t n, double v0, RngStream& rng) {
    std::vector<Vec2> v(n);
    for (auto& u : v) u = {rng.uniform(-v0, v0), rng.uniform(-v0, v0)};
    return v;
}

} // namespace granrepro
