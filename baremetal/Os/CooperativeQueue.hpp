// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  CooperativeQueue.hpp
// \brief  Os::Queue for the one-context baremetal model: no lock, no waiting
//
// Without this, F´'s generic priority queue runs on the stub mutex and
// condition variable: the locking is free but the calls, the heap and the
// indirections are not. Every sender and receiver here is the main loop
// (tasks are its slices; no interrupt handler sends, which send() asserts),
// so the store needs no lock. Nothing can wait either: a receive with no
// message returns EMPTY (a cooperative task is only dispatched with one
// queued), and a blocking send to a full queue returns FULL, where the
// generic queue's stub condition variable would spin forever.
// Chosen by CONFIG_KIT_QUEUE_KIT (app/Kconfig).
// ======================================================================
#ifndef KIT_COOPERATIVEQUEUE_HPP
#define KIT_COOPERATIVEQUEUE_HPP

#include "modules/kit-os/SlotQueue.hpp"

#include <Os/Queue.hpp>

namespace Kit {

struct CooperativeQueueHandle : public Os::QueueHandle {};

class CooperativeQueue final : public Os::QueueInterface {
  public:
    CooperativeQueue() = default;
    ~CooperativeQueue() override;
    CooperativeQueue(const QueueInterface& other) = delete;
    CooperativeQueue& operator=(const QueueInterface& other) override = delete;

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

    //! Messages waiting in every queue of the deployment: a main loop with
    //! nothing queued has nothing left to run until the next tick
    static FwSizeType queuedMessages();
    //! Messages taken from every queue of the deployment so far (it wraps).
    //! A pass of the tasks that leaves it unchanged handled nothing: what is
    //! still queued waits for a queued component's rate group (Svc.Health's
    //! ping answers wait for its Run), which runs at a tick, not in a pass
    static U32 receivedMessages();

  private:
    static FwSizeType s_queued;  //!< the sum of every queue's count (only the main loop touches it)
    static U32 s_received;       //!< messages taken from any queue (only the main loop touches it)
    SlotQueue m_slots;
    bool m_watched = false;  //!< this queue's component is the one broken into stages
    CooperativeQueueHandle m_handle;
};

}  // namespace Kit

#endif
