// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/test/ut/LockedFileTest.cpp
// \brief  Host test of the rtos model's locked MicroFs (LockedFile.hpp):
//         fprime-baremetal's MicroFs and its Os classes compiled from the
//         workspace, F´'s POSIX mutex as the lock, real threads
// ======================================================================
#include <gtest/gtest.h>

#include <Fw/Types/MallocAllocator.hpp>
#include <array>
#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include <fprime-baremetal/Os/Baremetal/MicroFs/MicroFs.hpp>
#include "rtos/Os/LockedFile.hpp"

namespace {

using MicroFs = Os::Baremetal::MicroFs;
using Kit::Os::LockedFile;

constexpr char FILE_NAME[] = "/bin0/file0";
constexpr FwSizeType FILE_SIZE = 64;
constexpr U32 OPENS_PER_THREAD = 20000;
constexpr U32 THREADS = 4;  // fewer than MicroFs's descriptors per file (MAX_MICROFS_FD)
const std::array<U8, 8> CONTENT = {1, 2, 3, 4, 5, 6, 7, 8};

class LockedFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        MicroFs::MicroFsConfig config{};
        MicroFs::MicroFsSetCfgBins(config, 1);
        MicroFs::MicroFsAddBin(config, 0, FILE_SIZE, 2);
        MicroFs::MicroFsInit(config, 0, m_allocator);
        LockedFile file;
        ASSERT_EQ(file.open(FILE_NAME, Os::File::OPEN_CREATE, Os::File::OVERWRITE), Os::File::OP_OK);
        FwSizeType size = CONTENT.size();
        ASSERT_EQ(file.write(CONTENT.data(), size, Os::File::WAIT), Os::File::OP_OK);
        file.close();
    }
    void TearDown() override { MicroFs::MicroFsCleanup(0, m_allocator); }

    Fw::MallocAllocator m_allocator;
};

// One thread's share: open the file, read it whole, close it, over and over;
// the count of opens that failed or read something else
U32 openReadClose() {
    U32 failures = 0;
    for (U32 i = 0; i < OPENS_PER_THREAD; i++) {
        LockedFile file;
        std::array<U8, CONTENT.size()> read{};
        FwSizeType size = read.size();
        const bool opened = file.open(FILE_NAME, Os::File::OPEN_READ, Os::File::NO_OVERWRITE) == Os::File::OP_OK;
        const bool readOk = opened && (file.read(read.data(), size, Os::File::WAIT) == Os::File::OP_OK) &&
                            (size == CONTENT.size()) && (read == CONTENT);
        failures += readOk ? 0U : 1U;
        if (opened) {
            file.close();
        }
    }
    return failures;
}

// The file's descriptors in use (MicroFs's table)
U32 descriptorsInUse() {
    FwIndexType entry = 0;
    EXPECT_EQ(MicroFs::getFileStateIndex(FILE_NAME, entry), MicroFs::VALID);
    const MicroFs::MicroFsFileState* state = MicroFs::getFileStateFromIndex(entry);
    U32 used = 0;
    for (FwIndexType fd = 0; fd < Os::MAX_MICROFS_FD; fd++) {
        used += (state->fd[fd].status == MicroFs::VALID) ? 1U : 0U;
    }
    return used;
}

}  // namespace

// BaremetalFile::open finds a free descriptor, then marks it: unlocked, two
// threads between the two share one, and the first to close frees the
// other's (its read then fails, or a descriptor stays marked)
TEST_F(LockedFileTest, ThreadsOpeningOneFileAtOnceEachReadItWholeAndFreeEveryDescriptor) {
    std::atomic<U32> failures{0};
    std::vector<std::thread> threads;
    for (U32 t = 0; t < THREADS; t++) {
        threads.emplace_back([&failures] { failures += openReadClose(); });
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    EXPECT_EQ(failures.load(), 0U);
    EXPECT_EQ(descriptorsInUse(), 0U);
}

// A copy takes a descriptor of its own, at the original's position
TEST_F(LockedFileTest, ACopyReadsOnFromTheOriginalsPositionWithADescriptorOfItsOwn) {
    LockedFile original;
    ASSERT_EQ(original.open(FILE_NAME, Os::File::OPEN_READ, Os::File::NO_OVERWRITE), Os::File::OP_OK);
    std::array<U8, 3> head{};
    FwSizeType size = head.size();
    ASSERT_EQ(original.read(head.data(), size, Os::File::WAIT), Os::File::OP_OK);
    LockedFile copy(original);
    EXPECT_EQ(descriptorsInUse(), 2U);
    std::array<U8, 5> tail{};
    size = tail.size();
    ASSERT_EQ(copy.read(tail.data(), size, Os::File::WAIT), Os::File::OP_OK);
    EXPECT_EQ(0, std::memcmp(tail.data(), CONTENT.data() + head.size(), tail.size()));
    copy.close();
    original.close();
    EXPECT_EQ(descriptorsInUse(), 0U);
}
