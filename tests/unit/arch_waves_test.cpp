// Successive arches as momentum waves (src/analysis/arch_waves.hpp), on constructed sequences:
// waves that climb the column (Sec. 5: cracks "ascend progressively"), waves that descend, one
// arch jittering in place (no new wave), and the strength of a later wave against the first
// ("a new, possibly stronger momentum wave"), where the first arch growing in place or a wave
// elsewhere before the first has settled must not count as a later, stronger wave.
#include "analysis/arch_waves.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace granrepro;

namespace {

ArchSighting arch(double y0, double size) { return {true, y0, size}; }
const ArchSighting none{};

} // namespace

TEST(ArchWaves, WavesClimbingTheColumnRiseAtEveryStep) {
    // first arch at 10 d, a gap, then waves starting at 20 d and 32 d (separation 5 d)
    const std::vector<ArchSighting> f = {arch(10, 40), arch(10.5, 45), none, arch(20, 30), arch(21, 30), arch(32, 30)};
    const ArchWaves w = follow_arch_waves(f, 2, 5.0);
    EXPECT_EQ(w.steps, 2);
    EXPECT_EQ(w.steps_up, 2);
    EXPECT_FALSE(w.stronger()); // 30 hot disks against the first arch's 45
}

TEST(ArchWaves, WavesDescendingTheColumnNeverRise) {
    const std::vector<ArchSighting> f = {arch(40, 40), arch(30, 20), arch(18, 20), arch(6, 20)};
    const ArchWaves w = follow_arch_waves(f, 1, 5.0);
    EXPECT_EQ(w.steps, 3);
    EXPECT_EQ(w.steps_up, 0);
}

TEST(ArchWaves, OneArchJitteringInPlaceIsNoNewWave) {
    // the detector's arch moves by up to 4 d between frames: one wave, no step
    const std::vector<ArchSighting> f = {arch(10, 40), arch(13, 40), arch(9.5, 40), none, arch(12, 40), arch(14, 40)};
    const ArchWaves w = follow_arch_waves(f, 2, 5.0);
    EXPECT_EQ(w.steps, 0);
    EXPECT_EQ(w.later_peak, 0);
}

TEST(ArchWaves, ALaterWaveElsewhereWithMoreHotDisksIsStronger) {
    // the first arch peaks at 40 hot disks; the material from above makes a wave of 60 at 25 d
    const std::vector<ArchSighting> strong = {arch(10, 30), arch(10, 40), arch(10, 20), arch(25, 60)};
    EXPECT_TRUE(follow_arch_waves(strong, 2, 5.0).stronger());
    EXPECT_EQ(follow_arch_waves(strong, 2, 5.0).first_peak, 40);
    // the first arch itself growing to 80 after settling is no new wave
    const std::vector<ArchSighting> grows = {arch(10, 30), arch(10, 40), arch(11, 80), arch(25, 35)};
    EXPECT_FALSE(follow_arch_waves(grows, 2, 5.0).stronger());
    // a big arch elsewhere within the first arch's settling frames is not a later wave
    const std::vector<ArchSighting> early = {arch(10, 30), arch(30, 90), arch(10, 40), arch(25, 35)};
    EXPECT_FALSE(follow_arch_waves(early, 3, 5.0).stronger()); // first 40 (frames 0-2), later 35
}

TEST(ArchWaves, NoArchInTheFirstFrameMeansNoWaves) {
    const ArchWaves w = follow_arch_waves({none, arch(10, 40), arch(30, 50)}, 1, 5.0);
    EXPECT_EQ(w.steps, 0);
    EXPECT_FALSE(w.stronger());
}
