// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_PINGPROBETESTER_HPP
#define KIT_PINGPROBETESTER_HPP

#include "app/Components/PingProbe/PingProbe.hpp"
#include "app/Components/PingProbe/PingProbeGTestBase.hpp"

namespace Kit {

class PingProbeTester : public PingProbeGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 16;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    PingProbeTester();

    void pingsPassThroughAndAreTimed();
    void aSegmentCountsItsLongestWaitAnsweredOrNot();
    void aPingThatWouldFindTheQueueFullWaitsForRoom();
    void aProbeGoneLeavesNoDeferredPing();
    void anAnswerWithNoPingOutIsPassedOnNotTimed();
    void percentilesComeFromTheLastWindow();

  private:
    void connectPorts();
    void initComponents();

    PingProbe component;
};

}  // namespace Kit

#endif
