// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/LockedFile.hpp
// \brief  fprime-baremetal's MicroFs behind one lock, for the model whose
//         F´ tasks preempt one another
//
// MicroFs keeps every file's state (its size, its descriptors and their
// positions) in one table and takes no lock: it was written for one
// cooperative loop. On Zephyr threads, two components opening the same file
// at once (the file uplink writing a sequence the sequencer reads, the file
// downlink reading a file the uplink writes, the fault injector's
// CORRUPT_FILE beside the parameter database) could both be handed the
// same free descriptor (BaremetalFile::open finds it, then marks it), and
// a file's size could be read while another thread writes it. Each call
// here holds one mutex for the whole file system while MicroFs runs: the
// files are small and in RAM, so a call holds it for microseconds.
//
// Each class is fprime-baremetal's own, with every call that reaches
// MicroFs's table taken under the lock: the same size, so the handles F´
// reserves for them (FW_*_HANDLE_MAX_SIZE) hold them as they are.
// ======================================================================
#ifndef KIT_RTOS_OS_LOCKEDFILE_HPP
#define KIT_RTOS_OS_LOCKEDFILE_HPP

#include <Os/Mutex.hpp>
#include <fprime-baremetal/Os/Baremetal/Directory.hpp>
#include <fprime-baremetal/Os/Baremetal/File.hpp>
#include <fprime-baremetal/Os/Baremetal/FileSystem.hpp>

namespace Kit {
namespace Os {

//! The lock every call of the classes below holds while MicroFs runs
::Os::Mutex& fileSystemLock();

class LockedFile final : public ::Os::Baremetal::File::BaremetalFile {
  public:
    LockedFile() = default;
    //! A copy takes a descriptor of its own from the table: under the lock
    LockedFile(const LockedFile& other);
    LockedFile& operator=(const LockedFile& other);
    ~LockedFile() override = default;

    Status open(const char* path, Mode mode, OverwriteType overwrite) override;
    void close() override;
    Status size(FwSizeType& size_result) override;
    Status position(FwSizeType& position_result) override;
    Status preallocate(FwSizeType offset, FwSizeType length) override;
    Status seek(FwSignedSizeType offset, SeekType seekType) override;
    Status flush() override;
    Status read(U8* buffer, FwSizeType& size, WaitType wait) override;
    Status write(const U8* buffer, FwSizeType& size, WaitType wait) override;
};

//! Renaming is not taken under the lock as a whole: MicroFs renames by
//! copying through Os::File (locked call by call) and removing the source
//! (locked), and F´'s mutex need not be recursive (a POSIX one is not)
class LockedFileSystem final : public ::Os::Baremetal::FileSystem::BaremetalFileSystem {
  public:
    Status _removeDirectory(const char* path) override;
    Status _removeFile(const char* path) override;
    Status _getFreeSpace(const char* path, FwSizeType& totalBytes, FwSizeType& freeBytes) override;
    Status _getPathType(const char* path, PathType& pathType) override;
};

class LockedDirectory final : public ::Os::Baremetal::Directory::BaremetalDirectory {
  public:
    Status open(const char* path, OpenMode mode) override;
    Status rewind() override;
    Status read(char* fileNameBuffer, FwSizeType buffSize) override;
    void close() override;
};

}  // namespace Os
}  // namespace Kit

#endif  // KIT_RTOS_OS_LOCKEDFILE_HPP
