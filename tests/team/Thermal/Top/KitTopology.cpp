// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.cpp
// \brief  The thermal deployment's tables and setup, for the kit
//         (app/src/Deployment.hpp)
// ======================================================================
#include "Thermal/Top/KitTopology.hpp"
#include <Fw/Types/Assert.hpp>
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Subtopologies/GroundLink/GroundLink.hpp"
#include "app/src/ServiceIds.hpp"

namespace Kit {

// The one place the deployment's rates are declared: the rate group driver
// and the kit's timing probe both take them from here. Offsets keep the
// slower groups off the ticks where the faster ones start.
const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT] = {
    {"rg50Hz", CONFIG_KIT_TICK_HZ / 50, 0},
    {"rg10Hz", CONFIG_KIT_TICK_HZ / 10, 1},
    {"rg1Hz", CONFIG_KIT_TICK_HZ / 1, 2},
};
static_assert(CONFIG_KIT_TICK_HZ % 50 == 0, "the tick must divide into the 50 Hz group");

const ActiveInstance ACTIVE_INSTANCES[ACTIVE_INSTANCE_COUNT] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    {"rg50Hz", &Thermal::rg50Hz, sizeof(Thermal::rg50Hz), &Thermal::rg50Hz},
    {"rg10Hz", &Thermal::rg10Hz, sizeof(Thermal::rg10Hz), &Thermal::rg10Hz},
    {"rg1Hz", &Thermal::rg1Hz, sizeof(Thermal::rg1Hz), &Thermal::rg1Hz},
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    {"cmdDisp", &Thermal::cmdDisp, sizeof(Thermal::cmdDisp), &Thermal::cmdDisp},
#endif
    {"events", &Thermal::events, sizeof(Thermal::events), &Thermal::events},
    {"tlmSend", &Thermal::tlmSend, sizeof(Thermal::tlmSend), &Thermal::tlmSend},
    {"load", &load, sizeof(load), &load},
    {"comQueue", &comQueue, sizeof(comQueue), &comQueue},
};

namespace {

// Members per rate group: the ports of the rate group class the build chose
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
constexpr FwIndexType RATE_GROUP_PORTS = PassiveRateGroupOutputPorts;
#else
constexpr FwIndexType RATE_GROUP_PORTS = Svc::ActiveRateGroup::CONNECTION_COUNT_MAX;
#endif

// The F´ allocator's memory ID of the passive dispatcher's tables (the
// link's is 0: app/Subtopologies/GroundLink/GroundLink.cpp)
constexpr FwEnumStoreType DISPATCHER_TABLES_ID = 3;

void configureTopology(const TopologyState& state) {
    Svc::RateGroupDriver::DividerSet dividers;
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        dividers.dividers[i] = {RATE_GROUPS[i].divisor, RATE_GROUPS[i].offset};
    }
    Thermal::rateGroupDriver.configure(dividers);
    timing.configure(RATE_GROUPS, RATE_GROUP_COUNT, TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);

    // Contexts are unused by the members; a rate group wants one per port
    U32 contexts[RATE_GROUP_PORTS] = {};
    Thermal::rg50Hz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));
    Thermal::rg10Hz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));
    Thermal::rg1Hz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));

    // Time starts at zero at boot
    Os::RawTime now;
    (void)now.now();
    Thermal::osTime.set_epoch(Fw::Time(0, 0), now);

    // No file uplink here: the link's buffers hold a command's frame
    GroundLink::configure(state.allocator, false, Thermal::events);
}

}  // namespace

FwOpcodeType noOpOpcode() {
    return Thermal::cmdDisp.getIdBase() + CmdDispIds::NO_OP;
}

void setupTopology(const TopologyState& state) {
    // The kit breaks the fastest group's dispatch into stages: its queue and
    // task know themselves by lying inside it
    Stages::watch(&Thermal::rg50Hz, sizeof(Thermal::rg50Hz));
    Thermal::initComponents(state);
    Thermal::setBaseIds();
    Thermal::connectComponents();
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    // fprime-baremetal's dispatcher takes its tables from F´'s allocator
    // before any command registers
    Thermal::cmdDisp.setup(DISPATCHER_TABLES_ID, state.allocator);
#endif
    Thermal::regCommands();
    Thermal::configComponents(state);
    configureTopology(state);
    Thermal::loadParameters();
    Thermal::startTasks(state);
}

void teardownTopology(const TopologyState& state) {
    Thermal::stopTasks(state);
    Thermal::freeThreads(state);
    Thermal::tearDownComponents(state);
    GroundLink::cleanup();
}

}  // namespace Kit
