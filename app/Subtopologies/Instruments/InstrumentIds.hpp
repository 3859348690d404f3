// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  InstrumentIds.hpp
// \brief  Opcodes and event IDs of the kit's instruments, by name
//
// FPP generates them as protected members of each component base. These
// derived types (never instantiated) make the few the kit uses readable
// without hard-coding numbers; add the instance's base ID to get the global
// ID. F´'s services' are app/src/ServiceIds.hpp.
// ======================================================================
#ifndef KIT_INSTRUMENTIDS_HPP
#define KIT_INSTRUMENTIDS_HPP

#include "app/Components/Faults/FaultsComponentAc.hpp"
#include "app/Components/Load/LoadComponentAc.hpp"
#include "app/Components/Timing/TimingComponentAc.hpp"

namespace Kit {

struct LoadIds : LoadComponentBase {
    static constexpr FwOpcodeType SET_SLICE = OPCODE_SET_SLICE;
    static constexpr FwOpcodeType SET_BURST = OPCODE_SET_BURST;
    static constexpr FwOpcodeType SET_PACE = OPCODE_SET_PACE;
    static constexpr FwEventIdType MESSAGES_DROPPED = EVENTID_MESSAGESDROPPED;
};

struct FaultsIds : FaultsComponentBase {
    static constexpr FwOpcodeType OVERRUN = OPCODE_OVERRUN;
    static constexpr FwOpcodeType STACK_OVERFLOW = OPCODE_STACK_OVERFLOW;
    static constexpr FwOpcodeType ASSERT = OPCODE_ASSERT;
};

struct TimingIds : TimingComponentBase {
    static constexpr FwEventIdType RATE_GROUP_SLIP = EVENTID_RATEGROUPSLIP;
};

}  // namespace Kit

#endif
