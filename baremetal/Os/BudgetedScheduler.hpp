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
//  - the critical task (the highest priority: the 1 kHz rate group) is
//    cycle-locked: it runs first after every tick, always;
//  - every other task carries an anticipated slice time, learned from its
//    measured slices (the longest recent one: it jumps up to a longer slice
//    at once and decays slowly, by 1/64 per shorter one);
//  - a task runs only if its anticipated time plus a guard fits before the
//    next tick; otherwise it is deferred to a later tick;
//  - the guard adapts: it grows when a slice overran its anticipated end and
//    shrinks when the anticipation held (Kconfig bounds and steps);
//  - tasks are offered in dynamic-priority order, static priority times
//    (1 + ticks deferred), so a deferred task rises; one deferred more than
//    KIT_BUDGET_EXPEDITE_AGE ticks in a row has its anticipation cut by a
//    tenth at each further deferral until it fits (Betaflight's expedite),
//    so nothing starves: a slice that is really longer than a tick leaves
//    then runs anyway and makes the next tick late;
//  - every task still gets at most one slice per tick, as in the plain pass.
// Per-task deferrals, expedited slices and late slices (those that ended
// after the next tick was due), and the guard, are the record's SCHED lines.
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
    U32 expedited;          //!< slices run after more than KIT_BUDGET_EXPEDITE_AGE deferrals in a row
    U32 late;               //!< slices that ended after the next tick was due
    bool critical;          //!< the cycle-locked task: never deferred
};

//! The guard: now, and the largest it reached
struct GuardStats {
    U32 cycles;
    U32 maxCycles;
};

//! After a tick has been handed to the rate group driver: run the critical
//! task, then whatever fits before `nextTickAt` (a cycle count)
void runTick(U32 nextTickAt);

//! A task's statistics, by its TimedTask index
TaskStats stats(FwSizeType index);

GuardStats guard();

}  // namespace BudgetedScheduler
}  // namespace Kit

#endif
