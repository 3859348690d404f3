// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  TopologyChecks.cpp
// \brief  Build-time checks that the topology and its table agree
//
// The topology's active instances and the priority and stack table
// (app/Top/Tables.fpp, or a board's override) are written in two places; a
// mismatch would show only at run time (a task without a stack, a queue
// that asserts when full). These asserts stop the build instead. They test
// the deployment's own capabilities (passive rate groups, the passive
// dispatcher) and nothing of a model: each execution model checks that the
// topology fits it in its own folder (<model>/ModelChecks.cpp).
// ======================================================================
#include "app/Subtopologies/GroundLink/FppConstantsAc.hpp"
#include "app/Top/ActiveStacks.hpp"
#include "app/Top/FppConstantsAc.hpp"
#include "app/Top/KitTopology.hpp"
// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

namespace Kit {
namespace {

static_assert(ACTIVE_STACK_ENTRIES == ACTIVE_INSTANCE_COUNT,
              "the stack table (app/Top/Tables.fpp or boards/<board>/Tables.fpp) and ACTIVE_INSTANCES (app/Top) "
              "must list the same active instances");

#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
// The dispatcher's queue asserts when full: the ground's commands in flight,
// its 10 Hz telemetry call and a scripted command must all fit
static_assert(Link::commandsInFlight + 2 <= Queues::cmdDisp,
              "Queues.cmdDisp (app/Top/instances.fpp) cannot hold Link.commandsInFlight ground commands, the "
              "dispatcher's 10 Hz call and a scripted command");
#endif

#if defined(CONFIG_KIT_SERVICE_CDH)
// Health's port arrays are sized by the count app/config/CMakeLists.txt
// makes from Kconfig; the topology's entries must be exactly those
static_assert(PING_ENTRY_COUNT == HealthPingPorts,
              "HealthPingPorts (app/config/CMakeLists.txt) and PING_ENTRY_COUNT (app/Top/KitTopology.hpp) disagree");
#endif

#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
// The file uplink's queue asserts when full: each packet in it holds one of
// the link's buffers, so it must take them all and health's ping
static_assert(Link::bufferCount + 1 <= Queues::fileUplink,
              "Queues.fileUplink (app/Top/instances.fpp) cannot hold a packet in every link buffer and a ping");
#endif

}  // namespace
}  // namespace Kit
