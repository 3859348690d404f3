// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_LOADTESTER_HPP
#define KIT_LOADTESTER_HPP

#include "app/Components/Load/Load.hpp"
#include "app/Components/Load/LoadGTestBase.hpp"

namespace Kit {

class LoadTester : public LoadGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 64;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;
    static const FwSizeType TEST_INSTANCE_QUEUE_DEPTH = 4;

    LoadTester();
    ~LoadTester();

    void sliceComputesForTheCommandedTime();
    void settingsAboveTheirLimitsAreRejected();
    void burstPushesTheCommandedMessages();
    void aFullQueueDropsCountsAndReports();
    void everySliceSendsTheCommandedDownlinkPackets();
    void patternIsXorshift32sLowBytes();
    void fillFileWritesThePatternOrRefuses();

  private:
    void connectPorts();
    void initComponents();

    Load component;
};

}  // namespace Kit

#endif
