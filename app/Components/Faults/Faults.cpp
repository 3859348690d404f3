// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Faults.cpp
// \brief  Fault injection by command
// ======================================================================
#include "app/Components/Faults/Faults.hpp"
#include <Os/FileSystem.hpp>
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

Faults::Faults(const char* const compName) : FaultsComponentBase(compName), m_overrunUs(), m_lcg(1), m_restartIn(0) {}

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

Os::File::Status Faults::flip(const Fw::CmdStringArg& file, U32 offset) {
    U8 byte = 0;
    FwSizeType count = 1;
    Os::File reader;
    Os::File::Status status = reader.open(file.toChar(), Os::File::OPEN_READ);
    if (status == Os::File::OP_OK) {
        status = reader.seek(static_cast<FwSignedSizeType>(offset), Os::File::ABSOLUTE);
    }
    if (status == Os::File::OP_OK) {
        status = reader.read(&byte, count, Os::File::WAIT);
    }
    reader.close();
    if (status != Os::File::OP_OK) {
        return status;
    }
    // F´'s OPEN_WRITE keeps the file's content (on POSIX and MicroFs alike):
    // the one byte is written over in place
    byte = static_cast<U8>(~byte);
    Os::File writer;
    status = writer.open(file.toChar(), Os::File::OPEN_WRITE);
    if (status == Os::File::OP_OK) {
        status = writer.seek(static_cast<FwSignedSizeType>(offset), Os::File::ABSOLUTE);
    }
    if (status == Os::File::OP_OK) {
        status = writer.write(&byte, count, Os::File::WAIT);
    }
    return status;
}

Os::File::Status Faults::truncate(const Fw::CmdStringArg& file, U32 size) {
    FW_ASSERT(size <= TRUNCATE_MAX_BYTES, static_cast<FwAssertArgType>(size));
    U8 kept[TRUNCATE_MAX_BYTES];
    FwSizeType count = size;
    Os::File reader;
    Os::File::Status status = reader.open(file.toChar(), Os::File::OPEN_READ);
    if (status == Os::File::OP_OK && size > 0) {
        status = reader.read(kept, count, Os::File::WAIT);
    }
    reader.close();
    if (status != Os::File::OP_OK) {
        return status;
    }
    // Created anew, so the file ends where the kept bytes do
    Os::File writer;
    status = writer.open(file.toChar(), Os::File::OPEN_CREATE, Os::File::OVERWRITE);
    if (status == Os::File::OP_OK && size > 0) {
        status = writer.write(kept, count, Os::File::WAIT);
    }
    return status;
}

void Faults::CORRUPT_FILE_cmdHandler(FwOpcodeType opCode,
                                     U32 cmdSeq,
                                     const Fw::CmdStringArg& file,
                                     FileDamage damage,
                                     U32 offset) {
    FwSizeType size = 0;
    const Os::FileSystem::Status found = Os::FileSystem::getFileSize(file.toChar(), size);
    if (found != Os::FileSystem::OP_OK) {
        this->log_WARNING_LO_FileNotCorrupted(file, static_cast<I32>(found));
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::EXECUTION_ERROR);
        return;
    }
    // TRUNCATE keeps at most the whole file (and what the stack holds);
    // FLIP needs a byte at offset
    const U32 bytes = static_cast<U32>(size);
    const bool truncating = damage == FileDamage::TRUNCATE;
    const U32 limit =
        truncating ? (bytes < TRUNCATE_MAX_BYTES ? bytes : TRUNCATE_MAX_BYTES) : (bytes > 0 ? bytes - 1 : 0);
    if ((!truncating && bytes == 0) || offset > limit) {
        this->log_WARNING_LO_InjectionRejected(offset, limit);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    const Os::File::Status status = truncating ? this->truncate(file, offset) : this->flip(file, offset);
    if (status != Os::File::OP_OK) {
        this->log_WARNING_LO_FileNotCorrupted(file, static_cast<I32>(status));
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
