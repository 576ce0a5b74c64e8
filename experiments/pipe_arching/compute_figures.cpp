// pipe-arching: one run's fits of Eqs. (21), (22) to P(N_c) (Fig. 14), and run 0's tables (relaxation, Figs. 13 and 14).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "experiments/pipe_arching/spec.hpp"
#include "observables/collision_rate_fit.hpp"

namespace granrepro::experiments::pipe_arching_detail {

namespace {

// A converged fit, or none (too few counts, or no convergence).
std::optional<CollisionRateFit> try_fit(const RateHistogram& h, CollisionRateFit::Model m, double lo, double hi) {
    try {
        if (const CollisionRateFit f = CollisionRateFit::fit(h, m, lo, hi); f.converged) return f;
    } catch (const std::invalid_argument&) {
    }
    return std::nullopt;
}

// A Fig. 13 snapshot (run 0): the disks, the frame's arch and the crack.
void add_snapshot(std::vector<FigureTable>& F, const Pipe& s, const Frame& fr) {
    const double d = s.d;
    const auto &arch = fr.arch.members, &side = fr.crack.side;
    const std::vector<long> disks = index_order(fr.pos.size());
    FigureTable& t = F.emplace_back(FigureTable{fill_pattern(out_snapshot.pattern, {}, {ttext(fr.t)}), out_snapshot.description});
    t.add("x", "d", column(fr.pos, [&](const Vec2& r) { return r.x / d; }));
    t.add("y", "d", column(fr.pos, [&](const Vec2& r) { return (r.y - s.y_floor) / d; }));
    t.add("Nc", "1/s", fr.rate);
    t.add("arch", "1", column(disks, [&](long i) { return std::ranges::find(arch, int(i)) != arch.end() ? 1 : 0; }));
    t.add("crack_side", "1", column(disks, [&](long i) { return side.empty() ? 0 : side[std::size_t(i)]; }));
    FigureTable& c = F.emplace_back(FigureTable{fill_pattern(out_crack.pattern, {}, {ttext(fr.t)}), out_crack.description});
    c.add("x", "d", column(fr.crack.course_x, [&](double x) { return x / d; }));
    c.add("y", "d", column(fr.crack.course_y, [&](double y) { return (y - s.y_floor) / d; }));
}

} // namespace

// Fits of Eqs. (21), (22) to P(N_c) pooled over the Fig. 14 times that lie, in this run, before
// the first arch (panel a: "before the first arch (or crack) occurs") or after it (panel b: "when
// cracks and arches exist"); a run without an arch has no panel (b). Then the same fits at each
// time alone (Fig. 14 draws four times per panel); returns the histograms of those times.
std::vector<RateHistogram> fit_fig14(SeedRun& out, const PipeArchingSpec& s, const Fall& fl) {
    const double ddt = s.dist_dt, rmin = 1.0 / ddt; // one collision per window
    const std::size_t n_before = s.dist_times_before.size();
    auto hist_lin = [&](const std::vector<double>& rs) { return RateHistogram::per_count(rs, ddt, 200); };
    auto hist_log = [&](const std::vector<double>& rs) {
        return RateHistogram::make(rs, ddt, RateHistogram::Binning::Log, 30, 0.5 * rmin, 1.0e6);
    };
    const double hi_lin = (200 + 0.5) / ddt;
    std::vector<double> before, after;
    out.times_before = out.times_after = 0;
    for (std::size_t k = 0; k < fl.dist_rates.size(); ++k) {
        const std::vector<double>& rk = fl.dist_rates[k];
        const bool arched = std::isfinite(out.t_arch) && fl.dist_t[k] >= out.t_arch - 1e-12;
        if (k < n_before && !arched) { before.insert(before.end(), rk.begin(), rk.end()); out.times_before += 1; }
        if (k >= n_before && arched) { after.insert(after.end(), rk.begin(), rk.end()); out.times_after += 1; }
    }
    using Model = CollisionRateFit::Model;
    if (!before.empty()) {
        const RateHistogram h = hist_lin(before);
        const auto fe = try_fit(h, Model::Exponential, 0.5 * rmin, hi_lin), fp = try_fit(h, Model::PowerLaw, 0.5 * rmin, hi_lin);
        if (fe) { out.A = fe->value; out.A_err = fe->error; out.A_chi2 = fe->chi2_reduced; out.dev_exp_early = fe->deviance; }
        if (fp) out.dev_pow_early = fp->deviance;
        out.mean_rate_early = std::accumulate(before.begin(), before.end(), 0.0) / double(before.size());
    }
    if (!after.empty()) {
        const RateHistogram h = hist_log(after);
        const auto fe = try_fit(h, Model::Exponential, 0.5 * rmin, 1.0e6), fp = try_fit(h, Model::PowerLaw, 0.5 * rmin, 1.0e6);
        if (fp) { out.B = fp->value; out.B_err = fp->error; out.B_chi2 = fp->chi2_reduced; out.dev_pow_late = fp->deviance; }
        if (fe) out.dev_exp_late = fe->deviance;
    }
    // B at the Fig. 14(b) times taken relative to this seed's own first arch: the paper's times
    // 0.055-0.085 s are t_arch_paper - 1 ms .. + 29 ms after its arch (Fig. 13: 0.056 s), while
    // the arch's wake rises and decays within ~20 ms, so fixed times sample each seed at another
    // age of its arch (issue 43, B_rate). N_c over dist_dt ending at frame f is the mean of the
    // dist_dt / frame_dt frame rates ending there (the frames tile the fall); a time that falls
    // before the first full window or after t_end is left out.
    if (std::isfinite(out.t_arch)) {
        const long fa = frame_of(out.t_arch, s.frame_dt), w = frame_of(ddt, s.frame_dt);
        const long n_frames = long(fl.frames.size()) - 1;
        std::vector<double> rel;
        out.times_rel = 0;
        for (double t : s.dist_times_after) {
            const long f = fa + frame_of(t - s.t_arch_paper, s.frame_dt);
            if (f - w + 1 < 1 || f > n_frames) continue;
            std::vector<double> r(fl.frames[std::size_t(f)].rate.size(), 0.0);
            for (long g = f - w + 1; g <= f; ++g)
                for (std::size_t i = 0; i < r.size(); ++i) r[i] += fl.frames[std::size_t(g)].rate[i] / double(w);
            rel.insert(rel.end(), r.begin(), r.end());
            out.times_rel += 1;
        }
        if (!rel.empty())
            if (const auto fp = try_fit(hist_log(rel), Model::PowerLaw, 0.5 * rmin, 1.0e6)) out.B_rel = fp->value;
    }
    std::vector<RateHistogram> hs;
    for (std::size_t k = 0; k < fl.dist_rates.size(); ++k) {
        const bool early = k < n_before;
        hs.push_back(early ? hist_lin(fl.dist_rates[k]) : hist_log(fl.dist_rates[k]));
        const auto f = try_fit(hs.back(), early ? Model::Exponential : Model::PowerLaw, 0.5 * rmin, early ? hi_lin : 1.0e6);
        out.per_time.push_back({fl.dist_t[k], f ? f->value : NAN, f ? f->error : NAN});
    }
    return hs;
}

// Run 0's tables: the relaxation, the Fig. 13 snapshots and their marks (the initiating disk, the
// frame's arch, the crack), the timeline per frame, the Fig. 14 histograms.
std::vector<FigureTable> figure_tables(const Pipe& s, const Fall& fl, const Relaxation& rel,
                                       const std::vector<RateHistogram>& hs, int i_prec) {
    std::vector<FigureTable> F{{out_relaxation.pattern, out_relaxation.description}};
    F[0].add("t", "s", rel.t);
    F[0].add("vbar", "m/s", rel.vbar);
    std::vector<std::reference_wrapper<const Frame>> snaps;
    for (long f = 1; f <= s.n_frames; ++f)
        if (s.at(s.snapshot_times, f)) add_snapshot(F, s, snaps.emplace_back(fl.at(f)));
    auto per_snap = [&](auto x) { return column(snaps, x); };
    auto arch_y = [](const Frame& fr) { return fr.arch.found ? fr.arch.y : NAN; };
    auto opening = [&](const Frame& fr) { return fr.crack.course_x.empty() ? NAN : fr.crack.opening / s.d; };
    auto initiator = [&](const Frame& fr) { return i_prec >= 0 ? fr.pos[std::size_t(i_prec)] : Vec2{NAN, NAN}; };
    FigureTable& mk = F.emplace_back(FigureTable{out_marks.pattern, out_marks.description});
    mk.add("t", "s", per_snap([](const Frame& fr) { return fr.t; }));
    mk.add("initiator_x", "d", per_snap([&](const Frame& fr) { return initiator(fr).x / s.d; }));
    mk.add("initiator_y", "d", per_snap([&](const Frame& fr) { return (initiator(fr).y - s.y_floor) / s.d; }));
    mk.add("arch_y", "d", per_snap(arch_y));
    mk.add("crack_opening", "d", per_snap(opening));
    mk.add("crack_visible", "1", per_snap([&](const Frame& fr) { return opening(fr) >= s.crack_opening ? 1.0 : 0.0; }));
    FigureTable& tl = F.emplace_back(FigureTable{out_timeline.pattern, out_timeline.description});
    tl.add("t", "s", fl.per_frame(&Frame::t));
    tl.add("hot", "1", fl.per_frame([](const Frame& fr) { return double(fr.hot.size()); }));
    tl.add("hot_wall", "1", fl.per_frame([](const Frame& fr) { return double(fr.hot_wall.size()); }));
    tl.add("mean", "1/s", fl.per_frame([](const Frame& fr) {
        return std::accumulate(fr.rate.begin(), fr.rate.end(), 0.0) / double(fr.rate.size());
    }));
    tl.add("opening", "d", fl.per_frame(opening));
    tl.add("vy", "m/s", fl.per_frame(&Frame::vy));
    tl.add("wall_rate", "1/s", fl.per_frame(&Frame::wall_rate));
    tl.add("wall_load", "1", fl.per_frame(&Frame::wall_load));
    tl.add("arch_y", "d", fl.per_frame(arch_y));
    for (std::size_t k = 0; k < hs.size(); ++k) {
        FigureTable& h = F.emplace_back(FigureTable{fill_pattern(out_pnc.pattern, {}, {ttext(fl.dist_t[k])}), out_pnc.description});
        h.add("Nc", "1/s", hs[k].centres);
        h.add("P", "s", hs[k].density);
        h.add("err", "s", hs[k].error);
    }
    return F;
}

} // namespace granrepro::experiments::pipe_arching_detail
