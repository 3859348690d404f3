// SPDX-License-Identifier: Apache-2.0
// The message store under the kit's queues: F´'s order (highest priority
// first, FIFO within a priority), sizes kept per message, slots reused.
#include <gtest/gtest.h>
#include "modules/kit-os/SlotQueue.hpp"

namespace {

constexpr FwSizeType DEPTH = 4;
constexpr FwSizeType SIZE = 8;

struct Fixture : public ::testing::Test {
    alignas(Kit::SlotQueue::ALIGNMENT) U8 block[Kit::SlotQueue::bytesFor(DEPTH, SIZE)] = {};
    Kit::SlotQueue queue;
    void SetUp() override { queue.create(block, DEPTH, SIZE); }
    void push(U8 tag, FwQueuePriorityType priority, FwSizeType size = 1) {
        U8 message[SIZE] = {};
        message[0] = tag;
        queue.push(message, size, priority);
    }
    U8 pop(FwQueuePriorityType* priority = nullptr, FwSizeType* size = nullptr) {
        U8 message[SIZE] = {};
        FwQueuePriorityType got = 0;
        const FwSizeType length = queue.pop(message, SIZE, got);
        if (priority != nullptr) {
            *priority = got;
        }
        if (size != nullptr) {
            *size = length;
        }
        return message[0];
    }
};

using SlotQueueTest = Fixture;

TEST_F(SlotQueueTest, FifoWithinOnePriority) {
    push(1, 0);
    push(2, 0);
    push(3, 0);
    EXPECT_EQ(pop(), 1);
    EXPECT_EQ(pop(), 2);
    EXPECT_EQ(pop(), 3);
    EXPECT_TRUE(queue.empty());
}

TEST_F(SlotQueueTest, HigherPriorityFirstThenArrivalOrder) {
    push(1, 0);
    push(2, 5);
    push(3, 5);
    push(4, 1);
    FwQueuePriorityType priority = 0;
    EXPECT_EQ(pop(&priority), 2);
    EXPECT_EQ(priority, 5u);
    EXPECT_EQ(pop(), 3);
    EXPECT_EQ(pop(), 4);
    EXPECT_EQ(pop(), 1);
}

TEST_F(SlotQueueTest, FullAfterDepthAndSlotsAreReused) {
    for (U8 round = 0; round < 3; round++) {
        for (U8 i = 0; i < DEPTH; i++) {
            push(static_cast<U8>(round * 10 + i), 0);
        }
        EXPECT_TRUE(queue.full());
        for (U8 i = 0; i < DEPTH; i++) {
            EXPECT_EQ(pop(), round * 10 + i);
        }
        EXPECT_TRUE(queue.empty());
    }
    EXPECT_EQ(queue.highWater(), DEPTH);
}

TEST_F(SlotQueueTest, InterleavedKeepsOrderAndSizes) {
    push(1, 0, 3);
    push(2, 0, SIZE);
    FwSizeType size = 0;
    EXPECT_EQ(pop(nullptr, &size), 1);
    EXPECT_EQ(size, 3u);
    push(3, 0, 5);
    push(4, 2, 1);
    EXPECT_EQ(pop(nullptr, &size), 4);
    EXPECT_EQ(size, 1u);
    EXPECT_EQ(pop(nullptr, &size), 2);
    EXPECT_EQ(size, SIZE);
    EXPECT_EQ(pop(nullptr, &size), 3);
    EXPECT_EQ(size, 5u);
    EXPECT_EQ(queue.count(), 0u);
    EXPECT_EQ(queue.highWater(), 3u);  // 2, 3 and 4 at once
}

}  // namespace
