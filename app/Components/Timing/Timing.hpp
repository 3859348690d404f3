// ======================================================================
// \title  Timing.hpp
// \brief  Tick source and rate-group timing probe
// ======================================================================
#ifndef KIT_TIMING_HPP
#define KIT_TIMING_HPP

#include "app/Components/Timing/CycleStats.hpp"
#include "app/Components/Timing/TimingComponentAc.hpp"

namespace Kit {

//! How one rate group is derived from the tick (mirrors Svc::RateGroupDriver::Divider)
struct RateGroupSpec {
    const char* name;
    U32 divisor;  //!< ticks per cycle
    U32 offset;   //!< tick of the first cycle
};

//! What the probe knows about one rate group
struct RateGroupRecord {
    RateGroupSpec spec;
    U32 cycles;         //!< cycles completed
    U32 slips;          //!< cycles that ended past their deadline
    U32 lateStarts;     //!< cycles that started after their deadline
    U32 lostStamps;     //!< starts whose tick stamp had left the ring (counted as slips too)
    CycleStats period;  //!< start to start
    CycleStats latency; //!< tick ISR to cycle start
    CycleStats exec;    //!< cycle start to end
    U32 lastStart;
    bool running;
};

class Timing final : public TimingComponentBase {
  public:
    static constexpr FwIndexType MAX_RATE_GROUPS = NUM_CYCLESTART_INPUT_PORTS;

    explicit Timing(const char* const compName);
    ~Timing();

    //! Must run before the first tick; specs must match the rate group driver's dividers
    void configure(const RateGroupSpec* specs, FwIndexType count);

    //! Called by the variant's main loop once per board tick, in tick order
    void tick();

    FwIndexType rateGroupCount() const { return m_count; }
    const RateGroupRecord& record(FwIndexType rateGroup) const;
    //! Ticks handed to the rate group driver
    U32 ticksDriven() const { return m_ticksDriven; }
    U32 totalSlips() const;

  private:
    void cycleStart_handler(FwIndexType portNum, U32 context) override;
    void cycleEnd_handler(FwIndexType portNum, U32 context) override;

    static constexpr U32 TLM_DECIMATION = 100;

    U32 releaseTick(const RateGroupRecord& rg) const;

    RateGroupRecord m_records[MAX_RATE_GROUPS];
    FwIndexType m_count;
    U32 m_ticksDriven;
    Os::RawTime m_rawTime;
};

}  // namespace Kit

#endif
