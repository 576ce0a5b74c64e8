// Fig. 13's crack "at the position of the initiating particle" (issue 43 §1): the local opening
// beside a wall disk (experiments/pipe_arching/compute_arches.cpp, local_opening) on constructed
// columns. The intact lattice (s = 1.01 d) is closed beside a wall disk; a column cut below a
// wall disk and lowered by delta opens, in the strip of that disk's own width, delta less the
// height by which the offset row below reaches up beside the wall disk; an opening outside the strip (a cut that leaves the wall side
// connected) is not seen; the right wall is mirrored onto the left.
#include "engines/ed/ed_initial_states.hpp"
#include "experiments/pipe_arching/spec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace granrepro::experiments::pipe_arching_detail {
// Defined in compute_arches.cpp; declared here so that the experiment's header keeps its
// interface (the measure is internal to the run).
double local_opening(const std::vector<Vec2>& pos, int i, const Pipe& s, double x_right);
} // namespace granrepro::experiments::pipe_arching_detail

using namespace granrepro;
using namespace granrepro::experiments::pipe_arching_detail;

namespace {

constexpr double kD = 1e-3;

Pipe pipe() {
    PipeArchingSpec s;
    s.n_particles = 781;
    s.width = 20.2;
    s.lattice = 1.01;
    s.d = kD;
    s.g = 9.81;
    s.t_end = 0.1;
    s.frame_dt = 1e-3;
    s.crack_min_particles = 20;
    s.crack_min_above = 20;
    s.below_depth = 10;
    return Pipe(s);
}

std::vector<Vec2> column(const Pipe& p) {
    return triangular_lattice_positions(std::size_t(p.n_particles), 0.5 * kD, p.L - 0.5 * kD, 0.5 * kD, p.a);
}

// The disk at the left wall (x = d/2) whose centre is nearest to height y.
int left_wall_disk(const std::vector<Vec2>& pos, double y) {
    int best = -1;
    for (std::size_t i = 0; i < pos.size(); ++i)
        if (std::abs(pos[i].x - 0.5 * kD) < 1e-9 && (best < 0 || std::abs(pos[i].y - y) < std::abs(pos[std::size_t(best)].y - y)))
            best = int(i);
    return best;
}

// The opening of a column cut below a wall disk and lowered by delta [d]: the row below is offset
// by a/2, so its disk nearest the wall (centre at d/2 + a/2, 0.005 d inside the strip) reaches
// into the strip with the half chord h = sqrt(1/4 - 0.005^2) d and to a sqrt(3)/2 - h below the
// wall disk's centre; the channel runs from there (lowered) up to the wall disk's bottom.
double lowered_opening(const Pipe& p, double delta) {
    const double dx = 0.5 * p.a / kD - 0.5, h = std::sqrt(0.25 - dx * dx);
    return delta + 0.5 * std::sqrt(3.0) * p.a / kD - h - 0.5;
}

} // namespace

TEST(PipeArchingLocalOpening, IntactLatticeIsClosedBesideAWallDisk) {
    const Pipe p = pipe();
    const std::vector<Vec2> pos = column(p);
    const int i = left_wall_disk(pos, 20 * kD);
    ASSERT_GE(i, 0);
    EXPECT_NEAR(local_opening(pos, i, p, p.L), 0.0, 1e-12);
}

TEST(PipeArchingLocalOpening, ALoweredColumnOpensItsDropBelowTheWallDisk) {
    const Pipe p = pipe();
    std::vector<Vec2> pos = column(p);
    const int i = left_wall_disk(pos, 20 * kD);
    ASSERT_GE(i, 0);
    const double cut = pos[std::size_t(i)].y - 0.5 * kD, delta = 0.6 * kD;
    for (Vec2& r : pos)
        if (r.y < cut) r.y -= delta;
    EXPECT_NEAR(local_opening(pos, i, p, p.L), lowered_opening(p, 0.6), 1e-9); // 0.4747
}

TEST(PipeArchingLocalOpening, AGapAwayFromTheWallIsNotLocal) {
    const Pipe p = pipe();
    std::vector<Vec2> pos = column(p);
    const int i = left_wall_disk(pos, 20 * kD);
    ASSERT_GE(i, 0);
    const double cut = pos[std::size_t(i)].y - 0.5 * kD;
    for (Vec2& r : pos) // lower only the disks more than 3 d from the left wall
        if (r.y < cut && r.x > 3 * kD) r.y -= 0.6 * kD;
    EXPECT_NEAR(local_opening(pos, i, p, p.L), 0.0, 1e-12);
}

TEST(PipeArchingLocalOpening, TheRightWallIsMirrored) {
    const Pipe p = pipe();
    std::vector<Vec2> pos = column(p);
    for (Vec2& r : pos) r.x = p.L - r.x; // the column mirrored: the wall disk now at the right wall
    const int i = [&] {
        for (std::size_t k = 0; k < pos.size(); ++k)
            if (std::abs(pos[k].x - (p.L - 0.5 * kD)) < 1e-9 && std::abs(pos[k].y - 20 * kD) < 0.9 * kD) return int(k);
        return -1;
    }();
    ASSERT_GE(i, 0);
    const double cut = pos[std::size_t(i)].y - 0.5 * kD;
    for (Vec2& r : pos)
        if (r.y < cut) r.y -= 0.6 * kD;
    EXPECT_NEAR(local_opening(pos, i, p, p.L), lowered_opening(p, 0.6), 1e-9);
}
