# SPDX-License-Identifier: Apache-2.0
"""kit sizing: a build's fixed tables against its dictionary and run, and its ports' cost."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from kittools import console
from kittools.sizes import sizing
from kittools.workspace import KitError


def run(args: argparse.Namespace) -> int:
    build = Path(args.build).resolve()
    queues: list[dict[str, str]] = []
    if args.log:
        log = Path(args.log)
        if not log.is_file():
            raise KitError(f"no console log at {log}")
        # Any run that printed its queues will do, finished or halted
        records = (console.parse_line(line) for line in log.read_text(errors="replace").splitlines())
        queues = [r.fields for r in records if r is not None and r.kind == "QUEUE"]
        if not queues:
            raise KitError(f"{log} has no KIT QUEUE lines (a nominal, load, faults or soak run prints them)")
    found = sizing.measure(build, queues)
    for line in sizing.render(found):
        print(line)
    faults = sizing.too_small(found.advice)
    for fault in faults:
        print(f"kit: TOO SMALL: {fault}", file=sys.stderr)
    return 1 if faults else 0
