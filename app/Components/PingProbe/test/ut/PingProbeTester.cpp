// SPDX-License-Identifier: Apache-2.0

#include "app/Components/PingProbe/test/ut/PingProbeTester.hpp"
#include <Fw/Types/String.hpp>
#include <Os/Queue.hpp>
#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {

PingProbeTester::PingProbeTester() : PingProbeGTestBase("PingProbeTester", MAX_HISTORY_SIZE), component("PingProbe") {
    this->initComponents();
    this->connectPorts();
    FakeTickClock::reset();
}

void PingProbeTester::pingsPassThroughAndAreTimed() {
    FakeTickClock::now = 1000;
    this->invoke_to_pingIn(0, 7);
    ASSERT_from_pingOut_SIZE(1);
    ASSERT_from_pingOut(0, 7);
    EXPECT_TRUE(this->component.outstanding());
    FakeTickClock::now = 5000;
    this->invoke_to_returnIn(0, 7);
    ASSERT_from_returnOut_SIZE(1);
    ASSERT_from_returnOut(0, 7);
    EXPECT_FALSE(this->component.outstanding());
    EXPECT_EQ(this->component.roundTrips().count(), 1u);
    EXPECT_EQ(this->component.roundTrips().max(), 4000u);
    // Across the counter's wrap
    FakeTickClock::now = 0xFFFFFF00u;
    this->invoke_to_pingIn(0, 8);
    FakeTickClock::now = 0x100u;
    this->invoke_to_returnIn(0, 8);
    EXPECT_EQ(this->component.roundTrips().count(), 2u);
    EXPECT_EQ(this->component.roundTrips().percentile(0), 0x200u);
    EXPECT_EQ(this->component.roundTrips().max(), 4000u);
}

void PingProbeTester::aSegmentCountsItsLongestWaitAnsweredOrNot() {
    FakeTickClock::now = 100;
    this->invoke_to_pingIn(0, 1);
    FakeTickClock::now = 700;
    this->invoke_to_returnIn(0, 1);
    EXPECT_EQ(this->component.segmentWorst(FakeTickClock::now), 600u);
    this->component.startSegment();
    EXPECT_EQ(this->component.segmentWorst(FakeTickClock::now), 0u);
    this->invoke_to_pingIn(0, 2);
    // Not answered yet: its wait so far
    EXPECT_EQ(this->component.segmentWorst(FakeTickClock::now + 900), 900u);
    FakeTickClock::now += 200;
    this->invoke_to_returnIn(0, 2);
    EXPECT_EQ(this->component.segmentWorst(FakeTickClock::now + 5000), 200u);
    // The run's maximum is not the segment's
    EXPECT_EQ(this->component.roundTrips().max(), 600u);
}

void PingProbeTester::aPingThatWouldFindTheQueueFullWaitsForRoom() {
    // The pinged component's queue, one message deep and full
    Os::Queue queue;
    ASSERT_EQ(queue.create(0, Fw::String("pinged"), 1, sizeof(U32)), Os::Queue::OP_OK);
    this->component.watchQueue(queue);
    U32 message = 0;
    ASSERT_EQ(queue.send(reinterpret_cast<const U8*>(&message), sizeof(message), 0, Os::Queue::NONBLOCKING),
              Os::Queue::OP_OK);
    FakeTickClock::now = 100;
    this->invoke_to_pingIn(0, 9);
    ASSERT_from_pingOut_SIZE(0);  // F´'s pingIn would have asserted on it
    EXPECT_TRUE(this->component.deferring());
    EXPECT_TRUE(this->component.outstanding());
    EXPECT_EQ(this->component.deferredPings(), 1u);
    EXPECT_EQ(PingProbe::deferredNow(), 1u);
    // Health's next cycle, still full: still waiting
    PingProbe::sendDeferredPings();
    ASSERT_from_pingOut_SIZE(0);
    // Room: the ping goes, with health's key
    FwSizeType size = 0;
    FwQueuePriorityType priority = 0;
    ASSERT_EQ(queue.receive(reinterpret_cast<U8*>(&message), sizeof(message), Os::Queue::NONBLOCKING, size, priority),
              Os::Queue::OP_OK);
    PingProbe::sendDeferredPings();
    ASSERT_from_pingOut_SIZE(1);
    ASSERT_from_pingOut(0, 9);
    EXPECT_FALSE(this->component.deferring());
    EXPECT_EQ(PingProbe::deferredNow(), 0u);
    // The round trip counts from health's send, not from when room came
    FakeTickClock::now = 900;
    this->invoke_to_returnIn(0, 9);
    EXPECT_EQ(this->component.roundTrips().max(), 800u);
    // With room, a ping goes at once
    this->invoke_to_pingIn(0, 10);
    ASSERT_from_pingOut_SIZE(2);
    EXPECT_EQ(this->component.deferredPings(), 1u);
    queue.teardown();  // F´'s generic queue frees its store here, not in its destructor
}

void PingProbeTester::aProbeGoneLeavesNoDeferredPing() {
    Os::Queue queue;
    ASSERT_EQ(queue.create(0, Fw::String("pinged"), 1, sizeof(U32)), Os::Queue::OP_OK);
    U32 message = 0;
    ASSERT_EQ(queue.send(reinterpret_cast<const U8*>(&message), sizeof(message), 0, Os::Queue::NONBLOCKING),
              Os::Queue::OP_OK);
    {
        PingProbe other("other");
        other.init(0);
        other.watchQueue(queue);
        other.pingIn_handlerBase(0, 3);
        EXPECT_EQ(PingProbe::deferredNow(), 1u);
    }
    EXPECT_EQ(PingProbe::deferredNow(), 0u);
    queue.teardown();
}

void PingProbeTester::anAnswerWithNoPingOutIsPassedOnNotTimed() {
    this->invoke_to_returnIn(0, 42);
    ASSERT_from_returnOut_SIZE(1);
    ASSERT_from_returnOut(0, 42);
    EXPECT_EQ(this->component.roundTrips().count(), 0u);
}

void PingProbeTester::percentilesComeFromTheLastWindow() {
    PingRoundTrips trips;
    EXPECT_EQ(trips.percentile(500), 0u);
    for (U32 i = 1; i <= 10; i++) {
        trips.add(i * 10);
    }
    EXPECT_EQ(trips.held(), 10u);
    EXPECT_EQ(trips.percentile(500), 50u);
    EXPECT_EQ(trips.percentile(990), 100u);
    EXPECT_EQ(trips.percentile(0), 10u);
    // A long run: the window holds the last WINDOW, the maximum is every one's
    const U32 window = PingRoundTrips::WINDOW;  // a copy: gtest's macros take references
    for (U32 i = 0; i < window; i++) {
        trips.add(1);
    }
    EXPECT_EQ(trips.count(), 10u + window);
    EXPECT_EQ(trips.held(), window);
    EXPECT_EQ(trips.percentile(990), 1u);
    EXPECT_EQ(trips.max(), 100u);
}

}  // namespace Kit
