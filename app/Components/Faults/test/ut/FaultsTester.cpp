// SPDX-License-Identifier: Apache-2.0

#include "app/Components/Faults/test/ut/FaultsTester.hpp"
#include <Os/File.hpp>
#include <Os/FileSystem.hpp>
#include "app/Components/Faults/test/ut/FakeRestart.hpp"
#include "app/Components/Timing/test/ut/FakeTickClock.hpp"

namespace Kit {

namespace {
constexpr U32 CYCLES_PER_US = 12;  // the fake clock's 12 MHz
constexpr U32 READING_STEP = 60;   // the clock moves 5 us per reading
// A file in the test's working directory (the host's file system)
constexpr const char* FILE_PATH = "FaultsTestFile.bin";
constexpr U32 FILE_SIZE = 10;
constexpr FwIndexType SLOWEST = RateGroupDriverRateGroupPorts - 1;  // a port per rate group
}  // namespace

FaultsTester::FaultsTester() : FaultsGTestBase("FaultsTester", MAX_HISTORY_SIZE), component("Faults") {
    this->initComponents();
    this->connectPorts();
    FakeTickClock::reset();
    FakeTickClock::step = READING_STEP;
}

FaultsTester::~FaultsTester() {
    (void)Os::FileSystem::removeFile(FILE_PATH);
}

void FaultsTester::overrunRunsOnceInItsRateGroup() {
    this->sendCmd_OVERRUN(0, 5, 1, 1500);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_OVERRUN, 5, Fw::CmdResponse::OK);
    U32 before = FakeTickClock::now;
    this->invoke_to_schedIn(0, 0);  // another group: untouched
    EXPECT_EQ(FakeTickClock::now, before);
    this->invoke_to_schedIn(1, 0);
    EXPECT_GE(FakeTickClock::now - before, 1500 * CYCLES_PER_US);
    ASSERT_EVENTS_OverrunInjected_SIZE(1);
    ASSERT_EVENTS_OverrunInjected(0, 1, 1500);
    before = FakeTickClock::now;
    this->invoke_to_schedIn(1, 0);  // taken: the next cycle is normal
    EXPECT_EQ(FakeTickClock::now, before);
}

void FaultsTester::injectionsAboveTheirLimitsAreRejected() {
    this->sendCmd_OVERRUN(0, 1, FaultsComponentBase::NUM_SCHEDIN_INPUT_PORTS, 100);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_OVERRUN, 1, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_OVERRUN(0, 2, 0, Faults::OVERRUN_MAX_US + 1);
    ASSERT_CMD_RESPONSE(1, FaultsComponentBase::OPCODE_OVERRUN, 2, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_STACK_OVERFLOW(0, 3, Faults::STACK_MAX_BYTES + 1);
    ASSERT_CMD_RESPONSE(2, FaultsComponentBase::OPCODE_STACK_OVERFLOW, 3, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_InjectionRejected_SIZE(3);
    ASSERT_EVENTS_InjectionRejected(2, Faults::STACK_MAX_BYTES + 1, Faults::STACK_MAX_BYTES);
    const U32 before = FakeTickClock::now;
    this->invoke_to_schedIn(0, 0);  // nothing was armed
    EXPECT_EQ(FakeTickClock::now, before);
}

void FaultsTester::stackUseWithinTheLimitCompletes() {
    // A host thread's stack holds this easily: the command runs to its answer
    this->sendCmd_STACK_OVERFLOW(0, 4, 512);
    ASSERT_EVENTS_StackOverflowInjected(0, 512);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_STACK_OVERFLOW, 4, Fw::CmdResponse::OK);
}

void FaultsTester::assertReachesTheAssertHook() {
    // No assert hook here but F´'s default, which aborts: the assert fired
    EXPECT_DEATH(this->sendCmd_ASSERT(0, 6, 42), "");
}

void FaultsTester::writeFile(const char* path, U32 size) {
    U8 data[2 * Faults::TRUNCATE_MAX_BYTES];
    ASSERT_LE(size, sizeof(data));
    for (U32 i = 0; i < size; i++) {
        data[i] = static_cast<U8>(i);
    }
    Os::File file;
    ASSERT_EQ(file.open(path, Os::File::OPEN_CREATE, Os::File::OVERWRITE), Os::File::OP_OK);
    FwSizeType written = size;
    ASSERT_EQ(file.write(data, written, Os::File::WAIT), Os::File::OP_OK);
    ASSERT_EQ(written, size);
}

FwSizeType FaultsTester::readFile(const char* path, U8* data, FwSizeType capacity) {
    Os::File file;
    EXPECT_EQ(file.open(path, Os::File::OPEN_READ), Os::File::OP_OK);
    FwSizeType read = capacity;
    EXPECT_EQ(file.read(data, read, Os::File::WAIT), Os::File::OP_OK);
    return read;
}

void FaultsTester::fileDamagedInPlace() {
    writeFile(FILE_PATH, FILE_SIZE);
    this->sendCmd_CORRUPT_FILE(0, 1, Fw::CmdStringArg(FILE_PATH), FileDamage::FLIP, 3);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_CORRUPT_FILE, 1, Fw::CmdResponse::OK);
    ASSERT_EVENTS_FileCorrupted(0, FILE_PATH, FileDamage::FLIP, 3, FILE_SIZE);
    U8 data[FILE_SIZE + 1] = {};
    ASSERT_EQ(readFile(FILE_PATH, data, sizeof(data)), FILE_SIZE);
    EXPECT_EQ(data[2], 2);
    EXPECT_EQ(data[3], static_cast<U8>(~3));
    EXPECT_EQ(data[4], 4);

    this->sendCmd_CORRUPT_FILE(0, 2, Fw::CmdStringArg(FILE_PATH), FileDamage::TRUNCATE, 4);
    ASSERT_CMD_RESPONSE(1, FaultsComponentBase::OPCODE_CORRUPT_FILE, 2, Fw::CmdResponse::OK);
    ASSERT_EQ(readFile(FILE_PATH, data, sizeof(data)), 4U);
    EXPECT_EQ(data[0], 0);
    EXPECT_EQ(data[3], static_cast<U8>(~3));  // the earlier damage kept
}

