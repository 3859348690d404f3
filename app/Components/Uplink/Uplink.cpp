// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Uplink.cpp
// \brief  Scripted command uplink into the command dispatcher
// ======================================================================
#include "app/Components/Uplink/Uplink.hpp"
#include <Fw/Com/ComPacket.hpp>

namespace Kit {

Uplink::Frame Uplink::commandFrame(U32 cycle, FwOpcodeType opcode, const U8* args, FwSizeType argSize) {
    Frame frame = {};
    frame.cycle = cycle;
    Fw::ExternalSerializeBuffer buffer(frame.bytes, FRAME_MAX);
    Fw::SerializeStatus status =
        buffer.serializeFrom(static_cast<FwPacketDescriptorType>(Fw::ComPacketType::FW_PACKET_COMMAND));
    FW_ASSERT(status == Fw::FW_SERIALIZE_OK, status);
    status = buffer.serializeFrom(opcode);
    FW_ASSERT(status == Fw::FW_SERIALIZE_OK, status);
    if (argSize > 0) {
        FW_ASSERT(args != nullptr);
        status = buffer.serializeFrom(args, argSize, Fw::Serialization::OMIT_LENGTH);
        FW_ASSERT(status == Fw::FW_SERIALIZE_OK, status);
    }
    frame.size = static_cast<U8>(buffer.getSize());
    frame.expected = Fw::CmdResponse::OK;
    return frame;
}

Uplink::Frame Uplink::rawFrame(U32 cycle, const U8* bytes, FwSizeType size, Fw::CmdResponse expected) {
    FW_ASSERT(size <= FRAME_MAX, static_cast<FwAssertArgType>(size));
    FW_ASSERT(bytes != nullptr || size == 0);
    Frame frame = {};
    frame.cycle = cycle;
    for (FwSizeType i = 0; i < size; i++) {
        frame.bytes[i] = bytes[i];
    }
    frame.size = static_cast<U8>(size);
    frame.expected = expected;
    return frame;
}

Uplink::Uplink(const char* const compName)
    : UplinkComponentBase(compName),
      m_frames(nullptr),
      m_count(0),
      m_cycle(0),
      m_playStart(0),
      m_sent(0),
      m_rejected(0) {}

Uplink::~Uplink() {}

void Uplink::play(Frame* frames, FwSizeType count) {
    FW_ASSERT(count <= SCRIPT_MAX, static_cast<FwAssertArgType>(count));
    FW_ASSERT(frames != nullptr || count == 0);
    for (FwSizeType i = 0; i < count; i++) {
        FW_ASSERT(frames[i].size <= FRAME_MAX, static_cast<FwAssertArgType>(i));
        frames[i].result = FrameResult();
    }
    m_frames = frames;
    m_count = count;
    m_playStart = m_cycle;
}

void Uplink::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    for (FwSizeType i = 0; i < m_count; i++) {
        Frame& frame = m_frames[i];
        if (frame.cycle != m_cycle - m_playStart) {
            continue;
        }
        Fw::ComBuffer packet;
        const Fw::SerializeStatus status =
            packet.serializeFrom(frame.bytes, frame.size, Fw::Serialization::OMIT_LENGTH);
        FW_ASSERT(status == Fw::FW_SERIALIZE_OK, status);
        frame.result.sent = true;
        m_sent++;
        this->log_ACTIVITY_LO_FrameSent(static_cast<U32>(i), frame.size);
        // The frame index travels as the context and comes back as cmdSeq
        this->cmdOut_out(0, packet, static_cast<U32>(i));
    }
    this->tlmWrite_FramesSent(m_sent);
    m_cycle++;
}

void Uplink::cmdResponseIn_handler(FwIndexType portNum,
                                   FwOpcodeType opCode,
                                   U32 cmdSeq,
                                   const Fw::CmdResponse& response) {
    (void)portNum;
    FW_ASSERT(cmdSeq < m_count, static_cast<FwAssertArgType>(cmdSeq));
    FrameResult& result = m_frames[cmdSeq].result;
    result.answered = true;
    result.opcode = opCode;
    result.response = response;
    if (response != Fw::CmdResponse::OK) {
        m_rejected++;
        this->tlmWrite_FramesRejected(m_rejected);
    }
    this->log_ACTIVITY_HI_FrameAnswered(cmdSeq, opCode, response);
}

}  // namespace Kit
