// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  LinkHealth.hpp
// \brief  The ground link's rejections, by reason, as telemetry
// ======================================================================
#ifndef KIT_LINKHEALTH_HPP
#define KIT_LINKHEALTH_HPP

#include "app/Components/LinkHealth/CountingFrameDetector.hpp"
#include "app/Components/LinkHealth/LinkHealthComponentAc.hpp"

#include <atomic>

namespace Kit {

class LinkHealth final : public LinkHealthComponentBase {
  public:
    //! What the link UART's receive interrupt counted (its driver's counts)
    struct UartCounts {
        U32 received;   //!< bytes read from the UART
        U32 ringDrops;  //!< of those, bytes the driver's receive ring dropped
        U32 overruns;   //!< receive errors the UART reported, by kind
        U32 parity;
        U32 framing;
        U32 breaks;
    };
    //! Reads the link UART's counts (the topology knows the driver; this
    //! component does not, so that its unit test needs no UART)
    using UartCountsSource = UartCounts (*)();
    //! Free message slots in the event service's queue (the topology knows
    //! the event service; this component does not)
    using EventRoomSource = FwSizeType (*)();
    //! Room a ground command needs there to be sent on: the events it can
    //! raise on its way (the dispatcher's dispatched and completed, its
    //! handler's one) and health's ping of the event service. F´ asserts
    //! when that ping finds the queue full, where the events themselves are
    //! dropped: a flood of commands whose events outrun the event service
    //! (the serial-load sweep's uplink axis on qemu_cortex_m3's budgeted
    //! policy, a fresh-clone run) halted the deployment that way.
    static constexpr FwSizeType EVENT_ROOM_PER_COMMAND = 4;

    explicit LinkHealth(const char* const compName);
    ~LinkHealth();

    //! \param accumulatorSize the FrameAccumulator's ring size
    //! \param largestFrame the largest frame a link buffer holds
    //! \param commandsInFlight ground commands the dispatcher may hold at once
    //! \param uartCounts the link UART's receive counts
    //! \param eventRoom the event service's free queue slots
    void configure(FwSizeType accumulatorSize,
                   FwSizeType largestFrame,
                   U32 commandsInFlight,
                   UartCountsSource uartCounts,
                   EventRoomSource eventRoom);

    //! The detector the FrameAccumulator is configured with
    const Svc::FrameDetector& detector() const { return m_detector; }
    CountingFrameDetector::Counts counts() const { return m_detector.counts(); }
    U32 unknownPackets() const { return m_unknownPackets; }
    U32 commandsDropped() const { return m_commandsDropped.load(); }

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    void unknownIn_handler(FwIndexType portNum, Fw::Buffer& data, const ComCfg::FrameContext& context) override;
    void commandIn_handler(FwIndexType portNum, Fw::ComBuffer& data, U32 context) override;
    void commandStatusIn_handler(FwIndexType portNum,
                                 FwOpcodeType opCode,
                                 U32 cmdSeq,
                                 const Fw::CmdResponse& response) override;

    CountingFrameDetector m_detector;
    U32 m_unknownPackets;
    // Commands come in on the link's context (a rate group) and their
    // answers on the dispatcher's: one counter both update
    std::atomic<U32> m_inFlight;
    std::atomic<U32> m_commandsDropped;
    U32 m_inFlightLimit;
    UartCountsSource m_uartCounts;
    EventRoomSource m_eventRoom;
};

}  // namespace Kit

#endif
