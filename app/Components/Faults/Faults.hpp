// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Faults.hpp
// \brief  Fault injection by command
// ======================================================================
#ifndef KIT_FAULTS_HPP
#define KIT_FAULTS_HPP

#include "app/Components/Faults/FaultsComponentAc.hpp"

namespace Kit {

class Faults final : public FaultsComponentBase {
  public:
    static constexpr U32 OVERRUN_MAX_US = 50000;
    static constexpr U32 STACK_MAX_BYTES = 8192;

    explicit Faults(const char* const compName);
    ~Faults();

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;

    void OVERRUN_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U8 rateGroup, U32 us) override;
    void STACK_OVERFLOW_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 bytes) override;
    void ASSERT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 code) override;

    //! Armed overrun per rate group, in microseconds (0: none); set by a
    //! command, taken by the group's next cycle
    volatile U32 m_overrunUs[NUM_SCHEDIN_INPUT_PORTS];
    U32 m_lcg;
};

}  // namespace Kit

#endif
