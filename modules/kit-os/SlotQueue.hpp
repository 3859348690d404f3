// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  SlotQueue.hpp
// \brief  The message store of the kit's Os::Queue implementations
//
// Fixed message slots in one block the queue takes from F´'s allocator at
// create(), never after. Messages leave highest priority first and, within
// a priority, in the order they came (F´'s queue semantics). No locking and
// no blocking: the model's queue adds what its contexts need around it
// (rtos/Os/ZephyrQueue.cpp: a spinlock and two semaphores; baremetal/Os/
// CooperativeQueue.cpp: nothing, one context runs everything).
//
// The order is an array of slot indices kept sorted; an insert or a removal
// shifts at most `depth` entries (a rate group's queue holds 2).
// Header-only plain C++: both models' OS layers and host tests use it. It
// lives in modules/kit-os/, the OS code the models share, so that neither
// model's folder nor the deployment (app/) holds what only the OS layers use.
// ======================================================================
#ifndef KIT_SLOTQUEUE_HPP
#define KIT_SLOTQUEUE_HPP

#include <Fw/FPrimeBasicTypes.hpp>
#include <Fw/Types/Assert.hpp>
#include <Fw/Types/MemAllocator.hpp>
#include <Os/Queue.hpp>
#include <config/MemoryAllocatorTypeEnumAc.hpp>

#include <cstring>

namespace Kit {

// Zephyr's <zephyr/sys/util_macro.h> defines EMPTY (as nothing), which hides
// F´'s Os::QueueInterface::Status::EMPTY in any file that includes both
#pragma push_macro("EMPTY")
#undef EMPTY
//! F´'s "no message" status, under a name Zephyr's headers leave alone
constexpr Os::QueueInterface::Status QUEUE_EMPTY = Os::QueueInterface::Status::EMPTY;
#pragma pop_macro("EMPTY")

class SlotQueue {
  public:
    //! Bytes of the block a queue of `depth` messages of up to `messageSize` bytes needs
    static constexpr FwSizeType bytesFor(FwSizeType depth, FwSizeType messageSize) {
        return depth * (2 * sizeof(FwSizeType) + sizeof(FwQueuePriorityType)) + depth * messageSize;
    }
    //! The block's alignment
    static constexpr FwSizeType ALIGNMENT = alignof(FwSizeType);

    //! Lay the queue out in `block` (bytesFor(depth, messageSize) bytes, ALIGNMENT-aligned)
    void create(U8* block, FwSizeType depth, FwSizeType messageSize) {
        FW_ASSERT(block != nullptr);
        FW_ASSERT(depth > 0);
        m_order = reinterpret_cast<FwSizeType*>(block);
        m_sizes = m_order + depth;
        m_priorities = reinterpret_cast<FwQueuePriorityType*>(m_sizes + depth);
        m_data = reinterpret_cast<U8*>(m_priorities + depth);
        m_depth = depth;
        m_maxSize = messageSize;
        m_count = 0;
        m_highWater = 0;
        // Slots are handed out in order after the queued ones: order[count..depth) are free
        for (FwSizeType i = 0; i < depth; i++) {
            m_order[i] = i;
            m_sizes[i] = 0;
            m_priorities[i] = 0;
        }
    }

    bool created() const { return m_data != nullptr; }
    bool full() const { return m_count == m_depth; }
    bool empty() const { return m_count == 0; }
    FwSizeType count() const { return m_count; }
    FwSizeType maxSize() const { return m_maxSize; }
    FwSizeType highWater() const { return m_highWater; }

    //! Store a message of `size` bytes (the caller checked it fits and there is room)
    void push(const U8* data, FwSizeType size, FwQueuePriorityType priority) {
        FW_ASSERT(!this->full());
        FW_ASSERT(size <= m_maxSize, static_cast<FwAssertArgType>(size));
        const FwSizeType slot = m_order[m_count];  // the first free slot
        // After every message of the same or a higher priority
        FwSizeType at = m_count;
        while (at > 0 && m_priorities[m_order[at - 1]] < priority) {
            m_order[at] = m_order[at - 1];
            at--;
        }
        m_order[at] = slot;
        (void)std::memcpy(m_data + slot * m_maxSize, data, static_cast<size_t>(size));
        m_sizes[slot] = size;
        m_priorities[slot] = priority;
        m_count++;
        m_highWater = m_count > m_highWater ? m_count : m_highWater;
    }

    //! Take the next message into `destination` (`capacity` bytes, at least
    //! maxSize(): the caller checked); returns its size
    FwSizeType pop(U8* destination, FwSizeType capacity, FwQueuePriorityType& priority) {
        FW_ASSERT(!this->empty());
        const FwSizeType slot = m_order[0];
        const FwSizeType size = m_sizes[slot];
        FW_ASSERT(size <= capacity, static_cast<FwAssertArgType>(size), static_cast<FwAssertArgType>(capacity));
        (void)std::memcpy(destination, m_data + slot * m_maxSize, static_cast<size_t>(size));
        priority = m_priorities[slot];
        m_count--;
        for (FwSizeType i = 0; i < m_count; i++) {
            m_order[i] = m_order[i + 1];
        }
        m_order[m_count] = slot;  // free again
        return size;
    }

    //! create() in a block from F´'s allocator for queues (the one F´'s own
    //! generic queue takes from), tagged with the queue's `id`
    Os::QueueInterface::Status allocate(FwEnumStoreType id, FwSizeType depth, FwSizeType messageSize) {
        FW_ASSERT(!this->created());
        Fw::MemAllocator& allocator = Fw::MemAllocatorRegistry::getInstance().getAnAllocator(
            Fw::MemoryAllocation::MemoryAllocatorType::OS_GENERIC_PRIORITY_QUEUE);
        const FwSizeType bytes = bytesFor(depth, messageSize);
        FwSizeType granted = bytes;
        void* const block = allocator.allocate(id, granted, ALIGNMENT);
        if (block == nullptr) {
            return Os::QueueInterface::Status::ALLOCATION_FAILED;
        }
        if (granted < bytes) {
            allocator.deallocate(id, block);
            return Os::QueueInterface::Status::ALLOCATION_FAILED;
        }
        m_id = id;
        this->create(static_cast<U8*>(block), depth, messageSize);
        return Os::QueueInterface::Status::OP_OK;
    }

    //! Give the block back (teardown)
    void release() {
        if (this->created()) {
            Fw::MemAllocatorRegistry::getInstance()
                .getAnAllocator(Fw::MemoryAllocation::MemoryAllocatorType::OS_GENERIC_PRIORITY_QUEUE)
                .deallocate(m_id, m_order);
            m_order = nullptr;
            m_sizes = nullptr;
            m_priorities = nullptr;
            m_data = nullptr;
            m_count = 0;
        }
    }

  private:
    FwSizeType* m_order = nullptr;  //!< queued slots, next first; then the free ones
    FwSizeType* m_sizes = nullptr;
    FwQueuePriorityType* m_priorities = nullptr;
    U8* m_data = nullptr;
    FwSizeType m_depth = 0;
    FwSizeType m_maxSize = 0;
    FwSizeType m_count = 0;
    FwSizeType m_highWater = 0;
    FwEnumStoreType m_id = 0;  //!< the allocation's identifier
};

}  // namespace Kit

#endif