void FaultsTester::fileDamageRefusedWhereItCannotBeDone() {
    writeFile(FILE_PATH, FILE_SIZE);
    // Past the end: FLIP needs a byte there, TRUNCATE cannot grow a file
    this->sendCmd_CORRUPT_FILE(0, 1, Fw::CmdStringArg(FILE_PATH), FileDamage::FLIP, FILE_SIZE);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_CORRUPT_FILE, 1, Fw::CmdResponse::VALIDATION_ERROR);
    this->sendCmd_CORRUPT_FILE(0, 2, Fw::CmdStringArg(FILE_PATH), FileDamage::TRUNCATE, FILE_SIZE + 1);
    ASSERT_CMD_RESPONSE(1, FaultsComponentBase::OPCODE_CORRUPT_FILE, 2, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_InjectionRejected_SIZE(2);
    // More kept than a truncation copies, and a file that is not there
    writeFile(FILE_PATH, 2 * Faults::TRUNCATE_MAX_BYTES);
    this->sendCmd_CORRUPT_FILE(0, 3, Fw::CmdStringArg(FILE_PATH), FileDamage::TRUNCATE, Faults::TRUNCATE_MAX_BYTES + 1);
    ASSERT_CMD_RESPONSE(2, FaultsComponentBase::OPCODE_CORRUPT_FILE, 3, Fw::CmdResponse::VALIDATION_ERROR);
    ASSERT_EVENTS_InjectionRejected(2, Faults::TRUNCATE_MAX_BYTES + 1, Faults::TRUNCATE_MAX_BYTES);
    this->sendCmd_CORRUPT_FILE(0, 4, Fw::CmdStringArg("NoSuchFile.bin"), FileDamage::FLIP, 0);
    ASSERT_CMD_RESPONSE(3, FaultsComponentBase::OPCODE_CORRUPT_FILE, 4, Fw::CmdResponse::EXECUTION_ERROR);
    ASSERT_EVENTS_FileNotCorrupted_SIZE(1);
    ASSERT_EVENTS_FileCorrupted_SIZE(0);
}

void FaultsTester::restartComesAfterItsDelay() {
    Restart::FakeRestart::restarts = 0;
    this->sendCmd_RESTART(0, 9);
    ASSERT_CMD_RESPONSE(0, FaultsComponentBase::OPCODE_RESTART, 9, Fw::CmdResponse::OK);
    ASSERT_EVENTS_RestartArmed(0, Faults::RESTART_DELAY_CYCLES);
    for (U32 cycle = 1; cycle < Faults::RESTART_DELAY_CYCLES; cycle++) {
        this->invoke_to_schedIn(SLOWEST, 0);
        this->invoke_to_schedIn(0, 0);  // the faster groups do not count
    }
    EXPECT_EQ(Restart::FakeRestart::restarts, 0U);
    this->invoke_to_schedIn(SLOWEST, 0);
    EXPECT_EQ(Restart::FakeRestart::restarts, 1U);
    this->invoke_to_schedIn(SLOWEST, 0);  // once
    EXPECT_EQ(Restart::FakeRestart::restarts, 1U);
}

}  // namespace Kit
