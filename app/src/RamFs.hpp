// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  RamFs.hpp
// \brief  F´'s file system in RAM: fprime-baremetal's MicroFs, mounted
//
// One bin of CONFIG_KIT_RAMFS_FILES files of CONFIG_KIT_RAMFS_FILE_SIZE
// bytes, named /bin0/file<n> (MicroFs's rule), in a static region the C
// runtime does not clear at reset: a warm restart keeps the files.
// ======================================================================
#ifndef KIT_RAMFS_HPP
#define KIT_RAMFS_HPP

#include <Fw/FPrimeBasicTypes.hpp>
// Kit.RamFs: its files' names (the parameter file, the scratch and bulk
// files), constants of the kit's instruments (every deployment has them)
#include "app/Subtopologies/Instruments/FppConstantsAc.hpp"

namespace Kit {
namespace RamFs {

//! How the files were found at mount
enum class Mount : U8 {
    FORMATTED,  //!< cold start (or a region that did not check): every file empty
    KEPT,       //!< warm restart: the files as the last run left them
    ABSENT,     //!< the build has no RAM file system (CONFIG_KIT_RAMFS=n)
};

//! Mounts the file system, before the topology's setup reads a file
Mount mount();

//! The region the file system takes: its files' states and data, and the
//! header that says whether a warm restart kept them
FwSizeType regionBytes();

}  // namespace RamFs
}  // namespace Kit

#endif
