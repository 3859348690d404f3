// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ZephyrQueue.hpp
// \brief  Os::Queue on Zephyr semaphores: the rtos model's message queue
//
// fprime-zephyr has no queue, so without this F´'s generic priority queue
// runs: a mutex and two condition variables around a heap, so a send to a
// waiting, more urgent thread locks, signals, and the woken thread then
// contends for the mutex the sender still holds before it can run. Here a
// send stores the message under a spinlock (a few instructions) and gives
// a semaphore: the one kernel call that wakes the receiver. F´'s semantics
// stand: priority order, FIFO within a priority, blocking and non-blocking.
// Chosen by CONFIG_KIT_QUEUE_KIT (app/Kconfig).
// ======================================================================
#ifndef KIT_ZEPHYRQUEUE_HPP
#define KIT_ZEPHYRQUEUE_HPP

#include "modules/kit-os/SlotQueue.hpp"

#include <zephyr/kernel.h>
#include <Os/Queue.hpp>

namespace Kit {

struct ZephyrQueueHandle : public Os::QueueHandle {
    //! Given after each send where set: the shared thread's wake-up, for a
    //! queue whose component runs on it (rtos/Os/SharedThread.cpp)
    struct k_sem* m_listener = nullptr;
};

class ZephyrQueue final : public Os::QueueInterface {
  public:
    ZephyrQueue() = default;
    ~ZephyrQueue() override;
    ZephyrQueue(const QueueInterface& other) = delete;
    ZephyrQueue& operator=(const QueueInterface& other) override = delete;

    Status create(FwEnumStoreType id,
                  const Fw::ConstStringBase& name,
                  FwSizeType depth,
                  FwSizeType messageSize) override;
    void teardown() override;
    Status send(const U8* buffer, FwSizeType size, FwQueuePriorityType priority, BlockingType blockType) override;
    Status receive(U8* destination,
                   FwSizeType capacity,
                   BlockingType blockType,
                   FwSizeType& actualSize,
                   FwQueuePriorityType& priority) override;
    FwSizeType getMessagesAvailable() const override;
    FwSizeType getMessageHighWaterMark() const override;
    Os::QueueHandle* getHandle() override;

  private:
    SlotQueue m_slots;
    mutable struct k_spinlock m_lock = {};
    struct k_sem m_messages = {};  //!< counts queued messages: a receiver waits on it
    struct k_sem m_free = {};      //!< counts free slots: a blocking sender waits on it
    bool m_watched = false;        //!< this queue's component is the one broken into stages
    ZephyrQueueHandle m_handle;
};

}  // namespace Kit

#endif
