// Arithmetic of the timing probe: statistics, deadlines, and the 32-bit
// counter wrap (the 12 MHz cycle counter wraps every 358 s).
#include <gtest/gtest.h>
#include "app/Components/Timing/CycleStats.hpp"

namespace {

TEST(CycleStats, EmptyReportsZeros) {
    Kit::CycleStats stats;
    EXPECT_EQ(stats.count(), 0u);
    EXPECT_EQ(stats.min(), 0u);
    EXPECT_EQ(stats.max(), 0u);
    EXPECT_EQ(stats.mean(), 0u);
}

TEST(CycleStats, MinMaxMean) {
    Kit::CycleStats stats;
    for (U32 value : {500u, 100u, 900u, 300u}) {
        stats.add(value);
    }
    EXPECT_EQ(stats.count(), 4u);
    EXPECT_EQ(stats.min(), 100u);
    EXPECT_EQ(stats.max(), 900u);
    EXPECT_EQ(stats.mean(), 450u);
}

TEST(CycleStats, SumDoesNotOverflowAtU32Extremes) {
    Kit::CycleStats stats;
    stats.add(0xFFFFFFFFu);
    stats.add(0xFFFFFFFFu);
    EXPECT_EQ(stats.mean(), 0xFFFFFFFFu);
}

TEST(CycleStats, ResetForgetsEverything) {
    Kit::CycleStats stats;
    stats.add(7);
    stats.reset();
    EXPECT_EQ(stats.count(), 0u);
    EXPECT_EQ(stats.max(), 0u);
}

TEST(ElapsedCycles, WithinOnePeriod) {
    EXPECT_EQ(Kit::elapsedCycles(1000u, 13000u), 12000u);
    EXPECT_EQ(Kit::elapsedCycles(5u, 5u), 0u);
}

TEST(ElapsedCycles, AcrossTheCounterWrap) {
    // The counter wrapped between the two readings: 0x100 cycles before the
    // wrap and 0x100 after.
    EXPECT_EQ(Kit::elapsedCycles(0xFFFFFF00u, 0x00000100u), 0x200u);
    EXPECT_EQ(Kit::elapsedCycles(0xFFFFFFFFu, 0u), 1u);
}

TEST(Deadline, OnTimeUntilTheNextReleaseFires) {
    // 100 Hz group (divisor 10) released at tick 11: its deadline is tick 21
    EXPECT_FALSE(Kit::pastDeadline(12u, 11u, 10u));  // only tick 11 fired
    EXPECT_FALSE(Kit::pastDeadline(21u, 11u, 10u));  // ticks up to 20 fired
    EXPECT_TRUE(Kit::pastDeadline(22u, 11u, 10u));   // tick 21 fired: missed
    EXPECT_EQ(Kit::ticksLate(21u, 11u, 10u), 0u);
    EXPECT_EQ(Kit::ticksLate(24u, 11u, 10u), 3u);
}

TEST(Deadline, AcrossTheTickCounterWrap) {
    const U32 release = 0xFFFFFFFEu;
    EXPECT_FALSE(Kit::pastDeadline(0xFFFFFFFFu, release, 1u));
    EXPECT_TRUE(Kit::pastDeadline(0u, release, 1u));
    EXPECT_EQ(Kit::ticksLate(1u, release, 1u), 2u);
}

}  // namespace
