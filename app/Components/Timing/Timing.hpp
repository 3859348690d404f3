// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Timing.hpp
// \brief  Tick source and rate-group timing probe
// ======================================================================
#ifndef KIT_TIMING_HPP
#define KIT_TIMING_HPP

#include "app/Components/Timing/CycleStats.hpp"
#include "app/Components/Timing/TimingComponentAc.hpp"

#include <atomic>

namespace Kit {

//! How one rate group is derived from the tick (mirrors Svc::RateGroupDriver::Divider)
struct RateGroupSpec {
    const char* name;
    U32 divisor;  //!< ticks per cycle
    U32 offset;   //!< tick of the first cycle
};

//! What the probe knows about one rate group (cycle counts in counter cycles)
struct RateGroupRecord {
    RateGroupSpec spec;
    U32 nominalPeriod;       //!< divisor x cycles per tick
    U32 cycles;              //!< cycles completed
    U32 slips;               //!< cycles that ended past their deadline
    U32 lateStarts;          //!< cycles that started after their deadline
    U32 lostStamps;          //!< starts whose tick stamp had left the ring
    CycleStats latency;      //!< tick ISR to cycle start
    CycleStats exec;         //!< cycle start to end
    CycleStats periodError;  //!< |start to start - nominal period|
    U32 periodMin;           //!< start to start, exact
    U32 periodMax;
    U32 lastStart;
    bool running;
};

class Timing final : public TimingComponentBase {
  public:
    static constexpr FwIndexType MAX_RATE_GROUPS = NUM_CYCLESTART_INPUT_PORTS;

    explicit Timing(const char* const compName);
    ~Timing();

    //! Must run before the first tick; specs must match the rate group driver's
    //! dividers; cyclesPerTick is the counter's cycles per board tick
    void configure(const RateGroupSpec* specs, FwIndexType count, U32 cyclesPerTick);

    //! The probe's own cost: counter cycles of one start plus one end record
    //! (port call overhead excluded), averaged over `pairs` runs on the fastest
    //! group's record, which is reset afterwards. Call before the first tick.
    U32 measureProbeCost(U32 pairs);

    //! Called by the variant's main loop once per board tick, in tick order
    void tick();

    //! Start a new measured segment: every record back to empty and the tick
    //! count to zero (the tick clock restarts too), the sample hash kept. Call
    //! between segments, with the tick stopped and every rate group idle; the
    //! segment before must have lasted a whole number of `hyperperiod` ticks so
    //! the rate group driver's phase matches the records' again.
    void restart(U32 hyperperiod);

    //! A segment the ground asked for (MEASURE_SEGMENT)
    struct Segment {
        SegmentAxis axis;
        U32 point;
        U32 level;
        U32 ticks;
    };
    //! Longest segment the ground may ask for: 10 s at 1 kHz
    static constexpr U32 SEGMENT_MAX_TICKS = 10000;

    //! The ground scenario measures segments on request from now on, each a
    //! whole number of `hyperperiod` ticks; before, MEASURE_SEGMENT is refused
    void serveSegments(U32 hyperperiod);
    //! A segment was requested and not yet taken (the main loop asks)
    bool segmentRequested() const;
    //! The requested segment; the next request is accepted once it was
    //! measured (segmentDone())
    Segment takeSegment() const;
    void segmentDone();

    FwIndexType rateGroupCount() const { return m_count; }
    const RateGroupRecord& record(FwIndexType rateGroup) const;
    //! Ticks handed to the rate group driver
    U32 ticksDriven() const { return m_ticksDriven; }
    U32 totalSlips() const;
    //! Hash of every latency, execution and period sample, in recording order
    const SampleHash& sampleHash() const { return m_hash; }

  private:
    void cycleStart_handler(FwIndexType portNum, U32 context) override;
    void cycleEnd_handler(FwIndexType portNum, U32 context) override;
    void MEASURE_SEGMENT_cmdHandler(FwOpcodeType opCode, U32 cmdSeq, SegmentAxis axis, U32 point, U32 level, U32 ticks)
        override;

#if defined(CONFIG_KIT_TICK_HZ)
    static constexpr U32 TICK_HZ = CONFIG_KIT_TICK_HZ;  // app/Kconfig
#else
    static constexpr U32 TICK_HZ = 1000;  // the host's unit tests: the default tick
#endif
    //! The fastest group's telemetry rate: 10 Hz, whatever its own rate
    static constexpr U32 TLM_HZ = 10;
    //! Its cycles between two telemetry writes (100 at 1 kHz, 5 at 50 Hz)
    static U32 tlmDecimation(const RateGroupSpec& spec) {
        const U32 cycles = TICK_HZ / (TLM_HZ * spec.divisor);
        return (cycles > 0U) ? cycles : 1U;
    }

    U32 releaseTick(const RateGroupRecord& rg) const;
    //! Back to the configured, empty state, in place (a record is ~1.6 KiB: no temporaries)
    void resetRecord(FwIndexType rateGroup);
    //! The probe's work at a cycle's start, and at its end (returns ticks late)
    //! `probeCycles`: the dispatch-stage marks' cost on the way, out of the latency
    void recordStart(RateGroupRecord& rg, U32 now, U32 fired, U32 probeCycles = 0);
    U32 recordEnd(RateGroupRecord& rg, U32 now, U32 fired);

    RateGroupRecord m_records[MAX_RATE_GROUPS];
    FwIndexType m_count;
    U32 m_cyclesPerTick;
    U32 m_ticksDriven;
    SampleHash m_hash;
    Os::RawTime m_rawTime;
    // Written by the command's thread (the dispatcher's), read by the main
    // loop: the request is complete before m_segmentState says so
    enum SegmentState : U32 { SEGMENTS_OFF, SEGMENT_IDLE, SEGMENT_REQUESTED };
    std::atomic<U32> m_segmentState;
    U32 m_hyperperiod;
    Segment m_segment;
};

}  // namespace Kit

#endif
