# SPDX-License-Identifier: Apache-2.0
"""The load sweeps of a variant, from its SWEEP and BREAK records: the
background-load axes (app/scenarios/load.cpp) and the serial-load axes
(app/scenarios/ground.cpp, driven by kittools.link.serial_sweep). Each axis has
its unit (`us` of computation, `cmd/s` up the link, `pkt/s` down it, `B/s`
of file data down it);
docs/results.md describes the records."""

from __future__ import annotations

import dataclasses
import statistics
from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True)
class Point:
    """One rate group at one load, over one measured segment (counter cycles)."""

    axis: str
    level: int  # the axis' setting, in `unit`
    unit: str
    burst: int
    rate_group: str
    hz: int
    slips: int
    late_starts: int
    latency_p99: int
    latency_max: int
    jitter_max: int
    #: Load messages the load's queue dropped during the segment (a policy
    #: that defers work may shed it: CONFIG_KIT_MODEL_SHEDS_LOAD)
    shed: int = 0
    #: Cycles the segment should have run (its record's `expected`)
    expected: int = 0

    @property
    def missed(self) -> bool:
        """A deadline was missed: a cycle started or ended past its next release."""
        return self.slips > 0 or self.late_starts > 0

    @property
    def breaks(self) -> bool:
        """The group is broken at this point: on a deterministic axis any
        missed deadline; on a host-timed one more than HOST_TIMED_SHARE of
        its cycles (and at least one)."""
        if self.unit not in HOST_TIMED_UNITS:
            return self.missed
        return self.slips + self.late_starts > HOST_TIMED_SHARE * self.expected


@dataclass
class Sweep:
    points: list[Point]
    #: (axis, rate group) -> the firmware's own breaking point (µs, None: none)
    reported: dict[tuple[str, str], int | None]
    #: SWEEP records cut short (an interrupt's console message printed
    #: into the middle of one)
    malformed: int = 0
    #: (axis, level, rate group) -> the smallest and largest latency_max of
    #: a level played more than once (the serial axes: host-timed input
    #: makes their latencies differ from play to play); its point is the
    #: median of the plays, field by field
    spread: dict[tuple[str, int, str], tuple[int, int]] = field(default_factory=dict)
    #: (axis, level, rate group) -> how many times it was played
    plays: dict[tuple[str, int, str], int] = field(default_factory=dict)
    #: axis -> how the load scenario shaped it (its AXIS record's fields:
    #: period_us, step_us, top_us, burst, every; docs/results.md)
    shapes: dict[str, dict[str, int]] = field(default_factory=dict)

    def shape_text(self, axis: str) -> str:
        """How an axis was shaped, in words ("" where its run did not say)."""
        shape = self.shapes.get(axis)
        if shape is None:
            return ""
        paced = f", its work on one call in {shape['every']}" if shape["every"] > 1 else ""
        burst = f", {shape['burst']} message{'s' if shape['burst'] > 1 else ''} a burst" if shape["burst"] else ""
        return (f"the load's port called each {shape['period_us']:,} µs{paced}{burst}; levels "
                f"0–{shape['top_us']:,} µs in steps of {shape['step_us']:,} µs")

    def repeats(self, axis: str) -> int:
        """How many times each level of an axis was played (the most of any)."""
        return max((n for key, n in self.plays.items() if key[0] == axis), default=1)

    def axes(self) -> list[str]:
        return list(dict.fromkeys(p.axis for p in self.points))

    def rate_groups(self) -> list[str]:
        return list(dict.fromkeys(p.rate_group for p in self.points))

    def series(self, axis: str, rate_group: str) -> list[Point]:
        return sorted((p for p in self.points if p.axis == axis and p.rate_group == rate_group),
                      key=lambda p: p.level)

    def unit(self, axis: str) -> str:
        return next((p.unit for p in self.points if p.axis == axis), "")

    def breaking_point(self, axis: str, rate_group: str) -> int | None:
        """The smallest load at which the group broke (Point.breaks), from the points."""
        for point in self.series(axis, rate_group):
            if point.breaks:
                return point.level
        return None

    def shed(self, axis: str, rate_group: str, below: int | None = None) -> int:
        """Load messages dropped on an axis (counted once, on the group's
        points), at levels below `below` if given."""
        return sum(p.shed for p in self.series(axis, rate_group) if below is None or p.level < below)

    def max_load(self, axis: str) -> int:
        return max((p.level for p in self.points if p.axis == axis), default=0)

    def inconsistencies(self) -> list[str]:
        """Where the firmware's BREAK line and its SWEEP points disagree, and
        records that could not be read."""
        found = [f"{self.malformed} SWEEP record(s) cut short, left out"] if self.malformed else []
        for (axis, rg), reported in sorted(self.reported.items()):
            computed = self.breaking_point(axis, rg)
            if computed != reported:
                unit = self.unit(axis)
                found.append(f"{axis} {rg}: BREAK says {level_text(reported, unit)}, "
                             f"the points say {level_text(computed, unit)}")
        return found


