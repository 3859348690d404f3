// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Load/test/ut/LoadTester.hpp"
#include <Os/File.hpp>
#include <Os/FileSystem.hpp>
#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {

namespace {
constexpr U32 CYCLES_PER_US = 12;  // the fake clock's 12 MHz
constexpr U32 READING_STEP = 60;   // the clock moves 5 us per reading
}  // namespace

LoadTester::LoadTester() : LoadGTestBase("LoadTester", MAX_HISTORY_SIZE), component("Load") {
    this->initComponents();
    this->connectPorts();
    FakeTickClock::reset();
    FakeTickClock::step = READING_STEP;
}

LoadTester::~LoadTester() {
    this->component.deinit();  // frees the queue (the leak sanitizer checks)
}

void LoadTester::sliceComputesForTheCommandedTime() {
    this->sendCmd_SET_SLICE(0, 3, 400);
    ASSERT_CMD_RESPONSE(0, LoadComponentBase::OPCODE_SET_SLICE, 3, Fw::CmdResponse::OK);
    ASSERT_EVENTS_LoadSet(0, 400, 0, 0);
    const U32 before = FakeTickClock::now;
    this->invoke_to_sliceIn(0, 0);
    EXPECT_EQ(FakeTickClock::now, before);  // queued, not run: the load's own context runs it
    ASSERT_EQ(this->component.doDispatch(), Fw::QueuedComponentBase::MSG_DISPATCH_OK);
    const U32 elapsed = FakeTickClock::now - before;
    EXPECT_GE(elapsed, 400 * CYCLES_PER_US);
    EXPECT_LE(elapsed, 400 * CYCLES_PER_US + 2 * READING_STEP);
    EXPECT_EQ(this->component.processed(), 1u);
    ASSERT_TLM_Processed(0, 1);
}

