// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopology.cpp
// \brief  Set up and tear down the kit's deployment (shared by both variants)
// ======================================================================
#include "app/Top/KitTopology.hpp"
#include <zephyr/device.h>
#include <zephyr/devicetree.h>
#include <Fw/Types/Assert.hpp>
#include "app/Components/Timing/DispatchStages.hpp"
#include "app/Components/Timing/TickClock.hpp"
#include "app/Top/GeneratedIds.hpp"

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
namespace {
// Health's ping entries, entry i on health's port i (FPP generates health's
// table from the same connections): the pinged instance and its probe
struct PingEntry {
    const char* name;
    PingProbe* probe;
    const Fw::QueuedComponentBase* pinged;  //!< whose queue the probe watches (PingProbe::watchQueue)
};
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
}  // namespace

const char* pingEntryName(FwIndexType entry) {
    FW_ASSERT(entry >= 0 && entry < PING_ENTRY_COUNT, static_cast<FwAssertArgType>(entry));
    return PING_ENTRIES[entry].name;
}

const PingProbe& pingProbe(FwIndexType entry) {
    FW_ASSERT(entry >= 0 && entry < PING_ENTRY_COUNT, static_cast<FwAssertArgType>(entry));
    return *PING_ENTRIES[entry].probe;
}

void startPingSegment() {
    for (const PingEntry& entry : PING_ENTRIES) {
        entry.probe->startSegment();
    }
}
#endif

namespace {
// Members per rate group: the ports of the rate group class the build chose
#if defined(CONFIG_KIT_RATE_GROUPS_PASSIVE)
constexpr FwIndexType RATE_GROUP_PORTS = PassiveRateGroupOutputPorts;  // app/config/AcConstants.fpp.in
#else
constexpr FwIndexType RATE_GROUP_PORTS = Svc::ActiveRateGroup::CONNECTION_COUNT_MAX;
#endif
}  // namespace

const char* activeInstanceHolding(const void* address) {
    const U8* const byte = static_cast<const U8*>(address);
    for (const ActiveInstance& instance : ACTIVE_INSTANCES) {
        const U8* const start = static_cast<const U8*>(instance.object);
        if (byte >= start && byte < start + instance.size) {
            return instance.name;
        }
    }
    return nullptr;
}

namespace {

// F´ keeps a component's message queue protected
// (Fw::QueuedComponentBase::m_queue) and has no accessor for it; a member
// pointer formed in a derived class's scope reads it, without changing F´.
// Never instantiated.
struct QueueOf : Fw::QueuedComponentBase {
    static const Os::Queue& of(const Fw::QueuedComponentBase& component) { return component.*(&QueueOf::m_queue); }
    // F´'s count of messages its `drop` ports lost: a protected accessor, and not const
    static FwSizeType dropped(const Fw::QueuedComponentBase& component) {
        return (const_cast<Fw::QueuedComponentBase&>(component).*(&QueueOf::getNumMsgsDropped))();
    }
};

}  // namespace

#if defined(CONFIG_KIT_SERVICE_CDH)
namespace {
// Each probe watches its pinged component's queue, to defer a ping that
// would find it full (PingProbe::watchQueue)
void watchPingedQueues() {
    for (const PingEntry& entry : PING_ENTRIES) {
        entry.probe->watchQueue(QueueOf::of(*entry.pinged));
    }
}
}  // namespace
#endif

QueueUse queueUse(const ActiveInstance& instance) {
    FW_ASSERT(instance.component != nullptr);
    const Os::Queue& queue = QueueOf::of(*instance.component);
    // Os::Generic::PriorityQueue (both models) keeps, per slot, the message
    // and two FwSizeType words (its index and the message's size)
    return {queue.getDepth(), queue.getMessageSize() + 2 * sizeof(FwSizeType), queue.getMessageHighWaterMark(),
            QueueOf::dropped(*instance.component)};
}

