// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopologyDefs.hpp
// \brief  Definitions the generated topology code expects
// ======================================================================
#ifndef KIT_KITTOPOLOGYDEFS_HPP
#define KIT_KITTOPOLOGYDEFS_HPP

#include <Fw/Types/MemAllocator.hpp>
#include "app/Top/FppConstantsAc.hpp"

namespace Kit {
//! Nothing to pass at setup: the kit runs no ground link
//! What the topology's setup needs from main: the allocator the ground
//! link's queues and buffers come from (F´'s are registered with it too)
struct TopologyState {
    Fw::MemAllocator& allocator;
};
}  // namespace Kit

#endif
