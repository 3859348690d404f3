// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CountingFrameDetector.hpp
// \brief  F´'s F´-protocol frame detector, with every rejection counted
// ======================================================================
#ifndef KIT_COUNTINGFRAMEDETECTOR_HPP
#define KIT_COUNTINGFRAMEDETECTOR_HPP

#include <Svc/FrameAccumulator/FrameDetector/FprimeFrameDetector.hpp>

namespace Kit {

//! Delegates every decision to Svc::FrameDetectors::FprimeFrameDetector and
//! counts its outcomes by reason. FrameAccumulator calls detect() on its
//! ring once per candidate position and discards one byte after each "no
//! frame", so a rejected frame counts once here and its other bytes count
//! as discarded bytes.
//!
//! One decision it takes itself, before F´'s: a length field the
//! accumulator can never hold. F´'s detector (6c80056) computes the frame's
//! size as header + length + trailer in FwSizeType; a length of 0xFFFFFFF4
//! to 0xFFFFFFF7 wraps that sum to 0..3, CircularBuffer::peek's own bound
//! (size + offset) wraps too, and its checksum loop then peeks past the
//! data and asserts: one 12-byte frame from the ground halted the
//! deployment (found by the kit's uplink fuzzing, kittools/link/fuzz.py). Here
//! such a frame is oversized, as any other too long for the accumulator:
//! FrameAccumulator drops a byte and reports FrameDetectionSizeError.
//!
//! The same for a frame the ring holds but no link buffer does: the
//! accumulator copies a whole frame into a buffer of the link's pool, and
//! when none is that large it keeps the frame and tries again on the next
//! bytes, forever (F´'s FrameAccumulator: NoBufferAvailable, then break):
//! one valid frame too long for a buffer would close the uplink for good.
class CountingFrameDetector final : public Svc::FrameDetector {
  public:
    struct Counts {
        U32 detected;        //!< frames found whole, checksum good (one retried for want of a buffer counts again)
        U32 badChecksums;    //!< start word and length fit, checksum failed
        U32 bytesDiscarded;  //!< positions where no frame starts
        U32 oversized;       //!< length beyond what the accumulator or a link buffer holds
    };

    CountingFrameDetector() : m_capacity(0), m_largestFrame(0), m_counts() {}

    //! \param capacity the accumulator's ring size
    //! \param largestFrame the largest frame a link buffer holds (at most
    //!        the ring's size): a longer one can never be taken, and
    //!        FrameAccumulator is told it exceeds the ring (it drops a byte)
    void setCapacity(FwSizeType capacity, FwSizeType largestFrame) {
        m_capacity = capacity;
        m_largestFrame = (largestFrame < capacity) ? largestFrame : capacity;
    }

    Status detect(const Types::CircularBuffer& data, FwSizeType& size_out) const override;

    Counts counts() const { return m_counts; }

  private:
    Svc::FrameDetectors::FprimeFrameDetector m_fprime;
    FwSizeType m_capacity;
    FwSizeType m_largestFrame;
    // detect() is const in F´'s interface; counting is not the detector's
    // state, only a record of its answers
    mutable Counts m_counts;
};

}  // namespace Kit

#endif
