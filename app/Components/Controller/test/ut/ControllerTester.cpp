// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Controller/test/ut/ControllerTester.hpp"

namespace Kit {

ControllerTester::ControllerTester()
    : ControllerGTestBase("ControllerTester", MAX_HISTORY_SIZE), component("Controller") {
    this->initComponents();
    this->connectPorts();
}

ControllerTester::~ControllerTester() {}

ControlStatus ControllerTester::status() {
    return this->invoke_to_statusGet(0);
}

void ControllerTester::setpointInRangeIsAccepted() {
    this->sendCmd_SET_SETPOINT(0, 7, 2000);
    ASSERT_CMD_RESPONSE_SIZE(1);
    ASSERT_CMD_RESPONSE(0, ControllerComponentBase::OPCODE_SET_SETPOINT, 7, Fw::CmdResponse::OK);
    ASSERT_EVENTS_SetpointChanged_SIZE(1);
    ASSERT_EVENTS_SetpointChanged(0, 2000);
    EXPECT_EQ(status().get_setpoint(), 2000);
}

void ControllerTester::setpointOutOfRangeIsRejected() {
    const I32 before = status().get_setpoint();
    this->sendCmd_SET_SETPOINT(0, 8, Controller::SETPOINT_LIMIT + 1);
    ASSERT_CMD_RESPONSE(0, ControllerComponentBase::OPCODE_SET_SETPOINT, 8, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_SetpointRejected_SIZE(1);
    ASSERT_EVENTS_SetpointRejected(0, Controller::SETPOINT_LIMIT + 1, Controller::SETPOINT_LIMIT);
    EXPECT_EQ(status().get_setpoint(), before);
}

void ControllerTester::loopSettlesOnTheSetpoint() {
    this->sendCmd_SET_SETPOINT(0, 1, 5000);
    // Two seconds of 1 kHz steps
    for (U32 i = 0; i < 2000; i++) {
        this->invoke_to_schedIn(0, 0);
    }
    const ControlStatus s = status();
    const I32 error = s.get_setpoint() - s.get_measurement();
    EXPECT_LT(error < 0 ? -error : error, 200);  // within noise plus filter lag
    EXPECT_GT(s.get_actuator(), 0);
}

void ControllerTester::telemetryIsDecimated() {
    for (U32 i = 0; i < Controller::TLM_DECIMATION * 3; i++) {
        this->invoke_to_schedIn(0, 0);
    }
    ASSERT_TLM_Measurement_SIZE(3);
    ASSERT_TLM_Setpoint_SIZE(3);
}

}  // namespace Kit
