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

#include "Svc/CmdDispatcher/CommandDispatcherComponentAc.hpp"
#include "app/Components/Controller/ControllerComponentAc.hpp"

namespace Kit {

struct CmdDispIds : Svc::CommandDispatcherComponentBase {
    static constexpr FwOpcodeType NO_OP = OPCODE_CMD_NO_OP;
    static constexpr FwEventIdType NO_OP_RECEIVED = EVENTID_NOOPRECEIVED;
};

struct ControllerIds : ControllerComponentBase {
    static constexpr FwOpcodeType SET_SETPOINT = OPCODE_SET_SETPOINT;
};

}  // namespace Kit

#endif
