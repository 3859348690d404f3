// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ZephyrQueue.cpp
// ======================================================================
#include "rtos/Os/ZephyrQueue.hpp"
#include "app/Components/Timing/DispatchStages.hpp"

#include <Fw/Types/Assert.hpp>
#include <Os/Delegate.hpp>

namespace Kit {

ZephyrQueue::~ZephyrQueue() {
    this->teardown();
}

Os::QueueInterface::Status ZephyrQueue::create(FwEnumStoreType id,
                                               const Fw::ConstStringBase& name,
                                               FwSizeType depth,
                                               FwSizeType messageSize) {
    (void)name;
    if (depth == 0 || depth > K_SEM_MAX_LIMIT) {
        return Status::ALLOCATION_FAILED;
    }
    const Status status = m_slots.allocate(id, depth, messageSize);
    if (status != Status::OP_OK) {
        return status;
    }
    (void)k_sem_init(&m_messages, 0, static_cast<unsigned int>(depth));
    (void)k_sem_init(&m_free, static_cast<unsigned int>(depth), static_cast<unsigned int>(depth));
    m_watched = Stages::watches(this);
    return Status::OP_OK;
}

void ZephyrQueue::teardown() {
    m_slots.release();
}

Os::QueueInterface::Status ZephyrQueue::send(const U8* buffer,
                                             FwSizeType size,
                                             FwQueuePriorityType priority,
                                             BlockingType blockType) {
    if (!m_slots.created()) {
        return Status::UNINITIALIZED;
    }
    if (size > m_slots.maxSize()) {
        return Status::SIZE_MISMATCH;
    }
    if (m_watched) {
        Stages::mark(StageMark::SENT);
    }
    // A free slot is reserved by taking its count; then only the store is locked
    if (k_sem_take(&m_free, blockType == BlockingType::BLOCKING ? K_FOREVER : K_NO_WAIT) != 0) {
        return Status::FULL;
    }
    const k_spinlock_key_t key = k_spin_lock(&m_lock);
    m_slots.push(buffer, size, priority);
    k_spin_unlock(&m_lock, key);
    if (m_watched) {
        Stages::mark(StageMark::QUEUED);  // before the give: a more urgent receiver runs inside it
    }
    k_sem_give(&m_messages);
    if (m_handle.m_listener != nullptr) {
        k_sem_give(m_handle.m_listener);
    }
    return Status::OP_OK;
}

Os::QueueInterface::Status ZephyrQueue::receive(U8* destination,
                                                FwSizeType capacity,
                                                BlockingType blockType,
                                                FwSizeType& actualSize,
                                                FwQueuePriorityType& priority) {
    if (!m_slots.created()) {
        return Status::UNINITIALIZED;
    }
    if (capacity < m_slots.maxSize()) {
        return Status::SIZE_MISMATCH;
    }
    if (k_sem_take(&m_messages, blockType == BlockingType::BLOCKING ? K_FOREVER : K_NO_WAIT) != 0) {
        return QUEUE_EMPTY;
    }
    if (m_watched) {
        Stages::mark(StageMark::PICKED);  // the wait ended: this thread was switched in
    }
    const k_spinlock_key_t key = k_spin_lock(&m_lock);
    actualSize = m_slots.pop(destination, capacity, priority);
    k_spin_unlock(&m_lock, key);
    k_sem_give(&m_free);
    if (m_watched) {
        Stages::mark(StageMark::RECEIVED);
    }
    return Status::OP_OK;
}

FwSizeType ZephyrQueue::getMessagesAvailable() const {
    const k_spinlock_key_t key = k_spin_lock(&m_lock);
    const FwSizeType count = m_slots.count();
    k_spin_unlock(&m_lock, key);
    return count;
}

FwSizeType ZephyrQueue::getMessageHighWaterMark() const {
    const k_spinlock_key_t key = k_spin_lock(&m_lock);
    const FwSizeType highWater = m_slots.highWater();
    k_spin_unlock(&m_lock, key);
    return highWater;
}

Os::QueueHandle* ZephyrQueue::getHandle() {
    return &m_handle;
}

}  // namespace Kit

namespace Os {

QueueInterface* QueueInterface::getDelegate(QueueHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<QueueInterface, Kit::ZephyrQueue, QueueHandleStorage>(aligned_new_memory);
}

}  // namespace Os
