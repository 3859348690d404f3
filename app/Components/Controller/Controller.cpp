// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Controller.cpp
// \brief  1 kHz filtered PI loop on a simulated plant
//
// Integer arithmetic with power-of-two gains: a realistic amount of work for a
// Cortex-M3 control loop, bit-for-bit repeatable under QEMU icount.
// ======================================================================
#include "app/Components/Controller/Controller.hpp"
#include "app/Components/Controller/FppConstantsAc.hpp"

namespace Kit {

namespace {
constexpr I32 NOISE = 64;        // sensor noise amplitude, counts
constexpr I32 PLANT_SHIFT = 5;   // plant time constant: 32 steps
constexpr I32 FILTER_SHIFT = 3;  // filter time constant: 8 steps
constexpr I32 INTEGRAL_LIMIT = 1 << 20;

I32 clamp(I32 value, I32 limit) {
    return value > limit ? limit : (value < -limit ? -limit : value);
}
}  // namespace

Controller::Controller(const char* const compName)
    : ControllerComponentBase(compName),
      m_setpoint(1000),
      m_plant(0),
      m_filtered(0),
      m_integral(0),
      m_output(0),
      m_rng(12345u),
      m_cycles(0),
      m_kpShift(ControllerGains::kpShift),
      m_kiShift(ControllerGains::kiShift) {}

Controller::~Controller() {}

I32 Controller::noise() {
    m_rng = m_rng * 1664525u + 1013904223u;
    return static_cast<I32>((m_rng >> 16) % (2 * NOISE + 1)) - NOISE;
}

void Controller::step() {
    // Plant: first-order lag toward the actuator output
    m_plant += (m_output - m_plant) >> PLANT_SHIFT;
    // Sensor reading and low-pass filter
    const I32 sensor = m_plant + this->noise();
    m_filtered += (sensor - m_filtered) >> FILTER_SHIFT;
    // PI with anti-windup
    const I32 error = m_setpoint - m_filtered;
    m_integral = clamp(m_integral + error, INTEGRAL_LIMIT);
    m_output = clamp((error >> m_kpShift) + (m_integral >> m_kiShift), OUTPUT_LIMIT);
    m_cycles++;
}

void Controller::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    this->step();
    if ((m_cycles % TLM_DECIMATION) == 0) {
        this->tlmWrite_Setpoint(m_setpoint);
        this->tlmWrite_Measurement(m_filtered);
        this->tlmWrite_Output(m_output);
    }
}

ControlStatus Controller::statusGet_handler(FwIndexType portNum) {
    (void)portNum;
    return ControlStatus(m_setpoint, m_filtered, m_output);
}

void Controller::SET_SETPOINT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, I32 setpoint) {
    if (setpoint > SETPOINT_LIMIT || setpoint < -SETPOINT_LIMIT) {
        this->log_WARNING_LO_SetpointRejected(setpoint, SETPOINT_LIMIT);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_setpoint = setpoint;
    this->log_ACTIVITY_HI_SetpointChanged(setpoint);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

// The gains change between two steps: the parameter hooks run in the
// commanding context (or at start-up), the step in the 1 kHz group's, and
// each shift is one byte, written whole.
void Controller::parametersLoaded() {
    (void)this->applyGains();
    this->log_ACTIVITY_HI_GainsApplied(m_kpShift, m_kiShift);
}

void Controller::parameterUpdated(FwPrmIdType id) {
    (void)id;
    if (this->applyGains()) {
        this->log_ACTIVITY_HI_GainsApplied(m_kpShift, m_kiShift);
    }
}

bool Controller::applyGains() {
    Fw::ParamValid kpValid;
    Fw::ParamValid kiValid;
    const U8 kpShift = this->paramGet_KP_SHIFT(kpValid);
    const U8 kiShift = this->paramGet_KI_SHIFT(kiValid);
    // A shift past the word's width would be undefined; F´ stores what the
    // ground set, so the controller keeps its gains and says why
    if (kpShift > ControllerGains::maxShift || kiShift > ControllerGains::maxShift) {
        this->log_WARNING_LO_GainRejected(kpShift > ControllerGains::maxShift ? kpShift : kiShift,
                                          ControllerGains::maxShift);
        return false;
    }
    const bool changed = kpShift != m_kpShift || kiShift != m_kiShift;
    m_kpShift = kpShift;
    m_kiShift = kiShift;
    return changed;
}

}  // namespace Kit