namespace {

// The ground link's UART: the board's app.overlay chooses it
#if !DT_HAS_CHOSEN(kit_link_uart)
#error "kit: the board's app.overlay must choose its link UART (chosen { kit,link-uart = &uartN; })"
#endif
#if !DT_NODE_HAS_PROP(DT_CHOSEN(kit_link_uart), current_speed)
#error "kit: the link UART needs its line rate: current-speed = <115200>; in the board's app.overlay"
#endif
// The line rate: the ground tools pace their bytes to it (the LINK line prints it)
constexpr U32 LINK_BAUD_RATE = DT_PROP(DT_CHOSEN(kit_link_uart), current_speed);

// The link UART's receive counts, for LinkHealth's telemetry
LinkHealth::UartCounts linkUartCounts() {
    const Zephyr::ZephyrUartDriver::ReceiveCounts counts = linkUart.receiveCounts();
    return {counts.received, counts.ringDrops, counts.overruns, counts.parity, counts.framing, counts.breaks};
}

// The event service's free queue slots, for LinkHealth's shedding of ground
// commands whose events would fill it
FwSizeType eventServiceRoom() {
    const Os::Queue& queue = QueueOf::of(events);
    const FwSizeType held = queue.getMessagesAvailable();
    const FwSizeType depth = queue.getDepth();
    return held < depth ? depth - held : 0;
}

// F´'s ComFprime chain (Svc/Subtopologies/ComFprime/ComFprime.fpp), with
// the kit's sizes (Kit.Link in instances.fpp) instead of a Linux host's
// The F´ allocator's memory IDs of TlmLinearChan's table
// (CONFIG_KIT_TELEMETRY_LINEAR) and PassiveCmdDispatcher's tables
// (CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
constexpr FwEnumStoreType TELEMETRY_STORE_ID = 2;
constexpr FwEnumStoreType DISPATCHER_TABLES_ID = 3;

// The F´ allocator's bytes the link's buffers, accumulator and queues took
FwSizeType s_linkBufferBytes = 0;

void configureLink(Fw::MemAllocator& allocator) {
    // A file packet's frame is the largest the ground sends, where the
    // build takes file packets at all
    const FwSizeType largestFrame =
        (FILE_UPLINKS > 0) ? static_cast<FwSizeType>(Link::fileFrameSize) : static_cast<FwSizeType>(Link::bufferSize);
    Svc::BufferManager::BufferBins bins = {};
    bins.bins[0].bufferSize = largestFrame;
    bins.bins[0].numBuffers = Link::bufferCount;
    linkBuffers.setup(Link::bufferManagerId, 0, allocator, bins);

    // F´'s F´-protocol detector, wrapped to count what it rejects: a frame
    // no buffer holds among them
    linkHealth.configure(Link::accumulatorSize, largestFrame, Link::commandsInFlight, linkUartCounts, eventServiceRoom);
    frameAccumulator.configure(linkHealth.detector(), 1, allocator, Link::accumulatorSize);

    // Events first, then telemetry, then the file downlink's packets (one at
    // a time: it sends the next when the last comes back). A build without
    // the file downlink keeps the slot: ComQueue's depth telemetry asserts
    // on a queue of depth 0.
    Svc::ComQueue::QueueConfigurationTable queues;
    queues.entries[0] = {Link::eventDepth, 0};
    queues.entries[1] = {Link::telemetryDepth, 1};
    queues.entries[2] = {1, 2};
    comQueue.configure(queues, 0, allocator);

    // fprime-zephyr's driver returns from configure() without a word when
    // the device is not ready, leaving a link that never speaks: stop here
    const struct device* const uart = DEVICE_DT_GET(DT_CHOSEN(kit_link_uart));
    FW_ASSERT(device_is_ready(uart));
    linkUart.configure(uart, LINK_BAUD_RATE);
}

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

    const FwSizeType before = state.allocator.currentBytes();
    configureLink(state.allocator);
    s_linkBufferBytes = state.allocator.currentBytes() - before;
#if defined(CONFIG_KIT_TELEMETRY_LINEAR)
    // fprime-baremetal's telemetry store takes its one table from the allocator
    tlmSend.setup(TELEMETRY_STORE_ID, state.allocator);
#endif
}

}  // namespace

FwSizeType linkBufferBytes() {
    return s_linkBufferBytes;
}

U32 linkBaudRate() {
    return LINK_BAUD_RATE;
}

bool linkUartErrorsReported() {
    return linkUart.errorsReported();
}

FwOpcodeType noOpOpcode() {
    return cmdDisp.getIdBase() + CmdDispIds::NO_OP;
}

Uplink::Frame noOpFrame(U32 cycle) {
    return Uplink::commandFrame(cycle, noOpOpcode(), nullptr, 0);
}

U32 expectedCycles(FwIndexType rg, U32 ticks) {
    FW_ASSERT(rg >= 0 && rg < RATE_GROUP_COUNT, static_cast<FwAssertArgType>(rg));
    const RateGroupSpec& spec = RATE_GROUPS[rg];
    return ticks <= spec.offset ? 0 : (ticks - spec.offset + spec.divisor - 1) / spec.divisor;
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
    comQueue.cleanup();
    frameAccumulator.cleanup();
    linkBuffers.cleanup();
}

}  // namespace Kit
