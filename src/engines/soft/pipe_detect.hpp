// The contact test of the pipe engine (pipe_engine.hpp): for each listed pair (slots i, j), does
// it touch, !(d^2 >= (r_i + r_j)^2) with the periodic minimum image along y? A touching pair
// yields its list entries k and mirror.
//
// One pair at a time. (Four pairs per AVX2 instruction, with gathered positions and the minimum
// image by bit masks, took 40 % fewer instructions but 10 % more time: the gathers of six
// scattered doubles per pair cost more than the scalar loads.)
#pragma once
#include <cstddef>

namespace granrepro::pipe_detail {

// The pairs to test, as parallel arrays.
struct PairList {
    const int *i, *j, *k, *mirror;
    std::size_t n;
};

struct GrainArrays {
    const double *x, *y, *r;
    double len; // periodic length [m]
};

// Writes the entries of the pairs in contact to hits (room for 2 n); returns their number.
inline std::size_t detect(const PairList& pl, const GrainArrays& g, int* hits) {
    const double half = 0.5 * g.len;
    std::size_t nh = 0;
    for (std::size_t p = 0; p < pl.n; ++p) {
        const std::size_t i = std::size_t(pl.i[p]), j = std::size_t(pl.j[p]);
        const double dx = g.x[i] - g.x[j];
        double dy = g.y[i] - g.y[j];
        dy = dy > half ? dy - g.len : (dy < -half ? dy + g.len : dy);
        const double rs = g.r[i] + g.r[j];
        if (!(dx * dx + dy * dy >= rs * rs)) {
            hits[nh++] = pl.k[p];
            hits[nh++] = pl.mirror[p];
        }
    }
    return nh;
}

} // namespace granrepro::pipe_detail
