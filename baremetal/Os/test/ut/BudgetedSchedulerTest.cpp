// SPDX-License-Identifier: Apache-2.0
// The budgeted policy's decisions (baremetal/Os/BudgetedScheduler.hpp), on a
// clock the test moves: critical tasks first and never deferred, the
// learned slice (up at once, down by 1/64), the skip decision (anticipated
// slice plus guard against the cycles left), the guard's steps and bounds,
// ageing (a deferred task rises), the expedite cut, the open tick, late
// slices, the counter's wrap. The fake kernel's counter runs at 1 MHz, so
// the Kconfig bounds (us) are cycles here; the settings are
// baremetal/Kconfig.model's defaults but the expedite age (CMakeLists.txt).
#include <gtest/gtest.h>

#include <vector>

// The scheduler's state is file-static (one policy per program): the test
// compiles the source itself, to start each test from a fresh scheduler
#include "baremetal/Os/BudgetedScheduler.cpp"

namespace {

//! A task of the fake table: its F´ priority and what its next slices cost
struct FakeTask {
    FwTaskPriorityType priority;
    U32 cost;
};

std::vector<FakeTask> s_fakeTasks;
Kit::SliceRecord s_fakeRecords[Kit::TimedTask::MAX_TASKS];
std::vector<FwSizeType> s_ran;  //!< the slices run, in order

}  // namespace

// The TimedTask table the scheduler reads (baremetal/Os/TimedTask.cpp on the
// target): the fake table, each slice moving the clock by its task's cost
namespace Kit {

FwSizeType TimedTask::taskCount() {
    return s_fakeTasks.size();
}

const SliceRecord& TimedTask::record(FwSizeType index) {
    s_fakeRecords[index].priority = s_fakeTasks.at(index).priority;
    return s_fakeRecords[index];
}

U32 TimedTask::runSlice(FwSizeType index) {
    s_ran.push_back(index);
    const U32 cost = s_fakeTasks.at(index).cost;
    KitFake::cycles += cost;
    return cost;
}

}  // namespace Kit

namespace {

using Kit::BudgetedScheduler::guard;
using Kit::BudgetedScheduler::stats;

constexpr U32 GUARD_MIN = CONFIG_KIT_BUDGET_GUARD_MIN_US;  // cycles at 1 MHz
constexpr U32 GUARD_MAX = CONFIG_KIT_BUDGET_GUARD_MAX_US;
constexpr U32 STEP_UP = CONFIG_KIT_BUDGET_GUARD_STEP_UP_US;
constexpr U32 STEP_DOWN = CONFIG_KIT_BUDGET_GUARD_STEP_DOWN_US;
constexpr U32 PLENTY = 100000;  // cycles left: everything fits

// The kit's table (app/Top/Tables.fpp), in an order of starting that is not
// the priority order: critical are 13, 11, 10, 6, 5 (at least 5)
enum KitTask : FwSizeType { LOAD, RG1KHZ, EVENTS, CMDDISP, TLMSEND, COMQUEUE, RG10HZ, RG100HZ };
const std::vector<FakeTask> KIT_TABLE = {{2, 10}, {13, 10}, {3, 10}, {6, 10}, {4, 10}, {5, 10}, {10, 10}, {11, 10}};

class BudgetedSchedulerTest : public ::testing::Test {
  public:
    void SetUp() override { use(KIT_TABLE); }

    //! A fresh scheduler over `tasks`, its first tick not yet run
    void use(const std::vector<FakeTask>& tasks, U32 start = 1000) {
        s_fakeTasks = tasks;
        s_ran.clear();
        KitFake::cycles = start;
        KitFake::cyclesPerSecond = 1000000;
        Kit::BudgetedScheduler::s_ready = false;  // setUp() again on the next tick
        Kit::BudgetedScheduler::s_ticks = 0;
        Kit::BudgetedScheduler::s_guard = {0, 0};
    }

