// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Faults.cpp
// \brief  Fault injection by command
// ======================================================================
#include "app/Components/Faults/Faults.hpp"
#include <Os/File.hpp>
#include "app/Components/Faults/Restart.hpp"
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

Faults::Faults(const char* const compName)
    : FaultsComponentBase(compName), m_overrunUs(), m_lcg(1), m_restartIn(0), m_file() {}

Faults::~Faults() {}

void Faults::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)context;
    FW_ASSERT(portNum >= 0 && portNum < NUM_SCHEDIN_INPUT_PORTS, static_cast<FwAssertArgType>(portNum));
    if (portNum == NUM_SCHEDIN_INPUT_PORTS - 1 && m_restartIn > 0) {
        m_restartIn = m_restartIn - 1;
        if (m_restartIn == 0) {
            Restart::warm();
        }
    }
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

I32 Faults::readWhole(const Fw::CmdStringArg& file) {
    Os::File reader;
    Os::File::Status status = reader.open(file.toChar(), Os::File::OPEN_READ);
    FwSizeType size = 0;
    if (status == Os::File::OP_OK) {
        status = reader.size(size);
    }
    if (status == Os::File::OP_OK && size > FILE_MAX_BYTES) {
        this->log_WARNING_LO_InjectionRejected(static_cast<U32>(size), FILE_MAX_BYTES);
        return -1;
    }
    if (status == Os::File::OP_OK) {
        status = reader.read(m_file, size, Os::File::WAIT);
    }
    if (status != Os::File::OP_OK) {
        this->log_WARNING_LO_FileNotCorrupted(file, static_cast<I32>(status));
        return -1;
    }
    return static_cast<I32>(size);
}

bool Faults::writeWhole(const Fw::CmdStringArg& file, U32 size) {
    // Created anew, so the file ends where this content does (a file
    // system may keep a longer old content past a plain write's end)
    Os::File writer;
    Os::File::Status status = writer.open(file.toChar(), Os::File::OPEN_CREATE, Os::File::OVERWRITE);
    FwSizeType written = size;
    if (status == Os::File::OP_OK && size > 0) {
        status = writer.write(m_file, written, Os::File::WAIT);
    }
    if (status != Os::File::OP_OK || written != size) {
        this->log_WARNING_LO_FileNotCorrupted(file, static_cast<I32>(status));
        return false;
    }
    return true;
}

void Faults::CORRUPT_FILE_cmdHandler(FwOpcodeType opCode,
                                     U32 cmdSeq,
                                     const Fw::CmdStringArg& file,
                                     FileDamage damage,
                                     U32 offset) {
    const I32 size = this->readWhole(file);
    if (size < 0) {
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::EXECUTION_ERROR);
        return;
    }
    // TRUNCATE keeps at most the whole file; FLIP needs a byte at offset
    const U32 bytes = static_cast<U32>(size);
    const bool truncate = damage == FileDamage::TRUNCATE;
    if ((truncate && offset > bytes) || (!truncate && offset >= bytes)) {
        this->log_WARNING_LO_InjectionRejected(offset, truncate ? bytes : bytes - 1);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    if (!truncate) {
        m_file[offset] = static_cast<U8>(~m_file[offset]);
    }
    if (!this->writeWhole(file, truncate ? offset : bytes)) {
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::EXECUTION_ERROR);
        return;
    }
    this->log_WARNING_LO_FileCorrupted(file, damage, offset, bytes);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Faults::RESTART_cmdHandler(FwOpcodeType opCode, U32 cmdSeq) {
    this->log_WARNING_HI_RestartArmed(RESTART_DELAY_CYCLES);
    m_restartIn = RESTART_DELAY_CYCLES;
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

}  // namespace Kit
