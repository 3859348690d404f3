// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_FAULTSTESTER_HPP
#define KIT_FAULTSTESTER_HPP

#include "app/Components/Faults/Faults.hpp"
#include "app/Components/Faults/FaultsGTestBase.hpp"

namespace Kit {

class FaultsTester : public FaultsGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 64;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    FaultsTester();
    ~FaultsTester();

    void overrunRunsOnceInItsRateGroup();
    void injectionsAboveTheirLimitsAreRejected();
    void stackUseWithinTheLimitCompletes();
    void assertReachesTheAssertHook();
    void fileDamagedInPlace();
    void fileDamageRefusedWhereItCannotBeDone();
    void restartComesAfterItsDelay();

  private:
    //! Writes `size` bytes 0, 1, ... as `path`; reads a file back
    static void writeFile(const char* path, U32 size);
    static FwSizeType readFile(const char* path, U8* data, FwSizeType capacity);

    void connectPorts();
    void initComponents();

    Faults component;
};

}  // namespace Kit

#endif
