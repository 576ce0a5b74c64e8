// The event queues (the binary heap the engine uses, a 4-ary heap and the test-only calendar
// queue of tests/support) against a brute-force minimum over (time, id), in an ED-like access pattern.
#include "calendar_queue.hpp"
#include "engines/ed/dary_heap_queue.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

template <class Q>
class EdEventQueue : public ::testing::Test {};
using QueueTypes = ::testing::Types<granrepro::BinaryHeapQueue, granrepro::DaryHeapQueue<4>, granrepro::CalendarQueue>;
TYPED_TEST_SUITE(EdEventQueue, QueueTypes);

TYPED_TEST(EdEventQueue, TopIsMinimumOverTimeAndId) {
    const int n = 500;
    std::mt19937_64 gen(1);
    std::exponential_distribution<double> ex(1.0);
    std::uniform_int_distribution<int> pick(0, n - 1);
    std::vector<double> t(n);
    for (auto& x : t) x = ex(gen);
    t[3] = std::numeric_limits<double>::infinity();
    TypeParam q;
    q.rebuild(t);
    for (int step = 0; step < 100000; ++step) {
        int best = 0;
        for (int i = 1; i < n; ++i)
            if (t[i] < t[best] || (t[i] == t[best] && i < best)) best = i;
        ASSERT_EQ(q.top_id(), best) << step;
        ASSERT_EQ(q.top_time(), t[best]);
        const double now = t[best];
        // Pop-like update of the top, plus a random re-key (ties and infinities included).
        t[best] = now + ex(gen);
        q.update(best, t[best]);
        const int j = pick(gen);
        const int kind = step % 5;
        t[j] = kind == 0 ? std::numeric_limits<double>::infinity() : kind == 1 ? now : now + 0.01 * ex(gen);
        q.update(j, t[j]);
    }
}

TYPED_TEST(EdEventQueue, AllInfiniteAndRebuild) {
    TypeParam q;
    q.reset(4);
    EXPECT_TRUE(std::isinf(q.top_time()));
    q.update(2, 5.0);
    q.update(1, 5.0);
    EXPECT_EQ(q.top_id(), 1);
    q.rebuild(std::vector<double>{3.0, 1.0, 2.0});
    EXPECT_EQ(q.top_id(), 1);
    EXPECT_EQ(q.top_time(), 1.0);
}
