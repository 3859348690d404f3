// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/SharedThread.hpp
// \brief  One thread for the active components of a band of F´ levels
//
// Where a board's RAM cannot hold a stack for every service
// (CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH, rtos/Kconfig.model), the active
// components whose priority is in [CONFIG_KIT_RTOS_SHARED_LEVEL_LOW,
// CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH] run on one thread, "services", at the
// band's top level: each of its passes dispatches one message of the most
// urgent member that has one (equal levels in turn). ArduPilot runs its
// I/O callbacks on one thread the same way; F´'s Os::Task has the notion
// (isCooperative), asked before the task's level is known, so the kit's
// task delegate routes a member here from its start() instead.
// ======================================================================
#ifndef KIT_SHAREDTHREAD_HPP
#define KIT_SHAREDTHREAD_HPP

#include <Os/Task.hpp>
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/kernel.h>

namespace Kit {
namespace SharedThread {

//! Whether the build shares a thread at all
constexpr bool enabled() {
    return CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH > 0;
}

//! Whether a task of this F´ level runs on the shared thread
constexpr bool hosts(FwTaskPriorityType level) {
    return enabled() && level >= CONFIG_KIT_RTOS_SHARED_LEVEL_LOW && level <= CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH;
}

//! Before the topology starts its tasks: the thread, on this stack (where
//! the deployment lists its tasks' levels: rtos/ThreadStacks.cpp)
void start(k_thread_stack_t* stack, size_t size);

//! Whether start() made the thread: the band's tasks join it, else each
//! is a thread of its own
bool running();

//! An active component's task, as Os::Task hands it to its delegate: the
//! component joins the thread's members (its queue then wakes the thread)
Os::TaskInterface::Status join(const Os::TaskInterface::Arguments& arguments);

//! One member's share of the thread
struct MemberUse {
    const void* owner;  //!< the component
    U32 runs;           //!< messages dispatched
    U32 maxCycles;      //!< the longest dispatch, on this thread's clock (preemption left out)
    U64 cycles;         //!< in all
};

//! Members so far
U32 memberCount();

//! Member index's use
MemberUse memberUse(U32 index);

}  // namespace SharedThread
}  // namespace Kit

#endif