    //! One tick with `left` cycles before the next; the slices it ran
    std::vector<FwSizeType> tick(U32 left) {
        s_ran.clear();
        Kit::BudgetedScheduler::runTick(KitFake::cycles + left);
        return s_ran;
    }
};

TEST_F(BudgetedSchedulerTest, CriticalFirstByPriorityThenTheRestByPriority) {
    // Tick 0 is open (every OPEN_EVERY-th): everything runs, once
    EXPECT_EQ(tick(PLENTY),
              (std::vector<FwSizeType>{RG1KHZ, RG100HZ, RG10HZ, CMDDISP, COMQUEUE, TLMSEND, EVENTS, LOAD}));
    // And on a budgeted tick with room for all, the same order, once each
    EXPECT_EQ(tick(PLENTY),
              (std::vector<FwSizeType>{RG1KHZ, RG100HZ, RG10HZ, CMDDISP, COMQUEUE, TLMSEND, EVENTS, LOAD}));
    EXPECT_TRUE(stats(CMDDISP).critical);
    EXPECT_TRUE(stats(COMQUEUE).critical);
    EXPECT_FALSE(stats(TLMSEND).critical);
}

TEST_F(BudgetedSchedulerTest, CriticalTasksRunWhenTheTickIsDueTheRestWait) {
    (void)tick(PLENTY);
    // No cycle left: the cycle-locked tasks run anyway (late), the rest wait
    EXPECT_EQ(tick(0), (std::vector<FwSizeType>{RG1KHZ, RG100HZ, RG10HZ, CMDDISP, COMQUEUE}));
    EXPECT_EQ(stats(RG1KHZ).late, 1u);
    EXPECT_EQ(stats(RG1KHZ).deferrals, 0u);
    for (FwSizeType budgeted : {TLMSEND, EVENTS, LOAD}) {
        EXPECT_EQ(stats(budgeted).deferrals, 1u);
        EXPECT_EQ(stats(budgeted).late, 0u);
    }
}

TEST_F(BudgetedSchedulerTest, LearnedSliceJumpsUpAtOnceAndDecaysByOneSixtyFourth) {
    use({{13, 10}, {2, 640}});
    (void)tick(PLENTY);
    EXPECT_EQ(stats(1).anticipatedCycles, 640u);
    s_fakeTasks[1].cost = 64;
    (void)tick(PLENTY);
    EXPECT_EQ(stats(1).anticipatedCycles, 630u);  // 640 - 640/64
    (void)tick(PLENTY);
    EXPECT_EQ(stats(1).anticipatedCycles, 621u);  // 630 - 630/64 (9)
    s_fakeTasks[1].cost = 1000;
    (void)tick(PLENTY);
    EXPECT_EQ(stats(1).anticipatedCycles, 1000u);  // a longer slice: at once
}

// The skip decision, at its boundary: a budgeted task runs when its
// anticipated slice plus the guard fits in the cycles left, not one cycle less
void skipDecisionAtTheBoundary(BudgetedSchedulerTest& test) {
    // Tick 0 (open): the task's first slice overran its anticipation (0): the guard steps up
    EXPECT_EQ(test.tick(PLENTY), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(stats(1).anticipatedCycles, 500u);
    ASSERT_EQ(guard().cycles, GUARD_MIN + STEP_UP);
    // 10 for the critical task, then exactly 500 + the guard left: it runs
    EXPECT_EQ(test.tick(10 + 500 + GUARD_MIN + STEP_UP), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(stats(1).deferrals, 0u);
    // It ended at its anticipated end (within the smallest guard): up again
    const U32 guardNow = guard().cycles;
    ASSERT_EQ(guardNow, GUARD_MIN + 2 * STEP_UP);
    // One cycle short (anticipation 493 now: 500 - 500/64): deferred, not run
    EXPECT_EQ(stats(1).anticipatedCycles, 493u);
    EXPECT_EQ(test.tick(10 + 493 + guardNow - 1), (std::vector<FwSizeType>{0}));
    EXPECT_EQ(stats(1).deferrals, 1u);
    EXPECT_EQ(stats(1).expedited, 0u);
}

TEST_F(BudgetedSchedulerTest, RunsWhenAnticipationPlusGuardFits) {
    use({{13, 10}, {2, 500}});
    skipDecisionAtTheBoundary(*this);
}

TEST_F(BudgetedSchedulerTest, SkipDecisionTheSameAcrossTheCycleCounterWrap) {
    use({{13, 10}, {2, 500}}, 0xFFFFFF00u);  // the next ticks fall after the wrap
    skipDecisionAtTheBoundary(*this);
}

TEST_F(BudgetedSchedulerTest, GuardStepsUpOnOverrunsAndDownWhenAnticipationHolds) {
    use({{13, 10}, {2, 500}});
    (void)tick(PLENTY);
    EXPECT_EQ(guard().cycles, GUARD_MIN + STEP_UP);
    // Slices that end at (or past) their anticipated end: up by a step, to the bound
    for (int i = 0; i < 30; i++) {
        (void)tick(PLENTY);
    }
    EXPECT_EQ(guard().cycles, GUARD_MAX);
    EXPECT_EQ(guard().maxCycles, GUARD_MAX);
    // Slices that end well before: down by a step, to the other bound
    s_fakeTasks[1].cost = 0;
    (void)tick(PLENTY);
    EXPECT_EQ(guard().cycles, GUARD_MAX - STEP_DOWN);
    for (int i = 0; i < 200; i++) {
        (void)tick(PLENTY);
    }
    EXPECT_EQ(guard().cycles, GUARD_MIN);
    EXPECT_EQ(guard().maxCycles, GUARD_MAX);
}

TEST_F(BudgetedSchedulerTest, CriticalSlicesLeaveTheGuardAlone) {
    use({{13, 500}, {6, 500}, {2, 0}});
    (void)tick(PLENTY);
    const U32 after = guard().cycles;  // the budgeted task's first slice: 0 of 0, within the guard: up
    EXPECT_EQ(after, GUARD_MIN + STEP_UP);
    s_fakeTasks[0].cost = 5000;  // critical overruns: not the guard's business
    (void)tick(PLENTY);
    EXPECT_EQ(guard().cycles, after + STEP_UP);  // only the budgeted slice (0 of 0) moved it
}

TEST_F(BudgetedSchedulerTest, ADeferredTaskRisesByItsAge) {
    // tlmSend (4) before the load (2) while neither waited
    use({{13, 10}, {4, 10}, {2, 500}});
    EXPECT_EQ(tick(PLENTY), (std::vector<FwSizeType>{0, 1, 2}));
    // Room for tlmSend, not for the load: the load waits two ticks
    const U32 room = 10 + 10 + 100;
    EXPECT_EQ(tick(room), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(tick(room), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(stats(2).deferrals, 2u);
    // Its dynamic priority is now 2 * (1 + 2) = 6 > 4: offered first
    EXPECT_EQ(tick(PLENTY), (std::vector<FwSizeType>{0, 2, 1}));
    // Having run, it is back to its static priority
    EXPECT_EQ(tick(PLENTY), (std::vector<FwSizeType>{0, 1, 2}));
}

TEST_F(BudgetedSchedulerTest, EqualDynamicPrioritiesKeepTheStaticOrder) {
    use({{13, 10}, {3, 10}, {6, 10}, {2, 500}, {4, 10}});
    (void)tick(PLENTY);
    // The load (2) waits once: 2 * (1 + 1) = 4, tlmSend's (4); the tie keeps
    // the static order, tlmSend first, both before events (3)
    EXPECT_EQ(tick(10 + 10 + 10 + 10 + 100), (std::vector<FwSizeType>{0, 2, 4, 1}));
    EXPECT_EQ(tick(PLENTY), (std::vector<FwSizeType>{0, 2, 4, 3, 1}));
}

TEST_F(BudgetedSchedulerTest, PastTheExpediteAgeEachDeferralCutsTheAnticipationByATenth) {
    use({{13, 10}, {2, 1000}});
    (void)tick(PLENTY);
    ASSERT_EQ(stats(1).anticipatedCycles, 1000u);
    std::vector<U32> anticipated;
    for (U32 i = 0; i < CONFIG_KIT_BUDGET_EXPEDITE_AGE + 2; i++) {
        (void)tick(10 + 200);  // never room for it
        anticipated.push_back(stats(1).anticipatedCycles);
    }
    std::vector<U32> expected(CONFIG_KIT_BUDGET_EXPEDITE_AGE, 1000u);
    expected.push_back(900u);
    expected.push_back(810u);
    EXPECT_EQ(anticipated, expected);
    EXPECT_EQ(stats(1).deferrals, CONFIG_KIT_BUDGET_EXPEDITE_AGE + 2);
    // 810 + the guard fits in 900: it runs, and its slice teaches it again
    EXPECT_EQ(tick(10 + 900), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(stats(1).expedited, 0u);
    EXPECT_EQ(stats(1).anticipatedCycles, 1000u);
}

TEST_F(BudgetedSchedulerTest, EveryOpenEveryThTickRunsWhatDoesNotFit) {
    use({{13, 10}, {2, 300}});
    (void)tick(PLENTY);  // tick 0: open
    for (U32 t = 1; t < CONFIG_KIT_BUDGET_OPEN_EVERY; t++) {
        EXPECT_EQ(tick(0), (std::vector<FwSizeType>{0})) << "tick " << t;
    }
    EXPECT_EQ(stats(1).deferrals, CONFIG_KIT_BUDGET_OPEN_EVERY - 1);
    // The open tick: it runs though nothing is left, counted expedited and late
    EXPECT_EQ(tick(0), (std::vector<FwSizeType>{0, 1}));
    EXPECT_EQ(stats(1).expedited, 1u);
    EXPECT_EQ(stats(1).late, 1u);
    EXPECT_EQ(stats(1).deferrals, CONFIG_KIT_BUDGET_OPEN_EVERY - 1);
    // And the count starts again
    EXPECT_EQ(tick(0), (std::vector<FwSizeType>{0}));
    EXPECT_EQ(stats(1).deferrals, CONFIG_KIT_BUDGET_OPEN_EVERY);
}

TEST_F(BudgetedSchedulerTest, ASliceIsLateOnlyWhenItEndsAfterTheTickWasDue) {
    use({{13, 10}, {2, 0}});
    (void)tick(10);  // ends exactly at the next tick: not late
    EXPECT_EQ(stats(0).late, 0u);
    (void)tick(9);
    EXPECT_EQ(stats(0).late, 1u);
}

TEST_F(BudgetedSchedulerTest, ATableWithoutACriticalTaskIsRefused) {
    // Nothing would be cycle-locked: CONFIG_KIT_BUDGET_CRITICAL_PRIORITY above every task
    use({{4, 10}, {2, 10}});
    EXPECT_DEATH((void)tick(PLENTY), "");
}

}  // namespace
