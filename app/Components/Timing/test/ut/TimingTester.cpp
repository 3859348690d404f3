// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Timing/test/ut/TimingTester.hpp"
#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {

namespace {
constexpr U32 PERIOD = 12000;  // 1 kHz at 12 MHz
const RateGroupSpec SPECS[3] = {{"rg1kHz", 1, 0}, {"rg100Hz", 10, 1}, {"rg10Hz", 100, 2}};
}  // namespace

TimingTester::TimingTester() : TimingGTestBase("TimingTester", MAX_HISTORY_SIZE), component("Timing"), m_cycleOuts(0) {
    this->initComponents();
    this->connectPorts();
    FakeTickClock::reset();
    component.configure(SPECS, 3, PERIOD);
}

TimingTester::~TimingTester() {}

void TimingTester::from_CycleOut_handler(FwIndexType portNum, Os::RawTime& cycleStart) {
    (void)portNum;
    (void)cycleStart;
    m_cycleOuts++;
}

void TimingTester::runFastCycle(U32 cycle, U32 latency, U32 exec, U32 firedAtEnd) {
    const U32 release = cycle * PERIOD;
    FakeTickClock::fire(cycle, release);
    FakeTickClock::now = release + latency;
    this->invoke_to_cycleStart(0, 0);
    FakeTickClock::now = release + latency + exec;
    FakeTickClock::fired = firedAtEnd;
    this->invoke_to_cycleEnd(0, 0);
}

void TimingTester::tickDrivesTheRateGroupDriver() {
    component.tick();
    component.tick();
    EXPECT_EQ(m_cycleOuts, 2u);
    EXPECT_EQ(component.ticksDriven(), 2u);
}

void TimingTester::onTimeCyclesRecordLatencyAndExecution() {
    runFastCycle(0, 500, 100, 1);
    runFastCycle(1, 700, 300, 2);
    const RateGroupRecord& rg = component.record(0);
    EXPECT_EQ(rg.cycles, 2u);
    EXPECT_EQ(rg.slips, 0u);
    EXPECT_EQ(rg.latency.min(), 500u);
    EXPECT_EQ(rg.latency.max(), 700u);
    EXPECT_EQ(rg.exec.max(), 300u);
    EXPECT_EQ(rg.periodMax, PERIOD + 200u);  // start to start
    EXPECT_EQ(rg.periodError.max(), 200u);   // against the nominal 1 ms
    ASSERT_EVENTS_SIZE(0);
}

void TimingTester::lateEndIsASlipWithEvent() {
    runFastCycle(0, 500, 100, 1);
    // Cycle 1 still running when ticks 2 and 3 fire: two ticks late
    runFastCycle(1, 500, 2 * PERIOD, 4);
    EXPECT_EQ(component.record(0).slips, 1u);
    EXPECT_EQ(component.totalSlips(), 1u);
    ASSERT_EVENTS_RateGroupSlip_SIZE(1);
    ASSERT_EVENTS_RateGroupSlip(0, 0, 1, 2);
    ASSERT_TLM_Slips(0, 1);
}

void TimingTester::latencyAcrossTheCounterWrap() {
    // The tick is stamped just before the 32-bit counter wraps, the cycle
    // starts just after it.
    FakeTickClock::fire(0, 0xFFFFFF00u);
    FakeTickClock::now = 0x00000100u;
    this->invoke_to_cycleStart(0, 0);
    FakeTickClock::now = 0x00000180u;
    this->invoke_to_cycleEnd(0, 0);
    EXPECT_EQ(component.record(0).latency.max(), 0x200u);
    EXPECT_EQ(component.record(0).exec.max(), 0x80u);
    EXPECT_EQ(component.record(0).slips, 0u);
}

void TimingTester::sameSamplesSameHash() {
    runFastCycle(0, 500, 100, 1);
    runFastCycle(1, 700, 300, 2);
    const SampleHash first = component.sampleHash();
    EXPECT_EQ(first.samples(), 5u);  // 2 latencies, 2 executions, 1 period

    TimingTester again;
    again.runFastCycle(0, 500, 100, 1);
    again.runFastCycle(1, 700, 300, 2);
    EXPECT_EQ(again.component.sampleHash().value(), first.value());

    TimingTester other;
    other.runFastCycle(0, 500, 100, 1);
    other.runFastCycle(1, 701, 300, 2);  // one cycle later
    EXPECT_NE(other.component.sampleHash().value(), first.value());
}

