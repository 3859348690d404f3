// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  baremetal/ModelChecks.cpp
// \brief  Build-time checks that the topology fits the baremetal model
//
// The topology's active instances, the TaskRunner's fixed table and the
// budgeted policy's threshold (baremetal/Kconfig.model) against the
// priority table (app/Top/Tables.fpp, or a board's override) are sized in
// different places; a mismatch would show only at run time (a task that
// never runs, a dispatcher deferred until its queue asserts). These asserts
// stop the build instead. (app/Top/TopologyChecks.cpp checks what holds in
// every model.)
// ======================================================================
#include "Top/FppConstantsAc.hpp"
#include "Top/KitTopology.hpp"
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

#include <fprime-baremetal/Os/TaskRunner/TaskRunner.hpp>
#include "baremetal/Os/TimedTask.hpp"

namespace Kit {
namespace {

// Every active instance is one task of the TaskRunner's fixed table
static_assert(ACTIVE_INSTANCE_COUNT <= Os::Baremetal::TASK_CAPACITY,
              "more active instances than fprime-baremetal's TaskRunner holds (TASK_CAPACITY)");
// ... and one timed slice record of the model's (baremetal/Os/TimedTask.hpp)
static_assert(ACTIVE_INSTANCE_COUNT <= TimedTask::MAX_TASKS,
              "more active instances than the model's timed tasks hold (TimedTask::MAX_TASKS)");

#if defined(CONFIG_KIT_BAREMETAL_POLICY_BUDGETED)
// The budgeted policy never defers a task of at least this priority: the
// rate groups, the dispatcher (its queue asserts when full) and the
// downlink (Betaflight's serial task) must be among them, the background
// load (what the policy is for) must not. The least urgent rate group is
// the deployment's (RATE_GROUP_PRIORITIES).
constexpr FwTaskPriorityType leastUrgentRateGroup() {
    FwTaskPriorityType least = RATE_GROUP_PRIORITIES[0];
    for (FwTaskPriorityType priority : RATE_GROUP_PRIORITIES) {
        least = (priority < least) ? priority : least;
    }
    return least;
}
static_assert(static_cast<int>(leastUrgentRateGroup()) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY &&
                  static_cast<int>(Priorities::cmdDisp) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY &&
                  static_cast<int>(Priorities::comQueue) >= CONFIG_KIT_BUDGET_CRITICAL_PRIORITY,
              "CONFIG_KIT_BUDGET_CRITICAL_PRIORITY would let the budgeted policy defer a rate group, the "
              "dispatcher or the downlink (Tables.fpp: the deployment's, or the board's)");
static_assert(static_cast<int>(Priorities::load) < CONFIG_KIT_BUDGET_CRITICAL_PRIORITY,
              "CONFIG_KIT_BUDGET_CRITICAL_PRIORITY leaves the background load cycle-locked: nothing to budget");
#endif

}  // namespace
}  // namespace Kit
