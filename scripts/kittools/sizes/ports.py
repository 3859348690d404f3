# SPDX-License-Identifier: Apache-2.0
"""What the topology's ports cost: every component instance's input and
output port objects (members, or arrays of them, of classes derived from F´'s
`Fw::InputPortBase` / `Fw::OutputPortBase`), counted and sized from the
build's debug information (kittools.sizes.debuginfo). Every declared port takes its
bytes in the instance's object, connected or not."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from kittools.sizes.debuginfo import DebugInfo, name

_DIRECTIONS = (("input", "InputPortBase"), ("output", "OutputPortBase"))


@dataclass(frozen=True)
class InstancePorts:
    """One component instance: its object's size and its ports."""

    name: str
    component: str
    object_bytes: int
    inputs: int
    outputs: int
    input_bytes: int
    output_bytes: int


@dataclass(frozen=True)
class PortCost:
    """The topology's ports, all instances together."""

    instances: list[InstancePorts]

    def total(self, field: str) -> int:
        return sum(int(getattr(i, field)) for i in self.instances)

    def to_json(self) -> dict[str, Any]:
        return {"instances": len(self.instances), "inputs": self.total("inputs"), "outputs": self.total("outputs"),
                "input_bytes": self.total("input_bytes"), "output_bytes": self.total("output_bytes"),
                "object_bytes": self.total("object_bytes")}


def measure(info: DebugInfo) -> PortCost:
    found = []
    for instance in info.instances():
        counts = {"input": [0, 0], "output": [0, 0]}
        for _, member in info.members(instance.cls):
            if member.element is None or not member.count:
                continue
            for direction, base in _DIRECTIONS:
                if info.derives_from(member.element, base):
                    counts[direction][0] += member.count
                    counts[direction][1] += member.bytes
        found.append(InstancePorts(instance.name, name(instance.cls),
                                   info.size(instance.cls), counts["input"][0], counts["output"][0],
                                   counts["input"][1], counts["output"][1]))
    return PortCost(sorted(found, key=lambda i: i.name))

