# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep: what traffic on the ground link costs the rate groups.

Two axes, each driven from outside through the real link (a build of the
ground scenario under QEMU, kittools.link_client on its socket):

  uplink    NO_OP commands at a steady rate (cmd/s), paced by the
            deployment's own clock as the downlink shows it: QEMU's virtual
            time is not the host's;
  downlink  extra downlink packets (pkt/s): Load.SET_DOWNLINK events from
            every 100 Hz slice, framed and written to the link UART by the
            deployment, read and counted by the host.

At each level the deployment measures a segment on request
(Timing.MEASURE_SEGMENT) and prints one SWEEP line per rate group, the
record the load scenario writes for its axes; breaking points come from them
as for those axes (kittools.sweep). The host adds what only it sees:
commands sent and packets received.
"""

from __future__ import annotations

import json
import struct
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from . import console, ground, runner, sweep
from .link_client import Downlink, command, frame
from .workspace import KitError


@dataclass(frozen=True)
class Axis:
    name: str  # as the SWEEP lines name it (app/scenarios/ground.cpp)
    code: int  # Kit.SegmentAxis
    unit: str
    levels: tuple[int, ...]


# The uplink's ceiling is the link driver's: fprime-zephyr's UART driver
# takes at most 64 bytes per 100 Hz poll, 355 NO_OP frames (18 B) a second;
# above that its receive ring overflows. The downlink's is the load's:
# at most Load.DOWNLINK_MAX (16) packets per 100 Hz slice.
UPLINK = Axis("uplink", 0, "cmd/s", (0, 50, 100, 200, 300))
DOWNLINK = Axis("downlink", 1, "pkt/s", (0, 100, 200, 400, 800, 1600))
AXES = (UPLINK, DOWNLINK)
SLICE_HZ = 100  # Load's slices per second: a downlink level is packets per slice times this
# One second of measurement per point (ten hyperperiods)
SEGMENT_TICKS = 1000
# The deployment's seconds a new level runs before its segment is requested
SETTLE_S = 0.3
REPLY_TIMEOUT_S = 30.0
NOOP_EVENT = "Kit.cmdDisp.NoOpReceived"
# Ground commands the link dropped (LinkHealth), written every 100 ms
DROPPED_CHANNEL = "Kit.linkHealth.CommandsDropped"
DOWNLINK_PACKET_EVENT = "Kit.load.DownlinkLoadPacket"
# fprime-zephyr's UART driver, for every byte its receive ring drops
RECEIVE_OVERRUN = "UART buffer overrun"
# The uplink's pause before a segment request (two of the link driver's
# 100 Hz polls), and the wait for a segment after one
REQUEST_QUIET_S = 0.02
REQUEST_RETRY_S = 1.0
# Most NO_OPs written at once when the deployment's clock jumps ahead
BURST_MAX = 8
U32 = struct.Struct(">I")
SEGMENT_ARGUMENTS = struct.Struct(">iIII")  # SegmentAxis (I32), point, level, ticks


@dataclass
class PointTraffic:
    """What the host saw on the link during one point: what was offered, and
    what got through (commands the link passed to the dispatcher, as its
    telemetry says; packets received, and those the numbering shows were
    lost)."""

    axis: str
    point: int
    level: int
    commands_sent: int = 0
    commands_dispatched: int = 0
    noops_answered: int = 0
    packets_received: int = 0
    packets_lost: int = 0
    #: Bytes the link UART's receive ring had no room for (fprime-zephyr's
    #: driver prints a console line for each)
    receive_overruns: int = 0
    #: MEASURE_SEGMENT commands sent (more than one: the link dropped one)
    requests: int = 0

    def offered(self) -> int:
        return self.commands_sent if self.axis == UPLINK.name else self.packets_received + self.packets_lost

    def delivered(self) -> int:
        return self.commands_dispatched if self.axis == UPLINK.name else self.packets_received

    def record(self) -> str:
        """The point as a console-style SERIAL record, beside the SWEEP lines."""
        return (f"KIT SERIAL axis={self.axis} point={self.point} level={self.level} offered={self.offered()} "
                f"delivered={self.delivered()} lost={self.offered() - self.delivered()} "
                f"receive_overruns={self.receive_overruns}")


@dataclass
class Outcome:
    lines: list[str] = field(default_factory=list)  # the SWEEP lines, as printed
    traffic: list[PointTraffic] = field(default_factory=list)
    #: Every event the deployment sent down during the sweep, by name, and
    #: the newest value of every channel at its end
    events: dict[str, int] = field(default_factory=dict)
    telemetry: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        return {"lines": self.lines + [t.record() for t in self.traffic],
                "traffic": [asdict(t) for t in self.traffic], "events": self.events,
                "telemetry": self.telemetry}

    def sweep(self) -> sweep.Sweep | None:
        return sweep.of_records([{"kind": r.kind, **r.fields} for r in _records(self.lines)])


def _records(lines: list[str]) -> list[console.Record]:
    return [r for line in lines if (r := console.parse_line(line)) is not None]


def records_of(path: Path) -> list[console.Record]:
    """The SWEEP records of a sweep's file (serial.json)."""
    return _records(json.loads(path.read_text())["lines"])


