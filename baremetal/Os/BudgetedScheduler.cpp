// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  BudgetedScheduler.cpp
// \brief  A time-budgeted cooperative policy, after Betaflight's scheduler
// ======================================================================
#include "baremetal/Os/BudgetedScheduler.hpp"

#include <zephyr/kernel.h>
#include <Fw/Types/Assert.hpp>

namespace Kit {
namespace BudgetedScheduler {

namespace {

constexpr FwSizeType MAX_TASKS = TimedTask::MAX_TASKS;
// A shorter slice lowers the anticipation by 1/2^DECAY_SHIFT of it
constexpr U32 DECAY_SHIFT = 6;
// Betaflight's TASK_AGE_EXPEDITE_SCALE: a task deferred past the expedite
// age has its anticipation cut to 9/10 at each further deferral, until it fits
constexpr U32 EXPEDITE_NUMERATOR = 9;
constexpr U32 EXPEDITE_DENOMINATOR = 10;

U32 cyclesOfUs(U32 us) {
    return static_cast<U32>((static_cast<U64>(us) * sys_clock_hw_cycles_per_sec()) / 1000000u);
}

struct TaskState {
    TaskStats stats;
    U32 age;  //!< ticks deferred in a row
};

TaskState s_tasks[MAX_TASKS];
// Task indices, critical ones first, each part by static priority
FwSizeType s_byPriority[MAX_TASKS];
FwSizeType s_criticalCount = 0;
GuardStats s_guard = {0, 0};
U32 s_ticks = 0;
bool s_ready = false;

// Cycles left before the tick at `nextTickAt` (negative: it is due)
I32 remaining(U32 nextTickAt) {
    return static_cast<I32>(nextTickAt - k_cycle_get_32());
}

bool isCritical(FwSizeType index) {
    return TimedTask::record(index).priority >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY;
}

// Critical tasks first; within each part, higher static priority first
bool before(FwSizeType a, FwSizeType b) {
    if (isCritical(a) != isCritical(b)) {
        return isCritical(a);
    }
    return TimedTask::record(a).priority > TimedTask::record(b).priority;
}

void setUp() {
    FW_ASSERT(CONFIG_KIT_BUDGET_GUARD_MIN_US <= CONFIG_KIT_BUDGET_GUARD_MAX_US);
    const FwSizeType count = TimedTask::taskCount();
    FW_ASSERT(count > 0 && count <= MAX_TASKS, static_cast<FwAssertArgType>(count));
    s_criticalCount = 0;
    for (FwSizeType i = 0; i < count; i++) {
        s_tasks[i] = {{0, 0, 0, 0, isCritical(i)}, 0};
        s_criticalCount += isCritical(i) ? 1 : 0;
        // Insertion into the static order (at most MAX_TASKS)
        FwSizeType j = i;
        while (j > 0 && before(i, s_byPriority[j - 1])) {
            s_byPriority[j] = s_byPriority[j - 1];
            j--;
        }
        s_byPriority[j] = i;
    }
    // Without a critical task nothing is cycle-locked: the priority threshold
    // (CONFIG_KIT_BUDGET_CRITICAL_PRIORITY) is above every task
    FW_ASSERT(s_criticalCount > 0, static_cast<FwAssertArgType>(CONFIG_KIT_BUDGET_CRITICAL_PRIORITY));
    s_guard = {cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_MIN_US), cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_MIN_US)};
    s_ready = true;
}

// Betaflight's anticipation: the longest recent slice, decaying slowly
void learn(TaskState& task, U32 cycles) {
    U32& anticipated = task.stats.anticipatedCycles;
    anticipated = cycles > anticipated ? cycles : anticipated - (anticipated >> DECAY_SHIFT);
}

// Betaflight's guard: up when a slice ran past its anticipated end (or
// within the smallest guard of it), down when the anticipation held
void adaptGuard(I32 overdue) {
    const U32 minimum = cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_MIN_US);
    const U32 maximum = cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_MAX_US);
    if (overdue > 0 || static_cast<U32>(-overdue) < minimum) {
        const U32 up = s_guard.cycles + cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_STEP_UP_US);
        s_guard.cycles = up < maximum ? up : maximum;
    } else {
        const U32 down = cyclesOfUs(CONFIG_KIT_BUDGET_GUARD_STEP_DOWN_US);
        s_guard.cycles = s_guard.cycles > minimum + down ? s_guard.cycles - down : minimum;
    }
    s_guard.maxCycles = s_guard.cycles > s_guard.maxCycles ? s_guard.cycles : s_guard.maxCycles;
}

