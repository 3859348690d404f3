// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.cpp
// \brief  Set up and tear down the kit's deployment (shared by both variants)
// ======================================================================
#include "app/Top/KitTopology.hpp"
#include <Fw/Types/Assert.hpp>
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Subtopologies/GroundLink/GroundLink.hpp"
#include "app/src/ServiceIds.hpp"

namespace Kit {

// One table drives both the rate group driver and the timing probe. Offsets
// keep the slower groups off the ticks where the faster ones start.
const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT] = {
    {"rg1kHz", 1, 0},
    {"rg100Hz", 10, 1},
    {"rg10Hz", 100, 2},
};

const ActiveInstance ACTIVE_INSTANCES[ACTIVE_INSTANCE_COUNT] = {
#if !defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
    {"rg1kHz", &rg1kHz, sizeof(rg1kHz), &rg1kHz},
    {"rg100Hz", &rg100Hz, sizeof(rg100Hz), &rg100Hz},
    {"rg10Hz", &rg10Hz, sizeof(rg10Hz), &rg10Hz},
#endif
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    {"cmdDisp", &cmdDisp, sizeof(cmdDisp), &cmdDisp},
#endif
    {"events", &events, sizeof(events), &events},
    {"tlmSend", &tlmSend, sizeof(tlmSend), &tlmSend},
    {"load", &load, sizeof(load), &load},
    {"comQueue", &comQueue, sizeof(comQueue), &comQueue},
#if defined(CONFIG_KIT_SERVICE_PARAMS)
    {"prmDb", &prmDb, sizeof(prmDb), &prmDb},
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
    {"fileDownlink", &fileDownlink, sizeof(fileDownlink), &fileDownlink},
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
    {"fileUplink", &fileUplink, sizeof(fileUplink), &fileUplink},
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    {"cmdSeq", &cmdSeq, sizeof(cmdSeq), &cmdSeq},
#endif
};

#if defined(CONFIG_KIT_SERVICE_CDH)
// Health's ping entries, entry i on health's port i: the pinged instance
// and its probe
const PingEntry PING_ENTRIES[PING_ENTRY_COUNT] = {
    {"events", &eventsPing, &events},
    {"tlmSend", &tlmSendPing, &tlmSend},
#if !defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    {"cmdDisp", &cmdDispPing, &cmdDisp},
#endif
#if defined(CONFIG_KIT_HEALTH_PINGS_RATE_GROUPS)
    {"rg1kHz", &rg1kHzPing, &rg1kHz},
    {"rg100Hz", &rg100HzPing, &rg100Hz},
    {"rg10Hz", &rg10HzPing, &rg10Hz},
#endif
#if defined(CONFIG_KIT_SERVICE_PARAMS)
    {"prmDb", &prmDbPing, &prmDb},
#endif
#if defined(CONFIG_KIT_SERVICE_FILES)
    {"fileDownlink", &fileDownlinkPing, &fileDownlink},
#endif
#if defined(CONFIG_KIT_SERVICE_FILE_UPLINK)
    {"fileUplink", &fileUplinkPing, &fileUplink},
#endif
#if defined(CONFIG_KIT_SERVICE_SEQUENCER)
    {"cmdSeq", &cmdSeqPing, &cmdSeq},
#endif
};
#endif

namespace {
// Members per rate group: the ports of the rate group class the build chose
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
constexpr FwIndexType RATE_GROUP_PORTS = PassiveRateGroupOutputPorts;  // app/config/AcConstants.fpp.in
#else
constexpr FwIndexType RATE_GROUP_PORTS = Svc::ActiveRateGroup::CONNECTION_COUNT_MAX;
#endif
}  // namespace

namespace {

// The F´ allocator's memory IDs of TlmLinearChan's table
// (CONFIG_KIT_TELEMETRY_LINEAR) and PassiveCmdDispatcher's tables
// (CONFIG_KIT_CMD_DISPATCHER_PASSIVE); the link's is 0
// (app/Subtopologies/GroundLink/GroundLink.cpp)
constexpr FwEnumStoreType TELEMETRY_STORE_ID = 2;
constexpr FwEnumStoreType DISPATCHER_TABLES_ID = 3;

void configureTopology(const TopologyState& state) {
    Svc::RateGroupDriver::DividerSet dividers;
    for (FwIndexType i = 0; i < RATE_GROUP_COUNT; i++) {
        dividers.dividers[i] = {RATE_GROUPS[i].divisor, RATE_GROUPS[i].offset};
    }
    rateGroupDriver.configure(dividers);
#if defined(CONFIG_KIT_SERVICE_CDH)
    watchPingedQueues();
#endif
    timing.configure(RATE_GROUPS, RATE_GROUP_COUNT, TickClock::cyclesPerSecond() / CONFIG_KIT_TICK_HZ);

    // Contexts are unused by the members; a rate group wants one per port
    U32 contexts[RATE_GROUP_PORTS] = {};
    rg1kHz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));
    rg100Hz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));
    rg10Hz.configure(contexts, FW_NUM_ARRAY_ELEMENTS(contexts));

    // Time starts at zero at boot (no ground command sets it)
    Os::RawTime now;
    (void)now.now();
    osTime.set_epoch(Fw::Time(0, 0), now);

    GroundLink::configure(state.allocator, FILE_UPLINKS > 0, events);
}

}  // namespace

FwOpcodeType noOpOpcode() {
    return cmdDisp.getIdBase() + CmdDispIds::NO_OP;
}

void setupTopology(const TopologyState& state) {
    // The fastest group's dispatch is broken into stages: its queue and task
    // know themselves by lying inside it, so watch it before they are made
    Stages::watch(&rg1kHz, sizeof(rg1kHz));
    initComponents(state);
    setBaseIds();
    connectComponents();
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
    // fprime-baremetal's dispatcher takes its dispatch and tracking tables
    // from F´'s allocator, and needs them before any command registers
    cmdDisp.setup(DISPATCHER_TABLES_ID, state.allocator);
#endif
#if defined(CONFIG_KIT_TELEMETRY_LINEAR)
    // fprime-baremetal's telemetry store takes its one table from F´'s
    // allocator, and needs it before any component writes a channel (the
    // services' configuration does: it asserted, set up after it)
    tlmSend.setup(TELEMETRY_STORE_ID, state.allocator);
#endif
    regCommands();
    configComponents(state);
    configureTopology(state);
    // The parameter database reads its file, then each component takes its
    // parameters from it (F´'s order: Svc/Subtopologies/FileHandling)
    readParameters();
    loadParameters();
    startTasks(state);
}

void teardownTopology(const TopologyState& state) {
    stopTasks(state);
    freeThreads(state);
    tearDownComponents(state);
    GroundLink::cleanup();
}

}  // namespace Kit
