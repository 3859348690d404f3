// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Faults/test/ut/FaultsTester.hpp"

TEST(Faults, OverrunRunsOnceInItsRateGroup) {
    Kit::FaultsTester tester;
    tester.overrunRunsOnceInItsRateGroup();
}

TEST(Faults, InjectionsAboveTheirLimitsAreRejected) {
    Kit::FaultsTester tester;
    tester.injectionsAboveTheirLimitsAreRejected();
}

TEST(Faults, StackUseWithinTheLimitCompletes) {
    Kit::FaultsTester tester;
    tester.stackUseWithinTheLimitCompletes();
}

TEST(Faults, AssertReachesTheAssertHook) {
    Kit::FaultsTester tester;
    tester.assertReachesTheAssertHook();
}

TEST(Faults, FileDamagedInPlace) {
    Kit::FaultsTester tester;
    tester.fileDamagedInPlace();
}

TEST(Faults, FileDamageRefusedWhereItCannotBeDone) {
    Kit::FaultsTester tester;
    tester.fileDamageRefusedWhereItCannotBeDone();
}

TEST(Faults, RestartComesAfterItsDelay) {
    Kit::FaultsTester tester;
    tester.restartComesAfterItsDelay();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
