// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Faults/test/ut/FaultsTester.hpp"
#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {

namespace {
constexpr U32 CYCLES_PER_US = 12;  // the fake clock's 12 MHz
constexpr U32 READING_STEP = 60;   // the clock moves 5 us per reading
}  // namespace

FaultsTester::FaultsTester() : FaultsGTestBase("FaultsTester", MAX_HISTORY_SIZE), component("Faults") {
    this->initComponents();
    this->connectPorts();
    FakeTickClock::reset();
    FakeTickClock::step = READING_STEP;
}

FaultsTester::~FaultsTester() {}

void FaultsTester::overrunRunsOnceInItsRateGroup() {
    this->sendCmd_OVERRUN(0, 5, 1, 1500);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_OVERRUN, 5, Fw::CmdResponse::OK);
    U32 before = FakeTickClock::now;
    this->invoke_to_schedIn(0, 0);  // another group: untouched
    EXPECT_EQ(FakeTickClock::now, before);
    this->invoke_to_schedIn(1, 0);
    EXPECT_GE(FakeTickClock::now - before, 1500 * CYCLES_PER_US);
    ASSERT_EVENTS_OverrunInjected_SIZE(1);
    ASSERT_EVENTS_OverrunInjected(0, 1, 1500);
    before = FakeTickClock::now;
    this->invoke_to_schedIn(1, 0);  // taken: the next cycle is normal
    EXPECT_EQ(FakeTickClock::now, before);
}

void FaultsTester::injectionsAboveTheirLimitsAreRejected() {
    this->sendCmd_OVERRUN(0, 1, FaultsComponentBase::NUM_SCHEDIN_INPUT_PORTS, 100);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_OVERRUN, 1, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_OVERRUN(0, 2, 0, Faults::OVERRUN_MAX_US + 1);
    ASSERT_CMD_RESPONSE(1, FaultsComponentBase::OPCODE_OVERRUN, 2, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_STACK_OVERFLOW(0, 3, Faults::STACK_MAX_BYTES + 1);
    ASSERT_CMD_RESPONSE(2, FaultsComponentBase::OPCODE_STACK_OVERFLOW, 3, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_InjectionRejected_SIZE(3);
    ASSERT_EVENTS_InjectionRejected(2, Faults::STACK_MAX_BYTES + 1, Faults::STACK_MAX_BYTES);
    const U32 before = FakeTickClock::now;
    this->invoke_to_schedIn(0, 0);  // nothing was armed
    EXPECT_EQ(FakeTickClock::now, before);
}

void FaultsTester::stackUseWithinTheLimitCompletes() {
    // A host thread's stack holds this easily: the command runs to its answer
    this->sendCmd_STACK_OVERFLOW(0, 4, 512);
    ASSERT_EVENTS_StackOverflowInjected(0, 512);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_STACK_OVERFLOW, 4, Fw::CmdResponse::OK);
}

void FaultsTester::assertReachesTheAssertHook() {
    // No assert hook here but F´'s default, which aborts: the assert fired
    EXPECT_DEATH(this->sendCmd_ASSERT(0, 6, 42), "");
}

}  // namespace Kit
