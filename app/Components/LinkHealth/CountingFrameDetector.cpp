// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CountingFrameDetector.cpp
// \brief  F´'s F´-protocol frame detector, with every rejection counted
// ======================================================================
#include "app/Components/LinkHealth/CountingFrameDetector.hpp"
#include <Fw/Types/Assert.hpp>
#include <Svc/FprimeProtocol/FrameHeaderSerializableAc.hpp>
#include <Svc/FprimeProtocol/FrameTrailerSerializableAc.hpp>

namespace Kit {

namespace {
constexpr FwSizeType HEADER_SIZE = Svc::FprimeProtocol::FrameHeader::SERIALIZED_SIZE;
constexpr FwSizeType TRAILER_SIZE = Svc::FprimeProtocol::FrameTrailer::SERIALIZED_SIZE;

//! The header's start word and length field, when the ring holds a header
bool peekHeader(const Types::CircularBuffer& data, U32& startWord, U32& length) {
    U8 header[HEADER_SIZE] = {};
    if (data.get_allocated_size() < HEADER_SIZE || data.peek(header, HEADER_SIZE, 0) != Fw::FW_SERIALIZE_OK) {
        return false;
    }
    // Both fields big-endian (F´ serialization)
    startWord = (static_cast<U32>(header[0]) << 24) | (static_cast<U32>(header[1]) << 16) |
                (static_cast<U32>(header[2]) << 8) | static_cast<U32>(header[3]);
    length = (static_cast<U32>(header[4]) << 24) | (static_cast<U32>(header[5]) << 16) |
             (static_cast<U32>(header[6]) << 8) | static_cast<U32>(header[7]);
    return true;
}
}  // namespace

Svc::FrameDetector::Status CountingFrameDetector::detect(const Types::CircularBuffer& data,
                                                         FwSizeType& size_out) const {
    FW_ASSERT(m_largestFrame > HEADER_SIZE + TRAILER_SIZE, static_cast<FwAssertArgType>(m_largestFrame));
    const Svc::FprimeProtocol::FrameHeader expected;
    U32 startWord = 0;
    U32 length = 0;
    const bool header = peekHeader(data, startWord, length);
    if (header && startWord == expected.get_startWord() && length > m_largestFrame - HEADER_SIZE - TRAILER_SIZE) {
        // Never holdable: FrameAccumulator drops a byte on a size beyond its
        // ring. Decided here, not by F´'s detector (see the header).
        m_counts.oversized++;
        size_out = m_capacity + 1;
        return Status::MORE_DATA_NEEDED;
    }
    const Status status = m_fprime.detect(data, size_out);
    switch (status) {
        case Status::FRAME_DETECTED:
            m_counts.detected++;
            break;
        case Status::MORE_DATA_NEEDED:
            break;
        case Status::NO_FRAME_DETECTED:
        default:
            // A start word whose frame was all there: the checksum failed.
            // Otherwise no frame starts at this byte.
            if (header && startWord == expected.get_startWord()) {
                m_counts.badChecksums++;
            } else {
                m_counts.bytesDiscarded++;
            }
            break;
    }
    return status;
}

}  // namespace Kit
