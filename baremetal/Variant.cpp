// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  baremetal/Variant.cpp
// \brief  The baremetal model's tick and rate-group dispatch: the cooperative main loop's half
//
// The tick ISR only counts and stamps the tick (app/src/TickClock.cpp): the
// count is the flag. The main loop sleeps until it moves, hands the tick to
// the rate group driver, then runs the tasks by the configured policy:
//  - pass (CONFIG_KIT_BAREMETAL_POLICY_PASS): every task one slice, highest
//    priority first (fprime-baremetal's TaskRunner::runAll);
//  - budgeted (CONFIG_KIT_BAREMETAL_POLICY_BUDGETED): the 1 kHz group's
//    task always, then each other task only if its anticipated slice fits
//    before the next tick (baremetal/Os/BudgetedScheduler.hpp);
//  - passive (CONFIG_KIT_BAREMETAL_POLICY_PASSIVE): the rate groups are
//    passive, so handing the tick to the driver already ran every due
//    group and its members; then one pass of the remaining tasks, then
//    slice by slice until a pass takes no message, none is queued or the
//    next tick is due, as F´'s baremetal main loop runs its tasks until
//    there is nothing left.
// Rate groups never run inside the ISR.
// ======================================================================
#include "app/src/Variant.hpp"
// Before any Zephyr header: F´'s Os::Queue has a status named EMPTY, a macro there
#include "baremetal/Os/CooperativeQueue.hpp"

#include "app/src/TickPath.h"
#include "baremetal/Os/BudgetedScheduler.hpp"
#include "baremetal/Os/TimedTask.hpp"

#include <Fw/Types/Assert.hpp>

#include <zephyr/kernel.h>
#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>

K_KERNEL_STACK_DECLARE(z_main_stack, CONFIG_MAIN_STACK_SIZE);

