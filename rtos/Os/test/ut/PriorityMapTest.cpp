// SPDX-License-Identifier: Apache-2.0
// F´ priorities (higher is more urgent) onto Zephyr's (lower is more urgent),
// with Zephyr's default 15 preemptive levels and the tick thread at 2 (the
// kit's: just below the fastest rate group).
#include <gtest/gtest.h>
#include "rtos/Os/PriorityMap.hpp"

namespace {
constexpr int LEVELS = 15;
constexpr int TICK = 2;

TEST(PriorityMap, HigherFprimeIsMoreUrgentZephyr) {
    EXPECT_LT(Kit::zephyrPriority(13, LEVELS, TICK), Kit::zephyrPriority(11, LEVELS, TICK));
    EXPECT_LT(Kit::zephyrPriority(6, LEVELS, TICK), Kit::zephyrPriority(4, LEVELS, TICK));
}

TEST(PriorityMap, KitTableAroundTheTick) {
    EXPECT_EQ(Kit::zephyrPriority(13, LEVELS, TICK), 1);  // rg1kHz: above the tick
    EXPECT_EQ(Kit::zephyrPriority(11, LEVELS, TICK), 3);  // rg100Hz: below it
    EXPECT_EQ(Kit::zephyrPriority(4, LEVELS, TICK), 10);  // tlmSend
    EXPECT_EQ(Kit::zephyrPriority(0, LEVELS, TICK), 14);  // least urgent
}

TEST(PriorityMap, TheTicksLevelIsRefused) {
    EXPECT_EQ(Kit::zephyrPriority(12, LEVELS, TICK), -1);  // would share the tick's level
    EXPECT_EQ(Kit::zephyrPriority(14, LEVELS, TICK), 0);
    EXPECT_EQ(Kit::zephyrPriority(14, LEVELS, 0), -1);
}

TEST(PriorityMap, OutOfTableIsRefusedNotClamped) {
    EXPECT_EQ(Kit::zephyrPriority(15, LEVELS, TICK), -1);
    EXPECT_EQ(Kit::zephyrPriority(255, LEVELS, TICK), -1);
    EXPECT_EQ(Kit::zephyrPriority(100, LEVELS, TICK), -1);
}
}  // namespace
