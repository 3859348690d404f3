// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CooperativeQueue.cpp
// \brief  The queue itself; DefaultCooperativeQueue.cpp makes it F´'s
//         Os::Queue (apart, so that host tests link it beside F´'s own)
// ======================================================================
#include "baremetal/Os/CooperativeQueue.hpp"
#include "app/Components/Timing/DispatchStages.hpp"

#include <Fw/Types/Assert.hpp>

#include <zephyr/kernel.h>

namespace Kit {

CooperativeQueue::~CooperativeQueue() {
    this->teardown();
}

Os::QueueInterface::Status CooperativeQueue::create(FwEnumStoreType id,
                                                    const Fw::ConstStringBase& name,
                                                    FwSizeType depth,
                                                    FwSizeType messageSize) {
    (void)name;
    if (depth == 0) {
        return Status::ALLOCATION_FAILED;
    }
    const Status status = m_slots.allocate(id, depth, messageSize);
    m_watched = status == Status::OP_OK && Stages::watches(this);
    return status;
}

void CooperativeQueue::teardown() {
    FW_ASSERT(s_queued >= m_slots.count(), static_cast<FwAssertArgType>(s_queued));
    s_queued -= m_slots.count();
    m_slots.release();
}

Os::QueueInterface::Status CooperativeQueue::send(const U8* buffer,
                                                  FwSizeType size,
                                                  FwQueuePriorityType priority,
                                                  BlockingType blockType) {
    (void)blockType;            // nothing to wait for: the receiver runs after this context yields
    FW_ASSERT(!k_is_in_isr());  // the store has no lock: only the main loop may touch it
    if (!m_slots.created()) {
        return Status::UNINITIALIZED;
    }
    if (size > m_slots.maxSize()) {
        return Status::SIZE_MISMATCH;
    }
    if (m_slots.full()) {
        return Status::FULL;
    }
    if (m_watched) {
        Stages::mark(StageMark::SENT);
    }
    m_slots.push(buffer, size, priority);
    s_queued++;
    if (m_watched) {
        Stages::mark(StageMark::QUEUED);
    }
    return Status::OP_OK;
}

Os::QueueInterface::Status CooperativeQueue::receive(U8* destination,
                                                     FwSizeType capacity,
                                                     BlockingType blockType,
                                                     FwSizeType& actualSize,
                                                     FwQueuePriorityType& priority) {
    (void)blockType;  // nothing can arrive while this context runs
    FW_ASSERT(!k_is_in_isr());
    if (!m_slots.created()) {
        return Status::UNINITIALIZED;
    }
    if (capacity < m_slots.maxSize()) {
        return Status::SIZE_MISMATCH;
    }
    if (m_slots.empty()) {
        return QUEUE_EMPTY;
    }
    actualSize = m_slots.pop(destination, capacity, priority);
    FW_ASSERT(s_queued > 0);
    s_queued--;
    s_received++;
    if (m_watched) {
        Stages::mark(StageMark::RECEIVED);
    }
    return Status::OP_OK;
}

FwSizeType CooperativeQueue::s_queued = 0;
U32 CooperativeQueue::s_received = 0;

FwSizeType CooperativeQueue::queuedMessages() {
    return s_queued;
}

U32 CooperativeQueue::receivedMessages() {
    return s_received;
}

FwSizeType CooperativeQueue::getMessagesAvailable() const {
    return m_slots.count();
}

FwSizeType CooperativeQueue::getMessageHighWaterMark() const {
    return m_slots.highWater();
}

Os::QueueHandle* CooperativeQueue::getHandle() {
    return &m_handle;
}

}  // namespace Kit
