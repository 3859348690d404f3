// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  GeneratedIds.hpp
// \brief  Opcodes and event IDs the deployment code needs by name
//
// FPP generates them as protected members of each component base. These
// derived types (never instantiated) make the few the kit uses readable
// without hard-coding numbers; add the instance's base ID to get the global ID.
// ======================================================================
#ifndef KIT_GENERATEDIDS_HPP
#define KIT_GENERATEDIDS_HPP

// The dispatcher in the build's form (app/Top/dispatcher/): the same
// opcodes and event IDs in both
#if defined(CONFIG_KIT_CMD_DISPATCHER_PASSIVE)
#include "fprime-baremetal/Svc/PassiveCmdDispatcher/PassiveCmdDispatcherComponentAc.hpp"
#else
#include "Svc/CmdDispatcher/CommandDispatcherComponentAc.hpp"
#endif
#if defined(CONFIG_KIT_SERVICE_CDH)
#include "Svc/Health/HealthComponentAc.hpp"
#include "Svc/Version/VersionComponentAc.hpp"
#endif
#include "app/Components/Controller/ControllerComponentAc.hpp"
#include "app/Components/Faults/FaultsComponentAc.hpp"
#include "app/Components/Load/LoadComponentAc.hpp"
#include "app/Components/Timing/TimingComponentAc.hpp"

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

struct ControllerIds : ControllerComponentBase {
    static constexpr FwOpcodeType SET_SETPOINT = OPCODE_SET_SETPOINT;
};

struct LoadIds : LoadComponentBase {
    static constexpr FwOpcodeType SET_SLICE = OPCODE_SET_SLICE;
    static constexpr FwOpcodeType SET_BURST = OPCODE_SET_BURST;
    static constexpr FwEventIdType MESSAGES_DROPPED = EVENTID_MESSAGESDROPPED;
};

struct FaultsIds : FaultsComponentBase {
    static constexpr FwOpcodeType OVERRUN = OPCODE_OVERRUN;
    static constexpr FwOpcodeType STACK_OVERFLOW = OPCODE_STACK_OVERFLOW;
    static constexpr FwOpcodeType ASSERT = OPCODE_ASSERT;
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
struct TimingIds : TimingComponentBase {
    static constexpr FwEventIdType RATE_GROUP_SLIP = EVENTID_RATEGROUPSLIP;
};

}  // namespace Kit

#endif
