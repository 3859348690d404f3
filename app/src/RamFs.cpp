// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  RamFs.cpp
// \brief  F´'s file system in RAM: fprime-baremetal's MicroFs, mounted
//
// MicroFs takes its memory from an F´ allocator and clears it at init.
// Here that memory is a static region in Zephyr's .noinit section, which
// the start-up code neither loads nor zeroes, with a header that says
// whether the region holds a file system this image laid out. At a cold
// start the header does not check and MicroFs formats the region; after a
// warm restart (the same image, RAM powered throughout) it checks, and the
// kit hands MicroFs its region back without init: the files' states and
// data are where the last run left them, only their open descriptors are
// dropped (nothing is open across a reset). MicroFs's state is public for
// exactly this (MicroFs::getSingleton()).
// ======================================================================
#include "app/src/RamFs.hpp"

// After F´'s headers: Zephyr's define names (EMPTY) that F´'s enums use
#include <zephyr/autoconf.h>

#if defined(CONFIG_KIT_RAMFS)
#include <zephyr/linker/section_tags.h>
#include <Fw/Types/Assert.hpp>
#include <Fw/Types/MemAllocator.hpp>
#include <fprime-baremetal/Os/Baremetal/MicroFs/MicroFs.hpp>
#endif

namespace Kit {
namespace RamFs {

#if defined(CONFIG_KIT_RAMFS)
namespace {

using Os::Baremetal::MicroFs;

// The bins: the small files (the parameter database's, a scratch file),
// and where the build has one the bulk file (the file downlink's)
struct Bin {
    FwSizeType files;
    FwSizeType fileBytes;
};
constexpr Bin BINS[] = {
    {CONFIG_KIT_RAMFS_FILES, CONFIG_KIT_RAMFS_FILE_SIZE},
#if CONFIG_KIT_RAMFS_BULK_FILE_SIZE > 0
    {1, CONFIG_KIT_RAMFS_BULK_FILE_SIZE},
#endif
};
constexpr FwSizeType BIN_COUNT = sizeof(BINS) / sizeof(BINS[0]);
static_assert(CONFIG_KIT_RAMFS_FILES > 0 && CONFIG_KIT_RAMFS_FILE_SIZE > 0,
              "CONFIG_KIT_RAMFS_FILES and CONFIG_KIT_RAMFS_FILE_SIZE must be positive");

constexpr FwSizeType totalFiles() {
    FwSizeType files = 0;
    for (FwSizeType bin = 0; bin < BIN_COUNT; bin++) {
        files += BINS[bin].files;
    }
    return files;
}
constexpr FwSizeType totalDataBytes() {
    FwSizeType bytes = 0;
    for (FwSizeType bin = 0; bin < BIN_COUNT; bin++) {
        bytes += BINS[bin].files * BINS[bin].fileBytes;
    }
    return bytes;
}
constexpr FwSizeType FILES = totalFiles();
// MicroFs's layout: every file's state, then every file's data, bin by bin
constexpr FwSizeType REGION_BYTES = FILES * sizeof(MicroFs::MicroFsFileState) + totalDataBytes();

// What a warm restart finds: the layout it describes, and a check over it.
// A cold start's RAM is whatever it powered up as; a header that matches
// this image's layout and checks by chance is as likely as any 12 bytes.
struct Header {
    U32 magic;
    U32 layout;  //!< files, file size and the region's address, mixed
    U32 check;   //!< of magic and layout
};

constexpr U32 MAGIC = 0x4B524653u;  // "KRFS"

alignas(MicroFs::MicroFsFileState) __noinit U8 s_region[REGION_BYTES];
__noinit Header s_header;

U32 layoutWord() {
    const U32 address = static_cast<U32>(reinterpret_cast<PlatformPointerCastType>(&s_region[0]));
    U32 layout = address;
    for (FwSizeType bin = 0; bin < BIN_COUNT; bin++) {
        layout = (layout * 31u) ^ (static_cast<U32>(BINS[bin].files) << 24) ^ static_cast<U32>(BINS[bin].fileBytes);
    }
    return layout;
}

U32 checkWord(U32 magic, U32 layout) {
    return ~(magic ^ (layout * 2654435761u));
}

MicroFs::MicroFsConfig configuration() {
    MicroFs::MicroFsConfig config = {};
    MicroFs::MicroFsSetCfgBins(config, static_cast<FwIndexType>(BIN_COUNT));
    for (FwSizeType bin = 0; bin < BIN_COUNT; bin++) {
        MicroFs::MicroFsAddBin(config, static_cast<FwIndexType>(bin), BINS[bin].fileBytes, BINS[bin].files);
    }
    return config;
}

// MicroFs asks an F´ allocator for its memory: this one hands out the region
class RegionAllocator final : public Fw::MemAllocator {
  public:
    void* allocate(const FwEnumStoreType identifier,
                   FwSizeType& size,
                   bool& recoverable,
                   FwSizeType alignment) override {
        (void)identifier;
        (void)alignment;  // the region is aligned for MicroFs's states
        recoverable = false;
        FW_ASSERT(size <= REGION_BYTES, static_cast<FwAssertArgType>(size), REGION_BYTES);
        return &s_region[0];
    }
    void deallocate(const FwEnumStoreType identifier, void* ptr) override {
        (void)identifier;
        (void)ptr;
    }
};

// The states a warm restart finds must describe this region: each file's
// data where the layout puts it, its size within it
bool statesCheck() {
    const MicroFs::MicroFsFileState* const states = reinterpret_cast<const MicroFs::MicroFsFileState*>(&s_region[0]);
    const U8* data = reinterpret_cast<const U8*>(&states[FILES]);
    FwSizeType file = 0;
    for (FwSizeType bin = 0; bin < BIN_COUNT; bin++) {
        const FwSizeType bytes = BINS[bin].fileBytes;
        for (FwSizeType slot = 0; slot < BINS[bin].files; slot++) {
            const MicroFs::MicroFsFileState& state = states[file];
            if (state.data != data || state.dataSize != bytes || state.currSize > bytes) {
                return false;
            }
            data += bytes;
            file++;
        }
    }
    return true;
}

}  // namespace

Mount mount() {
    MicroFs& microFs = MicroFs::getSingleton();
    const MicroFs::MicroFsConfig config = configuration();
    const U32 layout = layoutWord();
    const bool kept = s_header.magic == MAGIC && s_header.layout == layout &&
                      s_header.check == checkWord(MAGIC, layout) && statesCheck();
    if (kept) {
        microFs.s_microFsConfig = config;
        microFs.s_microFsMem = &s_region[0];
        MicroFs::MicroFsFileState* const states = static_cast<MicroFs::MicroFsFileState*>(microFs.s_microFsMem);
        for (FwSizeType file = 0; file < FILES; file++) {
            for (FwIndexType fd = 0; fd < Os::MAX_MICROFS_FD; fd++) {
                states[file].fd[fd].loc = 0;
                states[file].fd[fd].status = MicroFs::Status::INVALID;
            }
        }
        return Mount::KEPT;
    }
    RegionAllocator allocator;
    MicroFs::MicroFsInit(config, 0, allocator);
    FW_ASSERT(microFs.s_microFsMem == &s_region[0]);
    s_header.magic = MAGIC;
    s_header.layout = layout;
    s_header.check = checkWord(MAGIC, layout);
    return Mount::FORMATTED;
}

FwSizeType regionBytes() {
    return REGION_BYTES + sizeof(Header);
}

#else

Mount mount() {
    return Mount::ABSENT;
}

FwSizeType regionBytes() {
    return 0;
}

#endif

}  // namespace RamFs
}  // namespace Kit
