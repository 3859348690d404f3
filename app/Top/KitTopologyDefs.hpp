// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopologyDefs.hpp
// \brief  Definitions the generated topology code expects
// ======================================================================
#ifndef KIT_KITTOPOLOGYDEFS_HPP
#define KIT_KITTOPOLOGYDEFS_HPP

#include "app/Top/FppConstantsAc.hpp"

namespace Kit {
//! Nothing to pass at setup: the kit runs no ground link
struct TopologyState {};
}  // namespace Kit

#endif
