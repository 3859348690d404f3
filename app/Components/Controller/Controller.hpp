// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Controller.hpp
// \brief  1 kHz filtered PI loop on a simulated plant
// ======================================================================
#ifndef KIT_CONTROLLER_HPP
#define KIT_CONTROLLER_HPP

#include "app/Components/Controller/ControllerComponentAc.hpp"

namespace Kit {

class Controller final : public ControllerComponentBase {
  public:
    static constexpr I32 SETPOINT_LIMIT = 20000;
    static constexpr I32 OUTPUT_LIMIT = 30000;
    //! Telemetry is written every TLM_DECIMATION cycles (10 Hz at 1 kHz)
    static constexpr U32 TLM_DECIMATION = 100;

    explicit Controller(const char* const compName);
    ~Controller();

    //! One control step; public so tests can drive it without a port
    void step();

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    ControlStatus statusGet_handler(FwIndexType portNum) override;
    void SET_SETPOINT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, I32 setpoint) override;
    void parametersLoaded() override;
    void parameterUpdated(FwPrmIdType id) override;

    //! Takes the gains from the parameters, unless one is out of range;
    //! whether they changed
    bool applyGains();

    //! Deterministic sensor noise in [-NOISE, NOISE] (linear congruential generator)
    I32 noise();

    I32 m_setpoint;
    I32 m_plant;     //!< simulated plant state
    I32 m_filtered;  //!< low-pass filtered measurement
    I32 m_integral;
    I32 m_output;
    U32 m_rng;
    U32 m_cycles;
    U8 m_kpShift;  //!< proportional gain, 1/2^m_kpShift
    U8 m_kiShift;  //!< integral gain, 1/2^m_kiShift
};

}  // namespace Kit

#endif
