// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Downlink.hpp
// \brief  Event and telemetry packet sink
// ======================================================================
#ifndef KIT_DOWNLINK_HPP
#define KIT_DOWNLINK_HPP

#include "app/Components/Downlink/DownlinkComponentAc.hpp"

namespace Kit {

class Downlink final : public DownlinkComponentBase {
  public:
    static constexpr FwIndexType EVENTS = 0;
    static constexpr FwIndexType TELEMETRY = 1;
    static constexpr FwSizeType EVENT_IDS = 32;  //!< distinct event IDs counted

    explicit Downlink(const char* const compName);
    ~Downlink();

    U32 eventPackets() const { return m_packets[EVENTS]; }
    U32 telemetryPackets() const { return m_packets[TELEMETRY]; }
    //! Packets whose header could not be decoded
    U32 malformedPackets() const { return m_malformed; }
    //! Events whose ID did not fit the count table
    U32 uncountedEvents() const { return m_uncounted; }
    //! How many events with this ID were downlinked
    U32 eventCount(FwEventIdType id) const;

  private:
    void comIn_handler(FwIndexType portNum, Fw::ComBuffer& data, U32 context) override;
    void tallyEvent(Fw::ComBuffer& data);

    U32 m_packets[2];
    U32 m_malformed;
    struct EventTally {
        FwEventIdType id;
        U32 count;
    };
    EventTally m_tally[EVENT_IDS];
    FwSizeType m_ids;  //!< entries of m_tally in use
    U32 m_uncounted;
};

}  // namespace Kit

#endif
