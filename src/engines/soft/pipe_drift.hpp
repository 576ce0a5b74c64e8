// The drift pass of the pipe engine (pipe_engine.hpp) over a range of grains, several grains per
// instruction: accelerations from the last force sums (which it clears), the last step's closing
// half kick (if pending), this step's half kick, drift, periodic wrap, predicted velocity, and
// partial sums for the neighbour-list rebuild test.
//
// Every grain sees the same IEEE operations in the same order whatever the lane width (one
// grain, two in SSE2, four in AVX2: add, multiply and bit masks, no fused multiply-add), so the
// results are bit-identical; only the partial sums (used for bounds, not for physics) are
// gathered in a different order. AVX2 is used when the processor has it (checked at run time;
// the build itself targets baseline x86-64).
#pragma once
#include <cstddef>
#include <cstring>

namespace granrepro::pipe_detail {

struct DriftArrays {
    double *x, *y, *vx, *vy, *vpx, *vpy, *ux, *uy, *fx, *fy;
    const double* inv_mass;
    double h, dt, len, g;  // half step, step [s], periodic length [m], gravity [m/s^2]
    double hp;             // half of the last step, whose closing kick is pending [s] (h unless dt changed)
    double cpx, cpy;       // reference displacement of the rebuild test [m]
};

struct DriftSums {
    double sx = 0, sy = 0; // sums of the displacements since the last build
    double qmax = 0;       // max |u - (cpx, cpy)|^2
};

template <class V>
[[gnu::always_inline]] inline void lanes_load(V& v, const double* p) {
    std::memcpy(&v, p, sizeof v);
}
template <class V>
[[gnu::always_inline]] inline void lanes_store(double* p, const V& v) {
    std::memcpy(p, &v, sizeof v);
}
// v where m holds, else +0 (a bit mask in lanes, a branch for one grain).
[[gnu::always_inline]] inline void lanes_masked(double& out, bool m, const double& v) { out = m ? v : 0.0; }
template <class V, class M>
[[gnu::always_inline]] inline void lanes_masked(V& out, const M& m, const V& v) {
    out = V(M(v) & m);
}

// The broadcast constants of one pass (computed once: the arrays could alias DriftArrays' own
// fields, so reading those inside the loop would reload them at every group).
template <class V>
struct DriftConsts {
    V zero, h, hp, dt, len, neg_len, g, cpx, cpy;
    explicit DriftConsts(const DriftArrays& a)
        : zero{}, h(zero + a.h), hp(zero + a.hp), dt(zero + a.dt), len(zero + a.len), neg_len(zero - a.len), g(zero + a.g),
          cpx(zero + a.cpx), cpy(zero + a.cpy) {}
};

template <bool Pending, class V>
[[gnu::always_inline]] inline void drift_lanes(const DriftArrays& a, const DriftConsts<V>& c, std::size_t i, V& sx,
                                               V& sy, V& qmax) {
    V im, fx, fy, vx, vy, x, y, ux, uy;
    lanes_load(im, a.inv_mass + i);
    lanes_load(fx, a.fx + i);
    lanes_load(fy, a.fy + i);
    lanes_store(a.fx + i, c.zero);
    lanes_store(a.fy + i, c.zero);
    const V ax = fx * im, ay = fy * im - c.g;
    lanes_load(vx, a.vx + i);
    lanes_load(vy, a.vy + i);
    if constexpr (Pending) {
        vx = vx + c.hp * ax;
        vy = vy + c.hp * ay;
    }
    vx = vx + c.h * ax;
    vy = vy + c.h * ay;
    lanes_store(a.vx + i, vx);
    lanes_store(a.vy + i, vy);
    const V dx = c.dt * vx, dy = c.dt * vy;
    lanes_load(x, a.x + i);
    lanes_load(y, a.y + i);
    lanes_store(a.x + i, x + dx);
    y = y + dy;
    // periodic wrap: y + len if y < 0, y - len if y >= len (and x - 0 = x, also for x = -0)
    V above, below;
    lanes_masked(above, y >= c.len, c.len);
    lanes_masked(below, y < c.zero, c.neg_len);
    y = (y - above) - below;
    lanes_store(a.y + i, y);
    lanes_load(ux, a.ux + i);
    lanes_load(uy, a.uy + i);
    ux = ux + dx;
    uy = uy + dy;
    lanes_store(a.ux + i, ux);
    lanes_store(a.uy + i, uy);
    lanes_store(a.vpx + i, vx + c.h * ax);
    lanes_store(a.vpy + i, vy + c.h * ay);
    sx = sx + ux;
    sy = sy + uy;
    const V qx = ux - c.cpx, qy = uy - c.cpy;
    const V q = qx * qx + qy * qy;
    qmax = q > qmax ? q : qmax;
}

// Grains i, i + W, ... while a whole group of W = sizeof(V) / 8 fits before e; returns where it
// stopped.
template <bool Pending, class V>
[[gnu::always_inline]] inline std::size_t drift_run(const DriftArrays& in, std::size_t i, std::size_t e,
                                                    DriftSums& out) {
    constexpr std::size_t w = sizeof(V) / sizeof(double);
    const DriftArrays a = in; // a local copy: no store can alias it
    const DriftConsts<V> c(a);
    V sx{}, sy{}, qmax{};
    for (; i + w <= e; i += w) drift_lanes<Pending, V>(a, c, i, sx, sy, qmax);
    double lx[w], ly[w], lq[w];
    std::memcpy(lx, &sx, sizeof sx);
    std::memcpy(ly, &sy, sizeof sy);
    std::memcpy(lq, &qmax, sizeof qmax);
    for (std::size_t k = 0; k < w; ++k) {
        out.sx += lx[k];
        out.sy += ly[k];
        out.qmax = lq[k] > out.qmax ? lq[k] : out.qmax;
    }
    return i;
}

#if defined(__GNUC__) && defined(__x86_64__)
// Whether drift() uses AVX2: by default when the processor has it; tests switch it off to check
// that the lanes give the same bits.
inline bool& use_avx2() {
    static bool on = __builtin_cpu_supports("avx2");
    return on;
}
template <bool Pending>
__attribute__((target("avx2"))) std::size_t drift_avx2(const DriftArrays& a, std::size_t i, std::size_t e,
                                                       DriftSums& out) {
    using v4d = double __attribute__((vector_size(32)));
    return drift_run<Pending, v4d>(a, i, e, out);
}
#endif

template <bool Pending>
DriftSums drift(const DriftArrays& a, std::size_t i, std::size_t e) {
    using v2d = double __attribute__((vector_size(16)));
    DriftSums out;
#if defined(__GNUC__) && defined(__x86_64__)
    if (use_avx2()) i = drift_avx2<Pending>(a, i, e, out);
#endif
    i = drift_run<Pending, v2d>(a, i, e, out);
    drift_run<Pending, double>(a, i, e, out);
    return out;
}

} // namespace granrepro::pipe_detail
