// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Faults.hpp
// \brief  Fault injection by command
// ======================================================================
#ifndef KIT_FAULTS_HPP
#define KIT_FAULTS_HPP

#include <Os/File.hpp>
#include "app/Components/Faults/FaultsComponentAc.hpp"

namespace Kit {

class Faults final : public FaultsComponentBase {
  public:
    static constexpr U32 OVERRUN_MAX_US = 50000;
    static constexpr U32 STACK_MAX_BYTES = 8192;
    //! The most a TRUNCATE keeps (its bytes are copied through the stack)
    static constexpr U32 TRUNCATE_MAX_BYTES = 32;
    //! Cycles of the slowest rate group (10 Hz) from RESTART to the restart
    static constexpr U32 RESTART_DELAY_CYCLES = 5;

    explicit Faults(const char* const compName);
    ~Faults();

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;

    void OVERRUN_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U8 rateGroup, U32 us) override;
    void STACK_OVERFLOW_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 bytes) override;
    void ASSERT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 code) override;
    void CORRUPT_FILE_cmdHandler(FwOpcodeType opCode,
                                 U32 cmdSeq,
                                 const Fw::CmdStringArg& file,
                                 FileDamage damage,
                                 U32 offset) override;
    void RESTART_cmdHandler(FwOpcodeType opCode, U32 cmdSeq) override;

    //! Inverts the byte at `offset` of `file`, in place
    Os::File::Status flip(const Fw::CmdStringArg& file, U32 offset);
    //! Cuts `file` to its first `size` bytes (at most TRUNCATE_MAX_BYTES)
    Os::File::Status truncate(const Fw::CmdStringArg& file, U32 size);

    //! Armed overrun per rate group, in microseconds (0: none); set by a
    //! command, taken by the group's next cycle
    volatile U32 m_overrunUs[NUM_SCHEDIN_INPUT_PORTS];
    U32 m_lcg;
    //! Cycles of the slowest group left before an armed restart (0: none)
    volatile U32 m_restartIn;
};

}  // namespace Kit

#endif
