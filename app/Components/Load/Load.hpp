// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Load.hpp
// \brief  Background load, set at run time by command
// ======================================================================
#ifndef KIT_LOAD_HPP
#define KIT_LOAD_HPP

#include "app/Components/Load/LoadComponentAc.hpp"

namespace Kit {

class Load final : public LoadComponentBase {
  public:
    //! Longest computation one message may be commanded to take: 50 ms, what
    //! the kit's sweep reaches (twice the fastest group's period) for a
    //! fastest group as slow as 40 Hz, still bounded
    static constexpr U32 SLICE_MAX_US = 50000;
    //! Most messages one burst may push (the queue holds fewer: a burst above
    //! its depth is how an overrun of the load is provoked)
    static constexpr U32 BURST_MAX = 32;
    //! Most calls per slice or burst (SET_PACE): a 50 ms slice each 64
    //! calls of a 1 kHz group is within half of their 64 ms
    static constexpr U32 PACE_MAX = 64;
    //! Extra downlink packets per slice message (the events queue holds 8)
    static constexpr U32 DOWNLINK_MAX = 16;

    //! The pattern FILL_FILE writes: a 32-bit xorshift stream (Marsaglia's
    //! 13, 17, 5), one byte per step, its low byte. No byte repeats with a
    //! short period, so a lost, repeated or reordered chunk of a transfer
    //! shows; the ground recomputes it (tests/integration/test_ground.py).
    class Pattern {
      public:
        explicit Pattern(U32 seed) : m_state(seed) {}
        U8 next() {
            m_state ^= m_state << 13;
            m_state ^= m_state >> 17;
            m_state ^= m_state << 5;
            return static_cast<U8>(m_state & 0xFFu);
        }

      private:
        U32 m_state;
    };
    //! Bytes FILL_FILE writes per call of the file system (its stack buffer)
    static constexpr FwSizeType FILL_CHUNK_BYTES = 32;

    explicit Load(const char* const compName);
    ~Load();

    //! Messages processed (slices and burst messages)
    U32 processed() const { return m_processed; }
    //! Messages dropped on a full queue
    U32 dropped() const { return m_dropped; }
    //! Slice messages handled, and calls of burstIn: the rate groups they
    //! are wired to, counted (the load sweep derives their periods from
    //! them, not from the topology)
    U32 slices() const { return m_slices; }
    U32 bursts() const { return m_bursts; }

  private:
    void sliceIn_handler(FwIndexType portNum, U32 context) override;
    void sliceIn_overflowHook(FwIndexType portNum, U32 context) override;
    void burstIn_handler(FwIndexType portNum, U32 context) override;
    void ioIn_handler(FwIndexType portNum, U32 context) override;
    void ioIn_overflowHook(FwIndexType portNum, U32 context) override;

    void SET_SLICE_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 us) override;
    void SET_BURST_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 count, U32 us) override;
    void SET_DOWNLINK_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 packets) override;
    void SET_PACE_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, U32 sliceEvery, U32 burstEvery) override;
    void FILL_FILE_cmdHandler(FwOpcodeType opCode,
                              U32 cmdSeq,
                              const Fw::CmdStringArg& file,
                              U32 bytes,
                              U32 seed) override;

    //! A message the queue could not take
    void dropOne();
    //! One message's computation
    void compute(U32 us);

    // Written by commands (dispatcher context), read by the load's own
    // context: aligned 32-bit words, so each read sees an old or a new value
    volatile U32 m_sliceUs;
    volatile U32 m_burstCount;
    volatile U32 m_burstUs;
    volatile U32 m_downlinkPackets;
    volatile U32 m_sliceEvery;
    volatile U32 m_burstEvery;
    U32 m_downlinkSequence;
    U32 m_processed;
    U32 m_dropped;
    U32 m_slices;
    U32 m_bursts;
    U32 m_lcg;  //!< the computation's state, kept so it is not optimized away
};

}  // namespace Kit

#endif
