# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep: what traffic on the ground link costs the rate groups.

Three axes, each driven from outside through the real link (a build of the
ground scenario under QEMU, kittools.link.client on its socket), all paced
by the deployment's own clock as the downlink shows it (QEMU's virtual time
is not the host's), at the link's line rate (the LINK line's baud: the link
UART's devicetree current-speed):

  uplink    NO_OP commands at a steady rate (cmd/s), up to a full line;
  downlink  extra downlink packets (pkt/s): Load.SET_DOWNLINK events from
            every 100 Hz slice, framed and written to the link UART by the
            deployment, read and counted by the host;
  noise     random bytes that frame nothing, at a share (%) of what the
            line carries beside NOISE_NOOP_RATE valid NO_OPs a second among
            them: a noisy or babbling line.

At each level the deployment measures a segment on request
(Timing.MEASURE_SEGMENT) and prints one SWEEP line per rate group, the
record the load scenario writes for its axes; breaking points come from them
as for those axes (kittools.sweep). Every level is played REPEATS times: the
host's bytes reach QEMU at host-timed moments, so a serial point's latencies
differ from run to run (the report gives their median and spread); what it
delivered, and where a group breaks, do not. The host adds what only it
sees: what it sent and what came back, and LinkHealth's counts of where
every byte went (received by the UART, dropped by its ring, discarded by the
frame detector).
"""

from __future__ import annotations

import json
import random
import struct
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from kittools import console, sweep
from kittools.build import runner
from kittools.link import ground
from kittools.link.client import Downlink, Pacer, bytes_per_second, command, frame, line_rate, noise
from kittools.workspace import KitError


@dataclass(frozen=True)
class Axis:
    name: str  # as the SWEEP lines name it (app/scenarios/ground.cpp)
    code: int  # Kit.SegmentAxis
    unit: str
    levels: tuple[int, ...]


# The uplink's levels below a full line (that level, full_line_commands(),
# depends on the line rate). fprime-zephyr's UART driver takes at most 64
# bytes per 100 Hz poll, 355 NO_OP frames (18 B) a second: above that its
# receive ring overflows, counted (LinkHealth.UartRingDrops). The downlink's
# ceiling is the load's: at most Load.DOWNLINK_MAX (16) packets per 100 Hz
# slice. Noise: percent of the line rate.
UPLINK = Axis("uplink", 0, "cmd/s", (0, 50, 100, 200, 300))
DOWNLINK = Axis("downlink", 1, "pkt/s", (0, 100, 200, 400, 800, 1600))
NOISE = Axis("noise", 2, "%", (0, 25, 50, 75, 100))
AXES = (UPLINK, DOWNLINK, NOISE)
#: Each level is played this many times (latencies as median and spread)
REPEATS = 3
SLICE_HZ = 100  # Load's slices per second: a downlink level is packets per slice times this
# One second of measurement per point (ten hyperperiods)
SEGMENT_TICKS = 1000
# The deployment's seconds a new level runs before its segment is requested
SETTLE_S = 0.3
REPLY_TIMEOUT_S = 30.0
NOOP_EVENT = "Kit.cmdDisp.NoOpReceived"
DOWNLINK_PACKET_EVENT = "Kit.load.DownlinkLoadPacket"
# Valid NO_OPs a second among the noise: what a noisy line still delivers.
# Enough of them (48 a point) that a level where the ring drops bytes loses
# one in every repeat: that level is the noise axis' delivery breaking point
NOISE_NOOP_RATE = 40
# The uplink's pause before a segment request: the UART driver's receive
# ring (1,024 bytes, drained 64 per 100 Hz poll) empties in 160 ms, so the
# request is not lost behind a full ring; and the wait for a segment after one
REQUEST_QUIET_S = 0.2
REQUEST_RETRY_S = 1.0
# Most bytes written at once (a burst is the pacer's, not the socket's)
WRITE_MAX = 256
# Seed of the noise (each point its own stream from it)
NOISE_SEED = 20261203
U32 = struct.Struct(">I")
SEGMENT_ARGUMENTS = struct.Struct(">iIII")  # SegmentAxis (I32), point, level, ticks


def full_line_commands(baud: int, noop_frame: bytes) -> int:
    """NO_OPs a second that fill the line."""
    return int(bytes_per_second(baud)) // len(noop_frame)


def noise_per_second(baud: int, noop_frame: bytes, level: int) -> float:
    """Noise bytes a second at a noise level: `level` percent of what the
    line carries beside the axis' NO_OPs (at 100 %, NO_OPs and noise fill it)."""
    return (bytes_per_second(baud) - NOISE_NOOP_RATE * len(noop_frame)) * level / 100


@dataclass(frozen=True)
class LinkCounts:
    """LinkHealth's counts, as its newest telemetry says (kittools reads
    deltas of them around a point or a flood)."""

    frames_detected: int = 0
    commands_dropped: int = 0
    uart_received: int = 0
    ring_drops: int = 0
    bytes_discarded: int = 0
    bad_checksums: int = 0
    oversized: int = 0
    #: The UART's receive errors, all kinds (written on change: none sent is none)
    uart_errors: int = 0

    CHANNELS = {"frames_detected": "FramesDetected", "commands_dropped": "CommandsDropped",
                "uart_received": "UartBytesReceived", "ring_drops": "UartRingDrops",
                "bytes_discarded": "BytesDiscarded", "bad_checksums": "BadChecksums", "oversized": "Oversized"}
    ERROR_CHANNELS = ("UartOverruns", "UartParityErrors", "UartFramingErrors", "UartBreaks")

    @staticmethod
    def of(link: Downlink) -> LinkCounts:
        values = {key: int(link.telemetry.get(f"Kit.linkHealth.{name}", 0))
                  for key, name in LinkCounts.CHANNELS.items()}
        errors = sum(int(link.telemetry.get(f"Kit.linkHealth.{name}", 0)) for name in LinkCounts.ERROR_CHANNELS)
        return LinkCounts(**values, uart_errors=errors)

    def since(self, before: LinkCounts) -> LinkCounts:
        return LinkCounts(**{key: getattr(self, key) - getattr(before, key)
                             for key in (*LinkCounts.CHANNELS, "uart_errors")})

    def positions(self, frame_size: int) -> int:
        """Byte positions the frame detector decided on: whole frames of
        `frame_size`, and one position per other decision."""
        return self.frames_detected * frame_size + self.bytes_discarded + self.bad_checksums + self.oversized


# LinkHealth writes its counts every 100 ms, changed or not
HEARTBEAT_CHANNEL = "Kit.linkHealth.UartBytesReceived"


def settled_counts(link: Downlink, after: float, what: str) -> LinkCounts:
    """LinkHealth's counts from a sample taken at least `after` (the
    deployment's time) that shows every byte this client sent read by the
    UART: QEMU takes host bytes only as fast as the firmware reads its UART,
    so some may still be on their way after the traffic stopped. The client
    is the link's only writer since boot (the UART counts from boot)."""
    def settled() -> bool:
        return (link.telemetry_time.get(HEARTBEAT_CHANNEL, 0.0) >= after and link.unsent() == 0
                and int(link.telemetry.get(HEARTBEAT_CHANNEL, 0)) >= link.bytes_sent)

    if not link.pump(settled, REPLY_TIMEOUT_S):
        raise KitError(f"no settled {HEARTBEAT_CHANNEL} telemetry after {what} (read "
                       f"{link.telemetry.get(HEARTBEAT_CHANNEL)} of {link.bytes_sent} bytes sent, "
                       f"{link.unsent()} not taken by the link)")
    return LinkCounts.of(link)


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

    def offered(self) -> int:
        return self.packets_received + self.packets_lost if self.axis == DOWNLINK.name else self.commands_sent

    def delivered(self) -> int:
        return self.packets_received if self.axis == DOWNLINK.name else self.commands_dispatched

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

    def to_json(self) -> dict[str, Any]:
        return {"lines": self.lines + [t.record() for t in self.traffic],
                "traffic": [asdict(t) for t in self.traffic], "events": self.events,
                "telemetry": self.telemetry}

    def sweep(self) -> sweep.Sweep | None:
        return sweep.of_records([{"kind": r.kind, **r.fields} for r in _records(self.lines)])


def _records(lines: list[str]) -> list[console.Record]:
    return [r for line in lines if (r := console.parse_line(line)) is not None]


def records_of(path: Path) -> list[console.Record]:
    """The records of a ground-link file (serial.json, flood.json: their "lines")."""
    return _records(json.loads(path.read_text())["lines"])


#: How long a point's traffic lasts, in the deployment's time: the settling
#: before the request (less the quiet before it), the hyperperiod the
#: deployment waits after it, and the segment. A fixed amount of traffic per
#: point, whatever the host's timing: what each level offers is the same in
#: every run.
HYPERPERIOD_S = 0.1
POINT_S = SETTLE_S - REQUEST_QUIET_S + HYPERPERIOD_S + SEGMENT_TICKS / 1000


def traffic_time(elapsed: float) -> float:
    """A point's traffic time at `elapsed`: the quiet before the request
    does not count (its traffic is not sent later in a burst: it is not sent)."""
    quiet_from = SETTLE_S - REQUEST_QUIET_S
    return elapsed - min(max(elapsed - quiet_from, 0.0), REQUEST_QUIET_S)


class Offer:
    """A point's traffic: NO_OPs at `commands_per_s`, and noise (bytes that
    frame nothing) at `noise_per_s` with its NO_OPs among it, for POINT_S of
    the deployment's time."""

    def __init__(self, noop: bytes, commands_per_s: float, noise_per_s: float = 0.0, seed: int = 0) -> None:
        self.noop = noop
        self.commands = int(commands_per_s * POINT_S)
        self.commands_per_s = commands_per_s
        self.noise = int(noise_per_s * POINT_S)
        self.noise_per_s = noise_per_s
        self.noise_sent = 0
        self._rng = random.Random(seed)

    def due(self, elapsed: float, traffic: PointTraffic) -> bytes:
        """The bytes due after `elapsed` seconds (the traffic's counts brought up to date)."""
        commands = max(0, min(int(self.commands_per_s * elapsed), self.commands) - traffic.commands_sent)
        commands = min(commands, WRITE_MAX // len(self.noop))
        traffic.commands_sent += commands
        data = self.noop * commands
        count = max(0, min(int(self.noise_per_s * elapsed), self.noise) - self.noise_sent)
        count = min(count, WRITE_MAX)
        self.noise_sent += count
        return data + noise(self._rng, count)

    def complete(self, traffic: PointTraffic) -> bool:
        return traffic.commands_sent >= self.commands and self.noise_sent >= self.noise


class Driver:
    """One booted ground build: bytes up its link, its console read for the records."""

    def __init__(self, qemu: runner.Qemu, link: Downlink, opcodes: dict[str, int]) -> None:
        self.qemu = qemu
        self.link = link
        self.opcodes = opcodes
        self.noop = frame(command(opcodes["Kit.cmdDisp.CMD_NO_OP"]))

    def send(self, name: str, arguments: bytes = b"") -> None:
        self.link.send(frame(command(self.opcodes[name], arguments)))

    def newest_packet(self) -> int:
        """The number of the newest downlink-load packet received (-1: none yet)."""
        return int(str(self.link.event_args.get(DOWNLINK_PACKET_EVENT, (-1,))[0]))

    def sweep_lines(self, axis: Axis, point: int) -> list[str]:
        prefix = f"KIT SWEEP axis={axis.name} point={point} "
        return [line for line in self.qemu.lines if line.startswith(prefix)]

    def measure(self, axis: Axis, traffic: PointTraffic, offer: Offer, unload: bytes = b"") -> list[str]:
        """Request a segment and keep up the offered traffic until its SWEEP
        lines are printed; then send `unload` (the command that takes the
        downlink load off) and account for what got through."""
        answered_before = self.link.events[NOOP_EVENT]
        before = LinkCounts.of(self.link)
        pacer = Pacer(self.link, 1.0)  # its clock only: the offer paces itself
        # The request is a command like the traffic's, and the link loses
        # commands beyond its limits (LinkHealth's in-flight limit, the UART's
        # ring): the traffic pauses just before it, and it is sent again if
        # no segment followed
        request_at = SETTLE_S
        deadline = time.monotonic() + REPLY_TIMEOUT_S + SEGMENT_TICKS / 1000
        while len(self.sweep_lines(axis, traffic.point)) < 3 or not offer.complete(traffic):
            if time.monotonic() > deadline:
                raise KitError(f"no SWEEP lines for {axis.name} point {traffic.point}:\n"
                               f"{runner.halt_lines(self.qemu.lines) or self.qemu.text()[-2000:]}")
            elapsed = pacer.elapsed()
            if not request_at - REQUEST_QUIET_S <= elapsed < request_at:
                data = offer.due(traffic_time(elapsed), traffic)
                if data:
                    self.link.send(data)
                    traffic.bytes_sent += len(data)
            if elapsed >= request_at:
                request = frame(command(self.opcodes["Kit.timing.MEASURE_SEGMENT"],
                                        SEGMENT_ARGUMENTS.pack(axis.code, traffic.point, traffic.level,
                                                               SEGMENT_TICKS)))
                self.link.send(request)
                traffic.bytes_sent += len(request)
                traffic.requests += 1
                request_at = elapsed + SEGMENT_TICKS / 1000 + REQUEST_RETRY_S
            self.link.pump(lambda: False, 0.005)
            self.qemu.read_until(lambda line: False, 0.001)
        if unload:
            self.link.send(unload)
            traffic.bytes_sent += len(unload)
        # Answers still on their way down; a lost one (the events queue
        # dropped it) shows as fewer answers than commands
        expected = answered_before + traffic.commands_sent
        last = self.link.now
        self.link.pump(lambda: self.link.events[NOOP_EVENT] >= expected or self.link.now - last > SETTLE_S,
                       REPLY_TIMEOUT_S)
        traffic.noops_answered = self.link.events[NOOP_EVENT] - answered_before
        # LinkHealth writes its counts every 100 ms, changed or not: a sample
        # taken SETTLE_S after the last answer is settled (the ring drained)
        counts = settled_counts(self.link, self.link.now + SETTLE_S,
                                f"{axis.name} point {traffic.point}:\n{runner.halt_lines(self.qemu.lines)}")
        got = counts.since(before)
        # Every frame detected went to the dispatcher but those LinkHealth
        # dropped (in flight beyond its limit) and the one segment request
        # that was measured; requests lost or dropped on the way count in
        # neither. (The downlink axis delivers packets, counted by the host.)
        if axis is not DOWNLINK:
            traffic.commands_dispatched = got.frames_detected - got.commands_dropped - 1
        traffic.uart_received = got.uart_received
        traffic.ring_drops = got.ring_drops
        traffic.uart_errors = got.uart_errors
        self.qemu.read_until(lambda line: False, 0.001)
        return self.sweep_lines(axis, traffic.point)


def run(build: Path, repeats: int = REPEATS) -> Outcome:
    """Boot a ground build and sweep every axis on its link, each level `repeats` times."""
    link_info = ground.link_of(build)
    data = json.loads(link_info.dictionary.read_text())
    opcodes = {c["name"]: c["opcode"] for c in data["commands"]}
    outcome = Outcome()
    with ground.boot(link_info) as qemu:
        baud = line_rate(ground.link_line(qemu))
        outcome.lines.append(f"KIT LINE baud={baud} bytes_per_s={int(bytes_per_second(baud))}")
        link = Downlink(link_info.socket, link_info.dictionary)
        try:
            driver = Driver(qemu, link, opcodes)
            # The deployment's clock reaches the host with its first telemetry
            if not link.pump(lambda: link.now > 0, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: no downlink within {REPLY_TIMEOUT_S:.0f} s")
            points = iter(range(1 << 30))
            uplink_levels = (*UPLINK.levels, full_line_commands(baud, driver.noop))
            for level in uplink_levels:
                for repeat in range(repeats):
                    traffic = PointTraffic(UPLINK.name, next(points), level, repeat)
                    outcome.lines += driver.measure(UPLINK, traffic, Offer(driver.noop, float(level)))
                    outcome.traffic.append(traffic)
            # The dispatcher runs commands in order: the new level is set
            # before the segment is requested (no wait for its event, which a
            # flooded events queue may drop)
            unload = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(0)))
            for level in DOWNLINK.levels:
                for repeat in range(repeats):
                    traffic = PointTraffic(DOWNLINK.name, next(points), level, repeat)
                    received_before = link.events[DOWNLINK_PACKET_EVENT]
                    newest_before = driver.newest_packet()
                    load = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(level // SLICE_HZ)))
                    link.send(load)
                    traffic.bytes_sent += len(load)
                    outcome.lines += driver.measure(DOWNLINK, traffic, Offer(driver.noop, 0.0), unload)
                    traffic.packets_received = link.events[DOWNLINK_PACKET_EVENT] - received_before
                    # Packets are numbered: those between the newest before the
                    # point and the newest after it that never arrived were lost
                    traffic.packets_lost = driver.newest_packet() - newest_before - traffic.packets_received
                    outcome.traffic.append(traffic)
            for level in NOISE.levels:
                for repeat in range(repeats):
                    traffic = PointTraffic(NOISE.name, next(points), level, repeat)
                    offer = Offer(driver.noop, NOISE_NOOP_RATE, noise_per_second(baud, driver.noop, level),
                                  NOISE_SEED + traffic.point)
                    outcome.lines += driver.measure(NOISE, traffic, offer)
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
