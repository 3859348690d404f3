// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/LockedFile.cpp
// \brief  fprime-baremetal's MicroFs calls, each under the file system's lock
//         (why: LockedFile.hpp)
// ======================================================================
#include "rtos/Os/LockedFile.hpp"

namespace Kit {
namespace Os {

namespace {
// Constructed with the other static objects, before any task runs
::Os::Mutex s_fileSystemLock;
}  // namespace

::Os::Mutex& fileSystemLock() {
    return s_fileSystemLock;
}

using Base = ::Os::Baremetal::File::BaremetalFile;

LockedFile::LockedFile(const LockedFile& other) : Base() {
    ::Os::ScopeLock lock(fileSystemLock());
    Base::operator=(other);
}

LockedFile& LockedFile::operator=(const LockedFile& other) {
    ::Os::ScopeLock lock(fileSystemLock());
    Base::operator=(other);
    return *this;
}

LockedFile::Status LockedFile::open(const char* path, Mode mode, OverwriteType overwrite) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::open(path, mode, overwrite);
}

void LockedFile::close() {
    ::Os::ScopeLock lock(fileSystemLock());
    Base::close();
}

LockedFile::Status LockedFile::size(FwSizeType& size_result) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::size(size_result);
}

LockedFile::Status LockedFile::position(FwSizeType& position_result) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::position(position_result);
}

LockedFile::Status LockedFile::preallocate(FwSizeType offset, FwSizeType length) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::preallocate(offset, length);
}

LockedFile::Status LockedFile::seek(FwSignedSizeType offset, SeekType seekType) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::seek(offset, seekType);
}

LockedFile::Status LockedFile::flush() {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::flush();
}

LockedFile::Status LockedFile::read(U8* buffer, FwSizeType& size, WaitType wait) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::read(buffer, size, wait);
}

LockedFile::Status LockedFile::write(const U8* buffer, FwSizeType& size, WaitType wait) {
    ::Os::ScopeLock lock(fileSystemLock());
    return Base::write(buffer, size, wait);
}

using FileSystemBase = ::Os::Baremetal::FileSystem::BaremetalFileSystem;

LockedFileSystem::Status LockedFileSystem::_removeDirectory(const char* path) {
    ::Os::ScopeLock lock(fileSystemLock());
    return FileSystemBase::_removeDirectory(path);
}

LockedFileSystem::Status LockedFileSystem::_removeFile(const char* path) {
    ::Os::ScopeLock lock(fileSystemLock());
    return FileSystemBase::_removeFile(path);
}

LockedFileSystem::Status LockedFileSystem::_getFreeSpace(const char* path,
                                                         FwSizeType& totalBytes,
                                                         FwSizeType& freeBytes) {
    ::Os::ScopeLock lock(fileSystemLock());
    return FileSystemBase::_getFreeSpace(path, totalBytes, freeBytes);
}

LockedFileSystem::Status LockedFileSystem::_getPathType(const char* path, PathType& pathType) {
    ::Os::ScopeLock lock(fileSystemLock());
    return FileSystemBase::_getPathType(path, pathType);
}

using DirectoryBase = ::Os::Baremetal::Directory::BaremetalDirectory;

LockedDirectory::Status LockedDirectory::open(const char* path, OpenMode mode) {
    ::Os::ScopeLock lock(fileSystemLock());
    return DirectoryBase::open(path, mode);
}

LockedDirectory::Status LockedDirectory::rewind() {
    ::Os::ScopeLock lock(fileSystemLock());
    return DirectoryBase::rewind();
}

LockedDirectory::Status LockedDirectory::read(char* fileNameBuffer, FwSizeType buffSize) {
    ::Os::ScopeLock lock(fileSystemLock());
    return DirectoryBase::read(fileNameBuffer, buffSize);
}

void LockedDirectory::close() {
    ::Os::ScopeLock lock(fileSystemLock());
    DirectoryBase::close();
}

}  // namespace Os
}  // namespace Kit
