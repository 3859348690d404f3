// SPDX-License-Identifier: Apache-2.0
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

TEST(Histogram, SmallValuesHaveABucketEach) {
    for (U32 v = 0; v < 16; v++) {
        EXPECT_EQ(Kit::Histogram::bucketOf(v), v);
        EXPECT_EQ(Kit::Histogram::lowerBound(v), v);
        EXPECT_EQ(Kit::Histogram::upperBound(v), v);
    }
}

TEST(Histogram, BucketsTileTheRangeWithoutGapsOrOverlap) {
    for (U32 b = 0; b + 1 < Kit::Histogram::BUCKETS; b++) {
        EXPECT_EQ(Kit::Histogram::upperBound(b) + 1, Kit::Histogram::lowerBound(b + 1)) << "bucket " << b;
        EXPECT_EQ(Kit::Histogram::bucketOf(Kit::Histogram::lowerBound(b)), b);
        EXPECT_EQ(Kit::Histogram::bucketOf(Kit::Histogram::upperBound(b)), b);
    }
}

TEST(Histogram, BucketWidthIsAtMostAnEighthOfItsValues) {
    for (U32 b = 16; b + 1 < Kit::Histogram::BUCKETS; b++) {
        const U32 width = Kit::Histogram::upperBound(b) - Kit::Histogram::lowerBound(b) + 1;
        EXPECT_LE(width * 8, Kit::Histogram::lowerBound(b)) << "bucket " << b;
    }
}

TEST(Histogram, HugeValuesLandInTheLastBucket) {
    const U32 last = Kit::Histogram::LAST;  // a copy: gtest takes its arguments by reference
    EXPECT_EQ(Kit::Histogram::bucketOf(0xFFFFFFFFu), last);
    EXPECT_EQ(Kit::Histogram::bucketOf(Kit::Histogram::lowerBound(last)), last);
}

TEST(Histogram, PercentileUsesTheRankOfTheSample) {
    Kit::Histogram histogram;
    for (U32 v = 1; v <= 10; v++) {  // exact buckets: percentiles are exact
        histogram.add(v);
    }
    EXPECT_EQ(histogram.percentileBound(500), 5u);   // rank 5 of 10
    EXPECT_EQ(histogram.percentileBound(990), 10u);  // rank ceil(9.9) = 10
    EXPECT_EQ(histogram.percentileBound(0), 1u);     // rank at least 1
    EXPECT_EQ(histogram.percentileBound(1000), 10u);
}

TEST(Histogram, EmptyPercentileIsZero) {
    EXPECT_EQ(Kit::Histogram().percentileBound(500), 0u);
}

TEST(CycleStats, PercentileIsClampedToTheExactExtremes) {
    Kit::CycleStats stats;
    for (U32 i = 0; i < 99; i++) {
        stats.add(1000);
    }
    stats.add(1001);
    // 1000 and 1001 share a bucket [960, 1023]: the bound is clamped to the max
    EXPECT_EQ(stats.percentile(500), 1001u);
    EXPECT_EQ(stats.percentile(990), 1001u);
    EXPECT_GE(stats.percentile(500), 1000u);  // never below the true value
}

TEST(SampleHash, OrderMatters) {
    Kit::SampleHash a, b;
    a.add(1);
    a.add(2);
    b.add(2);
    b.add(1);
    EXPECT_NE(a.value(), b.value());
    EXPECT_EQ(a.samples(), 2u);
}

}  // namespace
