// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ActiveStacks.hpp
// \brief  The stack table's entry of every active instance this build has
//         (the rtos model gives each thread its stack from it:
//         rtos/ThreadStacks.cpp)
// ======================================================================
#ifndef THERMAL_ACTIVESTACKS_HPP
#define THERMAL_ACTIVESTACKS_HPP

#include "Thermal/Top/KitTopology.hpp"

namespace Kit {

constexpr FwSizeType ACTIVE_STACKS[] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    Stacks::rg50Hz,  Stacks::rg10Hz,  Stacks::rg1Hz,
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    Stacks::cmdDisp,
#endif
    Stacks::events,  Stacks::tlmSend, Stacks::load,  Stacks::comQueue,
};
constexpr FwSizeType ACTIVE_STACK_ENTRIES = sizeof(ACTIVE_STACKS) / sizeof(ACTIVE_STACKS[0]);
static_assert(ACTIVE_STACK_ENTRIES == ACTIVE_INSTANCE_COUNT, "ACTIVE_STACKS and ACTIVE_INSTANCES disagree");

}  // namespace Kit

#endif
