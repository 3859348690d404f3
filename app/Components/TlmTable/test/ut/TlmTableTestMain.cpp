// SPDX-License-Identifier: Apache-2.0

#include "app/Components/TlmTable/test/ut/TlmTableTester.hpp"

TEST(TlmTable, ValuesAreKeptAndRead) {
    Kit::TlmTableTester tester;
    tester.valuesAreKeptAndRead();
}

TEST(TlmTable, ACycleSendsEachWrittenChannelOnce) {
    Kit::TlmTableTester tester;
    tester.aCycleSendsEachWrittenChannelOnce();
}

TEST(TlmTable, ChannelsSharingAHomeEntryKeepTheirOwn) {
    Kit::TlmTableTester tester;
    tester.channelsSharingAHomeEntryKeepTheirOwn();
}

TEST(TlmTable, ACycleSpansPacketsAndLosesNone) {
    Kit::TlmTableTester tester;
    tester.aCycleSpansPacketsAndLosesNone();
}

TEST(TlmTable, AChannelPastTheTableAsserts) {
    Kit::TlmTableTester tester;
    tester.aChannelPastTheTableAsserts();
}

TEST(TlmTable, AValueBeingWrittenGoesInTheNextCycle) {
    Kit::TlmTableTester tester;
    tester.aValueBeingWrittenGoesInTheNextCycle();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
