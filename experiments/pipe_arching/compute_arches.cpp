// pipe-arching: what one fall shows (Sec. 5, Fig. 13): the first arch, its initiating disk, what follows, its plug, the cracks.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "analysis/arch_waves.hpp"
#include "experiments/pipe_arching/spec.hpp"

namespace granrepro::experiments::pipe_arching_detail {

namespace {
long count_hot(const std::vector<int>& disks, const std::vector<int>& hot) {
    return long(std::count_if(disks.begin(), disks.end(), [&](int j) { return std::binary_search(hot.begin(), hot.end(), j); }));
}
} // namespace

// The first arch (frame fa) and its initiating disk, which the function returns (-1 if none):
// the earliest hot wall disk within precursor_window before the arch that started within
// precursor_band of the arch's initial height (the black bar, Fig. 13).
int first_arch(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const ArchFound& a = fl.at(fa).arch;
    out.t_arch = s.t(fa); out.y_arch = a.y; out.y0_arch = a.y0;
    out.arch_size = a.size; out.arch_pL = a.pL; out.arch_pR = a.pR;
    int i_prec = -1;
    long f_prec = -1;
    for (long k = std::max(s.detect_from, fa - s.frames(s.precursor_window)); k <= fa && i_prec < 0; ++k)
        for (int i : fl.at(k).hot_wall)
            if (std::abs(fl.y0[std::size_t(i)] - a.y0) <= s.precursor_band) {
                f_prec = k;
                i_prec = i;
                out.t_precursor = s.t(k);
                break;
            }
    if (i_prec < 0) return i_prec;
    // Its neighbours react (Sec. 5: "already 0.004 s later"): the first frame from the
    // precursor's on in which at least half of the disks that were its neighbours (within
    // `link` at t = 0) are hot.
    const double link2 = std::pow(s.link * s.d, 2);
    std::vector<int> nb;
    for (std::size_t j = 0; j < fl.pos0.size(); ++j)
        if (int(j) != i_prec && norm2(fl.pos0[j] - fl.pos0[std::size_t(i_prec)]) <= link2) nb.push_back(int(j));
    for (long k = f_prec; k <= s.n_frames && !nb.empty(); ++k)
        if (2 * count_hot(nb, fl.at(k).hot) >= long(nb.size())) {
            out.react_lag = s.t(k) - out.t_precursor;
            break;
        }
    return i_prec;
}

// What follows the first arch (Sec. 5): "0.004 s later this region ... has almost disappeared"
// (the share of its disks still hot 4 ms after it spanned the width) and "new arches above and
// below the original one appeared".
void arch_aftermath(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const ArchFound& a = fl.at(fa).arch;
    const long f4 = fa + s.frames(0.004);
    if (f4 > s.n_frames) return;
    out.arch_left_4ms = double(count_hot(a.members, fl.at(f4).hot)) / double(a.members.size());
    out.arch_above_later = out.arch_below_later = 0;
    for (long k = f4; k <= s.n_frames; ++k) {
        const ArchFound& b = fl.at(k).arch;
        if (!b.found) continue;
        if (b.y0 > a.y0 + s.arch_separation) out.arch_above_later = 1;
        if (b.y0 < a.y0 - s.arch_separation) out.arch_below_later = 1;
    }
    // Successive arches as momentum waves (src/analysis/arch_waves.hpp): do they rise, is a later one stronger.
    std::vector<ArchSighting> seen;
    for (long k = fa; k <= s.n_frames; ++k) {
        const ArchFound& b = fl.at(k).arch;
        seen.push_back({b.found, b.y0, double(b.members.size())});
    }
    const ArchWaves w = follow_arch_waves(seen, std::size_t(f4 - fa), s.arch_separation);
    out.wave_steps = w.steps;
    out.wave_steps_up = w.steps_up;
    out.wave_stronger = w.stronger() ? 1 : 0;
}

// The first arch's plug and the material below it, as Lagrangian bands (initial heights): how
// much of the plug's weight the walls carry around the arch, how much slower the plug falls than
// the material below, and how far the two move apart (an opening crack), all over
// [t_arch - arch_window, t_arch + arch_window] and relative to its start. Disks at the walls slow
// down (Sec. 5): in the plug, v_y at the walls minus v_y inside (> 0: the wall disks fall
// slower), at the arch and at the window's start.
void plug_motion(SeedRun& out, const Pipe& s, const Fall& fl, long fa) {
    const double y0 = fl.at(fa).arch.y0, hp = s.plug_half_height, depth = s.below_depth;
    const long w = s.frames(s.arch_window);
    const long f0 = std::max(1L, fa - w), f1 = std::min(s.n_frames, fa + w);
    auto plug = [&](long f) { return fl.bands.group(std::size_t(f - 1), y0 - hp, y0 + hp); };
    auto below = [&](long f) { return fl.bands.group(std::size_t(f - 1), y0 - hp - depth, y0 - hp); };
    const double dv0 = plug(f0).vy - below(f0).vy, dy0 = plug(f0).y - below(f0).y;
    double jp = 0, jn = 0, brake = -INFINITY, open = -INFINITY;
    for (long f = f0; f <= f1; ++f) {
        const auto P = plug(f), B = below(f);
        if (std::abs(f - fa) <= s.frames(0.004)) { jp += P.jy; jn += 1; }
        brake = std::max(brake, P.vy - B.vy - dv0);
        open = std::max(open, (P.y - B.y - dy0) / s.d);
    }
    const auto P = plug(fa);
    out.plug_wall_load = jp / (P.n * s.mass * s.g * jn * s.frame_dt);
    out.arch_brake = brake;
    out.opening_below = open;
    out.wall_slowdown_arch = P.vy_wall - P.vy_inner;
    out.wall_slowdown_before = plug(f0).vy_wall - plug(f0).vy_inner;
}

// Sec. 5, Fig. 13: "for t >= 0.060 s at the position of the initiating particle (at the black
// bar) a crack is visible" (issue 43 §1): the local opening beside the initiating disk i, in the
// strip of its own width at its wall, x in [x_i - d/2, x_i + d/2] clipped at the wall. Every disk
// reaching into the strip blocks [y - h, y + h], h its half chord inside the strip (d/2 when its
// centre is inside); the opening is the longest height interval no disk blocks, from i's centre
// down below_depth d and never below the crack_min_particles-th lowest disk (the spray at the
// bottom, which the wall-to-wall detector ignores too). The intact lattice gives 0. In d; NaN if
// the window is empty. The same measure as scripts/studies/pipe_arching_crack.py (own strip).
double local_opening(const std::vector<Vec2>& pos, int i, const Pipe& s, double x_right) {
    const double d = s.d, r = 0.5 * d;
    const bool right = pos[std::size_t(i)].x > 0.5 * x_right; // mirror: i's wall at x = 0
    auto xm = [&](const Vec2& p) { return right ? x_right - p.x : p.x; };
    const double xi = xm(pos[std::size_t(i)]), yi = pos[std::size_t(i)].y;
    const double a = std::max(0.0, xi - r), b = xi + r;
    std::vector<double> ys(pos.size());
    std::transform(pos.begin(), pos.end(), ys.begin(), [](const Vec2& p) { return p.y; });
    const std::size_t nmin = std::size_t(std::clamp(s.crack_min_particles, 1L, long(ys.size())));
    std::nth_element(ys.begin(), ys.begin() + long(nmin - 1), ys.end());
    const double top = yi, bot = std::max(yi - s.below_depth * d, ys[nmin - 1]);
    if (top <= bot) return NAN;
    std::vector<std::pair<double, double>> iv; // blocked [lo, hi]
    for (const Vec2& p : pos) {
        const double x = xm(p), dx = x < a ? a - x : (x > b ? x - b : 0.0);
        if (dx >= r) continue;
        const double h = std::sqrt(std::max(0.0, r * r - dx * dx));
        iv.emplace_back(p.y - h, p.y + h);
    }
    std::sort(iv.begin(), iv.end());
    double best = 0, cover = bot; // sweep upward: cover = the highest blocked height so far
    for (const auto& [lo, hi] : iv) {
        if (hi <= bot) continue;
        if (lo >= top) break;
        if (lo > cover) best = std::max(best, std::min(lo, top) - cover);
        cover = std::max(cover, hi);
        if (cover >= top) break;
    }
    if (cover < top) best = std::max(best, top - cover);
    return best / d;
}

// The local opening at the initiating disk i_prec (local_opening) from its first hot frame on:
// the first time it reaches crack_opening, and its largest value within arch_window after the arch.
void local_crack(SeedRun& out, const Pipe& s, const Fall& fl, long fa, int i_prec) {
    if (fa < 0 || i_prec < 0 || std::isnan(out.t_precursor)) return;
    const double x_right = s.L + (out.wall_left + out.wall_right) * s.d;
    double omax = -INFINITY;
    for (long f = std::max(s.detect_from, frame_of(out.t_precursor, s.frame_dt)); f <= s.n_frames; ++f) {
        const double o = local_opening(fl.at(f).pos, i_prec, s, x_right);
        if (std::isnan(o)) continue;
        if (o >= s.crack_opening && std::isnan(out.t_local_crack)) out.t_local_crack = s.t(f);
        if (f >= fa && f <= fa + s.frames(s.arch_window)) omax = std::max(omax, o);
    }
    out.local_opening_after = std::isfinite(omax) ? omax : NAN;
}

// Cracks: the first frame with an opening >= crack_opening and how it relates to the first arch
// (frame fa, -1 if none) and its initiating disk i_prec; the widest openings before the arch,
// within arch_window after it, and at any frame.
void cracks(SeedRun& out, const Pipe& s, const Fall& fl, long fa, int i_prec) {
    const double d = s.d;
    double omax_before = -INFINITY, omax_after = -INFINITY, omax_all = -INFINITY;
    for (long f = s.detect_from; f <= s.n_frames; ++f) {
        const Crack& k = fl.at(f).crack;
        const double o = k.opening / d;
        omax_all = std::max(omax_all, o);
        if (fa < 0 || f < fa) omax_before = std::max(omax_before, o);
        else if (f <= fa + s.frames(s.arch_window)) omax_after = std::max(omax_after, o);
        if (k.opening >= s.crack_opening * d && std::isnan(out.t_crack)) {
            out.t_crack = s.t(f);
            out.crack_opening = o;
            out.y_crack = (k.y_mean - s.y_floor) / d;
            if (k.narrow_i >= 0) out.y0_crack = 0.5 * (fl.y0[std::size_t(k.narrow_i)] + fl.y0[std::size_t(k.narrow_j)]);
            if (fa >= 0) out.crack_below_arch = out.y0_arch - out.y0_crack;
            if (i_prec >= 0) {
                // The course at the initiating disk's wall against the disk's height then.
                const Vec2 rp = fl.at(f).pos[std::size_t(i_prec)];
                const double yc = rp.x < 0.5 * s.L ? k.y_left : k.y_right;
                out.crack_at_initiator = (yc - rp.y) / d;
            }
        }
    }
    auto finite = [](double x) { return std::isfinite(x) ? x : NAN; };
    out.opening_max_before = finite(omax_before); out.opening_max_after = finite(omax_after); out.opening_max_all = finite(omax_all);
}

} // namespace granrepro::experiments::pipe_arching_detail
