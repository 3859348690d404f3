// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.hpp
// \brief  The reference deployment's side of the seam (app/src/Deployment.hpp):
//         its counts; its tables and setup are KitTopology.cpp
// ======================================================================
#ifndef KIT_KITTOPOLOGY_HPP
#define KIT_KITTOPOLOGY_HPP

#include "app/Top/KitTopologyAc.hpp"
#include "app/src/ActiveForms.hpp"

namespace Kit {

//! Rate groups, in the order of the rate group driver's outputs (their
//! table: KitTopology.cpp)
constexpr FwIndexType RATE_GROUP_COUNT = 3;
//! ... and their priorities in the table (Tables.fpp), in the same order:
//! each model's build-time checks hold them to its rules
constexpr FwTaskPriorityType RATE_GROUP_PRIORITIES[RATE_GROUP_COUNT] = {Priorities::rg1kHz, Priorities::rg100Hz,
                                                                        Priorities::rg10Hz};

//! The active instances: events, tlmSend, load, comQueue, and the rate
//! groups (app/Top/rategroups/) and the dispatcher (app/Top/dispatcher/)
//! where the build has them in their active form, and F´'s services where
//! the build has them (app/Top/services/)
constexpr FwSizeType ACTIVE_RATE_GROUPS = activeRateGroups(RATE_GROUP_COUNT);
#if defined(CONFIG_KIT_SERVICE_PARAMS)
constexpr FwSizeType PARAMETER_DATABASES = 1;
#else
constexpr FwSizeType PARAMETER_DATABASES = 0;
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
constexpr FwSizeType FILE_DOWNLINKS = 1;
#else
constexpr FwSizeType FILE_DOWNLINKS = 0;
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
constexpr FwSizeType FILE_UPLINKS = 1;
#else
constexpr FwSizeType FILE_UPLINKS = 0;
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
constexpr FwSizeType SEQUENCERS = 1;
#else
constexpr FwSizeType SEQUENCERS = 0;
#endif
constexpr FwSizeType SERVICES = PARAMETER_DATABASES + FILE_DOWNLINKS + FILE_UPLINKS + SEQUENCERS;
constexpr FwSizeType ACTIVE_INSTANCE_COUNT = 4 + ACTIVE_RATE_GROUPS + ACTIVE_DISPATCHERS + SERVICES;

//! Svc.Health's ping entries: events, tlmSend, the dispatcher where it is
//! active, the rate groups where the model pings them
//! (CONFIG_KIT_HEALTH_PINGS_RATE_GROUPS), then the parameter database, the
//! file downlink, the file uplink and the sequencer where the build has
//! them. Entry i is health's port i.
#if defined(CONFIG_KIT_SERVICE_CDH)
#if defined(CONFIG_KIT_HEALTH_PINGS_RATE_GROUPS)
constexpr FwSizeType PINGED_RATE_GROUPS = 3;
#else
constexpr FwSizeType PINGED_RATE_GROUPS = 0;
#endif
constexpr FwIndexType PING_ENTRY_COUNT = 2 + ACTIVE_DISPATCHERS + PINGED_RATE_GROUPS + SERVICES;
#endif
//! The rate group that runs health (its Run port): the 10 Hz group
constexpr FwIndexType HEALTH_RATE_GROUP = 2;

}  // namespace Kit

// What the kit's code asks of a deployment, with these counts
#include "app/src/Deployment.hpp"

#endif
