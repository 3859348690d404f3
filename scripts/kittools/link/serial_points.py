# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep's plan (kittools.link.serial_sweep plays it): its
axes and their levels, the timing of a point, the traffic each point offers
(paced by the deployment's time, so that every run offers the same), what
the host records of a point (a SERIAL record beside the deployment's SWEEP
lines) and a sweep's outcome, as serial.json holds it."""

from __future__ import annotations

import json
import math
import random
import struct
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from kittools import console, sweep
from kittools.link.client import bytes_per_second, noise
from kittools.workspace import KitError


@dataclass(frozen=True)
class Axis:
    name: str  # as the SWEEP lines name it (app/scenarios/ground.cpp)
    code: int  # Kit.SegmentAxis
    unit: str
    levels: tuple[int, ...]


# The uplink's levels below a full line (that level, full_line_commands(),
# depends on the line rate). fprime-zephyr's UART driver takes what its
# 1 KiB receive ring holds at each 100 Hz poll (the kit's patch 0003: it took
# 64 bytes, 355 NO_OP frames of 18 B a second, below a full line); what the
# ring cannot hold is counted (LinkHealth.UartRingDrops). The downlink's
# ceiling is the load's: at most Load.DOWNLINK_MAX (16) packets per slice
# (the reference's slices run at 100 Hz: downlink_levels says what another
# deployment's offer). Noise: percent of the line rate.
UPLINK = Axis("uplink", 0, "cmd/s", (0, 50, 100, 200, 300))
DOWNLINK = Axis("downlink", 1, "pkt/s", (0, 100, 200, 400, 800, 1600))
NOISE = Axis("noise", 2, "%", (0, 25, 50, 75, 100))
# The file downlink (F´'s Svc.FileDownlink, where the build has it): file
# data a second, asked for by the ground as SendPartial commands of the bulk
# file, up to a full line (the sweep adds that level: the line rate in bytes)
FILE = Axis("file", 3, "B/s", (0, 1024, 2048, 4096, 8192))
# A sequence (Svc.CmdSequencer, where the build has it: kittools.link.
# sequence_load): the commands it runs a second, its runs asked for by the
# ground at the rate that offers them; the top runs a sequence each 10 Hz
# cycle of the reference deployment
SEQUENCE = Axis("sequence", 4, "cmd/s", (0, 10, 20, 40, 80))
AXES = (UPLINK, DOWNLINK, NOISE, FILE, SEQUENCE)
# A file level asks for a part of the bulk file this often (a steadier load
# than a whole file now and then), the whole file when a part that size is
# more than it holds, then more often: FileDownlink starts a queued file at
# its 10 Hz Run, and pauses 100 ms after each (Kit.FileDownlinkTimings), so
# past some level it cannot keep up, and refuses what its one-deep queue
# cannot take: the axis' delivery breaking point
FILE_PERIOD_S = 0.25
#: Each level is played this many times (latencies as median and spread)
REPEATS = 3
#: Load.DOWNLINK_MAX: the downlink-load packets a slice sends at most
DOWNLINK_PER_SLICE_MAX = 16
# About a second of measurement per point: the deployment measures whole
# hyperperiods of its rate groups (SegmentClock.ticks)
SEGMENT_S = 1.0
# The deployment's seconds a new level runs before its segment is requested
SETTLE_S = 0.3
# Valid NO_OPs a second among the noise: what a noisy line still delivers.
# Enough of them (48 a point) that a level where the ring drops bytes loses
# one in every repeat: that level is the noise axis' delivery breaking point
NOISE_NOOP_RATE = 40
# The uplink's pause before a segment request: the UART driver's receive
# ring (1,024 bytes, drained at each 100 Hz poll) empties well within it, so
# the request is not lost behind a full ring
REQUEST_QUIET_S = 0.2
# Seed of the noise (each point its own stream from it)
NOISE_SEED = 20261203
SEGMENT_ARGUMENTS = struct.Struct(">iIII")  # SegmentAxis (I32), point, level, ticks


def full_line_commands(baud: int, noop_frame: bytes) -> int:
    """NO_OPs a second that fill the line."""
    return int(bytes_per_second(baud)) // len(noop_frame)


def file_request(level: int, file_bytes: int) -> tuple[int, float]:
    """(bytes each SendPartial asks for, SendPartials a second) of a file
    level, from a bulk file of `file_bytes`."""
    if level <= 0 or file_bytes <= 0:
        return 0, 0.0
    part = min(file_bytes, max(1, int(level * FILE_PERIOD_S)))
    return part, level / part


def noise_per_second(baud: int, noop_frame: bytes, level: int) -> float:
    """Noise bytes a second at a noise level: `level` percent of what the
    line carries beside the axis' NO_OPs (at 100 %, NO_OPs and noise fill it)."""
    return (bytes_per_second(baud) - NOISE_NOOP_RATE * len(noop_frame)) * level / 100


@dataclass
class PointTraffic:
    """What the host saw on the link during one point: what was offered, and
    what got through (commands the link passed to the dispatcher, from
    LinkHealth's counts; packets received, and those the numbering shows
    were lost), and where the bytes it sent went."""

    axis: str
    point: int
    level: int
    repeat: int = 0
    commands_sent: int = 0
    commands_dispatched: int = 0
    noops_answered: int = 0
    packets_received: int = 0
    packets_lost: int = 0
    #: Bytes written to the link, and LinkHealth's counts over the point
    bytes_sent: int = 0
    uart_received: int = 0
    #: Bytes the UART driver's receive ring had no room for
    ring_drops: int = 0
    uart_errors: int = 0
    #: MEASURE_SEGMENT commands sent (more than one: the link lost one)
    requests: int = 0
    #: The file axis: file bytes its SendPartials asked for, and the data
    #: bytes of the file packets the ground received for them
    file_bytes_asked: int = 0
    file_bytes_received: int = 0
    #: The sequence axis: the commands of the runs the ground asked for, and
    #: those the sequencer ran (their answers, the NO_OPs answered)
    sequence_commands_asked: int = 0
    sequence_commands_run: int = 0

    def offered(self) -> int:
        if self.axis == DOWNLINK.name:
            return self.packets_received + self.packets_lost
        if self.axis == SEQUENCE.name:
            return self.sequence_commands_asked
        return self.file_bytes_asked if self.axis == FILE.name else self.commands_sent

    def delivered(self) -> int:
        if self.axis == DOWNLINK.name:
            return self.packets_received
        if self.axis == SEQUENCE.name:
            return self.sequence_commands_run
        return self.file_bytes_received if self.axis == FILE.name else self.commands_dispatched

    def record(self) -> str:
        """The point as a console-style SERIAL record, beside the SWEEP lines."""
        return (f"KIT SERIAL axis={self.axis} point={self.point} level={self.level} repeat={self.repeat} "
                f"offered={self.offered()} delivered={self.delivered()} lost={self.offered() - self.delivered()} "
                f"bytes_sent={self.bytes_sent} uart_received={self.uart_received} ring_drops={self.ring_drops} "
                f"uart_errors={self.uart_errors}")


@dataclass
class Outcome:
    lines: list[str] = field(default_factory=list)  # the SWEEP lines, as printed
    traffic: list[PointTraffic] = field(default_factory=list)
    #: Every event the deployment sent down during the sweep, by name, and
    #: the newest value of every channel at its end
    events: dict[str, int] = field(default_factory=dict)
    telemetry: dict[str, Any] = field(default_factory=dict)
    #: The STACK lines the deployment printed after the sweep's last
    #: segment: every stack's high-water mark over the whole sweep, the
    #: ground link's paths included (the suite's scenarios reach none of them)
    stacks: list[str] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        return {"lines": self.lines + [t.record() for t in self.traffic],
                "traffic": [asdict(t) for t in self.traffic], "events": self.events,
                "telemetry": self.telemetry, "stacks": self.stacks}

    def sweep(self) -> sweep.Sweep | None:
        return sweep.of_records([{"kind": r.kind, **r.fields} for r in _records(self.lines)])


def last_stacks(console: list[str]) -> list[str]:
    """The last run of consecutive STACK lines of a console (none: [])."""
    found: list[str] = []
    run: list[str] = []
    for line in console:
        if line.startswith("KIT STACK "):
            run.append(line)
        elif run:
            found, run = run, []
    return run or found


def _records(lines: list[str]) -> list[console.Record]:
    return [r for line in lines if (r := console.parse_line(line)) is not None]


def records_of(path: Path) -> list[console.Record]:
    """The records of a ground-link file (serial.json, flood.json: their "lines")."""
    return _records(json.loads(path.read_text())["lines"])


def downlink_levels(slice_hz: int) -> list[tuple[int, int]]:
    """The downlink axis where the load's slices run at `slice_hz` (the
    rate of the group the deployment gives Load.sliceIn): each level as
    (packets a second offered, packets per slice), at the packets per slice
    nearest the axis' level, at most DOWNLINK_PER_SLICE_MAX; a level that
    would offer what the one before it did is left out. The reference's 100
    Hz slices offer the axis' levels as they are."""
    levels: list[tuple[int, int]] = []
    for level in DOWNLINK.levels:
        per_slice = min(DOWNLINK_PER_SLICE_MAX, math.floor(level / slice_hz + 0.5))
        if not levels or per_slice * slice_hz > levels[-1][0]:
            levels.append((per_slice * slice_hz, per_slice))
    return levels


@dataclass(frozen=True)
class SegmentClock:
    """The deployment's rate-group tick and hyperperiod (its BANNER line:
    tick_hz, hyperperiod_ticks). A segment it measures is a whole number of
    hyperperiods (Timing refuses any other length) and starts at the next
    one after its request."""

    tick_hz: int
    hyperperiod_ticks: int

    def ticks(self, seconds: float) -> int:
        """The whole number of hyperperiods nearest `seconds`, at least one, in ticks."""
        periods = max(1, math.floor(seconds * self.tick_hz / self.hyperperiod_ticks + 0.5))
        return periods * self.hyperperiod_ticks

    def seconds(self, ticks: int) -> float:
        return ticks / self.tick_hz

    def segment_ticks(self) -> int:
        """A point's segment (about SEGMENT_S)."""
        return self.ticks(SEGMENT_S)

    def point_s(self) -> float:
        """How long a point's traffic lasts, in the deployment's time: the
        settling before the request (less the quiet before it), the
        hyperperiod the deployment may wait after it, and the segment. A
        fixed amount of traffic per point, whatever the host's timing: what
        each level offers is the same in every run."""
        return (SETTLE_S - REQUEST_QUIET_S + self.seconds(self.hyperperiod_ticks)
                + self.seconds(self.segment_ticks()))

    @staticmethod
    def of_console(lines: list[str]) -> SegmentClock:
        """From a booted build's BANNER line; a build of a kit older than
        hyperperiod_ticks is an error."""
        banner = next((r for line in lines if (r := console.parse_line(line)) is not None and r.kind == "BANNER"),
                      None)
        fields = banner.fields if banner is not None else {}
        try:
            return SegmentClock(int(fields["tick_hz"]), int(fields["hyperperiod_ticks"]))
        except (KeyError, ValueError):
            raise KitError(f"the firmware's BANNER line gives no tick_hz and hyperperiod_ticks "
                           f"({fields or 'no line'}): a build of an older kit; rebuild it") from None


def traffic_time(elapsed: float) -> float:
    """A point's traffic time at `elapsed`: the quiet before the request
    does not count (its traffic is not sent later in a burst: it is not sent)."""
    quiet_from = SETTLE_S - REQUEST_QUIET_S
    return elapsed - min(max(elapsed - quiet_from, 0.0), REQUEST_QUIET_S)


#: How far a late host makes up what it owes at once (its loop stalled): a
#: 100 Hz poll of the UART driver's, what the deployment reads at once
#: anyway. Beyond it the schedule moves on instead: a level offers its
#: rate, never a catch-up burst at the line rate, whose commands the
#: dispatcher's in-flight limit dropped in some plays and not others.
CATCH_UP_S = 0.01


class Schedule:
    """`total` items at `per_second` of the deployment's time: how many are
    due at `elapsed`. Late by more than CATCH_UP_S, the schedule slips
    (what it owes goes later, at its rate): every host offers the same
    items at no more than their rate, only some hosts take longer."""

    def __init__(self, per_second: float, total: int) -> None:
        self.per_second = per_second
        self.total = total
        self.sent = 0
        self._origin = 0.0  # the elapsed time the schedule counts from (moved on when it slips)

    def due(self, elapsed: float) -> int:
        if self.per_second <= 0 or self.sent >= self.total:
            return 0
        # (a hair over: a slipped origin is a float sum, and 1.9999 is 2)
        owed = int(self.per_second * (elapsed - self._origin) + 1e-9) - self.sent
        allowed = max(1, int(self.per_second * CATCH_UP_S))
        if owed > allowed:
            self._origin += (owed - allowed) / self.per_second
            owed = allowed
        count = max(0, min(owed, self.total - self.sent))
        self.sent += count
        return count

    def complete(self) -> bool:
        return self.sent >= self.total


class Offer:
    """A point's traffic: a command's frame (a NO_OP; the file axis'
    SendPartial) at `commands_per_s`, and noise (bytes that frame nothing)
    at `noise_per_s` with its commands among it, `point_s` of the
    deployment's time of each (SegmentClock.point_s; a Line carries them at
    the line rate)."""

    def __init__(self, command_frame: bytes, point_s: float, commands_per_s: float, noise_per_s: float = 0.0,
                 seed: int = 0) -> None:
        self.command_frame = command_frame
        self._commands = Schedule(commands_per_s, int(commands_per_s * point_s))
        self._noise = Schedule(noise_per_s, int(noise_per_s * point_s))
        self._rng = random.Random(seed)

    def due(self, elapsed: float, traffic: PointTraffic) -> bytes:
        """The bytes due after `elapsed` seconds (the traffic's counts brought up to date)."""
        commands = self._commands.due(elapsed)
        traffic.commands_sent += commands
        return self.command_frame * commands + noise(self._rng, self._noise.due(elapsed))

    def complete(self) -> bool:
        return self._commands.complete() and self._noise.complete()

