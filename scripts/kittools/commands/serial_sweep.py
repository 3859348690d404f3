# SPDX-License-Identifier: Apache-2.0
"""kit serial-sweep: the serial-load sweep of a board and model through its ground link."""

from __future__ import annotations

import argparse
import json

from kittools import sweep
from kittools.commands.gds import ground_build
from kittools.link import serial_sweep
from kittools.link.serial_points import PointTraffic
from kittools.log import say
from kittools.suite import results


def run(args: argparse.Namespace) -> int:
    build_dir, logs = ground_build(args)
    say(f"serial-load sweep on {build_dir}'s link ...")
    outcome = serial_sweep.run(build_dir, axes=args.axes)
    out = logs / results.SERIAL_SWEEP_FILE
    out.write_text(json.dumps(outcome.to_json(), indent=2) + "\n")
    found = outcome.sweep()
    levels: dict[tuple[str, int], list[PointTraffic]] = {}
    for traffic in outcome.traffic:
        levels.setdefault((traffic.axis, traffic.level), []).append(traffic)
    for (axis, level), plays in levels.items():
        if found is None:
            break
        at = {p.rate_group: p for p in found.points if p.axis == axis and p.level == level}
        spread = {rg: "-".join(map(str, found.spread.get((axis, level, rg), ()))) for rg in at}
        latency = ", ".join(f"{rg} p99/max {p.latency_p99}/{p.latency_max}"
                            f"{f' (max {spread[rg]})' if spread[rg] else ''} cycles{' MISSED' if p.missed else ''}"
                            for rg, p in at.items())
        print(f"{axis} {sweep.level_text(level, found.unit(axis))}: {latency} (median of {len(plays)} plays); "
              f"delivered {'/'.join(str(t.delivered()) for t in plays)} of {plays[0].offered()}, ring drops "
              f"{'/'.join(str(t.ring_drops) for t in plays)} B")
    say(f"records: {out}")
    return 0
