// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  HeaterControl.cpp
// \brief  Bang-bang heater control with hysteresis, and its duty report
// ======================================================================
#include "Thermal/Components/HeaterControl/HeaterControl.hpp"
#include <Fw/Types/Assert.hpp>

namespace Thermal {

HeaterControl::HeaterControl(const char* const compName)
    : HeaterControlComponentBase(compName), m_zones(), m_cycles(0) {
    for (Zone& zone : m_zones) {
        zone = {SETPOINT_DEFAULT_MC, false, 0};
    }
}

HeaterControl::~HeaterControl() {}

void HeaterControl::controlIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    for (U8 index = 0; index < ZONES; index++) {
        Zone& zone = m_zones[index];
        const I32 temperature = this->temperatureGet_out(0, index);
        const bool on =
            zone.on ? (temperature < zone.setpointMc + HYSTERESIS_MC) : (temperature < zone.setpointMc - HYSTERESIS_MC);
        if (on != zone.on) {
            zone.on = on;
            this->heaterOut_out(0, index, on);
            this->log_ACTIVITY_LO_HeaterSwitched(index, on);
        }
        zone.onCycles += on ? 1U : 0U;
    }
    m_cycles++;
}

void HeaterControl::reportIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    U8 duty[ZONES] = {};
    for (U8 index = 0; index < ZONES; index++) {
        const U32 onCycles =
            (m_zones[index].onCycles < CYCLES_PER_REPORT) ? m_zones[index].onCycles : CYCLES_PER_REPORT;
        duty[index] = static_cast<U8>(onCycles * 100U / CYCLES_PER_REPORT);
        m_zones[index].onCycles = 0;
    }
    this->tlmWrite_Duty0(duty[0]);
    this->tlmWrite_Duty1(duty[1]);
    this->tlmWrite_Cycles(m_cycles);
}

void HeaterControl::SET_SETPOINT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U8 zone, I32 setpointMc) {
    if (zone >= ZONES || setpointMc < SETPOINT_MIN_MC || setpointMc > SETPOINT_MAX_MC) {
        this->log_WARNING_LO_SetpointRejected(zone, setpointMc);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_zones[zone].setpointMc = setpointMc;
    this->log_ACTIVITY_HI_SetpointChanged(zone, setpointMc);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

}  // namespace Thermal
