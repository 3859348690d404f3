// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ThermalTopologyDefs.hpp
// \brief  Definitions the generated topology code expects
// ======================================================================
#ifndef THERMAL_THERMALTOPOLOGYDEFS_HPP
#define THERMAL_THERMALTOPOLOGYDEFS_HPP

#include "app/src/TopologyState.hpp"
#include "Thermal/Top/FppConstantsAc.hpp"

namespace Thermal {
//! The kit's: its main hands the setup the kit's counting allocator
using Kit::TopologyState;
}  // namespace Thermal

#endif
