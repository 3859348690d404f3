// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/Os/DefaultLockedFile.cpp
// \brief  F´'s Os::File, Os::FileSystem and Os::Directory are the kit's
//         locked MicroFs (rtos/Os/LockedFile.hpp), as fprime-baremetal's
//         DefaultFile.cpp makes them its unlocked one
// ======================================================================
#include <Os/Delegate.hpp>
#include "rtos/Os/LockedFile.hpp"

namespace Os {
FileInterface* FileInterface::getDelegate(FileHandleStorage& aligned_new_memory, const FileInterface* to_copy) {
    return Os::Delegate::makeDelegate<FileInterface, Kit::Os::LockedFile>(aligned_new_memory, to_copy);
}
FileSystemInterface* FileSystemInterface::getDelegate(FileSystemHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<FileSystemInterface, Kit::Os::LockedFileSystem>(aligned_new_memory);
}
DirectoryInterface* DirectoryInterface::getDelegate(DirectoryHandleStorage& aligned_new_memory) {
    return Os::Delegate::makeDelegate<DirectoryInterface, Kit::Os::LockedDirectory>(aligned_new_memory);
}
}  // namespace Os
