// SPDX-License-Identifier: Apache-2.0

#ifndef KIT_TIMINGTESTER_HPP
#define KIT_TIMINGTESTER_HPP

#include "app/Components/Timing/Timing.hpp"
#include "app/Components/Timing/TimingGTestBase.hpp"

namespace Kit {

class TimingTester : public TimingGTestBase {
  public:
    static const FwSizeType MAX_HISTORY_SIZE = 16;
    static const FwEnumStoreType TEST_INSTANCE_ID = 0;

    TimingTester();
    ~TimingTester();

    void tickDrivesTheRateGroupDriver();
    void onTimeCyclesRecordLatencyAndExecution();
    void lateEndIsASlipWithEvent();
    void latencyAcrossTheCounterWrap();
    void sameSamplesSameHash();
    void probeCostLeavesTheRunUntouched();
    void restartEmptiesTheRecordsAndKeepsTheHash();
    void restartRefusesASegmentOffTheHyperperiod();
    void segmentsOnlyWhenServedWholeHyperperiodsOneAtATime();

  private:
    void from_CycleOut_handler(FwIndexType portNum, Os::RawTime& cycleStart) override;
    void connectPorts();
    void initComponents();
    //! Run cycle `cycle` of the 1 kHz group: released at its tick, started
    //! `latency` and ended `exec` cycles later, with `firedAtEnd` ticks fired
    void runFastCycle(U32 cycle, U32 latency, U32 exec, U32 firedAtEnd);

    Timing component;
    U32 m_cycleOuts;
};

}  // namespace Kit

#endif
