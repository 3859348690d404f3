// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.hpp
// \brief  The thermal deployment's side of the kit's seam
//         (app/src/Deployment.hpp): its counts; its tables and setup are
//         KitTopology.cpp
// ======================================================================
#ifndef THERMAL_KITTOPOLOGY_HPP
#define THERMAL_KITTOPOLOGY_HPP

#include "app/src/ActiveForms.hpp"
#include "Thermal/Top/ThermalTopologyAc.hpp"

namespace Kit {

// The deployment's dispatcher, where the kit's code reads its IDs
using Thermal::cmdDisp;

//! Rate groups, in the order of the rate group driver's outputs (their
//! table: KitTopology.cpp), and their priorities in the same order
constexpr FwIndexType RATE_GROUP_COUNT = 3;
constexpr FwTaskPriorityType RATE_GROUP_PRIORITIES[RATE_GROUP_COUNT] = {Priorities::rg50Hz, Priorities::rg10Hz,
                                                                        Priorities::rg1Hz};

//! The active instances: the rate groups and the dispatcher in their active
//! form, events, tlmSend, and the kit's load and comQueue
constexpr FwSizeType ACTIVE_INSTANCE_COUNT = 4 + activeRateGroups(RATE_GROUP_COUNT) + ACTIVE_DISPATCHERS;

//! The 10 Hz group: where health would run (this deployment has none)
constexpr FwIndexType HEALTH_RATE_GROUP = 1;

}  // namespace Kit

// What the kit's code asks of a deployment, with these counts
#include "app/src/Deployment.hpp"

#endif
