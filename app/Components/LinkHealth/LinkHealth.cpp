// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  LinkHealth.cpp
// \brief  The ground link's rejections, by reason, as telemetry
// ======================================================================
#include "app/Components/LinkHealth/LinkHealth.hpp"

namespace Kit {

LinkHealth::LinkHealth(const char* const compName)
    : LinkHealthComponentBase(compName),
      m_detector(),
      m_unknownPackets(0),
      m_inFlight(0),
      m_commandsDropped(0),
      m_inFlightLimit(0),
      m_uartCounts(nullptr),
      m_eventRoom(nullptr) {}

LinkHealth::~LinkHealth() {}

void LinkHealth::configure(FwSizeType accumulatorSize,
                           FwSizeType largestFrame,
                           U32 commandsInFlight,
                           UartCountsSource uartCounts,
                           EventRoomSource eventRoom) {
    FW_ASSERT(commandsInFlight > 0);
    FW_ASSERT(uartCounts != nullptr);
    FW_ASSERT(eventRoom != nullptr);
    m_eventRoom = eventRoom;
    m_detector.setCapacity(accumulatorSize, largestFrame);
    m_inFlightLimit = commandsInFlight;
    m_uartCounts = uartCounts;
}

void LinkHealth::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    const CountingFrameDetector::Counts counts = m_detector.counts();
    tlmWrite_FramesDetected(counts.detected);
    tlmWrite_BadChecksums(counts.badChecksums);
    tlmWrite_BytesDiscarded(counts.bytesDiscarded);
    tlmWrite_Oversized(counts.oversized);
    tlmWrite_UnknownPackets(m_unknownPackets);
    tlmWrite_CommandsDropped(m_commandsDropped.load());
    FW_ASSERT(m_uartCounts != nullptr);  // configure() first
    const UartCounts uart = m_uartCounts();
    tlmWrite_UartBytesReceived(uart.received);
    tlmWrite_UartRingDrops(uart.ringDrops);
    tlmWrite_UartOverruns(uart.overruns);
    tlmWrite_UartParityErrors(uart.parity);
    tlmWrite_UartFramingErrors(uart.framing);
    tlmWrite_UartBreaks(uart.breaks);
}

void LinkHealth::commandIn_handler(FwIndexType portNum, Fw::ComBuffer& data, U32 context) {
    (void)portNum;
    FW_ASSERT(m_inFlightLimit > 0);  // configure() first
    const U32 inFlight = m_inFlight.load();
    const FwSizeType room = m_eventRoom();
    if (inFlight >= m_inFlightLimit || room < EVENT_ROOM_PER_COMMAND) {
        // Only the link's context sends: the count cannot rise meanwhile.
        // The event below is dropped, not queued, where the room is short.
        const U32 dropped = m_commandsDropped.fetch_add(1) + 1;
        this->log_WARNING_HI_CommandDropped(inFlight, static_cast<U32>(room), dropped);
        return;
    }
    m_inFlight.fetch_add(1);
    this->commandOut_out(0, data, context);
}

void LinkHealth::commandStatusIn_handler(FwIndexType portNum,
                                         FwOpcodeType opCode,
                                         U32 cmdSeq,
                                         const Fw::CmdResponse& response) {
    (void)portNum;
    const U32 before = m_inFlight.fetch_sub(1);
    FW_ASSERT(before > 0, static_cast<FwAssertArgType>(opCode));  // an answer to a command never sent
    this->commandStatusOut_out(0, opCode, cmdSeq, response);
}

void LinkHealth::unknownIn_handler(FwIndexType portNum, Fw::Buffer& data, const ComCfg::FrameContext& context) {
    (void)portNum;
    (void)context;
    m_unknownPackets++;
    unknownReturnOut_out(0, data);
}

}  // namespace Kit
