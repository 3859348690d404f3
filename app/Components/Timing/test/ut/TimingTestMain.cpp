// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Timing/test/ut/TimingTester.hpp"

TEST(Timing, TickDrivesTheRateGroupDriver) {
    Kit::TimingTester tester;
    tester.tickDrivesTheRateGroupDriver();
}

TEST(Timing, OnTimeCyclesRecordLatencyAndExecution) {
    Kit::TimingTester tester;
    tester.onTimeCyclesRecordLatencyAndExecution();
}

TEST(Timing, LateEndIsASlipWithEvent) {
    Kit::TimingTester tester;
    tester.lateEndIsASlipWithEvent();
}

TEST(Timing, LatencyAcrossTheCounterWrap) {
    Kit::TimingTester tester;
    tester.latencyAcrossTheCounterWrap();
}

TEST(Timing, SameSamplesSameHash) {
    Kit::TimingTester tester;
    tester.sameSamplesSameHash();
}

TEST(Timing, RestartEmptiesTheRecordsAndKeepsTheHash) {
    Kit::TimingTester tester;
    tester.restartEmptiesTheRecordsAndKeepsTheHash();
}

TEST(Timing, RestartRefusesASegmentOffTheHyperperiod) {
    Kit::TimingTester tester;
    tester.restartRefusesASegmentOffTheHyperperiod();
}

TEST(Timing, SegmentsOnlyWhenServedWholeHyperperiodsOneAtATime) {
    Kit::TimingTester tester;
    tester.segmentsOnlyWhenServedWholeHyperperiodsOneAtATime();
}

TEST(Timing, ProbeCostLeavesTheRunUntouched) {
    Kit::TimingTester tester;
    tester.probeCostLeavesTheRunUntouched();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
