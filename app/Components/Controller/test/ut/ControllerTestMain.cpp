// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Controller/test/ut/ControllerTester.hpp"

TEST(Controller, SetpointInRangeIsAccepted) {
    Kit::ControllerTester tester;
    tester.setpointInRangeIsAccepted();
}

TEST(Controller, SetpointOutOfRangeIsRejected) {
    Kit::ControllerTester tester;
    tester.setpointOutOfRangeIsRejected();
}

TEST(Controller, LoopSettlesOnTheSetpoint) {
    Kit::ControllerTester tester;
    tester.loopSettlesOnTheSetpoint();
}

TEST(Controller, TelemetryIsDecimated) {
    Kit::ControllerTester tester;
    tester.telemetryIsDecimated();
}

TEST(Controller, GainsLoadedFromTheDatabase) {
    Kit::ControllerTester tester;
    tester.gainsLoadedFromTheDatabase();
}

TEST(Controller, GainOutOfRangeIsRejected) {
    Kit::ControllerTester tester;
    tester.gainOutOfRangeIsRejected();
}

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