void run(FwSizeType index, U32 nextTickAt) {
    TaskState& task = s_tasks[index];
    const U32 cycles = TimedTask::runSlice(index);
    learn(task, cycles);
    task.age = 0;
    if (remaining(nextTickAt) < 0) {
        task.stats.late++;
    }
}

U32 dynamicPriority(FwSizeType index) {
    return static_cast<U32>(TimedTask::record(index).priority) * (1 + s_tasks[index].age);
}

// One budgeted task's turn: run it if it fits (or the tick is open), else
// defer it, cutting a starving task's anticipation
void offer(FwSizeType index, U32 nextTickAt, bool open) {
    TaskState& task = s_tasks[index];
    const U32 need = task.stats.anticipatedCycles + s_guard.cycles;
    const I32 left = remaining(nextTickAt);
    const bool fits = left >= 0 && need <= static_cast<U32>(left);
    if (!fits && !open) {
        task.stats.deferrals++;
        task.age++;
        if (task.age > CONFIG_KIT_BUDGET_EXPEDITE_AGE) {
            // Starving: anticipate less until it fits (a slice really
            // longer than the time a tick leaves then makes a tick late)
            task.stats.anticipatedCycles = static_cast<U32>(
                (static_cast<U64>(task.stats.anticipatedCycles) * EXPEDITE_NUMERATOR) / EXPEDITE_DENOMINATOR);
        }
        return;
    }
    if (!fits) {
        task.stats.expedited++;
    }
    const U32 anticipatedEnd = k_cycle_get_32() + task.stats.anticipatedCycles;
    run(index, nextTickAt);
    if (fits) {
        adaptGuard(static_cast<I32>(k_cycle_get_32() - anticipatedEnd));
    }
}

}  // namespace

void runTick(U32 nextTickAt) {
    if (!s_ready) {
        setUp();  // every task has started by the first tick
    }
    const FwSizeType count = TimedTask::taskCount();
    FW_ASSERT(count <= MAX_TASKS, static_cast<FwAssertArgType>(count));

    // The cycle-locked tasks first, always, by static priority
    for (FwSizeType k = 0; k < s_criticalCount; k++) {
        run(s_byPriority[k], nextTickAt);
    }
    // The rest by dynamic priority, highest first (insertion sort of at
    // most MAX_TASKS; ties keep the static order)
    FwSizeType order[MAX_TASKS];
    const FwSizeType offered = count - s_criticalCount;
    for (FwSizeType i = 0; i < offered; i++) {
        const FwSizeType moving = s_byPriority[s_criticalCount + i];
        FwSizeType j = i;
        while (j > 0 && dynamicPriority(order[j - 1]) < dynamicPriority(moving)) {
            order[j] = order[j - 1];
            j--;
        }
        order[j] = moving;
    }
    // Betaflight's SCHED_TASK_DEFER_MASK: every so many ticks the budget is
    // waived and every task runs, so none waits longer than that
    const bool open = (s_ticks % CONFIG_KIT_BUDGET_OPEN_EVERY) == 0;
    s_ticks++;
    for (FwSizeType k = 0; k < offered; k++) {
        offer(order[k], nextTickAt, open);
    }
}

TaskStats stats(FwSizeType index) {
    FW_ASSERT(index < TimedTask::taskCount(), static_cast<FwAssertArgType>(index));
    return s_tasks[index].stats;
}

GuardStats guard() {
    return s_guard;
}

}  // namespace BudgetedScheduler
}  // namespace Kit
