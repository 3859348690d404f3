// SPDX-License-Identifier: Apache-2.0
// F´ priorities (higher is more urgent) onto Zephyr's (lower is more urgent),
// with Zephyr's default 15 preemptive levels and the tick thread at 0.
#include <gtest/gtest.h>
#include "rtos/Os/PriorityMap.hpp"

namespace {
constexpr int LEVELS = 15;
constexpr int TICK = 0;

TEST(PriorityMap, HigherFprimeIsMoreUrgentZephyr) {
    EXPECT_LT(Kit::zephyrPriority(12, LEVELS, TICK), Kit::zephyrPriority(11, LEVELS, TICK));
    EXPECT_LT(Kit::zephyrPriority(6, LEVELS, TICK), Kit::zephyrPriority(4, LEVELS, TICK));
}

TEST(PriorityMap, KitTableLandsBelowTheTick) {
    EXPECT_EQ(Kit::zephyrPriority(12, LEVELS, TICK), 2);  // rg1kHz
    EXPECT_EQ(Kit::zephyrPriority(4, LEVELS, TICK), 10);  // tlmSend
    EXPECT_EQ(Kit::zephyrPriority(0, LEVELS, TICK), 14);  // least urgent
}

TEST(PriorityMap, MostUrgentMappablePriorityStaysBelowTheTick) {
    EXPECT_EQ(Kit::zephyrPriority(13, LEVELS, TICK), 1);
    EXPECT_EQ(Kit::zephyrPriority(14, LEVELS, TICK), -1);  // would share the tick's level
}

TEST(PriorityMap, OutOfTableIsRefusedNotClamped) {
    // fprime-zephyr clamps anything above 14 to 14; the kit refuses instead
    EXPECT_EQ(Kit::zephyrPriority(255, LEVELS, TICK), -1);
    EXPECT_EQ(Kit::zephyrPriority(100, LEVELS, TICK), -1);
}

TEST(PriorityMap, ReservedTickLevelsShrinkTheRange) {
    EXPECT_EQ(Kit::zephyrPriority(11, LEVELS, 2), 3);
    EXPECT_EQ(Kit::zephyrPriority(12, LEVELS, 2), -1);
}
}  // namespace
