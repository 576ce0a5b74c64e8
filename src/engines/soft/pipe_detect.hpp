// The contact test of the pipe engine (pipe_engine.hpp): for each listed pair (slots i, j), does
// it touch, !(d^2 >= (r_i + r_j)^2) with the periodic minimum image along y? A touching pair
// sets the flags of its two list entries (k and mirror); the caller has cleared the flags.
//
// The same IEEE operations per pair whether four pairs share an AVX2 instruction (gathered
// positions, bit-mask selects for the minimum image, no fused multiply-add) or one is tested
// alone, so the decisions are the same; AVX2 is used when use_avx2() (pipe_drift.hpp).
#pragma once
#include <cstddef>

#include "engines/soft/pipe_drift.hpp"

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

namespace granrepro::pipe_detail {

// The pairs one thread tests, as parallel arrays.
struct PairList {
    const int *i, *j, *k, *mirror;
    std::size_t n;
};

struct GrainArrays {
    const double *x, *y, *r;
    double len; // periodic length [m]
};

// Tests pairs from `p` on, one at a time.
inline void detect_scalar(const PairList& pl, const GrainArrays& g, std::size_t p, unsigned char* flag) {
    const double half = 0.5 * g.len;
    for (; p < pl.n; ++p) {
        const std::size_t i = std::size_t(pl.i[p]), j = std::size_t(pl.j[p]);
        const double dx = g.x[i] - g.x[j];
        double dy = g.y[i] - g.y[j];
        dy = dy > half ? dy - g.len : (dy < -half ? dy + g.len : dy);
        const double rs = g.r[i] + g.r[j];
        if (!(dx * dx + dy * dy >= rs * rs)) flag[pl.k[p]] = flag[pl.mirror[p]] = 1;
    }
}

#if defined(__GNUC__) && defined(__x86_64__)
// Four doubles base[index[0..3]]. The masked gather with a zero source is the plain gather; GCC
// 12 warns about the plain intrinsic's undefined source (-Wmaybe-uninitialized, avx2intrin.h).
__attribute__((target("avx2"), always_inline)) inline __m256d gather(const double* base, __m128i index) {
    return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), base, index,
                                    _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
}

// Tests groups of four pairs; returns where it stopped. The minimum image as masks:
// dy - (dy > half ? len : 0) - (dy < -half ? -len : 0) equals the scalar select bit for bit
// (x - 0 = x, and x - (-len) = x + len).
__attribute__((target("avx2"))) inline std::size_t detect_avx2(const PairList& pl, const GrainArrays& g,
                                                              unsigned char* flag) {
    const __m256d half = _mm256_set1_pd(0.5 * g.len), neg_half = _mm256_set1_pd(-(0.5 * g.len));
    const __m256d len = _mm256_set1_pd(g.len), neg_len = _mm256_set1_pd(-g.len);
    const double *x = g.x, *y = g.y, *r = g.r;
    std::size_t p = 0;
    for (; p + 4 <= pl.n; p += 4) {
        const __m128i vi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pl.i + p));
        const __m128i vj = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pl.j + p));
        const __m256d dx = _mm256_sub_pd(gather(x, vi), gather(x, vj));
        __m256d dy = _mm256_sub_pd(gather(y, vi), gather(y, vj));
        const __m256d above = _mm256_and_pd(_mm256_cmp_pd(dy, half, _CMP_GT_OQ), len);
        const __m256d below = _mm256_and_pd(_mm256_cmp_pd(dy, neg_half, _CMP_LT_OQ), neg_len);
        dy = _mm256_sub_pd(_mm256_sub_pd(dy, above), below);
        const __m256d rs = _mm256_add_pd(gather(r, vi), gather(r, vj));
        const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
        const int touch = _mm256_movemask_pd(_mm256_cmp_pd(d2, _mm256_mul_pd(rs, rs), _CMP_NGE_UQ));
        if (touch)
            for (std::size_t l = 0; l < 4; ++l)
                if (touch >> l & 1) flag[pl.k[p + l]] = flag[pl.mirror[p + l]] = 1;
    }
    return p;
}
#endif

inline void detect(const PairList& pl, const GrainArrays& g, unsigned char* flag) {
    std::size_t p = 0;
#if defined(__GNUC__) && defined(__x86_64__)
    if (use_avx2()) p = detect_avx2(pl, g, flag);
#endif
    detect_scalar(pl, g, p, flag);
}

} // namespace granrepro::pipe_detail
