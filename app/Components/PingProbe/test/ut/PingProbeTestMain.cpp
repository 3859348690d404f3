// SPDX-License-Identifier: Apache-2.0

#include "app/Components/PingProbe/test/ut/PingProbeTester.hpp"

TEST(PingProbe, PingsPassThroughAndAreTimed) {
    Kit::PingProbeTester tester;
    tester.pingsPassThroughAndAreTimed();
}

TEST(PingProbe, ASegmentCountsItsLongestWaitAnsweredOrNot) {
    Kit::PingProbeTester tester;
    tester.aSegmentCountsItsLongestWaitAnsweredOrNot();
}

TEST(PingProbe, APingThatWouldFindTheQueueFullWaitsForRoom) {
    Kit::PingProbeTester tester;
    tester.aPingThatWouldFindTheQueueFullWaitsForRoom();
}

TEST(PingProbe, AProbeGoneLeavesNoDeferredPing) {
    Kit::PingProbeTester tester;
    tester.aProbeGoneLeavesNoDeferredPing();
}

TEST(PingProbe, AnAnswerWithNoPingOutIsPassedOnNotTimed) {
    Kit::PingProbeTester tester;
    tester.anAnswerWithNoPingOutIsPassedOnNotTimed();
}

TEST(PingProbe, PercentilesComeFromTheLastWindow) {
    Kit::PingProbeTester tester;
    tester.percentilesComeFromTheLastWindow();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
