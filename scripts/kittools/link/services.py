# SPDX-License-Identifier: Apache-2.0
"""Commands the ground tools build for F´'s services beyond the dispatcher:
a command's string argument, health's ping toggle for the event service,
and the event service's severity filters (the serial-load sweep's downlink
and sequence axes)."""

from __future__ import annotations

import struct

from kittools.link.client import command, frame
from kittools.link.dictionary import Dictionary

# F´'s EventManager asserts when a health ping finds its queue full (its
# pingIn is an asserting async port; its LogRecv drops what a full queue
# cannot take). The downlink axis floods that queue by design, and on the
# models that serve one message per task per tick (baremetal, its budgeted
# policy) the ping then stopped the deployment (qemu_cortex_m3, 2026-12-04:
# EventManagerComponentAc.cpp's queue-full assert in the axis' first play of
# point 33, both models). So, as an operator would before flooding the event service, the
# sweep has health stop pinging it for the axis (F´'s HLTH_PING_ENABLE) and
# ping it again after; docs/design.md says why.
#: Svc.EventManager's command: its owner is the event service
EVENTS_COMMAND = "SET_ID_FILTER"
ENTRY_LENGTH = struct.Struct(">H")  # FwSizeStoreType, a string argument's length
ENABLED = struct.Struct(">B")  # Fw.Enabled


def string_argument(text: str) -> bytes:
    """A command's string argument: its length (FwSizeStoreType), then its bytes."""
    data = text.encode()
    return ENTRY_LENGTH.pack(len(data)) + data


def ping_enable(names: Dictionary, enabled: bool) -> bytes:
    """The frames of health's HLTH_PING_ENABLE for the event service's ping
    entries, or nothing where the build has no health (its deployment, or
    its board's profile, leaves it out). An entry is named after the
    instance health pings, F´'s way ("CdhCore_events" for CdhCore.events);
    the reference deployment pings its event service through a probe (the
    entry "Kit_eventsPing"). Health refuses the name it does not have with
    its lookup-error event, and pings on."""
    health = names.owner_of("HLTH_PING_ENABLE")
    events = names.owner_of(EVENTS_COMMAND)
    if health is None or events is None:
        return b""
    entry = events.replace(".", "_")
    return b"".join(frame(command(names.opcodes[f"{health}.HLTH_PING_ENABLE"],
                                  string_argument(name) + ENABLED.pack(int(enabled))))
                    for name in (entry, f"{entry}Ping"))


#: Svc.EventManager.FilterSeverity (U8) of the events each command a
#: sequence runs makes beside its own: the dispatcher's (COMMAND:
#: OpCodeDispatched, OpCodeCompleted) and the sequencer's (ACTIVITY_LO:
#: CS_CommandComplete)
ROUTINE_SEVERITIES = {"COMMAND": 2, "ACTIVITY_LO": 4}
#: SET_EVENT_FILTER's arguments: the severity, then Svc.EventManager.Enabled
#: (U8: 0 sends the severity's events, 1 filters them out)
SEVERITY_FILTER = struct.Struct(">BB")


def routine_events(names: Dictionary, sent: bool) -> bytes:
    """The frames of the event service's SET_EVENT_FILTER that stop (or start
    again) sending the routine severities, as an operator does before a
    busy sequence; nothing where the build has no event service command."""
    events = names.owner_of(EVENTS_COMMAND)
    if events is None or f"{events}.SET_EVENT_FILTER" not in names.opcodes:
        return b""
    opcode = names.opcodes[f"{events}.SET_EVENT_FILTER"]
    return b"".join(frame(command(opcode, SEVERITY_FILTER.pack(code, 0 if sent else 1)))
                    for code in ROUTINE_SEVERITIES.values())
