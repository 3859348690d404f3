// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ServiceIds.hpp
// \brief  Opcodes and event IDs of F´'s services the kit needs by name: the
//         dispatcher's (in the form the build chose), health's,
//         version's and the link's queue's (the kit's instruments' are
//         app/Subtopologies/Instruments/InstrumentIds.hpp)
//
// FPP generates them as protected members of each component base. These
// derived types (never instantiated) make the few the kit uses readable
// without hard-coding numbers; add the instance's base ID to get the global ID.
// ======================================================================
#ifndef KIT_SERVICEIDS_HPP
#define KIT_SERVICEIDS_HPP

// The dispatcher in the build's form (CONFIG_KIT_CMD_DISPATCHER_PASSIVE):
// the same opcodes and event IDs in both
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
#include "fprime-baremetal/Svc/PassiveCmdDispatcher/PassiveCmdDispatcherComponentAc.hpp"
#else
#include "Svc/CmdDispatcher/CommandDispatcherComponentAc.hpp"
#endif
#include "Svc/ComQueue/ComQueueComponentAc.hpp"
#if defined(CONFIG_KIT_SERVICE_CDH)
#include "Svc/Health/HealthComponentAc.hpp"
#include "Svc/Version/VersionComponentAc.hpp"
#endif

namespace Kit {

#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
using CmdDispBase = Baremetal::PassiveCmdDispatcherComponentBase;
#else
using CmdDispBase = Svc::CommandDispatcherComponentBase;
#endif

struct CmdDispIds : CmdDispBase {
    static constexpr FwOpcodeType NO_OP = OPCODE_CMD_NO_OP;
    static constexpr FwEventIdType NO_OP_RECEIVED = EVENTID_NOOPRECEIVED;
    static constexpr FwEventIdType MALFORMED_COMMAND = EVENTID_MALFORMEDCOMMAND;
    static constexpr FwEventIdType INVALID_COMMAND = EVENTID_INVALIDCOMMAND;
    static constexpr FwEventIdType OPCODE_ERROR = EVENTID_OPCODEERROR;
};

//! The ground link's downlink queue: a packet it had no room for (F´'s
//! ComQueue throttles the event until that queue has room again)
struct ComQueueIds : Svc::ComQueueComponentBase {
    static constexpr FwEventIdType QUEUE_OVERFLOW = EVENTID_QUEUEOVERFLOW;
};

#if defined(CONFIG_KIT_SERVICE_CDH)
struct HealthIds : Svc::HealthComponentBase {
    static constexpr FwEventIdType PING_WARN = EVENTID_HLTH_PING_WARN;
    static constexpr FwEventIdType PING_LATE = EVENTID_HLTH_PING_LATE;
    static constexpr FwEventIdType PING_WRONG_KEY = EVENTID_HLTH_PING_WRONG_KEY;
};
struct VersionIds : Svc::VersionComponentBase {
    static constexpr FwEventIdType FRAMEWORK_VERSION = EVENTID_FRAMEWORKVERSION;
    static constexpr FwEventIdType PROJECT_VERSION = EVENTID_PROJECTVERSION;
};
#endif
}  // namespace Kit

#endif
