// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  HeaterControl.hpp
// \brief  Bang-bang heater control with hysteresis, and its duty report
// ======================================================================
#ifndef THERMAL_HEATERCONTROL_HPP
#define THERMAL_HEATERCONTROL_HPP

#include "Thermal/Components/HeaterControl/HeaterControlComponentAc.hpp"
#include "Thermal/Components/Ports/FppConstantsAc.hpp"

namespace Thermal {

class HeaterControl final : public HeaterControlComponentBase {
  public:
    static constexpr U8 ZONES = zones;
    static_assert(ZONES == 2, "HeaterControl.fpp has a duty channel for each of two zones");
    //! The setpoints a heater can hold, and where each zone starts
    static constexpr I32 SETPOINT_MIN_MC = -20000;
    static constexpr I32 SETPOINT_MAX_MC = 40000;
    static constexpr I32 SETPOINT_DEFAULT_MC = 15000;
    //! Below the setpoint by this much the heater goes on, above it off
    static constexpr I32 HYSTERESIS_MC = 500;
    //! Control cycles per report (10 Hz control, 1 Hz report)
    static constexpr U32 CYCLES_PER_REPORT = 10;

    explicit HeaterControl(const char* const compName);
    ~HeaterControl();

  private:
    void controlIn_handler(FwIndexType portNum, U32 context) override;
    void reportIn_handler(FwIndexType portNum, U32 context) override;
    void SET_SETPOINT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U8 zone, I32 setpointMc) override;

    struct Zone {
        I32 setpointMc;
        bool on;
        U32 onCycles;  //!< control cycles with the heater on since the last report
    };
    Zone m_zones[ZONES];
    U32 m_cycles;
};

}  // namespace Thermal

#endif
