// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  GroundLink.cpp
// \brief  Configure the kit's ground link (GroundLink.fpp) in any deployment
//
// F´'s ComFprime chain (Svc/Subtopologies/ComFprime/ComFprime.fpp), with the
// kit's sizes (Kit.Link in GroundLink.fpp) instead of a Linux host's. Its
// instances are the deployment's topology's, which imports the subtopology
// (Top/KitTopology.hpp declares them).
// ======================================================================
#include "app/Subtopologies/GroundLink/GroundLink.hpp"
#include <zephyr/device.h>
#include <zephyr/devicetree.h>
#include <Fw/Types/Assert.hpp>
#include "Top/KitTopology.hpp"
#include "app/Subtopologies/GroundLink/FppConstantsAc.hpp"
#include "app/src/QueueAccess.hpp"

namespace Kit {
namespace GroundLink {

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

// The deployment's event service, set once at configure()
const Fw::QueuedComponentBase* s_eventService = nullptr;

// The event service's free queue slots, for LinkHealth's shedding of ground
// commands whose events would fill it
FwSizeType eventServiceRoom() {
    FW_ASSERT(s_eventService != nullptr);
    const Os::Queue& queue = QueueOf::of(*s_eventService);
    const FwSizeType held = queue.getMessagesAvailable();
    const FwSizeType depth = queue.getDepth();
    return held < depth ? depth - held : 0;
}

// The F´ allocator's bytes the link's buffers, accumulator and queues took
FwSizeType s_bufferBytes = 0;

}  // namespace

void configure(CountingAllocator& allocator, bool takesFilePackets, const Fw::QueuedComponentBase& eventService) {
    s_eventService = &eventService;
    const FwSizeType before = allocator.currentBytes();

    // A file packet's frame is the largest the ground sends, where the
    // build takes file packets at all
    const FwSizeType largestFrame =
        takesFilePackets ? static_cast<FwSizeType>(Link::fileFrameSize) : static_cast<FwSizeType>(Link::bufferSize);
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
    queues.entries[0] = {CONFIG_KIT_LINK_EVENT_DEPTH, 0};
    queues.entries[1] = {CONFIG_KIT_LINK_TELEMETRY_DEPTH, 1};
    queues.entries[2] = {1, 2};
    comQueue.configure(queues, 0, allocator);
    s_bufferBytes = allocator.currentBytes() - before;

    // fprime-zephyr's driver returns from configure() without a word when
    // the device is not ready, leaving a link that never speaks: stop here
    const struct device* const uart = DEVICE_DT_GET(DT_CHOSEN(kit_link_uart));
    FW_ASSERT(device_is_ready(uart));
    linkUart.configure(uart, LINK_BAUD_RATE);
}

void cleanup() {
    comQueue.cleanup();
    frameAccumulator.cleanup();
    linkBuffers.cleanup();
}

FwSizeType bufferBytes() {
    return s_bufferBytes;
}

U32 baudRate() {
    return LINK_BAUD_RATE;
}

bool uartErrorsReported() {
    return linkUart.errorsReported();
}

}  // namespace GroundLink
}  // namespace Kit
