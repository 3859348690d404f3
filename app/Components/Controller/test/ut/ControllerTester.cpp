// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Controller/test/ut/ControllerTester.hpp"
#include "app/Components/Controller/FppConstantsAc.hpp"

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

void ControllerTester::gainsLoadedFromTheDatabase() {
    // Nothing in the database: the defaults, said once
    this->component.loadParameters();
    ASSERT_EVENTS_GainsApplied_SIZE(1);
    ASSERT_EVENTS_GainsApplied(0, ControllerGains::kpShift, ControllerGains::kiShift);
    // A saved gain, loaded at the next start-up
    this->paramSet_KP_SHIFT(3, Fw::ParamValid::VALID);
    this->component.loadParameters();
    ASSERT_EVENTS_GainsApplied(1, 3, ControllerGains::kiShift);
    // Set from the ground: applied at once; setting it again changes nothing
    this->paramSet_KI_SHIFT(4, Fw::ParamValid::VALID);
    this->paramSend_KI_SHIFT(0, 2);
    ASSERT_EVENTS_GainsApplied_SIZE(3);
    ASSERT_EVENTS_GainsApplied(2, 3, 4);
    this->paramSend_KI_SHIFT(0, 3);
    ASSERT_EVENTS_GainsApplied_SIZE(3);
}

void ControllerTester::gainOutOfRangeIsRejected() {
    this->component.loadParameters();
    this->paramSet_KP_SHIFT(ControllerGains::maxShift + 1, Fw::ParamValid::VALID);
    this->paramSend_KP_SHIFT(0, 1);
    ASSERT_EVENTS_GainRejected_SIZE(1);
    ASSERT_EVENTS_GainRejected(0, ControllerGains::maxShift + 1, ControllerGains::maxShift);
    ASSERT_EVENTS_GainsApplied_SIZE(1);  // the defaults, at the load only
    // The loop still runs on the defaults
    this->sendCmd_SET_SETPOINT(0, 2, 5000);
    for (U32 i = 0; i < 2000; i++) {
        this->component.step();
    }
    EXPECT_NEAR(status().get_measurement(), 5000, 200);
}

}  // namespace Kit
