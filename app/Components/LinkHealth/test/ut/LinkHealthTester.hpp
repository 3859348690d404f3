// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_LINKHEALTHTESTER_HPP
#define KIT_LINKHEALTHTESTER_HPP

#include "app/Components/LinkHealth/LinkHealth.hpp"
#include "app/Components/LinkHealth/LinkHealthGTestBase.hpp"

namespace Kit {

class LinkHealthTester : public LinkHealthGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 32;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;
    static constexpr U32 IN_FLIGHT = 2;
    static constexpr FwSizeType ACCUMULATOR_SIZE = 64;
    //! The link buffers' size: smaller than the ring, as the kit's are
    static constexpr FwSizeType LARGEST_FRAME = 48;
    //! The event service's queue, empty (app/Top/instances.fpp's is 12)
    static constexpr FwSizeType EVENT_QUEUE_DEPTH = 12;

    LinkHealthTester();
    ~LinkHealthTester();

    void commandsBeyondTheLimitAreDroppedAndCounted();
    void anAnswerFreesASlotAndGoesBackToTheRouter();
    void unknownPacketsAreCountedAndReturned();
    void uartCountsBecomeTelemetry();
    void detectorCountsEveryOutcomeByReason();
    void aLengthThatWrapsTheFrameSizeIsOversized();
    void aFrameNoBufferHoldsIsOversized();
    void aCommandWithoutRoomForItsEventsIsDropped();

  private:
    void connectPorts();
    void initComponents();

    //! Send a ground command (context: its position in the test)
    void sendCommand(U32 context);

    LinkHealth component;
};

}  // namespace Kit

#endif
