// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Deployment.cpp
// \brief  What the kit computes from the deployment's tables
//         (app/src/Deployment.hpp), the same for any deployment
// ======================================================================
#include <Fw/Types/Assert.hpp>
#include "Top/KitTopology.hpp"
#include "app/src/QueueAccess.hpp"

namespace Kit {

U32 expectedCycles(FwIndexType rg, U32 ticks) {
    FW_ASSERT(rg >= 0 && rg < RATE_GROUP_COUNT, static_cast<FwAssertArgType>(rg));
    const RateGroupSpec& spec = RATE_GROUPS[rg];
    return ticks <= spec.offset ? 0 : (ticks - spec.offset + spec.divisor - 1) / spec.divisor;
}

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

QueueUse queueUse(const ActiveInstance& instance) {
    FW_ASSERT(instance.component != nullptr);
    const Os::Queue& queue = QueueOf::of(*instance.component);
    // Os::Generic::PriorityQueue (both models) keeps, per slot, the message
    // and two FwSizeType words (its index and the message's size)
    return {queue.getDepth(), queue.getMessageSize() + 2 * sizeof(FwSizeType), queue.getMessageHighWaterMark(),
            QueueOf::dropped(*instance.component)};
}

#if defined(CONFIG_KIT_SERVICE_CDH)
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

void watchPingedQueues() {
    for (const PingEntry& entry : PING_ENTRIES) {
        entry.probe->watchQueue(QueueOf::of(*entry.pinged));
    }
}
#endif

Uplink::Frame noOpFrame(U32 cycle) {
    return Uplink::commandFrame(cycle, noOpOpcode(), nullptr, 0);
}

}  // namespace Kit
