// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  PingProbe.hpp
// \brief  Svc.Health's pings, timed per entry (see PingProbe.fpp)
// ======================================================================
#ifndef KIT_PINGPROBE_HPP
#define KIT_PINGPROBE_HPP

#include <Os/Queue.hpp>
#include "app/Components/PingProbe/PingProbeComponentAc.hpp"

namespace Kit {

//! Round trips of one ping entry: all of them counted, the largest kept, and
//! the last WINDOW kept for percentiles (a nominal run's pings all fit:
//! 20 per entry at 10 Hz). Fixed RAM whatever the run's length.
class PingRoundTrips {
  public:
    static constexpr U32 WINDOW = 24;

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

    //! The pinged component's message queue: a ping that finds it full is
    //! deferred, not sent (F´'s generated pingIn asserts on a full queue,
    //! where its events and commands are dropped or shed: a flood of events
    //! at the event service had filled it). Without one, pings always go.
    void watchQueue(const Os::Queue& queue);

    const PingRoundTrips& roundTrips() const { return m_trips; }
    //! Pings deferred so far because the pinged component's queue was full
    U32 deferredPings() const { return m_deferredPings; }
    //! A deferred ping is waiting for room
    bool deferring() const { return m_deferred; }

    //! Every deferred ping whose component's queue has room now, sent on.
    //! Called at each of health's pings (pingIn), so in health's context
    //! alone: a deferred ping goes at health's next cycle that finds room;
    //! the wait counts from health's send, and a component whose queue stays
    //! full past health's thresholds is late, as F´'s health judges it
    static void sendDeferredPings();

    //! Deferred pings of every probe (at most one per probe)
    static U32 deferredNow() { return s_deferredCount; }
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
    //! The pinged component's queue has no room for a ping
    bool targetFull() const;

    //! The probes holding a deferred ping (health's context only)
    static constexpr U32 MAX_DEFERRED = 16;
    static PingProbe* s_deferring[MAX_DEFERRED];
    static U32 s_deferredCount;

    const Os::Queue* m_targetQueue;  //!< nullptr: a component without a queue
    bool m_deferred;                 //!< a ping waits for room (its key in m_deferredKey)
    U32 m_deferredKey;
    U32 m_deferredPings;  //!< pings deferred so far
    U32 m_sentAt;         //!< the counter when the outstanding ping went out
    bool m_outstanding;
    PingRoundTrips m_trips;
    U32 m_segmentMax;  //!< the longest round trip since startSegment()
};

}  // namespace Kit

#endif
