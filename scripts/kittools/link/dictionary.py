# SPDX-License-Identifier: Apache-2.0
"""What the ground tools read from a build's F´ JSON dictionary: its commands'
opcodes, its constants, its channels and events, and the deployment's
command dispatcher.

The dispatcher is found, not named: every deployment has one (F´'s
`Svc.CommandDispatcher`, or fprime-baremetal's passive form), under the
instance name and module its topology gives it (`Kit.cmdDisp` in the
reference deployment, `Thermal.cmdDisp` in tests/team/Thermal). It is the one
instance with F´'s dispatcher's own command, CMD_NO_OP; its events and
channels are named from it. F´'s file uplink, where a deployment has one, is
found the same way (`Kit.fileUplink` in the reference, `FileHandling.fileUplink`
where a deployment takes F´'s FileHandling subtopology): the instance with
Svc.FileUplink's channels.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kittools.workspace import KitError

#: The command only F´'s command dispatcher (either form) has
NOOP_COMMAND = "CMD_NO_OP"
#: ... and the event it answers it with
NOOP_EVENT = "NoOpReceived"
#: The channels of F´'s Svc.FileUplink, all of which one instance has
FILE_UPLINK_CHANNELS = ("FilesReceived", "PacketsReceived", "Warnings")


@dataclass(frozen=True)
class Dictionary:
    path: Path
    opcodes: dict[str, int]
    constants: dict[str, Any]
    channels: frozenset[str]
    events: frozenset[str]

    @staticmethod
    def read(path: Path) -> Dictionary:
        try:
            data = json.loads(path.read_text())
            opcodes = {str(c["name"]): int(c["opcode"]) for c in data["commands"]}
            constants = {str(c["qualifiedName"]): c["value"] for c in data.get("constants", [])}
            channels = frozenset(str(c["name"]) for c in data.get("telemetryChannels", []))
            events = frozenset(str(e["name"]) for e in data.get("events", []))
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise KitError(f"{path} is not an F´ JSON dictionary a kit build writes: {error}") from None
        return Dictionary(path, opcodes, constants, channels, events)

    @property
    def modules(self) -> frozenset[str]:
        """The top-level FPP modules of its instances ("Kit", and a
        deployment's own: "Thermal" in tests/team/Thermal)."""
        return frozenset(name.split(".", 1)[0] for name in (*self.opcodes, *self.channels, *self.events))

    @property
    def dispatcher(self) -> str:
        """The dispatcher's qualified instance name, e.g. "Kit.cmdDisp";
        KitError where the dictionary has none, or several."""
        found = self.owner_of(NOOP_COMMAND)
        if found is None:
            raise KitError(f"{self.path}: the ground tools need a command dispatcher (the instance with "
                           f"{NOOP_COMMAND}), found none")
        return found

    def of_dispatcher(self, name: str) -> str:
        """A command, event or channel of the dispatcher, by its own name."""
        return f"{self.dispatcher}.{name}"

    @property
    def noop_opcode(self) -> int:
        return self.opcodes[self.of_dispatcher(NOOP_COMMAND)]

    @property
    def noop_command(self) -> str:
        return self.of_dispatcher(NOOP_COMMAND)

    @property
    def noop_event(self) -> str:
        return self.of_dispatcher(NOOP_EVENT)

    def owner_of(self, command: str) -> str | None:
        """The one instance with a command of this own name (F´'s
        FileDownlink's SendPartial, Health's HLTH_PING_ENABLE), whatever the
        deployment named it; None where no instance has it, KitError where
        several do."""
        owners = sorted(name.removesuffix(f".{command}") for name in self.opcodes if name.endswith(f".{command}"))
        if len(owners) > 1:
            raise KitError(f"{self.path}: the ground tools drive one instance with the command {command}, found "
                           f"{len(owners)}: {', '.join(owners)}")
        return owners[0] if owners else None

    @property
    def file_uplink(self) -> str | None:
        """F´'s file uplink's qualified instance name, e.g. "Kit.fileUplink";
        None where the deployment (or its board's profile) has none, KitError
        where it has several (the ground tools feed one)."""
        found = sorted(owner for owner in {name.rsplit(".", 1)[0] for name in self.channels if "." in name}
                       if all(f"{owner}.{channel}" in self.channels for channel in FILE_UPLINK_CHANNELS))
        if len(found) > 1:
            raise KitError(f"{self.path}: the ground tools feed one file uplink (an instance with the channels "
                           f"{', '.join(FILE_UPLINK_CHANNELS)}), found {len(found)}: {', '.join(found)}")
        return found[0] if found else None

    def opcode(self, name: str) -> int:
        """A command's opcode; KitError naming the dictionary where it lacks it."""
        return int(self._named(self.opcodes, "command", name))

    def constant(self, name: str) -> Any:
        """A constant's value; KitError naming the dictionary where it lacks it."""
        return self._named(self.constants, "constant", name)

    def _named(self, table: dict[str, Any], kind: str, name: str) -> Any:
        if name not in table:
            raise KitError(f"{self.path} has no {kind} {name}: is it a dictionary of a kit build of this version?")
        return table[name]

