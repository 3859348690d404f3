// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Load.cpp
// \brief  Background load, set at run time by command
// ======================================================================
#include "app/Components/Load/Load.hpp"
#include "app/Components/Timing/Busy.hpp"

#include <Os/File.hpp>

namespace Kit {

Load::Load(const char* const compName)
    : LoadComponentBase(compName),
      m_sliceUs(0),
      m_burstCount(0),
      m_burstUs(0),
      m_downlinkPackets(0),
      m_sliceEvery(1),
      m_burstEvery(1),
      m_downlinkSequence(0),
      m_processed(0),
      m_dropped(0),
      m_slices(0),
      m_bursts(0),
      m_lcg(1) {}

Load::~Load() {}

void Load::compute(U32 us) {
    if (us > 0) {
        m_lcg = busyFor(us, m_lcg);
    }
    m_processed++;
}

void Load::sliceIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    m_slices++;
    // One slice each m_sliceEvery messages (SET_PACE); the others are
    // processed with no computation
    this->compute(((m_slices % m_sliceEvery) == 0) ? m_sliceUs : 0);
    const U32 packets = m_downlinkPackets;
    for (U32 i = 0; i < packets; i++) {
        this->log_ACTIVITY_LO_DownlinkLoadPacket(m_downlinkSequence);
        m_downlinkSequence++;
    }
    this->tlmWrite_Processed(m_processed);
}

void Load::burstIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    m_bursts++;
    if ((m_bursts % m_burstEvery) != 0) {
        return;  // one burst each m_burstEvery calls (SET_PACE)
    }
    const U32 count = m_burstCount;
    for (U32 i = 0; i < count; i++) {
        this->ioOut_out(0, i);
    }
}

void Load::ioIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    this->compute(m_burstUs);
}

void Load::dropOne() {
    m_dropped++;
    this->log_WARNING_HI_MessagesDropped(m_dropped);
    this->tlmWrite_Dropped(m_dropped);
}

void Load::sliceIn_overflowHook(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    this->dropOne();
}

void Load::ioIn_overflowHook(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    this->dropOne();
}

void Load::SET_SLICE_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 us) {
    if (us > SLICE_MAX_US) {
        this->log_WARNING_LO_LoadRejected(us, SLICE_MAX_US);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_sliceUs = us;
    this->log_ACTIVITY_HI_LoadSet(us, m_burstCount, m_burstUs);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Load::SET_BURST_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 count, U32 us) {
    if (count > BURST_MAX || us > SLICE_MAX_US) {
        const bool countBad = count > BURST_MAX;
        this->log_WARNING_LO_LoadRejected(countBad ? count : us, countBad ? BURST_MAX : SLICE_MAX_US);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_burstCount = count;
    m_burstUs = us;
    this->log_ACTIVITY_HI_LoadSet(m_sliceUs, count, us);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Load::SET_PACE_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 sliceEvery, U32 burstEvery) {
    const bool sliceBad = sliceEvery == 0 || sliceEvery > PACE_MAX;
    if (sliceBad || burstEvery == 0 || burstEvery > PACE_MAX) {
        this->log_WARNING_LO_LoadRejected(sliceBad ? sliceEvery : burstEvery, PACE_MAX);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_sliceEvery = sliceEvery;
    m_burstEvery = burstEvery;
    this->log_ACTIVITY_HI_PaceSet(sliceEvery, burstEvery);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Load::SET_DOWNLINK_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 packets) {
    if (packets > DOWNLINK_MAX) {
        this->log_WARNING_LO_LoadRejected(packets, DOWNLINK_MAX);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    m_downlinkPackets = packets;
    this->log_ACTIVITY_HI_DownlinkLoadSet(packets);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

void Load::FILL_FILE_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, const Fw::CmdStringArg& file, U32 bytes, U32 seed) {
    if (seed == 0) {
        // xorshift's one fixed point: a stream of zeros
        this->log_WARNING_LO_LoadRejected(seed, 0);
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::VALIDATION_ERROR);
        return;
    }
    Os::File out;
    Os::File::Status status = out.open(file.toChar(), Os::File::OPEN_CREATE, Os::File::OverwriteType::OVERWRITE);
    U32 written = 0;
    Pattern pattern(seed);
    // Bounded: each pass writes a whole chunk or ends the loop; a file
    // system that is full writes less (MicroFs: what its file holds)
    while (status == Os::File::OP_OK && written < bytes) {
        U8 chunk[FILL_CHUNK_BYTES];
        const U32 left = bytes - written;
        const FwSizeType wanted = left < FILL_CHUNK_BYTES ? left : FILL_CHUNK_BYTES;
        for (FwSizeType index = 0; index < wanted; index++) {
            chunk[index] = pattern.next();
        }
        FwSizeType size = wanted;
        status = out.write(chunk, size, Os::File::WaitType::NO_WAIT);
        written += static_cast<U32>(size);
        if (size < wanted) {
            break;
        }
    }
    out.close();
    if (status != Os::File::OP_OK || written == 0) {
        this->log_WARNING_LO_FileNotFilled(file, written, static_cast<I32>(status));
        this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::EXECUTION_ERROR);
        return;
    }
    this->log_ACTIVITY_HI_FileFilled(file, written, seed);
    this->cmdResponse_out(opCode, cmdSeq, Fw::CmdResponse::OK);
}

}  // namespace Kit
