// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Faults.cpp
// \brief  Fault injection by command
// ======================================================================
#include "app/Components/Faults/Faults.hpp"
#include "app/Components/Timing/Busy.hpp"

namespace Kit {

namespace {
// One recursion level's frame: large enough that few levels cover the stack,
// small enough that the overflow is reached gradually, as a real one is
constexpr U32 FRAME_BYTES = 64;

// Uses `levels` frames of stack, each filled, so the stack really grows (and
// a guard below it is really overwritten). The addition after the call keeps
// the compiler from turning the recursion into a loop.
__attribute__((noinline)) U32 useStack(U32 levels) {
    volatile U8 frame[FRAME_BYTES];
    for (U32 i = 0; i < FRAME_BYTES; i++) {
        frame[i] = static_cast<U8>(levels + i);
    }
    if (levels == 0) {
        return frame[0];
    }
    return useStack(levels - 1) + frame[levels % FRAME_BYTES];
}
}  // namespace

Faults::Faults(const char* const compName) : FaultsComponentBase(compName), m_overrunUs(), m_lcg(1) {}

Faults::~Faults() {}

void Faults::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < NUM_SCHEDIN_INPUT_PORTS, static_cast<FwAssertArgType>(portNum));
    const U32 us = m_overrunUs[portNum];
    if (us == 0) {
        return;
    }
    m_overrunUs[portNum] = 0;
    m_lcg = busyFor(us, m_lcg);
    this->log_WARNING_LO_OverrunInjected(static_cast<U8>(portNum), us);
}

void Faults::OVERRUN_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U8 rateGroup, U32 us) {
    if (rateGroup >= NUM_SCHEDIN_INPUT_PORTS || us > OVERRUN_MAX_US) {
        const bool groupBad = rateGroup >= NUM_SCHEDIN_INPUT_PORTS;
        this->log_WARNING_LO_InjectionRejected(groupBad ? rateGroup : us,
                                               groupBad ? NUM_SCHEDIN_INPUT_PORTS - 1 : OVERRUN_MAX_US);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_overrunUs[rateGroup] = us;
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Faults::STACK_OVERFLOW_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 bytes) {
    if (bytes > STACK_MAX_BYTES) {
        this->log_WARNING_LO_InjectionRejected(bytes, STACK_MAX_BYTES);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    this->log_WARNING_HI_StackOverflowInjected(bytes);
    m_lcg += useStack(bytes / FRAME_BYTES);
    // Only reached if the overflow went unnoticed until here; the stack
    // protection stops the run at its next check
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Faults::ASSERT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 code) {
    FW_ASSERT(0, static_cast<FwAssertArgType>(code));
    // F´'s assert hook raises a FATAL event and returns; what follows runs
    // until the fatal handler stops the system
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::EXECUTION_ERROR);
}

}  // namespace Kit