void LoadTester::settingsAboveTheirLimitsAreRejected() {
    this->sendCmd_SET_SLICE(0, 1, Load::SLICE_MAX_US + 1);
    ASSERT_CMD_RESPONSE(0, LoadComponentBase::OPCODE_SET_SLICE, 1, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_LoadRejected(0, Load::SLICE_MAX_US + 1, Load::SLICE_MAX_US);
    this->sendCmd_SET_BURST(0, 2, Load::BURST_MAX + 1, 0);
    ASSERT_CMD_RESPONSE(1, LoadComponentBase::OPCODE_SET_BURST, 2, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_LoadRejected(1, Load::BURST_MAX + 1, Load::BURST_MAX);
    // Nothing changed: a slice still takes no time
    const U32 before = FakeTickClock::now;
    this->invoke_to_sliceIn(0, 0);
    (void)this->component.doDispatch();
    EXPECT_LE(FakeTickClock::now - before, 2 * READING_STEP);
}

void LoadTester::everySliceSendsTheCommandedDownlinkPackets() {
    this->sendCmd_SET_DOWNLINK(0, 5, Load::DOWNLINK_MAX + 1);
    ASSERT_CMD_RESPONSE(0, LoadComponentBase::OPCODE_SET_DOWNLINK, 5, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_LoadRejected(0, Load::DOWNLINK_MAX + 1, Load::DOWNLINK_MAX);
    this->sendCmd_SET_DOWNLINK(0, 6, 3);
    ASSERT_CMD_RESPONSE(1, LoadComponentBase::OPCODE_SET_DOWNLINK, 6, Fw::CmdResponse::OK);
    ASSERT_EVENTS_DownlinkLoadSet(0, 3);
    this->clearHistory();
    for (U32 slice = 0; slice < 2; slice++) {
        this->invoke_to_sliceIn(0, 0);
        ASSERT_EQ(this->component.doDispatch(), Fw::QueuedComponentBase::MSG_DISPATCH_OK);
    }
    // Numbered across slices, so the ground can tell a lost packet
    ASSERT_EVENTS_DownlinkLoadPacket_SIZE(6);
    for (U32 i = 0; i < 6; i++) {
        ASSERT_EVENTS_DownlinkLoadPacket(i, i);
    }
}

void LoadTester::burstPushesTheCommandedMessages() {
    this->sendCmd_SET_BURST(0, 4, 3, 10);
    ASSERT_CMD_RESPONSE(0, LoadComponentBase::OPCODE_SET_BURST, 4, Fw::CmdResponse::OK);
    this->invoke_to_burstIn(0, 0);
    ASSERT_from_ioOut_SIZE(3);
    this->invoke_to_burstIn(0, 0);
    ASSERT_from_ioOut_SIZE(6);
}

void LoadTester::aFullQueueDropsCountsAndReports() {
    const FwSizeType depth = TEST_INSTANCE_QUEUE_DEPTH;  // a value: gtest's macros take references
    for (FwSizeType i = 0; i < depth + 2; i++) {
        this->invoke_to_ioIn(0, static_cast<U32>(i));
    }
    EXPECT_EQ(this->component.dropped(), 2u);
    ASSERT_EVENTS_MessagesDropped_SIZE(2);
    ASSERT_EVENTS_MessagesDropped(1, 2);
    ASSERT_TLM_Dropped(1, 2);
    // What was queued is still processed
    for (FwSizeType i = 0; i < depth; i++) {
        ASSERT_EQ(this->component.doDispatch(), Fw::QueuedComponentBase::MSG_DISPATCH_OK);
    }
    EXPECT_EQ(this->component.processed(), depth);
}

void LoadTester::patternIsXorshift32sLowBytes() {
    // xorshift32 (13, 17, 5) from seed 1: 270369, 67634689, 2647435461,
    // worked from its definition; the ground's copy is held to the same
    // values (scripts/tests/test_ground_pattern.py)
    Load::Pattern pattern(1);
    EXPECT_EQ(pattern.next(), static_cast<U8>(270369u & 0xFFu));
    EXPECT_EQ(pattern.next(), static_cast<U8>(67634689u & 0xFFu));
    EXPECT_EQ(pattern.next(), static_cast<U8>(2647435461u & 0xFFu));
}

void LoadTester::fillFileWritesThePatternOrRefuses() {
    // The host's file system (F´'s POSIX Os::File), a file in the test's folder
    const char* const path = "load-fill-test.bin";
    const Fw::CmdStringArg name(path);
    this->sendCmd_FILL_FILE(0, 1, name, 100, 0);
    ASSERT_CMD_RESPONSE(0, LoadComponentBase::OPCODE_FILL_FILE, 1, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_FILL_FILE(0, 2, name, 100, 7);
    ASSERT_CMD_RESPONSE(1, LoadComponentBase::OPCODE_FILL_FILE, 2, Fw::CmdResponse::OK);
    ASSERT_EVENTS_FileFilled_SIZE(1);
    ASSERT_EVENTS_FileFilled(0, path, 100, 7);
    Os::File in;
    ASSERT_EQ(in.open(path, Os::File::OPEN_READ), Os::File::OP_OK);
    U8 data[128];
    FwSizeType size = sizeof(data);
    ASSERT_EQ(in.read(data, size), Os::File::OP_OK);
    in.close();
    ASSERT_EQ(size, 100u);
    Load::Pattern pattern(7);
    for (FwSizeType index = 0; index < size; index++) {
        EXPECT_EQ(data[index], pattern.next()) << "byte " << index;
    }
    // Leaves nothing behind in the folder the tests ran in
    ASSERT_EQ(Os::FileSystem::removeFile(path), Os::FileSystem::OP_OK);
    // A file that cannot be opened: its status, nothing written
    const Fw::CmdStringArg nowhere("no-such-folder/fill.bin");
    this->sendCmd_FILL_FILE(0, 3, nowhere, 100, 7);
    ASSERT_CMD_RESPONSE(2, LoadComponentBase::OPCODE_FILL_FILE, 3, Fw::CmdResponse::EXECUTION_ERROR);
    ASSERT_EVENTS_FileNotFilled_SIZE(1);
}

}  // namespace Kit
