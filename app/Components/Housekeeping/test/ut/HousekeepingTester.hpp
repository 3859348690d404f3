// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_HOUSEKEEPINGTESTER_HPP
#define KIT_HOUSEKEEPINGTESTER_HPP

#include "app/Components/Housekeeping/Housekeeping.hpp"
#include "app/Components/Housekeeping/HousekeepingGTestBase.hpp"

namespace Kit {

class HousekeepingTester : public HousekeepingGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 16;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    HousekeepingTester();
    ~HousekeepingTester();

    void crcMatchesTheStandardCheckValue();
    void intactTablePassesQuietly();
    void corruptedTableRaisesAnEvent();

  private:
    void connectPorts();
    void initComponents();
    void runPass();

    Housekeeping component;
};

}  // namespace Kit

#endif
