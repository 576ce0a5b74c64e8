#include "observables/kinetic_energy.hpp"
#include "observables/log_time_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;

TEST(ObsKineticEnergy, ComponentsAndRotation) {
    const std::vector<Vec2> v{{1.0, 2.0}, {-3.0, 0.5}};
    const std::vector<double> m{2.0, 4.0}, w{10.0, -5.0}, I{0.01, 0.02};
    const auto k = KineticEnergy::compute(v, m, w, I);
    EXPECT_DOUBLE_EQ(k.x, 0.5 * (2.0 * 1.0 + 4.0 * 9.0));
    EXPECT_DOUBLE_EQ(k.y, 0.5 * (2.0 * 4.0 + 4.0 * 0.25));
    EXPECT_DOUBLE_EQ(k.rot, 0.5 * (0.01 * 100.0 + 0.02 * 25.0));
    EXPECT_DOUBLE_EQ(k.total(), k.x + k.y + k.rot);
    EXPECT_DOUBLE_EQ(k.anisotropy(), (k.x - k.y) / (k.x + k.y));
    const auto k1 = KineticEnergy::compute(v, 3.0);
    EXPECT_DOUBLE_EQ(k1.translational(), 0.5 * 3.0 * (1 + 4 + 9 + 0.25));
    EXPECT_THROW(KineticEnergy::compute(v, std::vector<double>{1.0}), std::invalid_argument);
    EXPECT_DOUBLE_EQ(KineticEnergy{}.anisotropy(), 0.0);
}

TEST(ObsLogTimeSampler, LogSpacingAndConsumption) {
    LogTimeSampler s(1e-3, 10.0, 4);
    ASSERT_EQ(s.size(), 17u); // 4 decades x 4 + the endpoint
    for (std::size_t k = 0; k < s.size(); ++k)
        EXPECT_NEAR(std::log10(s.times()[k]), -3.0 + 0.25 * static_cast<double>(k), 1e-12);
    EXPECT_DOUBLE_EQ(s.next(), 1e-3);
    EXPECT_FALSE(s.due(5e-4));
    EXPECT_TRUE(s.due(2e-3)); // consumes 1e-3 and 10^-2.75
    EXPECT_NEAR(s.next(), std::pow(10.0, -2.5), 1e-15);
    EXPECT_TRUE(s.due(100.0));
    EXPECT_TRUE(s.done());
    EXPECT_TRUE(std::isinf(s.next()));
    EXPECT_THROW(LogTimeSampler(0.0, 1.0, 3), std::invalid_argument);
}
