// SPDX-License-Identifier: Apache-2.0

#include "app/Components/TlmTable/test/ut/TlmTableTester.hpp"

namespace Kit {

TlmTableTester::TlmTableTester() : TlmTableGTestBase("TlmTableTester", MAX_HISTORY_SIZE), component("TlmTable") {
    this->initComponents();
    this->connectPorts();
}

TlmTableTester::~TlmTableTester() {
    this->component.deinit();  // frees the queue (the leak sanitizer checks)
}

void TlmTableTester::write(FwChanIdType id, U32 value, U32 seconds) {
    Fw::TlmBuffer buffer;
    ASSERT_EQ(buffer.serializeFrom(value), Fw::FW_SERIALIZE_OK);
    Fw::Time time(TimeBase::TB_NONE, seconds, 0);
    this->invoke_to_TlmRecv(0, id, time, buffer);
}

std::map<FwChanIdType, U32> TlmTableTester::cycle() {
    this->clearHistory();
    this->invoke_to_Run(0, 0);
    EXPECT_EQ(this->component.doDispatch(), Fw::QueuedComponentBase::MSG_DISPATCH_OK);
    std::map<FwChanIdType, U32> sent;
    for (FwSizeType p = 0; p < this->fromPortHistory_PktSend->size(); p++) {
        // A telemetry packet: its descriptor, then (ID, time, value) to its end
        Fw::ComBuffer data = this->fromPortHistory_PktSend->at(p).data;
        data.resetDeser();
        FwPacketDescriptorType descriptor = 0;
        EXPECT_EQ(data.deserializeTo(descriptor), Fw::FW_SERIALIZE_OK);
        EXPECT_EQ(descriptor, static_cast<FwPacketDescriptorType>(Fw::ComPacketType::FW_PACKET_TELEM));
        EXPECT_GT(data.getDeserializeSizeLeft(), 0u) << "an empty packet";
        while (data.getDeserializeSizeLeft() > 0) {
            FwChanIdType id = 0;
            Fw::Time time;
            U32 value = 0;
            EXPECT_EQ(data.deserializeTo(id), Fw::FW_SERIALIZE_OK);
            EXPECT_EQ(data.deserializeTo(time), Fw::FW_SERIALIZE_OK);
            EXPECT_EQ(data.deserializeTo(value), Fw::FW_SERIALIZE_OK);
            EXPECT_EQ(sent.count(id), 0u) << "channel " << id << " sent twice in a cycle";
            sent[id] = value;
        }
    }
    return sent;
}

void TlmTableTester::valuesAreKeptAndRead() {
    this->write(0x700, 11, 5);
    this->write(0x701, 22);
    this->write(0x700, 33, 7);  // the latest value wins
    Fw::Time time;
    Fw::TlmBuffer buffer;
    ASSERT_EQ(this->invoke_to_TlmGet(0, 0x700, time, buffer), Fw::TlmValid::VALID);
    U32 value = 0;
    ASSERT_EQ(buffer.deserializeTo(value), Fw::FW_SERIALIZE_OK);
    EXPECT_EQ(value, 33u);
    EXPECT_EQ(time.getSeconds(), 7u);
    EXPECT_EQ(this->component.entriesUsed(), 2u);
    // A channel never written reads invalid and empty
    EXPECT_EQ(this->invoke_to_TlmGet(0, 0x702, time, buffer), Fw::TlmValid::INVALID);
    EXPECT_EQ(buffer.getSize(), 0u);
}

void TlmTableTester::aCycleSendsEachWrittenChannelOnce() {
    this->write(0x100, 1);
    this->write(0x200, 2);
    this->write(0x300, 3);
    this->write(0x200, 4);
    const std::map<FwChanIdType, U32> first = this->cycle();
    EXPECT_EQ(first, (std::map<FwChanIdType, U32>{{0x100, 1}, {0x200, 4}, {0x300, 3}}));
    // Nothing written since: nothing sent
    EXPECT_TRUE(this->cycle().empty());
    ASSERT_from_PktSend_SIZE(0);
    // Only what changed goes
    this->write(0x300, 5);
    EXPECT_EQ(this->cycle(), (std::map<FwChanIdType, U32>{{0x300, 5}}));
    // Answers Svc.Health's ping
    this->invoke_to_pingIn(0, 42);
    EXPECT_EQ(this->component.doDispatch(), Fw::QueuedComponentBase::MSG_DISPATCH_OK);
    ASSERT_from_pingOut_SIZE(1);
    ASSERT_from_pingOut(0, 42u);
}

void TlmTableTester::channelsSharingAHomeEntryKeepTheirOwn() {
    // Same home entry (ID modulo the table), and one whose home the second
    // took; the last entry's neighbour is the first
    const FwChanIdType last = TlmTable::ENTRIES - 1;
    const FwChanIdType ids[] = {3, 3 + TlmTable::ENTRIES, 4, last, last + TlmTable::ENTRIES};
    U32 value = 100;
    for (FwChanIdType id : ids) {
        this->write(id, value++);
    }
    value = 100;
    for (FwChanIdType id : ids) {
        Fw::Time time;
        Fw::TlmBuffer buffer;
        ASSERT_EQ(this->invoke_to_TlmGet(0, id, time, buffer), Fw::TlmValid::VALID) << id;
        U32 read = 0;
        ASSERT_EQ(buffer.deserializeTo(read), Fw::FW_SERIALIZE_OK);
        EXPECT_EQ(read, value++) << id;
    }
    EXPECT_EQ(this->cycle().size(), FW_NUM_ARRAY_ELEMENTS(ids));
}

void TlmTableTester::aCycleSpansPacketsAndLosesNone() {
    // Every entry taken: a cycle needs many packets
    for (FwChanIdType id = 0; id < TlmTable::ENTRIES; id++) {
        this->write(0x1000 + id, id * 3);
    }
    EXPECT_EQ(this->component.entriesUsed(), TlmTable::ENTRIES);
    const std::map<FwChanIdType, U32> sent = this->cycle();
    EXPECT_GT(this->fromPortHistory_PktSend->size(), 1u);
    ASSERT_EQ(sent.size(), TlmTable::ENTRIES);
    for (FwChanIdType id = 0; id < TlmTable::ENTRIES; id++) {
        EXPECT_EQ(sent.at(0x1000 + id), id * 3);
    }
}

void TlmTableTester::aChannelPastTheTableAsserts() {
    for (FwChanIdType id = 0; id < TlmTable::ENTRIES; id++) {
        this->write(id, id);
    }
    // A channel already held still writes when the table is full
    this->write(7, 70);
    EXPECT_DEATH(this->write(TlmTable::ENTRIES, 0), "");
}

void TlmTableTester::aValueBeingWrittenGoesInTheNextCycle() {
    this->write(0x10, 1);
    this->write(0x11, 2);
    // A writer Run preempted is in 0x10's entry (its sequence odd): Run
    // cannot wait for it, so it sends the other channel and leaves 0x10
    const U32 index = this->component.find(0x10);
    ASSERT_LT(index, TlmTable::ENTRIES);
    std::atomic<U32>& sequence = this->component.m_entries[index].sequence;
    const U32 whole = sequence.load();
    sequence.store(whole + 1);
    EXPECT_EQ(this->cycle(), (std::map<FwChanIdType, U32>{{0x11, 2}}));
    // The write ends: its value goes in the next cycle, once
    sequence.store(whole + 2);
    EXPECT_EQ(this->cycle(), (std::map<FwChanIdType, U32>{{0x10, 1}}));
    EXPECT_TRUE(this->cycle().empty());
}

}  // namespace Kit
