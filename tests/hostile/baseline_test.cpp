// The suite's own ground: an untouched results folder passes every reader, and the sentinel tree
// beside it notices a change (so a test that finds it unchanged means something).
#include "hostile_support.hpp"

using namespace hostile;

TEST(HostileBaseline, AnUntouchedFolderPassesCheckAndVerifyAndLeavesTheSentinel) {
    const Crafted c("baseline");
    EXPECT_EQ(run_argv({"check", "brake-failure", "--out", c.out.string()}).code, 0);
    EXPECT_EQ(run_argv({"verify", "brake-failure", "--point", "0", "--out", c.out.string()}).code, 0);
    c.expect_sentinel_unchanged();
}

TEST(HostileBaseline, TheSentinelNoticesAChangedVictim) {
    const Crafted c("sentinel");
    c.sentinel.write("victim.txt", "changed\n");
    EXPECT_NE(c.sentinel.digest(), c.before);
}
