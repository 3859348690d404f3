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

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
