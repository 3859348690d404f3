// SPDX-License-Identifier: Apache-2.0

#include "app/Components/LinkHealth/test/ut/LinkHealthTester.hpp"

TEST(LinkHealth, CommandsBeyondTheLimitAreDroppedAndCounted) {
    Kit::LinkHealthTester tester;
    tester.commandsBeyondTheLimitAreDroppedAndCounted();
}

TEST(LinkHealth, AnAnswerFreesASlotAndGoesBackToTheRouter) {
    Kit::LinkHealthTester tester;
    tester.anAnswerFreesASlotAndGoesBackToTheRouter();
}

TEST(LinkHealth, UnknownPacketsAreCountedAndReturned) {
    Kit::LinkHealthTester tester;
    tester.unknownPacketsAreCountedAndReturned();
}

TEST(LinkHealth, UartCountsBecomeTelemetry) {
    Kit::LinkHealthTester tester;
    tester.uartCountsBecomeTelemetry();
}

TEST(LinkHealth, DetectorCountsEveryOutcomeByReason) {
    Kit::LinkHealthTester tester;
    tester.detectorCountsEveryOutcomeByReason();
}

TEST(LinkHealth, ALengthThatWrapsTheFrameSizeIsOversized) {
    Kit::LinkHealthTester tester;
    tester.aLengthThatWrapsTheFrameSizeIsOversized();
}

TEST(LinkHealth, AFrameNoBufferHoldsIsOversized) {
    Kit::LinkHealthTester tester;
    tester.aFrameNoBufferHoldsIsOversized();
}

TEST(LinkHealth, ACommandWithoutRoomForItsEventsIsDropped) {
    Kit::LinkHealthTester tester;
    tester.aCommandWithoutRoomForItsEventsIsDropped();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
