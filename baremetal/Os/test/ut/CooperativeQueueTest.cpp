// SPDX-License-Identifier: Apache-2.0
// The baremetal model's Os::Queue (baremetal/Os/CooperativeQueue.hpp): F´'s
// order (highest priority first, FIFO within a priority), a full queue
// refuses and an empty one answers EMPTY without ever waiting (one context:
// nothing could arrive or leave meanwhile), the checks on sizes and on an
// uncreated queue, the count of messages waiting in every queue, the
// dispatch-stage marks of the watched queue, and no use from an ISR.
#include <gtest/gtest.h>
#include <zephyr/kernel.h>

#include <Fw/Types/String.hpp>

#include <vector>

#include "app/Components/Timing/DispatchStages.hpp"
#include "baremetal/Os/CooperativeQueue.hpp"

namespace {

const void* s_watched = nullptr;
std::vector<Kit::StageMark> s_marks;

}  // namespace

// The deployment's stage probe (app/src/Stages.cpp on the target): the
// queue asks whether it is the watched one and marks its crossings
namespace Kit {
namespace Stages {

bool watches(const void* address) {
    return address != nullptr && address == s_watched;
}

void mark(StageMark which) {
    s_marks.push_back(which);
}

}  // namespace Stages
}  // namespace Kit

namespace {

using Kit::CooperativeQueue;
using Status = Os::QueueInterface::Status;

constexpr FwSizeType DEPTH = 3;
constexpr FwSizeType SIZE = 4;

class CooperativeQueueTest : public ::testing::Test {
  protected:
    void SetUp() override {
        KitFake::inIsr = false;
        s_watched = nullptr;
        s_marks.clear();
        ASSERT_EQ(CooperativeQueue::queuedMessages(), 0u);  // every earlier test's queues are gone
    }

    static Status create(CooperativeQueue& queue, FwSizeType depth = DEPTH) {
        return queue.create(7, Fw::String("q"), depth, SIZE);
    }

    static Status send(CooperativeQueue& queue,
                       U8 tag,
                       FwQueuePriorityType priority = 0,
                       FwSizeType size = 1,
                       Os::QueueInterface::BlockingType block = Os::QueueInterface::NONBLOCKING) {
        U8 message[SIZE + 1] = {tag};
        return queue.send(message, size, priority, block);
    }

