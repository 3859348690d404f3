# SPDX-License-Identifier: Apache-2.0
"""The stacks' high-water marks a build's integration suite ends with.

After the suite's last test the deployment measures one segment
(tests/integration/conftest.py) and prints its KIT STACK lines at its end:
the suite's parameter files, file transfers, sequences and warm restarts
reach paths no scenario does, and these marks size the rtos stack table
(app/Top/Tables.fpp)."""

from __future__ import annotations

import time
from typing import Protocol

from kittools import console
from kittools.link.serial_points import last_stacks


class Console(Protocol):
    """A booted deployment's console (kittools.link.ground.GroundStation)."""

    def lines(self, read_s: float = 0.0) -> list[str]: ...


#: The stacks' high-water marks at the end of a build's integration suite
#: (its KIT STACK lines), in the build's integration logs
STACKS_FILE = "stacks.txt"
#: How long the deployment may take to answer the segment's request, run
#: it (a hyperperiod's wait, the hyperperiod) and print its stacks
STACKS_WAIT_S = 20


def stacks_after_the_suite(station: Console) -> list[str]:
    """The STACK lines the deployment prints at the end of the segment the
    suite asked for last: those after its SWEEP lines, once no more come;
    none if it printed none in STACKS_WAIT_S."""
    deadline = time.monotonic() + STACKS_WAIT_S
    seen: list[str] = []
    while time.monotonic() < deadline:
        lines = station.lines(read_s=0.5)
        sweeps = [i for i, line in enumerate(lines) if line.startswith("KIT SWEEP ")]
        stacks = last_stacks(lines[sweeps[-1]:]) if sweeps else []
        if stacks and stacks == seen:
            return stacks
        seen = stacks
    return seen


def stack_summary(stacks: list[str]) -> str:
    """name used/size, for each STACK line."""
    marks = [record.fields for line in stacks if (record := console.parse_line(line)) is not None]
    return ", ".join(f"{mark.get('name')} {mark.get('used')}/{mark.get('size')}" for mark in marks)
