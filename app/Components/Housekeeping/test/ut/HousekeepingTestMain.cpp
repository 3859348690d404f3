// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Housekeeping/test/ut/HousekeepingTester.hpp"

TEST(Housekeeping, CrcMatchesTheStandardCheckValue) {
    Kit::HousekeepingTester tester;
    tester.crcMatchesTheStandardCheckValue();
}

TEST(Housekeeping, IntactTablePassesQuietly) {
    Kit::HousekeepingTester tester;
    tester.intactTablePassesQuietly();
}

TEST(Housekeeping, CorruptedTableRaisesAnEvent) {
    Kit::HousekeepingTester tester;
    tester.corruptedTableRaisesAnEvent();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
