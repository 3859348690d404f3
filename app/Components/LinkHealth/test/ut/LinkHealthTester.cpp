// SPDX-License-Identifier: Apache-2.0

#include "app/Components/LinkHealth/test/ut/LinkHealthTester.hpp"

#include <Svc/FprimeProtocol/FrameHeaderSerializableAc.hpp>
#include <Svc/FprimeProtocol/FrameTrailerSerializableAc.hpp>
#include <Utils/Hash/Hash.hpp>
#include <Utils/Types/CircularBuffer.hpp>

namespace Kit {

namespace {
constexpr FwSizeType HEADER_SIZE = Svc::FprimeProtocol::FrameHeader::SERIALIZED_SIZE;
constexpr FwSizeType TRAILER_SIZE = Svc::FprimeProtocol::FrameTrailer::SERIALIZED_SIZE;
constexpr FwSizeType PAYLOAD_SIZE = 6;
constexpr FwSizeType FRAME_SIZE = HEADER_SIZE + PAYLOAD_SIZE + TRAILER_SIZE;

void putBigEndian(U8* at, U32 value) {
    at[0] = static_cast<U8>(value >> 24);
    at[1] = static_cast<U8>(value >> 16);
    at[2] = static_cast<U8>(value >> 8);
    at[3] = static_cast<U8>(value);
}

//! An F´-protocol frame as fprime-gds sends it: start word, length, the
//! payload, CRC32 of header and payload
void fprimeFrame(U8 (&frame)[FRAME_SIZE], U32 lengthField) {
    const Svc::FprimeProtocol::FrameHeader header;
    putBigEndian(&frame[0], header.get_startWord());
    putBigEndian(&frame[4], lengthField);
    for (FwSizeType i = 0; i < PAYLOAD_SIZE; i++) {
        frame[HEADER_SIZE + i] = static_cast<U8>(0xA0 + i);
    }
    Utils::HashBuffer crc;
    Utils::Hash::hash(frame, HEADER_SIZE + PAYLOAD_SIZE, crc);
    putBigEndian(&frame[HEADER_SIZE + PAYLOAD_SIZE], crc.asBigEndianU32());
}

//! The link UART's counts as the test sets them (the topology reads the driver's)
FwSizeType s_eventRoom = 0;
FwSizeType eventRoom() {
    return s_eventRoom;
}
LinkHealth::UartCounts s_uartCounts = {};
LinkHealth::UartCounts uartCounts() {
    return s_uartCounts;
}

//! What the detector answers for these bytes at the front of a ring
Svc::FrameDetector::Status detectIn(const CountingFrameDetector& detector,
                                    const U8* bytes,
                                    FwSizeType size,
                                    FwSizeType& sizeOut) {
    U8 storage[LinkHealthTester::ACCUMULATOR_SIZE] = {};
    Types::CircularBuffer ring(storage, sizeof storage);
    EXPECT_EQ(ring.serialize(bytes, size), Fw::FW_SERIALIZE_OK);
    return detector.detect(ring, sizeOut);
}
}  // namespace

LinkHealthTester::LinkHealthTester()
    : LinkHealthGTestBase("LinkHealthTester", MAX_HISTORY_SIZE), component("LinkHealth") {
    this->initComponents();
    this->connectPorts();
    s_uartCounts = {};
    s_eventRoom = EVENT_QUEUE_DEPTH;
    this->component.configure(ACCUMULATOR_SIZE, LARGEST_FRAME, IN_FLIGHT, uartCounts, eventRoom);
}

LinkHealthTester::~LinkHealthTester() {}

void LinkHealthTester::sendCommand(U32 context) {
    Fw::ComBuffer command;
    ASSERT_EQ(command.serialize(context), Fw::FW_SERIALIZE_OK);
    this->invoke_to_commandIn(0, command, context);
}

void LinkHealthTester::commandsBeyondTheLimitAreDroppedAndCounted() {
    for (U32 i = 0; i < IN_FLIGHT + 2; i++) {
        this->sendCommand(i);
    }
    // The first IN_FLIGHT reach the dispatcher, in order; the rest do not
    ASSERT_from_commandOut_SIZE(IN_FLIGHT);
    for (U32 i = 0; i < IN_FLIGHT; i++) {
        EXPECT_EQ(this->fromPortHistory_commandOut->at(i).context, i);
    }
    ASSERT_EVENTS_CommandDropped_SIZE(2);
    ASSERT_EVENTS_CommandDropped(0, IN_FLIGHT, EVENT_QUEUE_DEPTH, 1);
    ASSERT_EVENTS_CommandDropped(1, IN_FLIGHT, EVENT_QUEUE_DEPTH, 2);
    EXPECT_EQ(this->component.commandsDropped(), 2u);
    this->invoke_to_schedIn(0, 0);
    ASSERT_TLM_CommandsDropped(0, 2);
}

void LinkHealthTester::anAnswerFreesASlotAndGoesBackToTheRouter() {
    for (U32 i = 0; i < IN_FLIGHT; i++) {
        this->sendCommand(i);
    }
    this->invoke_to_commandStatusIn(0, 0x500, 7, Fw::CmdResponse::OK);
    ASSERT_from_commandStatusOut_SIZE(1);
    ASSERT_from_commandStatusOut(0, 0x500, 7, Fw::CmdResponse::OK);
    // One slot free: the next command goes through, the one after is dropped
    this->sendCommand(IN_FLIGHT);
    this->sendCommand(IN_FLIGHT + 1);
    ASSERT_from_commandOut_SIZE(IN_FLIGHT + 1);
    EXPECT_EQ(this->component.commandsDropped(), 1u);
    // Every answer drains one: with all answered, IN_FLIGHT pass again
    for (U32 i = 0; i < IN_FLIGHT; i++) {
        this->invoke_to_commandStatusIn(0, 0x500, i, Fw::CmdResponse::EXECUTION_ERROR);
    }
    this->clearHistory();
    for (U32 i = 0; i < IN_FLIGHT; i++) {
        this->sendCommand(i);
    }
    ASSERT_from_commandOut_SIZE(IN_FLIGHT);
    ASSERT_EVENTS_CommandDropped_SIZE(0);
}

void LinkHealthTester::unknownPacketsAreCountedAndReturned() {
    U8 data[4] = {1, 2, 3, 4};
    Fw::Buffer buffer(data, sizeof data);
    ComCfg::FrameContext context;
    this->invoke_to_unknownIn(0, buffer, context);
    this->invoke_to_unknownIn(0, buffer, context);
    ASSERT_from_unknownReturnOut_SIZE(2);  // the router's buffer, every time
    EXPECT_EQ(this->fromPortHistory_unknownReturnOut->at(0).fwBuffer.getData(), data);
    this->invoke_to_schedIn(0, 0);
    ASSERT_TLM_UnknownPackets(0, 2);
}

void LinkHealthTester::uartCountsBecomeTelemetry() {
    s_uartCounts = {1000, 40, 3, 2, 1, 5};
    this->invoke_to_schedIn(0, 0);
    ASSERT_TLM_UartBytesReceived(0, 1000);
    ASSERT_TLM_UartRingDrops(0, 40);
    ASSERT_TLM_UartOverruns(0, 3);
    ASSERT_TLM_UartParityErrors(0, 2);
    ASSERT_TLM_UartFramingErrors(0, 1);
    ASSERT_TLM_UartBreaks(0, 5);
    // The error kinds are written on change: a second call with the same
    // errors sends the byte counts again and no error count
    this->clearHistory();
    s_uartCounts.received = 1500;
    this->invoke_to_schedIn(0, 0);
    ASSERT_TLM_UartBytesReceived(0, 1500);
    ASSERT_TLM_UartOverruns_SIZE(0);
    ASSERT_TLM_UartBreaks_SIZE(0);
}

void LinkHealthTester::detectorCountsEveryOutcomeByReason() {
    const CountingFrameDetector& detector = static_cast<const CountingFrameDetector&>(this->component.detector());
    U8 frame[FRAME_SIZE];
    fprimeFrame(frame, PAYLOAD_SIZE);
    FwSizeType size = 0;

    EXPECT_EQ(detectIn(detector, frame, FRAME_SIZE, size), Svc::FrameDetector::Status::FRAME_DETECTED);
    EXPECT_EQ(size, FRAME_SIZE);

    U8 corrupted[FRAME_SIZE];
    fprimeFrame(corrupted, PAYLOAD_SIZE);
    corrupted[FRAME_SIZE - 1] ^= 0x01;
    EXPECT_EQ(detectIn(detector, corrupted, FRAME_SIZE, size), Svc::FrameDetector::Status::NO_FRAME_DETECTED);

    const U8 garbage[FRAME_SIZE] = {0x55};
    EXPECT_EQ(detectIn(detector, garbage, FRAME_SIZE, size), Svc::FrameDetector::Status::NO_FRAME_DETECTED);

    // Half a frame: neither detected nor rejected yet
    EXPECT_EQ(detectIn(detector, frame, FRAME_SIZE / 2, size), Svc::FrameDetector::Status::MORE_DATA_NEEDED);

    U8 tooLong[FRAME_SIZE];
    fprimeFrame(tooLong, ACCUMULATOR_SIZE);
    EXPECT_EQ(detectIn(detector, tooLong, FRAME_SIZE, size), Svc::FrameDetector::Status::MORE_DATA_NEEDED);
    EXPECT_GT(size, static_cast<FwSizeType>(ACCUMULATOR_SIZE));  // FrameAccumulator drops a byte on that

    const CountingFrameDetector::Counts counts = this->component.counts();
    EXPECT_EQ(counts.detected, 1u);
    EXPECT_EQ(counts.badChecksums, 1u);
    EXPECT_EQ(counts.bytesDiscarded, 1u);
    EXPECT_EQ(counts.oversized, 1u);
    this->invoke_to_schedIn(0, 0);
    ASSERT_TLM_FramesDetected(0, 1);
    ASSERT_TLM_BadChecksums(0, 1);
    ASSERT_TLM_BytesDiscarded(0, 1);
    ASSERT_TLM_Oversized(0, 1);
}

void LinkHealthTester::aFrameNoBufferHoldsIsOversized() {
    // The ring would hold it, but FrameAccumulator could never get a buffer
    // for it and would keep it at the front of the ring for good
    const CountingFrameDetector& detector = static_cast<const CountingFrameDetector&>(this->component.detector());
    const U32 largestPayload = static_cast<U32>(LARGEST_FRAME - HEADER_SIZE - TRAILER_SIZE);
    U8 frame[FRAME_SIZE];
    FwSizeType size = 0;
    fprimeFrame(frame, largestPayload + 1);
    EXPECT_EQ(detectIn(detector, frame, FRAME_SIZE, size), Svc::FrameDetector::Status::MORE_DATA_NEEDED);
    EXPECT_GT(size, static_cast<FwSizeType>(ACCUMULATOR_SIZE));  // FrameAccumulator drops a byte on that
    EXPECT_EQ(this->component.counts().oversized, 1u);
    // The largest a buffer holds is awaited whole, not refused
    fprimeFrame(frame, largestPayload);
    EXPECT_EQ(detectIn(detector, frame, FRAME_SIZE, size), Svc::FrameDetector::Status::MORE_DATA_NEEDED);
    EXPECT_EQ(size, static_cast<FwSizeType>(LARGEST_FRAME));
    EXPECT_EQ(this->component.counts().oversized, 1u);
}

void LinkHealthTester::aLengthThatWrapsTheFrameSizeIsOversized() {
    // F´'s own detector wraps header + length + trailer to 0..3 for these
    // lengths and asserts in its checksum loop (CountingFrameDetector.hpp)
    const CountingFrameDetector& detector = static_cast<const CountingFrameDetector&>(this->component.detector());
    for (U32 length = 0xFFFFFFF4u; length <= 0xFFFFFFF7u; length++) {
        U8 frame[FRAME_SIZE];
        fprimeFrame(frame, length);
        FwSizeType size = 0;
        EXPECT_EQ(detectIn(detector, frame, FRAME_SIZE, size), Svc::FrameDetector::Status::MORE_DATA_NEEDED);
        EXPECT_GT(size, static_cast<FwSizeType>(ACCUMULATOR_SIZE));
    }
    EXPECT_EQ(this->component.counts().oversized, 4u);
    EXPECT_EQ(this->component.counts().detected, 0u);
}

void LinkHealthTester::aCommandWithoutRoomForItsEventsIsDropped() {
    // Room for one command's events and health's ping: it goes through
    s_eventRoom = LinkHealth::EVENT_ROOM_PER_COMMAND;
    this->sendCommand(0);
    ASSERT_from_commandOut_SIZE(1);
    // One slot short: dropped and counted, nothing sent on
    s_eventRoom = LinkHealth::EVENT_ROOM_PER_COMMAND - 1;
    this->sendCommand(1);
    ASSERT_from_commandOut_SIZE(1);
    ASSERT_EVENTS_CommandDropped_SIZE(1);
    ASSERT_EVENTS_CommandDropped(0, 1, LinkHealth::EVENT_ROOM_PER_COMMAND - 1, 1);
    EXPECT_EQ(this->component.commandsDropped(), 1u);
    // Room again: the next one goes through
    s_eventRoom = EVENT_QUEUE_DEPTH;
    this->sendCommand(2);
    ASSERT_from_commandOut_SIZE(2);
}

}  // namespace Kit
