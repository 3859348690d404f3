# SPDX-License-Identifier: Apache-2.0
"""The background-load sweep of a variant, from its SWEEP and BREAK records
(app/scenarios/load.cpp prints them; docs/results.md describes them)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Point:
    """One rate group at one load, over one measured segment (counter cycles)."""

    axis: str
    load_us: int
    burst: int
    rate_group: str
    hz: int
    slips: int
    late_starts: int
    latency_p99: int
    latency_max: int
    jitter_max: int

    @property
    def missed(self) -> bool:
        """A deadline was missed: a cycle started or ended past its next release."""
        return self.slips > 0 or self.late_starts > 0


@dataclass
class Sweep:
    points: list[Point]
    #: (axis, rate group) -> the firmware's own breaking point (µs, None: none)
    reported: dict[tuple[str, str], int | None]

    def axes(self) -> list[str]:
        return list(dict.fromkeys(p.axis for p in self.points))

    def rate_groups(self) -> list[str]:
        return list(dict.fromkeys(p.rate_group for p in self.points))

    def series(self, axis: str, rate_group: str) -> list[Point]:
        return sorted((p for p in self.points if p.axis == axis and p.rate_group == rate_group),
                      key=lambda p: p.load_us)

    def breaking_point(self, axis: str, rate_group: str) -> int | None:
        """The smallest load at which the group missed a deadline, from the points."""
        for point in self.series(axis, rate_group):
            if point.missed:
                return point.load_us
        return None

    def max_load(self, axis: str) -> int:
        return max((p.load_us for p in self.points if p.axis == axis), default=0)

    def inconsistencies(self) -> list[str]:
        """Where the firmware's BREAK line and its SWEEP points disagree."""
        found = []
        for (axis, rg), reported in sorted(self.reported.items()):
            computed = self.breaking_point(axis, rg)
            if computed != reported:
                found.append(f"{axis} {rg}: BREAK says {_us(reported)}, the points say {_us(computed)}")
        return found


def _us(value: int | None) -> str:
    return "none" if value is None else f"{value} µs"


def _int(record: dict[str, Any], key: str) -> int:
    return int(str(record[key]), 0)


def of_records(records: list[dict[str, Any]]) -> Sweep | None:
    """The sweep in a variant's records, or None when it has none."""
    points = [Point(str(r["axis"]), _int(r, "load_us"), _int(r, "burst"), str(r["rg"]), _int(r, "hz"),
                    _int(r, "slips"), _int(r, "late_starts"), _int(r, "latency_p99"), _int(r, "latency_max"),
                    _int(r, "jitter_max"))
              for r in records if r.get("kind") == "SWEEP"]
    if not points:
        return None
    reported: dict[tuple[str, str], int | None] = {}
    for r in records:
        if r.get("kind") == "BREAK":
            value = str(r["load_us"])
            reported[(str(r["axis"]), str(r["rg"]))] = None if value == "none" else int(value)
    return Sweep(points, reported)