class Driver:
    """One booted ground build: commands up its link, its console read for the records."""

    def __init__(self, qemu: runner.Qemu, link: Downlink, opcodes: dict[str, int]) -> None:
        self.qemu = qemu
        self.link = link
        self.opcodes = opcodes
        self.noop = frame(command(opcodes["Kit.cmdDisp.CMD_NO_OP"]))

    def send(self, name: str, arguments: bytes = b"") -> None:
        self.link.send(frame(command(self.opcodes[name], arguments)))

    def pump(self, seconds: float) -> None:
        self.link.pump(lambda: False, seconds)
        self.qemu.read_until(lambda line: False, 0.001)

    def newest_packet(self) -> int:
        """The number of the newest downlink-load packet received (-1: none yet)."""
        return int(str(self.link.event_args.get(DOWNLINK_PACKET_EVENT, (-1,))[0]))

    def sweep_lines(self, axis: Axis, point: int) -> list[str]:
        prefix = f"KIT SWEEP axis={axis.name} point={point} "
        return [line for line in self.qemu.lines if line.startswith(prefix)]

    def measure(self, axis: Axis, point: int, level: int, rate: float, traffic: PointTraffic,
                unload: bytes = b"") -> list[str]:
        """Request a segment and keep the uplink at `rate` cmd/s until its
        SWEEP lines are printed; then send `unload` (the command that takes
        the downlink load off) and wait for what is still on its way down."""
        console_before = len(self.qemu.lines)
        answered_before = self.link.events[NOOP_EVENT]
        dropped_before = int(self.link.telemetry.get(DROPPED_CHANNEL, 0))
        started = self.link.now
        # The request is a command like the load's, and the link drops
        # commands beyond its limit in flight (LinkHealth): the uplink pauses
        # just before it, and it is sent again if no segment followed
        request_at = started + SETTLE_S
        deadline = time.monotonic() + REPLY_TIMEOUT_S + SEGMENT_TICKS / 1000
        while len(self.sweep_lines(axis, point)) < 3:
            if time.monotonic() > deadline:
                raise KitError(f"no SWEEP lines for {axis.name} point {point}:\n"
                               f"{runner.halt_lines(self.qemu.lines) or self.qemu.text()[-2000:]}")
            now = self.link.now
            due = int(rate * (now - started)) - traffic.commands_sent
            if due > 0 and not request_at - REQUEST_QUIET_S <= now < request_at:
                sending = min(due, BURST_MAX)
                self.link.send(self.noop * sending)
                traffic.commands_sent += sending
            if now >= request_at:
                self.send("Kit.timing.MEASURE_SEGMENT",
                          SEGMENT_ARGUMENTS.pack(axis.code, point, level, SEGMENT_TICKS))
                traffic.requests += 1
                request_at = now + SEGMENT_TICKS / 1000 + REQUEST_RETRY_S
            self.pump(0.005)
        if unload:
            self.link.send(unload)
        # Answers still on their way down; a lost one (the events queue
        # dropped it) shows as fewer answers than commands in the record
        expected = answered_before + traffic.commands_sent
        last = self.link.now
        self.link.pump(lambda: self.link.events[NOOP_EVENT] >= expected or self.link.now - last > SETTLE_S,
                       REPLY_TIMEOUT_S)
        traffic.noops_answered = self.link.events[NOOP_EVENT] - answered_before
        # LinkHealth writes its counts every 100 ms, changed or not: a sample
        # taken SETTLE_S after the last answer is settled, even if a full
        # downlink queue dropped earlier ones
        settled = self.link.now + SETTLE_S
        if not self.link.pump(lambda: self.link.telemetry_time.get(DROPPED_CHANNEL, 0.0) >= settled,
                              REPLY_TIMEOUT_S):
            raise KitError(f"no {DROPPED_CHANNEL} telemetry after {axis.name} point {point}:\n"
                           f"{runner.halt_lines(self.qemu.lines)}")
        # The link drops commands beyond its limit in flight; a dropped
        # segment request was sent again and is not the point's
        dropped = int(self.link.telemetry[DROPPED_CHANNEL]) - dropped_before - (traffic.requests - 1)
        traffic.commands_dispatched = traffic.commands_sent - dropped
        self.qemu.read_until(lambda line: False, 0.001)
        traffic.receive_overruns = sum(RECEIVE_OVERRUN in line for line in self.qemu.lines[console_before:])
        return self.sweep_lines(axis, point)


