// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/ModelChecks.cpp
// \brief  Build-time checks that the topology fits the RTOS model
//
// The topology's active instances, the priority table (app/Top/Tables.fpp,
// or a board's override) and the tick thread's priority are set in
// different places; a mismatch would show only at run time (a feeder that
// overfills the downlink's queue, a rate group behind the tick). These
// asserts stop the build instead. (app/Top/TopologyChecks.cpp checks what
// holds in every model.)
// ======================================================================
#include "Top/FppConstantsAc.hpp"
#include "Top/KitTopology.hpp"
#include "rtos/Os/PriorityMap.hpp"
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

namespace Kit {
namespace {

// ComQueue answers each of its sends through its own queue, which asserts
// when full: no thread that feeds that queue may run between its taking a
// message and that answer (app/Top/Tables.fpp says why)
static_assert(static_cast<int>(Priorities::comQueue) > static_cast<int>(Priorities::events) &&
                  static_cast<int>(Priorities::comQueue) > static_cast<int>(Priorities::tlmSend),
              "Tables.fpp (app/Top, or the board's): the downlink (comQueue) must be more urgent than the events "
              "and telemetry services that feed it");
// The tick thread sits just below the fastest rate group and above every
// other task (rtos/Kconfig.model says why): a handed-over cycle of the
// fastest group runs at once, and the tick still hands every slower group
// its cycle first (the deployment's RATE_GROUP_PRIORITIES, fastest first)
static_assert(RATE_GROUP_COUNT >= 2, "the model's tick rules want at least two rate groups");
static_assert(zephyrPriority(RATE_GROUP_PRIORITIES[0], CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) >=
                      0 &&
                  zephyrPriority(RATE_GROUP_PRIORITIES[0], CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) <
                      CONFIG_MAIN_THREAD_PRIORITY &&
                  zephyrPriority(RATE_GROUP_PRIORITIES[1], CONFIG_NUM_PREEMPT_PRIORITIES, CONFIG_MAIN_THREAD_PRIORITY) >
                      CONFIG_MAIN_THREAD_PRIORITY,
              "Tables.fpp (the deployment's, or the board's) and CONFIG_MAIN_THREAD_PRIORITY: only the fastest "
              "rate group may be more urgent than the tick thread");
// The shared thread wakes on its members' sends, which only the kit's queue
// tells it of (rtos/Os/SharedThread.hpp)
#if CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH > 0
#if !defined(CONFIG_KIT_QUEUE_KIT)
#error "CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH: the shared thread needs the kit's queue (CONFIG_KIT_QUEUE_KIT)"
#endif
static_assert(CONFIG_KIT_RTOS_SHARED_LEVEL_LOW <= CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH,
              "CONFIG_KIT_RTOS_SHARED_LEVEL_LOW is above CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH");
// Rate groups are what the kit measures: each keeps its own thread
static_assert(static_cast<int>(RATE_GROUP_PRIORITIES[RATE_GROUP_COUNT - 1]) > CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH,
              "CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH: a rate group's level is in the shared band; every rate group "
              "keeps a thread of its own");
#endif
// Every task's stack comes from the kit's heap, sized from the same table
// (rtos/ThreadStacks.cpp): a pool slot would take a stack before it does
static_assert(CONFIG_DYNAMIC_THREAD_POOL_SIZE == 0,
              "CONFIG_DYNAMIC_THREAD_POOL_SIZE: the rtos model sizes each thread's stack from its table "
              "(rtos/ThreadStacks.cpp); a pool slot would take one of them at the slot's size");

}  // namespace
}  // namespace Kit
