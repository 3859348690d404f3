// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TopologyState.hpp
// \brief  What a deployment's topology setup takes from the kit's main
//
// F´'s generated setup functions take a TopologyState, which F´'s
// convention has the deployment's <Name>TopologyDefs.hpp define: a
// deployment measured by the kit takes this one there (app/Top/KitTopologyDefs.hpp).
// ======================================================================
#ifndef KIT_TOPOLOGYSTATE_HPP
#define KIT_TOPOLOGYSTATE_HPP

#include "app/src/CountingAllocator.hpp"

namespace Kit {
//! The allocator the ground link's queues and buffers come from (F´'s are
//! registered with it too; it counts, so the link's share is known)
struct TopologyState {
    CountingAllocator& allocator;
};
}  // namespace Kit

#endif