    //! The next message's tag, or -1 with the status in `status`
    static int receive(CooperativeQueue& queue,
                       Status* status = nullptr,
                       FwQueuePriorityType* priority = nullptr,
                       FwSizeType capacity = SIZE,
                       Os::QueueInterface::BlockingType block = Os::QueueInterface::NONBLOCKING) {
        U8 message[SIZE + 1] = {};
        FwSizeType size = 0;
        FwQueuePriorityType got = 0;
        const Status result = queue.receive(message, capacity, block, size, got);
        if (status != nullptr) {
            *status = result;
        }
        if (priority != nullptr) {
            *priority = got;
        }
        return result == Status::OP_OK ? message[0] : -1;
    }
};

TEST_F(CooperativeQueueTest, HighestPriorityFirstThenTheOrderOfArrival) {
    CooperativeQueue queue;
    ASSERT_EQ(create(queue), Status::OP_OK);
    EXPECT_EQ(send(queue, 1, 0), Status::OP_OK);
    EXPECT_EQ(send(queue, 2, 5), Status::OP_OK);
    EXPECT_EQ(send(queue, 3, 5), Status::OP_OK);
    FwQueuePriorityType priority = 0;
    EXPECT_EQ(receive(queue, nullptr, &priority), 2);
    EXPECT_EQ(priority, 5u);
    EXPECT_EQ(receive(queue), 3);
    EXPECT_EQ(send(queue, 4, 1), Status::OP_OK);
    EXPECT_EQ(receive(queue), 4);  // after the fives, before the zero that came first
    EXPECT_EQ(receive(queue, nullptr, &priority), 1);
    EXPECT_EQ(priority, 0u);
}

TEST_F(CooperativeQueueTest, AFullQueueRefusesEvenABlockingSend) {
    CooperativeQueue queue;
    ASSERT_EQ(create(queue), Status::OP_OK);
    for (U8 i = 0; i < DEPTH; i++) {
        EXPECT_EQ(send(queue, i), Status::OP_OK);
    }
    // Nothing can drain it while this context runs: waiting would never end
    EXPECT_EQ(send(queue, 9, 0, 1, Os::QueueInterface::NONBLOCKING), Status::FULL);
    EXPECT_EQ(send(queue, 9, 0, 1, Os::QueueInterface::BLOCKING), Status::FULL);
    EXPECT_EQ(queue.getMessagesAvailable(), DEPTH);
    EXPECT_EQ(queue.getMessageHighWaterMark(), DEPTH);
    for (U8 i = 0; i < DEPTH; i++) {
        EXPECT_EQ(receive(queue), i);  // the refused message took no slot
    }
}

TEST_F(CooperativeQueueTest, AnEmptyQueueAnswersEmptyEvenToABlockingReceive) {
    CooperativeQueue queue;
    ASSERT_EQ(create(queue), Status::OP_OK);
    Status status = Status::OP_OK;
    EXPECT_EQ(receive(queue, &status, nullptr, SIZE, Os::QueueInterface::BLOCKING), -1);
    EXPECT_EQ(status, Kit::QUEUE_EMPTY);
    EXPECT_EQ(send(queue, 1), Status::OP_OK);
    EXPECT_EQ(receive(queue, &status), 1);
    EXPECT_EQ(receive(queue, &status), -1);
    EXPECT_EQ(status, Kit::QUEUE_EMPTY);
    EXPECT_EQ(queue.getMessagesAvailable(), 0u);
    EXPECT_EQ(queue.getMessageHighWaterMark(), 1u);
}

TEST_F(CooperativeQueueTest, SizesAndAnUncreatedQueueAreChecked) {
    CooperativeQueue queue;
    Status status = Status::OP_OK;
    EXPECT_EQ(send(queue, 1), Status::UNINITIALIZED);
    EXPECT_EQ(receive(queue, &status), -1);
    EXPECT_EQ(status, Status::UNINITIALIZED);
    EXPECT_EQ(create(queue, 0), Status::ALLOCATION_FAILED);  // no depth, no queue
    ASSERT_EQ(create(queue), Status::OP_OK);
    EXPECT_EQ(send(queue, 1, 0, SIZE + 1), Status::SIZE_MISMATCH);
    EXPECT_EQ(send(queue, 1, 0, SIZE), Status::OP_OK);
    // A receiver must take the largest message the queue holds
    EXPECT_EQ(receive(queue, &status, nullptr, SIZE - 1), -1);
    EXPECT_EQ(status, Status::SIZE_MISMATCH);
    EXPECT_EQ(receive(queue, &status, nullptr, SIZE), 1);
}

TEST_F(CooperativeQueueTest, QueuedMessagesCountsEveryQueueUntilItsTeardown) {
    // The main loop sleeps until the next tick only when this is 0
    {
        CooperativeQueue first;
        CooperativeQueue second;
        ASSERT_EQ(create(first), Status::OP_OK);
        ASSERT_EQ(create(second), Status::OP_OK);
        EXPECT_EQ(send(first, 1), Status::OP_OK);
        EXPECT_EQ(send(first, 2), Status::OP_OK);
        EXPECT_EQ(send(second, 3), Status::OP_OK);
        EXPECT_EQ(send(second, 4), Status::OP_OK);
        EXPECT_EQ(send(second, 5), Status::OP_OK);
        EXPECT_EQ(send(second, 6), Status::FULL);  // a refused message is not counted
        EXPECT_EQ(CooperativeQueue::queuedMessages(), 5u);
        EXPECT_EQ(receive(second), 3);
        EXPECT_EQ(CooperativeQueue::queuedMessages(), 4u);
        first.teardown();  // its two messages leave with it
        EXPECT_EQ(CooperativeQueue::queuedMessages(), 2u);
        first.teardown();  // twice: nothing more
        EXPECT_EQ(CooperativeQueue::queuedMessages(), 2u);
    }
    EXPECT_EQ(CooperativeQueue::queuedMessages(), 0u);  // the destructor tore the other down
}

TEST_F(CooperativeQueueTest, ReceivedMessagesCountsWhatWasTakenNotWhatWasRefused) {
    // The passive policy's drain ends on a pass that took nothing
    CooperativeQueue queue;
    ASSERT_EQ(create(queue), Status::OP_OK);
    const U32 before = CooperativeQueue::receivedMessages();
    Status status = Status::OP_OK;
    EXPECT_EQ(receive(queue, &status), -1);  // empty: nothing taken
    EXPECT_EQ(status, Status::EMPTY);
    EXPECT_EQ(CooperativeQueue::receivedMessages(), before);
    EXPECT_EQ(send(queue, 1), Status::OP_OK);
    EXPECT_EQ(send(queue, 2), Status::OP_OK);
    EXPECT_EQ(CooperativeQueue::receivedMessages(), before);  // sending takes nothing
    EXPECT_EQ(receive(queue), 1);
    EXPECT_EQ(receive(queue), 2);
    EXPECT_EQ(CooperativeQueue::receivedMessages(), before + 2);
    queue.teardown();
}

TEST_F(CooperativeQueueTest, OnlyTheWatchedQueueMarksItsStages) {
    CooperativeQueue watched;
    CooperativeQueue other;
    s_watched = &watched;  // as Stages::watch() of the component holding it
    ASSERT_EQ(create(watched), Status::OP_OK);
    ASSERT_EQ(create(other), Status::OP_OK);
    EXPECT_EQ(send(other, 1), Status::OP_OK);
    EXPECT_EQ(receive(other), 1);
    EXPECT_TRUE(s_marks.empty());
    EXPECT_EQ(send(watched, 2), Status::OP_OK);
    EXPECT_EQ(receive(watched), 2);
    EXPECT_EQ(s_marks,
              (std::vector<Kit::StageMark>{Kit::StageMark::SENT, Kit::StageMark::QUEUED, Kit::StageMark::RECEIVED}));
    // An empty receive crossed nothing
    s_marks.clear();
    EXPECT_EQ(receive(watched), -1);
    EXPECT_TRUE(s_marks.empty());
}

TEST_F(CooperativeQueueTest, NeverFromAnInterruptHandler) {
    // The store has no lock: an ISR's send could interleave with the main
    // loop's receive. The queue asserts instead of corrupting it.
    CooperativeQueue queue;
    ASSERT_EQ(create(queue), Status::OP_OK);
    EXPECT_EQ(send(queue, 1), Status::OP_OK);
    KitFake::inIsr = true;
    EXPECT_DEATH((void)send(queue, 2), "");
    EXPECT_DEATH((void)receive(queue), "");
    KitFake::inIsr = false;
    EXPECT_EQ(queue.getMessagesAvailable(), 1u);
}

}  // namespace
