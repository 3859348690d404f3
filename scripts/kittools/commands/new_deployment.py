# SPDX-License-Identifier: Apache-2.0
"""kit new-deployment: give a deployment made by `fprime-util new
--deployment` the kit's seam (kittools.deployments)."""

from __future__ import annotations

import argparse
from fractions import Fraction
from pathlib import Path

from kittools.deployments.adapt import new_deployment
from kittools.log import say


def run(args: argparse.Namespace) -> int:
    folder = Path(args.folder)
    fastest = Fraction(args.fastest_hz) if args.fastest_hz else None
    record = new_deployment(folder, fastest)
    if not record.changes:
        say(f"{folder}: nothing to change (the kit's seam is there)")
    for change in record.changes:
        say(f"changed: {change}")
    if record.kept:
        say(f"kept as they are: {', '.join(record.kept)}")
    for item in record.todo:
        say(f"left to do: {item}")
    say(f"next: scripts/kit compare --deployment {folder} --board mps2/an385 (docs/your-deployment.md)")
    return 0
