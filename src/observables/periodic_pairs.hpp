// Every unordered pair of points in a periodic rectangular box whose minimum-image distance may be
// below r_max, found with a cell list (cells of side >= r_max: a partner within r_max sits in the
// same or an adjacent cell). O(N). The callback gets (i, j) with i < j, in the same order for the
// same positions, and decides the distance itself, so observables keep their own arithmetic.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "core/vec2.hpp"

namespace granrepro {

// Lx, Ly box sides [m]; 0 < r_max <= min(Lx, Ly)/2 (the caller checks).
template <class F>
void for_each_near_pair(double Lx, double Ly, double r_max, std::span<const Vec2> pos, F&& f) {
    const int ncx = std::max(1, static_cast<int>(std::floor(Lx / r_max)));
    const int ncy = std::max(1, static_cast<int>(std::floor(Ly / r_max)));
    const std::size_t n = pos.size();
    // Linked-list cells: head per cell, next per particle. Inserting in reverse index order makes
    // each cell's list ascend in index, which is not needed for correctness but keeps access local.
    std::vector<int> head(static_cast<std::size_t>(ncx) * static_cast<std::size_t>(ncy), -1);
    std::vector<int> next(n, -1);
    std::vector<int> cell_of(n);
    auto wrap_cell = [](double x, double L, int nc) {
        double u = x / L;
        u -= std::floor(u); // positions may lie outside [0, L): wrap periodically
        return std::min(nc - 1, static_cast<int>(u * nc));
    };
    for (std::size_t ii = n; ii-- > 0;) {
        const int c = wrap_cell(pos[ii].x, Lx, ncx) + ncx * wrap_cell(pos[ii].y, Ly, ncy);
        cell_of[ii] = c;
        next[ii] = head[static_cast<std::size_t>(c)];
        head[static_cast<std::size_t>(c)] = static_cast<int>(ii);
    }
    // With only 1 or 2 cells along an axis the offsets -1, 0, +1 alias onto the same cell; visiting
    // each distinct neighbour cell once keeps every pair visited exactly once.
    auto distinct_offsets = [](int nc) {
        std::vector<int> o;
        for (int d : {-1, 0, 1}) {
            const int m = ((d % nc) + nc) % nc;
            if (std::find(o.begin(), o.end(), m) == o.end()) o.push_back(m);
        }
        return o;
    };
    const auto ox = distinct_offsets(ncx);
    const auto oy = distinct_offsets(ncy);
    for (std::size_t i = 0; i < n; ++i) {
        const int cx = cell_of[i] % ncx;
        const int cy = cell_of[i] / ncx;
        for (int dy : oy)
            for (int dx : ox) {
                const int c = (cx + dx) % ncx + ncx * ((cy + dy) % ncy);
                for (int j = head[static_cast<std::size_t>(c)]; j >= 0; j = next[static_cast<std::size_t>(j)])
                    if (static_cast<std::size_t>(j) > i) f(i, static_cast<std::size_t>(j));
            }
    }
}

} // namespace granrepro