def run(build: Path) -> Outcome:
    """Boot a ground build and sweep both axes on its link."""
    link_info = ground.link_of(build)
    data = json.loads(link_info.dictionary.read_text())
    opcodes = {c["name"]: c["opcode"] for c in data["commands"]}
    outcome = Outcome()
    with ground.boot(link_info) as qemu:
        link = Downlink(link_info.socket, link_info.dictionary)
        try:
            driver = Driver(qemu, link, opcodes)
            # The deployment's clock reaches the host with its first telemetry
            if not link.pump(lambda: link.now > 0, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: no downlink within {REPLY_TIMEOUT_S:.0f} s")
            for point, level in enumerate(UPLINK.levels):
                traffic = PointTraffic(UPLINK.name, point, level)
                outcome.lines += driver.measure(UPLINK, point, level, float(level), traffic)
                outcome.traffic.append(traffic)
            # The dispatcher runs commands in order: the new level is set
            # before the segment is requested (no wait for its event, which a
            # flooded events queue may drop)
            unload = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(0)))
            for point, level in enumerate(DOWNLINK.levels):
                traffic = PointTraffic(DOWNLINK.name, point, level)
                received_before = link.events[DOWNLINK_PACKET_EVENT]
                newest_before = driver.newest_packet()
                driver.send("Kit.load.SET_DOWNLINK", U32.pack(level // SLICE_HZ))
                outcome.lines += driver.measure(DOWNLINK, point, level, 0.0, traffic, unload=unload)
                traffic.packets_received = link.events[DOWNLINK_PACKET_EVENT] - received_before
                # Packets are numbered: those between the newest before the
                # point and the newest after it that never arrived were lost
                traffic.packets_lost = driver.newest_packet() - newest_before - traffic.packets_received
                outcome.traffic.append(traffic)
            outcome.events = dict(sorted(link.events.items()))
            outcome.telemetry = dict(sorted(link.telemetry.items()))
        except KitError as error:
            # What the deployment said before it stopped answering
            raise KitError(f"{error}\nevents: {dict(sorted(link.events.items()))}\n"
                           f"telemetry: {dict(sorted(link.telemetry.items()))}") from None
        finally:
            link.close()
    return outcome
