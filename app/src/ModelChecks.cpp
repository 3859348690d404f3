// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ModelChecks.cpp
// \brief  Build-time checks that the topology fits the execution model
//
// The topology's active instances, the board's stack table
// (boards/<board>/Tables.fpp), Zephyr's thread pool (rtos) and the
// TaskRunner's table (baremetal) are sized in four places; a mismatch
// would show only at run time (a task that never starts, a stack that
// does not fit its pool slot). These asserts stop the build instead.
// ======================================================================
#include "app/Top/FppConstantsAc.hpp"
#include "app/Top/KitTopology.hpp"
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

#if defined(CONFIG_KIT_MODEL_BAREMETAL)
#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>
#elif defined(CONFIG_KIT_MODEL_RTOS)
#include "rtos/Os/PriorityMap.hpp"
#endif

namespace Kit {
namespace {

// Every active instance of the stack table, and the largest stack
constexpr FwSizeType TABLE_STACKS[] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    Stacks::rg1kHz,  Stacks::rg100Hz, Stacks::rg10Hz,  // passive rate groups run on the caller's stack
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    Stacks::cmdDisp,  // the passive dispatcher runs on its sender's stack
#endif
    Stacks::events,  Stacks::tlmSend, Stacks::load,   Stacks::comQueue,
};
constexpr FwSizeType TABLE_ENTRIES = sizeof(TABLE_STACKS) / sizeof(TABLE_STACKS[0]);

constexpr FwSizeType largestStack() {
    FwSizeType largest = 0;
    for (FwSizeType i = 0; i < TABLE_ENTRIES; i++) {
        largest = TABLE_STACKS[i] > largest ? TABLE_STACKS[i] : largest;
    }
    return largest;
}

static_assert(TABLE_ENTRIES == ACTIVE_INSTANCE_COUNT,
              "the stack table (boards/<board>/Tables.fpp) and ACTIVE_INSTANCES (app/Top) must list the same "
              "active instances");

#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
// The dispatcher's queue asserts when full: the ground's commands in flight,
// its 10 Hz telemetry call and a scripted command must all fit
static_assert(Link::commandsInFlight + 2 <= Queues::cmdDisp,
              "Queues.cmdDisp (app/Top/instances.fpp) cannot hold Link.commandsInFlight ground commands, the "
              "dispatcher's 10 Hz call and a scripted command");
#endif

#if defined(CONFIG_KIT_MODEL_RTOS)
// ComQueue answers each of its sends through its own queue, which asserts
// when full: no thread that feeds that queue may run between its taking a
// message and that answer (boards/<board>/Tables.fpp says why)
static_assert(static_cast<int>(Priorities::comQueue) > static_cast<int>(Priorities::events) &&
                  static_cast<int>(Priorities::comQueue) > static_cast<int>(Priorities::tlmSend),
              "boards/<board>/Tables.fpp: the downlink (comQueue) must be more urgent than the events and "
              "telemetry services that feed it");
// The tick thread sits just below the fastest rate group and above every
// other task (rtos/Kconfig.model says why): a handed-over 1 kHz cycle runs
// at once, and the tick still hands every slower group its cycle first
static_assert(zephyrPriority(Priorities::rg1kHz, CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) >= 0 &&
                  zephyrPriority(Priorities::rg1kHz, CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) <
                      CONFIG_MAIN_THREAD_PRIORITY &&
                  zephyrPriority(Priorities::rg100Hz, CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) >
                      CONFIG_MAIN_THREAD_PRIORITY,
              "boards/<board>/Tables.fpp and CONFIG_MAIN_THREAD_PRIORITY: only the fastest rate group (rg1kHz) "
              "may be more urgent than the tick thread");
// fprime-zephyr takes every task's stack from Zephyr's dynamic thread pool
static_assert(CONFIG_DYNAMIC_THREAD_POOL_SIZE == ACTIVE_INSTANCE_COUNT,
              "CONFIG_DYNAMIC_THREAD_POOL_SIZE (rtos/Kconfig.model) must give one slot per active instance");
static_assert(largestStack() <= CONFIG_DYNAMIC_THREAD_STACK_SIZE,
              "a stack of boards/<board>/Tables.fpp is larger than a thread pool slot "
              "(CONFIG_DYNAMIC_THREAD_STACK_SIZE, boards/<board>/Kconfig.defconfig)");
#elif defined(CONFIG_KIT_MODEL_BAREMETAL)
// Every active instance is one task of the TaskRunner's fixed table
static_assert(ACTIVE_INSTANCE_COUNT <= Os::Baremetal::TASK_CAPACITY,
              "more active instances than fprime-baremetal's TaskRunner holds (TASK_CAPACITY)");
#if defined(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)
// The budgeted policy never defers a task of at least this priority: the
// rate groups, the dispatcher (its queue asserts when full) and the
// downlink (Betaflight's serial task) must be among them, the background
// load (what the policy is for) must not
static_assert(static_cast<int>(Priorities::rg10Hz) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY &&
                  static_cast<int>(Priorities::cmdDisp) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY &&
                  static_cast<int>(Priorities::comQueue) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY,
              "CONFIG_KIT_BUDGET_CRITICAL_PRIORITY would let the budgeted policy defer a rate group, the "
              "dispatcher or the downlink (boards/<board>/Tables.fpp)");
static_assert(static_cast<int>(Priorities::load) < CONFIG_KIT_BUDGET_CRITICAL_PRIORITY,
              "CONFIG_KIT_BUDGET_CRITICAL_PRIORITY leaves the background load cycle-locked: nothing to budget");
#endif
#endif

}  // namespace
}  // namespace Kit