void TimingTester::probeCostLeavesTheRunUntouched() {
    (void)component.measureProbeCost(8);
    EXPECT_EQ(component.record(0).cycles, 0u);
    EXPECT_EQ(component.sampleHash().samples(), 0u);
    runFastCycle(0, 500, 100, 1);
    EXPECT_EQ(component.record(0).cycles, 1u);
}

void TimingTester::restartEmptiesTheRecordsAndKeepsTheHash() {
    for (U32 tick = 0; tick < 100; tick++) {
        component.tick();
    }
    runFastCycle(0, 500, 100, 1);
    runFastCycle(1, 500, 2 * PERIOD, 4);  // a slip in this segment
    const U32 hashedSamples = component.sampleHash().samples();
    component.restart(100);
    EXPECT_EQ(component.ticksDriven(), 0u);
    EXPECT_EQ(component.record(0).cycles, 0u);
    EXPECT_EQ(component.record(0).slips, 0u);
    EXPECT_EQ(component.record(0).latency.count(), 0u);
    EXPECT_EQ(component.sampleHash().samples(), hashedSamples);
    // The next segment numbers its ticks from zero again (the tick clock restarts)
    FakeTickClock::reset();
    runFastCycle(0, 600, 100, 1);
    EXPECT_EQ(component.record(0).cycles, 1u);
    EXPECT_EQ(component.record(0).slips, 0u);
    EXPECT_EQ(component.record(0).latency.max(), 600u);
}

void TimingTester::restartRefusesASegmentOffTheHyperperiod() {
    for (U32 tick = 0; tick < 150; tick++) {
        component.tick();
    }
    // 150 ticks leave the 10 Hz group half way: its phase would not match
    EXPECT_DEATH(component.restart(100), "");
}

void TimingTester::segmentsOnlyWhenServedWholeHyperperiodsOneAtATime() {
    const FwOpcodeType opcode = TimingComponentBase::OPCODE_MEASURE_SEGMENT;
    // A scenario with its own sequence does not serve requests
    this->sendCmd_MEASURE_SEGMENT(0, 1, SegmentAxis::UPLINK, 0, 50, 1000);
    ASSERT_CMD_RESPONSE(0, opcode, 1, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_SegmentRefused(0, SegmentRefusal::NOT_SERVED, 1000);
    EXPECT_FALSE(component.segmentRequested());

    component.serveSegments(100);
    // Not whole hyperperiods, none at all, or too long
    const U32 badLengths[] = {150, 0, Timing::SEGMENT_MAX_TICKS + 100};
    for (const U32 ticks : badLengths) {
        this->clearHistory();
        this->sendCmd_MEASURE_SEGMENT(0, 2, SegmentAxis::UPLINK, 0, 50, ticks);
        ASSERT_CMD_RESPONSE(0, opcode, 2, Fw::CmdResponse::VALIDATION_ERROR);
        ASSERT_EVENTS_SegmentRefused(0, SegmentRefusal::BAD_LENGTH, ticks);
    }
    EXPECT_FALSE(component.segmentRequested());

    this->clearHistory();
    this->sendCmd_MEASURE_SEGMENT(0, 3, SegmentAxis::DOWNLINK, 4, 800, 1000);
    ASSERT_CMD_RESPONSE(0, opcode, 3, Fw::CmdResponse::OK);
    ASSERT_EVENTS_SegmentRequested(0, SegmentAxis::DOWNLINK, 4, 800, 1000);
    ASSERT_TRUE(component.segmentRequested());
    const Timing::Segment segment = component.takeSegment();
    EXPECT_EQ(segment.axis, SegmentAxis::DOWNLINK);
    EXPECT_EQ(segment.point, 4u);
    EXPECT_EQ(segment.level, 800u);
    EXPECT_EQ(segment.ticks, 1000u);

    // One at a time: the next waits until this one is measured
    this->clearHistory();
    this->sendCmd_MEASURE_SEGMENT(0, 4, SegmentAxis::UPLINK, 0, 50, 1000);
    ASSERT_CMD_RESPONSE(0, opcode, 4, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_SegmentRefused(0, SegmentRefusal::BUSY, 1000);
    component.segmentDone();
    EXPECT_FALSE(component.segmentRequested());
    this->sendCmd_MEASURE_SEGMENT(0, 5, SegmentAxis::UPLINK, 0, 50, 1000);
    ASSERT_CMD_RESPONSE(1, opcode, 5, Fw::CmdResponse::OK);
}

}  // namespace Kit
