// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Deployment.hpp
// \brief  What the kit's code asks of the deployment it measures
//
// The deployment's Top/KitTopology.hpp defines its counts
// (RATE_GROUP_COUNT, ACTIVE_INSTANCE_COUNT, PING_ENTRY_COUNT where it has
// health, HEALTH_RATE_GROUP) and includes this file; its tables and its
// setup are in its Top/ (app/Top/KitTopology.cpp is the reference's). The
// kit computes the rest from the tables (app/src/Deployment.cpp).
// docs/your-deployment.md gives the seam.
// ======================================================================
#ifndef KIT_DEPLOYMENT_HPP
#define KIT_DEPLOYMENT_HPP

#include <Fw/Comp/ActiveComponentBase.hpp>
#include "app/Components/PingProbe/PingProbe.hpp"
#include "app/Components/Timing/Timing.hpp"
#include "app/Components/Uplink/Uplink.hpp"

namespace Kit {

// ---------------------------------------------------------------------
// The deployment's tables
// ---------------------------------------------------------------------

//! Rate groups, in the order of the rate group driver's outputs: each
//! group's name, its divisor of the tick and its offset
extern const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT];

//! An active component instance, for reports that must name its task
struct ActiveInstance {
    const char* name;
    const void* object;  //!< the instance; its task's entry argument lies inside it
    FwSizeType size;
    const Fw::QueuedComponentBase* component;  //!< the same instance, as the owner of its message queue
};
//! Every active instance of the build
extern const ActiveInstance ACTIVE_INSTANCES[ACTIVE_INSTANCE_COUNT];

#if defined(CONFIG_KIT_SERVICE_CDH)
//! One of Svc.Health's ping entries: entry i is health's port i (FPP
//! generates health's table from the same connections)
struct PingEntry {
    const char* name;
    PingProbe* probe;                       //!< the kit's probe on the entry's connection
    const Fw::QueuedComponentBase* pinged;  //!< whose queue the probe watches (PingProbe::watchQueue)
};
extern const PingEntry PING_ENTRIES[PING_ENTRY_COUNT];
#endif

// ---------------------------------------------------------------------
// The deployment's setup
// ---------------------------------------------------------------------

//! Instantiate, wire, configure and start the deployment (tasks included)
void setupTopology(const TopologyState& state);

//! Stop and join the tasks, release resources
void teardownTopology(const TopologyState& state);

//! Opcode of the dispatcher's built-in NO_OP (its base ID + 0)
FwOpcodeType noOpOpcode();

// ---------------------------------------------------------------------
// What the kit computes from them (app/src/Deployment.cpp)
// ---------------------------------------------------------------------

//! Cycles rate group `rg` must complete in the first `ticks` ticks
U32 expectedCycles(FwIndexType rg, U32 ticks);

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

#if defined(CONFIG_KIT_SERVICE_CDH)
//! Name of ping entry `entry`
const char* pingEntryName(FwIndexType entry);
//! The probe timing ping entry `entry`'s round trips
const PingProbe& pingProbe(FwIndexType entry);
//! Starts a segment on every ping probe (a load sweep's point)
void startPingSegment();
//! Each probe watches its pinged component's queue, to defer a ping that
//! would find it full (PingProbe::watchQueue): the deployment's setup calls
//! it once its components exist
void watchPingedQueues();
#endif

//! A NO_OP command frame, sent at 10 Hz cycle `cycle` of a play
Uplink::Frame noOpFrame(U32 cycle);

}  // namespace Kit

#endif
