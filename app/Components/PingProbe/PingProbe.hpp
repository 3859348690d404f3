// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PingProbe.hpp
// \brief  Svc.Health's pings, timed per entry (see PingProbe.fpp)
// ======================================================================
#ifndef KIT_PINGPROBE_HPP
#define KIT_PINGPROBE_HPP

#include "app/Components/PingProbe/PingProbeComponentAc.hpp"

namespace Kit {

//! Round trips of one ping entry: all of them counted, the largest kept, and
//! the last WINDOW kept for percentiles (a nominal run's pings all fit:
//! 20 per entry at 10 Hz). Fixed RAM whatever the run's length.
class PingRoundTrips {
  public:
    static constexpr U32 WINDOW = 32;

    void add(U32 cycles);
    U32 count() const { return m_count; }
    U32 max() const { return m_max; }
    //! Round trips the window holds: min(count, WINDOW)
    U32 held() const { return m_count < WINDOW ? m_count : WINDOW; }
    //! Nearest-rank percentile of the held round trips; 0 when none
    U32 percentile(U32 permille) const;

  private:
    U32 m_window[WINDOW] = {};
    U32 m_count = 0;
    U32 m_max = 0;
};

class PingProbe final : public PingProbeComponentBase {
  public:
    explicit PingProbe(const char* const compName);
    ~PingProbe();

    const PingRoundTrips& roundTrips() const { return m_trips; }
    //! A ping went out and has not been answered yet
    bool outstanding() const { return m_outstanding; }

    //! Starts a segment of the run (a load sweep's point): its worst wait
    //! counts from here
    void startSegment();
    //! The longest a ping waited for its answer since startSegment(): the
    //! longest round trip, or how long the one still out has waited, at
    //! counter value `now`
    U32 segmentWorst(U32 now) const;

  private:
    void pingIn_handler(FwIndexType portNum, U32 key) override;
    void returnIn_handler(FwIndexType portNum, U32 key) override;

    // Written by health's caller on the way out and by the pinged
    // component's task on the way back, never both at once: health sends
    // the next ping only after it has processed this one's answer
    U32 m_sentAt;  //!< the counter when the outstanding ping went out
    bool m_outstanding;
    PingRoundTrips m_trips;
    U32 m_segmentMax;  //!< the longest round trip since startSegment()
};

}  // namespace Kit

#endif
