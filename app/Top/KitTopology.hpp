// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.hpp
// \brief  Set up and tear down the kit's deployment (shared by both variants)
// ======================================================================
#ifndef KIT_KITTOPOLOGY_HPP
#define KIT_KITTOPOLOGY_HPP

#include "app/Top/KitTopologyAc.hpp"

namespace Kit {

//! Rate groups, in the order of the rate group driver's outputs
constexpr FwIndexType RATE_GROUP_COUNT = 3;
extern const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT];

//! An active component instance, for reports that must name its task
struct ActiveInstance {
    const char* name;
    const void* object;  //!< the instance; its task's entry argument lies inside it
    FwSizeType size;
    const Fw::QueuedComponentBase* component;  //!< the same instance, as the owner of its message queue
};
//! The active instances: events, tlmSend, load, comQueue, and the rate
//! groups (app/Top/rategroups/) and the dispatcher (app/Top/dispatcher/)
//! where the build has them in their active form, and F´'s services where
//! the build has them (app/Top/services/)
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
constexpr FwSizeType ACTIVE_RATE_GROUPS = 0;
#else
constexpr FwSizeType ACTIVE_RATE_GROUPS = 3;
#endif
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
constexpr FwSizeType ACTIVE_DISPATCHERS = 0;
#else
constexpr FwSizeType ACTIVE_DISPATCHERS = 1;
#endif
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
extern const ActiveInstance ACTIVE_INSTANCES[ACTIVE_INSTANCE_COUNT];

//! Name of the active instance whose object holds `address`, or nullptr
const char* activeInstanceHolding(const void* address);

//! An active instance's message queue: its depth, the bytes one message
//! slot takes, and the most messages it has held at once
struct QueueUse {
    FwSizeType depth;
    FwSizeType slotBytes;
    FwSizeType highWater;
    FwSizeType dropped;  //!< messages to the component's `drop` ports lost to a full queue
};
QueueUse queueUse(const ActiveInstance& instance);

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
//! Name of ping entry `entry`
const char* pingEntryName(FwIndexType entry);
//! The probe timing ping entry `entry`'s round trips
const PingProbe& pingProbe(FwIndexType entry);
//! Starts a segment on every ping probe (a load sweep's point)
void startPingSegment();
#endif
//! The rate group that runs health (its Run port): the 10 Hz group
constexpr FwIndexType HEALTH_RATE_GROUP = 2;

//! Instantiate, wire, configure and start the deployment (tasks included)
void setupTopology(const TopologyState& state);

//! Stop and join the tasks, release resources
void teardownTopology(const TopologyState& state);

//! Cycles rate group `rg` must complete in the first `ticks` ticks
U32 expectedCycles(FwIndexType rg, U32 ticks);

//! Bytes of the F´ allocator the ground link took at setup (BufferManager
//! pool, frame accumulator, ComQueue's packet queues)
FwSizeType linkBufferBytes();

//! The link UART's line rate (bits/s: its devicetree current-speed)
U32 linkBaudRate();

//! The link UART's driver reports receive errors (uart_err_check)
bool linkUartErrorsReported();

//! Opcode of the dispatcher's built-in NO_OP (its base ID + 0)
FwOpcodeType noOpOpcode();

//! A NO_OP command frame, sent at 10 Hz cycle `cycle` of a play
Uplink::Frame noOpFrame(U32 cycle);

}  // namespace Kit

#endif
