#include "analysis/crack_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "analysis/disjoint_sets.hpp"

namespace granrepro {

namespace {

struct Pair {
    double gap;
    int i, j;
    bool operator<(const Pair& o) const { return std::tie(gap, i, j) < std::tie(o.gap, o.i, o.j); }
};

} // namespace

Crack find_crack(const std::vector<Vec2>& pos, const CrackSearch& s) {
    const std::size_t n = pos.size();
    if (!(s.diameter > 0) || !(s.width > 0) || !(s.max_opening > 0) || s.slice < 0)
        throw std::invalid_argument("find_crack: diameter, width and max_opening must be > 0");
    if (s.min_below == 0 || s.min_above == 0 || s.min_below + s.min_above > n)
        throw std::invalid_argument("find_crack: need 1 <= min_below, min_above and their sum <= number of disks");
    const double d = s.diameter;
    const int bottom = int(n), top = int(n) + 1;

    // Disks by height (ties by index, so the result does not depend on the sort).
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return std::tie(pos[std::size_t(a)].y, a) < std::tie(pos[std::size_t(b)].y, b);
    });
    // Neighbour pairs with a surface gap below max_opening: a sweep in height.
    std::vector<Pair> pairs;
    const double reach = d + s.max_opening;
    for (std::size_t a = 0; a < n; ++a) {
        const Vec2 pa = pos[std::size_t(order[a])];
        for (std::size_t b = a + 1; b < n; ++b) {
            const Vec2 pb = pos[std::size_t(order[b])];
            if (pb.y - pa.y >= reach) break;
            const double gap = norm(pb - pa) - d;
            if (gap < s.max_opening)
                pairs.push_back({gap, std::min(order[a], order[b]), std::max(order[a], order[b])});
        }
    }
    std::sort(pairs.begin(), pairs.end());

    auto seeded = [&] {
        DisjointSets u(n + 2);
        for (std::size_t k = 0; k < s.min_below; ++k) u.join(order[k], bottom);
        for (std::size_t k = n - s.min_above; k < n; ++k) u.join(order[k], top);
        return u;
    };
    Crack c;
    DisjointSets u = seeded();
    std::size_t used = pairs.size();
    c.wider = true;
    c.opening = s.max_opening;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        u.join(pairs[k].i, pairs[k].j);
        if (u.find(bottom) == u.find(top)) {
            c.wider = false;
            c.opening = std::max(0.0, pairs[k].gap);
            c.narrow_i = pairs[k].i;
            c.narrow_j = pairs[k].j;
            used = k;
            break;
        }
    }
    // The parts just below the opening: every pair narrower than the narrowest place joined.
    DisjointSets parts = seeded();
    for (std::size_t k = 0; k < used; ++k) parts.join(pairs[k].i, pairs[k].j);
    c.side.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const int r = parts.find(int(i));
        c.side[i] = r == parts.find(bottom) ? -1 : r == parts.find(top) ? +1 : 0;
    }

    // Course: midway between the bottom part's highest disk and the top part's lowest one above it.
    const std::size_t m = std::max<std::size_t>(1, std::size_t(std::lround(s.width / (s.slice > 0 ? s.slice : d))));
    const double sw = s.width / double(m);
    std::vector<std::size_t> k(n); // each disk's slice
    for (std::size_t i = 0; i < n; ++i) k[i] = std::min(m - 1, std::size_t(std::max(0.0, std::floor(pos[i].x / sw))));
    std::vector<double> lo(m, -INFINITY), hi(m, INFINITY);
    for (std::size_t i = 0; i < n; ++i)
        if (c.side[i] == -1) lo[k[i]] = std::max(lo[k[i]], pos[i].y);
    for (std::size_t i = 0; i < n; ++i)
        if (c.side[i] == +1 && pos[i].y > lo[k[i]]) hi[k[i]] = std::min(hi[k[i]], pos[i].y);
    c.y_mean = 0;
    c.y_low = INFINITY;
    c.y_high = -INFINITY;
    c.x_low = NAN;
    std::size_t defined = 0;
    for (std::size_t k = 0; k < m; ++k) {
        c.course_x.push_back((double(k) + 0.5) * sw);
        const bool ok = std::isfinite(lo[k]) && std::isfinite(hi[k]);
        const double y = ok ? 0.5 * (lo[k] + hi[k]) : NAN;
        c.course_y.push_back(y);
        if (!ok) continue;
        ++defined;
        c.y_mean += y;
        if (y < c.y_low) { c.y_low = y; c.x_low = c.course_x.back(); }
        c.y_high = std::max(c.y_high, y);
    }
    if (defined == 0) c.y_mean = c.y_low = c.y_high = NAN;
    else c.y_mean /= double(defined);
    c.y_left = c.course_y.front();
    c.y_right = c.course_y.back();
    return c;
}

} // namespace granrepro
