// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  BudgetedScheduler.hpp
// \brief  A time-budgeted cooperative policy, after Betaflight's scheduler
//
// The plain cooperative pass (fprime-baremetal's TaskRunner::runAll) gives
// every task one slice per tick in priority order, whatever the time left:
// a long slice that starts just before a tick makes that tick late. This
// policy (CONFIG_KIT_BAREMETAL_POLICY_BUDGETED) decides before each slice,
// as Betaflight's scheduler does:
//  - critical tasks (static priority at least KIT_BUDGET_CRITICAL_PRIORITY:
//    the rate groups, the dispatcher and the downlink) are cycle-locked:
//    they run first after every tick, by priority, never deferred. The
//    downlink is Betaflight's serial task, which its scheduler never defers
//    either (a downlink slice is 1.08 ms on mps2/an385: budgeted, it would
//    starve and the ground would lose events);
//  - every other task carries an anticipated slice time, learned from its
//    measured slices (the longest recent one: it jumps up to a longer slice
//    at once and decays slowly, by 1/64 per shorter one), and runs only if
//    that plus a guard fits before the next tick; otherwise it is deferred;
//  - the guard adapts: it grows when a slice overran its anticipated end and
//    shrinks when the anticipation held (Kconfig bounds and steps);
//  - budgeted tasks are offered in dynamic-priority order, static priority
//    times (1 + ticks deferred), so a deferred task rises; past
//    KIT_BUDGET_EXPEDITE_AGE deferrals in a row each further one cuts its
//    anticipation by a tenth until it fits (Betaflight's expedite);
//  - every KIT_BUDGET_OPEN_EVERY ticks the budget is waived and every task
//    runs (Betaflight's SCHED_TASK_DEFER_MASK), so no task waits longer and
//    no queue behind a deferred task waits for ever;
//  - every task still gets at most one slice per tick, as in the plain pass.
// Per-task deferrals, expedited slices (run on an open tick though they did
// not fit) and late slices (those that ended after the next tick was due),
// and the guard, are the record's SCHED lines.
// ======================================================================
#ifndef KIT_BUDGETEDSCHEDULER_HPP
#define KIT_BUDGETEDSCHEDULER_HPP

#include "baremetal/Os/TimedTask.hpp"

namespace Kit {
namespace BudgetedScheduler {

//! One task's scheduling statistics
struct TaskStats {
    U32 anticipatedCycles;  //!< the anticipated slice time now
    U32 deferrals;          //!< turns it did not fit and waited
    U32 expedited;          //!< slices run on an open tick though they did not fit
    U32 late;               //!< slices that ended after the next tick was due
    bool critical;          //!< cycle-locked: never deferred
};

//! The guard: now, and the largest it reached
struct GuardStats {
    U32 cycles;
    U32 maxCycles;
};

//! After a tick has been handed to the rate group driver: run the critical
//! tasks, then whatever fits before `nextTickAt` (a cycle count)
void runTick(U32 nextTickAt);

//! A task's statistics, by its TimedTask index
TaskStats stats(FwSizeType index);

GuardStats guard();

}  // namespace BudgetedScheduler
}  // namespace Kit

#endif
