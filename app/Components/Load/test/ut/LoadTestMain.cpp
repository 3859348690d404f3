// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Load/test/ut/LoadTester.hpp"

TEST(Load, SliceComputesForTheCommandedTime) {
    Kit::LoadTester tester;
    tester.sliceComputesForTheCommandedTime();
}

TEST(Load, SettingsAboveTheirLimitsAreRejected) {
    Kit::LoadTester tester;
    tester.settingsAboveTheirLimitsAreRejected();
}

TEST(Load, BurstPushesTheCommandedMessages) {
    Kit::LoadTester tester;
    tester.burstPushesTheCommandedMessages();
}

TEST(Load, AFullQueueDropsCountsAndReports) {
    Kit::LoadTester tester;
    tester.aFullQueueDropsCountsAndReports();
}

TEST(Load, EverySliceSendsTheCommandedDownlinkPackets) {
    Kit::LoadTester tester;
    tester.everySliceSendsTheCommandedDownlinkPackets();
}

TEST(Load, PatternIsXorshift32sLowBytes) {
    Kit::LoadTester tester;
    tester.patternIsXorshift32sLowBytes();
}

TEST(Load, FillFileWritesThePatternOrRefuses) {
    Kit::LoadTester tester;
    tester.fillFileWritesThePatternOrRefuses();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
