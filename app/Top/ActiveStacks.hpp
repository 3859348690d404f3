// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ActiveStacks.hpp
// \brief  The stack table's entry of every active instance this build has
//
// The priority and stack table (app/Top/Tables.fpp, or a board's override
// in boards/<board>/Tables.fpp) names every instance that can be active; a
// build where the rate groups or the dispatcher are passive has fewer tasks.
// The rtos model gives each thread its stack from this list
// (rtos/ThreadStacks.cpp), so it is written once, here.
// ======================================================================
#ifndef KIT_ACTIVESTACKS_HPP
#define KIT_ACTIVESTACKS_HPP

#include "app/Top/FppConstantsAc.hpp"
#include "app/Top/KitTopology.hpp"

namespace Kit {

//! The stack of every active instance, as the table gives it
constexpr FwSizeType ACTIVE_STACKS[] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    Stacks::rg1kHz,       Stacks::rg100Hz, Stacks::rg10Hz,  // passive rate groups run on the caller's stack
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    Stacks::cmdDisp,  // the passive dispatcher runs on its sender's stack
#endif
    Stacks::events,       Stacks::tlmSend, Stacks::load,   Stacks::comQueue,
#if defined(CONFIG_KIT_SERVICE_PARAMS)
    Stacks::prmDb,  // the parameter database (app/Top/services/)
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
    Stacks::fileDownlink,  // the file downlink (app/Top/services/)
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
    Stacks::fileUplink,  // the file uplink (app/Top/services/)
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    Stacks::cmdSeq,  // the sequencer (app/Top/services/)
#endif
};
constexpr FwSizeType ACTIVE_STACK_ENTRIES = sizeof(ACTIVE_STACKS) / sizeof(ACTIVE_STACKS[0]);

//! The priority of each, in the same order: the rtos model's shared thread
//! (rtos/Os/SharedThread.hpp) takes the stacks of the levels it hosts
//! out of the threads' heap (rtos/ThreadStacks.cpp). A deployment's own
//! ActiveStacks.hpp without this list runs every task on a thread of its own.
#define KIT_ACTIVE_PRIORITIES 1
constexpr FwTaskPriorityType ACTIVE_PRIORITIES[] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    Priorities::rg1kHz,       Priorities::rg100Hz, Priorities::rg10Hz,
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    Priorities::cmdDisp,
#endif
    Priorities::events,       Priorities::tlmSend, Priorities::load,   Priorities::comQueue,
#if defined(CONFIG_KIT_SERVICE_PARAMS)
    Priorities::prmDb,
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
    Priorities::fileDownlink,
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
    Priorities::fileUplink,
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    Priorities::cmdSeq,
#endif
};
static_assert(sizeof(ACTIVE_PRIORITIES) / sizeof(ACTIVE_PRIORITIES[0]) == ACTIVE_STACK_ENTRIES,
              "ACTIVE_PRIORITIES and ACTIVE_STACKS list the same instances");

}  // namespace Kit

#endif