#: The units of the host-timed axes: the serial ones, whose bytes reach
#: QEMU at instants the host's scheduling decides (load's `us` axes run
#: under icount alone and are exact)
HOST_TIMED_UNITS = ("cmd/s", "pkt/s", "%", "B/s")
#: On a host-timed axis a rate group breaks, and the link's delivery breaks,
#: where the median play missed more than this share of its deadlines or
#: lost more than this share of its commands. Below it misses and losses
#: come and go from run to run: 1-5 slips of a baremetal model's 1 kHz
#: group in some plays (2-3 ms stalls, mostly where the UART's ring
#: overflowed mid-frame), commands lost at the dispatcher's in-flight limit
#: (0-2 of 240 at 200 cmd/s in the baremetal models); past it they did not
#: (7-17 of 360 at 300 cmd/s). docs/ground.md has the runs; the report
#: shows every play's slips and losses.
HOST_TIMED_SHARE = 0.01


def level_text(value: int | None, unit: str) -> str:
    """A level in its unit, as a reader writes it."""
    if value is None:
        return "none"
    return f"{value} µs" if unit == "us" else f"{value} {unit}"


def _int(record: dict[str, Any], key: str) -> int:
    return int(str(record[key]), 0)


#: What a SWEEP record must hold to be read
#: The fields of an AXIS record (app/scenarios/load.cpp) the report reads
AXIS_FIELDS = ("period_us", "step_us", "top_us", "burst", "every")
SWEEP_FIELDS = ("axis", "level", "unit", "burst", "rg", "hz", "slips", "late_starts", "latency_p99", "latency_max",
                "jitter_max")


def median_point(plays: list[Point]) -> Point:
    """One point for a level played several times: the median of each
    count and latency (the lower median: a level misses a deadline when
    most of its plays did)."""
    medians = {name: statistics.median_low(getattr(p, name) for p in plays)
               for name in ("slips", "late_starts", "latency_p99", "latency_max", "jitter_max", "shed")}
    return dataclasses.replace(plays[0], **medians)


def of_records(records: list[dict[str, Any]]) -> Sweep | None:
    """The sweep in a variant's records, or None when it has none."""
    sweeps = [r for r in records if r.get("kind") == "SWEEP"]
    whole = [r for r in sweeps if all(key in r for key in SWEEP_FIELDS)]
    plays: dict[tuple[str, int, str], list[Point]] = {}
    for r in whole:
        point = Point(str(r["axis"]), _int(r, "level"), str(r["unit"]), _int(r, "burst"), str(r["rg"]), _int(r, "hz"),
                      _int(r, "slips"), _int(r, "late_starts"), _int(r, "latency_p99"), _int(r, "latency_max"),
                      _int(r, "jitter_max"), int(str(r.get("load_dropped", 0)), 0), int(str(r.get("expected", 0)), 0))
        plays.setdefault((point.axis, point.level, point.rate_group), []).append(point)
    points = [median_point(found) for found in plays.values()]
    if not points:
        return None
    reported: dict[tuple[str, str], int | None] = {}
    for r in records:
        if r.get("kind") == "BREAK":
            value = str(r["level"])
            reported[(str(r["axis"]), str(r["rg"]))] = None if value == "none" else int(value)
    spread = {key: (min(p.latency_max for p in found), max(p.latency_max for p in found))
              for key, found in plays.items() if len(found) > 1}
    shapes = {str(r["name"]): {key: _int(r, key) for key in AXIS_FIELDS} for r in records
              if r.get("kind") == "AXIS" and all(key in r for key in AXIS_FIELDS)}
    return Sweep(points, reported, len(sweeps) - len(whole), spread, {key: len(v) for key, v in plays.items()},
                 shapes)