namespace Kit {
namespace Variant {

// Every cooperative task, plus idle, is one CPU context
static_assert(TimedTask::MAX_TASKS + 1 <= MAX_CONTEXTS, "MAX_CONTEXTS cannot hold every task and idle");

namespace {
// After the last tick: passes enough to empty every queue (the deepest holds 8)
constexpr U32 DRAIN_PASSES = 32;

// The one stack: main's. Painted below the live frame at start-up; the
// high-water mark is where the paint ends.
constexpr U32 PAINT = 0xCAFEF00Du;
constexpr U32 PAINT_GUARD_BYTES = 128;  // below the current frame, left alone
// The stack guard: the lowest words of the stack, painted like the rest. No
// MPU is assumed, so nothing stops an overflow; a guard word that lost its
// paint means the stack reached its last 32 bytes (or went past them), and
// the run stops before corrupted memory is trusted.
constexpr U32 GUARD_WORDS = 8;

// The main stack was painted (prepareStacks()): its guard means something
bool s_painted = false;

// Cycles the main loop spent asleep waiting for a tick, and how often
U64 s_idleCycles = 0;
U32 s_idleWaits = 0;
U32 s_idleMax = 0;

U32* stackBottom() {
    return reinterpret_cast<U32*>(K_KERNEL_STACK_BUFFER(z_main_stack));
}

GuardBreach checkGuard() {
    const U32* const bottom = stackBottom();
    for (U32 i = 0; i < GUARD_WORDS; i++) {
        if (bottom[i] != PAINT) {
            return {true, i, reinterpret_cast<uintptr_t>(&bottom[i])};
        }
    }
    return {false, 0, 0};
}

// One pass of every task, then the stack guard
GuardBreach runPass() {
    Os::Baremetal::TaskRunner::getSingleton().runAll();
    return checkGuard();
}

#if defined(CONFIG_KIT_BAREMETAL_POLICY_PASSIVE)
// The tick at `nextTickAt` is not due yet
bool beforeTick(U32 nextTickAt) {
    return static_cast<I32>(nextTickAt - k_cycle_get_32()) > 0;
}
#endif

// The policy's tasks for one tick, then the stack guard
GuardBreach runTick(U32 nextTickAt) {
#if defined(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)
    BudgetedScheduler::runTick(nextTickAt);
    return checkGuard();
#elif defined(CONFIG_KIT_BAREMETAL_POLICY_PASSIVE)
    // One pass, as the pass policy: every task a slice, however late the
    // loop is. Then a burst (the telemetry service's packets, a batch of
    // ground commands and their events) is drained in the tick it arrived
    // in, not one message per tick, so the next burst finds the queues
    // empty. Slice by slice, so the next tick waits for one slice at most;
    // bounded, so a task feeding itself cannot hold the loop. A pass that
    // took no message ends it: what is still queued then sits at a queued
    // component (Svc.Health's ping answers), which its rate group empties
    // at a tick, and looping on it kept the CPU from ever idling (measured:
    // the 1 kHz tick's wait 9 cycles on average, every task sliced 26,000
    // times a virtual second with nothing to do).
    U32 received = CooperativeQueue::receivedMessages();
    GuardBreach breach = runPass();
    for (U32 pass = 1; pass < DRAIN_PASSES && !breach.breached; pass++) {
        if (CooperativeQueue::receivedMessages() == received) {
            return breach;
        }
        received = CooperativeQueue::receivedMessages();
        for (FwSizeType task = 0; task < TimedTask::taskCount(); task++) {
            if (CooperativeQueue::queuedMessages() == 0 || !beforeTick(nextTickAt)) {
                return breach;
            }
            (void)TimedTask::runSlice(task);
        }
        breach = checkGuard();
    }
    return breach;
#else
    (void)nextTickAt;  // the plain pass runs everything, whatever the time left
    return runPass();
#endif
}

U32 mainStackUsed() {
    // Where the paint ends is the high-water mark
    const U32 size = K_KERNEL_STACK_SIZEOF(z_main_stack);
    const U32* word = stackBottom();
    const U32* const top = word + size / sizeof(U32);
    while (word < top && *word == PAINT) {
        word++;
    }
    return size - static_cast<U32>(reinterpret_cast<const U8*>(word) - reinterpret_cast<const U8*>(stackBottom()));
}
}  // namespace

ContextKind contextKind() {
    return ContextKind::SLICE;
}

void onTickIsr() {}

Context currentContext() {
    return {"main", nullptr};  // the only context besides interrupts
}

void waitForTick(U32 (*ticksFired)(), U32 handled) {
    const U32 begin = k_cycle_get_32();
    // WFI until the tick moves, shared with the floor it is measured against
    kit_tick_idle_until(ticksFired, handled);
    const U32 slept = k_cycle_get_32() - begin;
    s_idleCycles += slept;
    s_idleWaits++;
    s_idleMax = slept > s_idleMax ? slept : s_idleMax;
}

GuardBreach afterTick(U32 nextTickAt) {
    return runTick(nextTickAt);
}

GuardBreach guardState() {
    // Unpainted, the guard says nothing (a fault during boot)
    return s_painted ? checkGuard() : GuardBreach{false, 0, 0};
}

GuardBreach drain() {
    for (U32 pass = 0; pass < DRAIN_PASSES; pass++) {
        const GuardBreach breach = runPass();
        if (breach.breached) {
            return breach;
        }
    }
    return {false, 0, 0};
}

void prepareStacks() {
    // Paint from the bottom of the stack up to a guard below this frame
    const uintptr_t end = reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) - PAINT_GUARD_BYTES;
    for (U32* word = stackBottom(); reinterpret_cast<uintptr_t>(word) < end; word++) {
        *word = PAINT;
    }
    s_painted = true;
}

StackUse currentStack() {
    return {currentContext(), static_cast<U32>(K_KERNEL_STACK_SIZEOF(z_main_stack)), mainStackUsed()};
}

U32 stacks(StackUse (&out)[MAX_CONTEXTS]) {
    out[0] = currentStack();
    return 1;
}

U32 schedule(ScheduleUse (&out)[MAX_CONTEXTS], GuardMargin& guard) {
#if defined(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)
    const FwSizeType tasks = TimedTask::taskCount();
    FW_ASSERT(tasks <= MAX_CONTEXTS, static_cast<FwAssertArgType>(tasks));
    for (FwSizeType i = 0; i < tasks; i++) {
        const BudgetedScheduler::TaskStats stats = BudgetedScheduler::stats(i);
        out[i] = {{nullptr, TimedTask::record(i).argument},
                  stats.critical,
                  stats.anticipatedCycles,
                  stats.deferrals,
                  stats.expedited,
                  stats.late};
    }
    const BudgetedScheduler::GuardStats margin = BudgetedScheduler::guard();
    guard = {margin.cycles, margin.maxCycles};
    return static_cast<U32>(tasks);
#else
    (void)out;
    guard = {0, 0};
    return 0;  // the plain pass budgets nothing
#endif
}

U32 cpu(CpuUse (&out)[MAX_CONTEXTS]) {
    const FwSizeType tasks = TimedTask::taskCount();
    FW_ASSERT(tasks + 1 <= MAX_CONTEXTS, static_cast<FwAssertArgType>(tasks));
    for (FwSizeType i = 0; i < tasks; i++) {
        const SliceRecord& task = TimedTask::record(i);
        out[i] = {{nullptr, task.argument},
                  task.slices,
                  static_cast<U32>(task.slices == 0 ? 0 : task.cycles / task.slices),
                  task.maxCycles,
                  task.cycles};
    }
    out[tasks] = {{"idle", nullptr},
                  s_idleWaits,
                  static_cast<U32>(s_idleWaits == 0 ? 0 : s_idleCycles / s_idleWaits),
                  s_idleMax,
                  s_idleCycles};
    return static_cast<U32>(tasks + 1);
}

}  // namespace Variant
}  // namespace Kit
