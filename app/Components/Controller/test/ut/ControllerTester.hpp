// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_CONTROLLERTESTER_HPP
#define KIT_CONTROLLERTESTER_HPP

#include "app/Components/Controller/Controller.hpp"
#include "app/Components/Controller/ControllerGTestBase.hpp"

namespace Kit {

class ControllerTester : public ControllerGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 128;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    ControllerTester();
    ~ControllerTester();

    void setpointInRangeIsAccepted();
    void setpointOutOfRangeIsRejected();
    void loopSettlesOnTheSetpoint();
    void telemetryIsDecimated();
    void gainsLoadedFromTheDatabase();
    void gainOutOfRangeIsRejected();

  private:
    void connectPorts();
    void initComponents();
    ControlStatus status();

    Controller component;
};

}  // namespace Kit

#endif
