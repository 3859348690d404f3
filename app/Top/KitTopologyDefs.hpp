// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopologyDefs.hpp
// \brief  Definitions the generated topology code expects
// ======================================================================
#ifndef KIT_KITTOPOLOGYDEFS_HPP
#define KIT_KITTOPOLOGYDEFS_HPP

#include "app/Top/FppConstantsAc.hpp"
#include "app/src/CountingAllocator.hpp"

namespace Kit {
//! What the topology's setup needs from main: the allocator the ground
//! link's queues and buffers come from (F´'s are registered with it too;
//! it counts, so the link's share is known)
struct TopologyState {
    CountingAllocator& allocator;
};
}  // namespace Kit

#endif
