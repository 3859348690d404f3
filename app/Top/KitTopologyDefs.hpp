// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  KitTopologyDefs.hpp
// \brief  Definitions the generated topology code expects
// ======================================================================
#ifndef KIT_KITTOPOLOGYDEFS_HPP
#define KIT_KITTOPOLOGYDEFS_HPP

#include "app/Subtopologies/Instruments/FppConstantsAc.hpp"  // Kit.RamFs: the parameter file's name
#include "app/Top/FppConstantsAc.hpp"
#include "app/src/TopologyState.hpp"

namespace Kit {
//! Health cycles (its rate group's: 10 Hz) an answer may take before
//! health's WARNING_HI (HLTH_PING_WARN), and before its FATAL
//! (HLTH_PING_LATE): F´'s defaults (Svc/Subtopologies/CdhCore/PingEntries.hpp)
constexpr U32 PING_WARN_CYCLES = 3;
constexpr U32 PING_FATAL_CYCLES = 5;
}  // namespace Kit

// The thresholds per ping entry, where FPP's health table looks for them:
// named by the instance on health's connection, the entry's probe
// (app/Top/topology.fpp and the subtopologies it imports). Every entry has
// the same; a build without an entry ignores its name.
namespace PingEntries {
namespace Kit_eventsPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_tlmSendPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_rg1kHzPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_rg100HzPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_rg10HzPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_cmdDispPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_prmDbPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_fileDownlinkPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_fileUplinkPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
namespace Kit_cmdSeqPing {
enum { WARN = Kit::PING_WARN_CYCLES, FATAL = Kit::PING_FATAL_CYCLES };
}
}  // namespace PingEntries

#endif
