# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep's driver: one booted ground build, its link and
console, what every point of every axis does (kittools.link.serial_sweep):
the traffic offered while a segment is requested and measured, and what got
through."""

from __future__ import annotations

import math
import struct
import time
from collections.abc import Callable

from kittools.build import runner
from kittools.link.client import (
    CONSOLE_PEEK_S,
    LINE_STEP_S,
    Downlink,
    Line,
    Stopwatch,
    command,
    frame,
)
from kittools.link.health import REPLY_TIMEOUT_S, LinkCounts, settled_counts
from kittools.link.serial_points import (
    DOWNLINK,
    REQUEST_QUIET_S,
    SEGMENT_ARGUMENTS,
    SETTLE_S,
    Axis,
    Offer,
    PointTraffic,
    SegmentClock,
    traffic_time,
)
from kittools.link.services import string_argument
from kittools.workspace import KitError

DOWNLINK_PACKET_EVENT = "Kit.load.DownlinkLoadPacket"
# Written at every slice the load runs (no burst in the ground scenario):
# its count over the deployment's time is the slices' rate
SLICES_CHANNEL = "Kit.load.Processed"
SLICES_SAMPLE_S = 1.0
# The wait for a segment after a request, before it is sent again
REQUEST_RETRY_S = 1.0
U32 = struct.Struct(">I")
# The file axis: the bulk file is filled with the kit's pattern first
# (Load.FILL_FILE, asked for more than any bulk file holds; its FileFilled
# event says how much it took)
FILE_FILLED_EVENT = "Kit.load.FileFilled"
FILL_ASK_BYTES = 1 << 20
FILL_SEED = 20261205
# A play of the file axis ends when no file data has come down for this
# long in the deployment's time: longer than FileDownlink's pause between
# files and its Run period together (and a play of the sequence axis, short
# of every answer it asked for, when no answer has come for as long)
QUIET_S = 0.5


class Driver:
    """One booted ground build: bytes up its link, its console read for the records."""

    def __init__(self, qemu: runner.Qemu, link: Downlink, opcodes: dict[str, int], baud: int) -> None:
        self.qemu = qemu
        self.link = link
        self.baud = baud
        self.clock = SegmentClock.of_console(qemu.lines)
        self.opcodes = opcodes
        self.noop = frame(command(link.dictionary.noop_opcode))
        self.noop_event = link.dictionary.noop_event

    def offer(self, command_frame: bytes, commands_per_s: float, noise_per_s: float = 0.0, seed: int = 0) -> Offer:
        """A point's traffic, as long as this deployment's points last."""
        return Offer(command_frame, self.clock.point_s(), commands_per_s, noise_per_s, seed)

    def send(self, name: str, arguments: bytes = b"") -> None:
        self.link.send(frame(command(self.opcodes[name], arguments)))

    def fill_bulk_file(self, bulk: str) -> int:
        """Fill the bulk file with the kit's pattern; the bytes it holds."""
        filled = self.link.events[FILE_FILLED_EVENT]
        self.send("Kit.load.FILL_FILE", string_argument(bulk) + U32.pack(FILL_ASK_BYTES) + U32.pack(FILL_SEED))
        if not self.link.pump(lambda: self.link.events[FILE_FILLED_EVENT] > filled, REPLY_TIMEOUT_S):
            raise KitError(f"no {FILE_FILLED_EVENT} within {REPLY_TIMEOUT_S:.0f} s of Load.FILL_FILE {bulk}")
        return int(str(self.link.event_args[FILE_FILLED_EVENT][1]))

    def quiet(self, count: Callable[[], int], what: str, reached: int | None = None) -> None:
        """Read the downlink until `count` has reached `reached`, or has not
        moved for QUIET_S of the deployment's time (the file downlink has
        sent what it was asked, the sequencer has run what it was asked)."""
        last_count, last_change = count(), self.link.now

        def quiet() -> bool:
            nonlocal last_count, last_change
            if count() != last_count:
                last_count, last_change = count(), self.link.now
            return (reached is not None and last_count >= reached) or self.link.now - last_change > QUIET_S

        if not self.link.pump(quiet, REPLY_TIMEOUT_S):
            raise KitError(f"{what} {REPLY_TIMEOUT_S:.0f} s after a point")

    def slice_hz(self) -> int:
        """The load's slices a second over SLICES_SAMPLE_S of the
        deployment's idle time: the rate of the group that runs them (the
        deployment's choice), which a downlink level's packets per slice
        are set from. A count and its time tag are written together, so the
        rate is exact to a slice."""
        telemetry, times = self.link.telemetry, self.link.telemetry_time
        if not self.link.pump(lambda: SLICES_CHANNEL in telemetry, REPLY_TIMEOUT_S):
            raise KitError(f"no {SLICES_CHANNEL} on the downlink in {REPLY_TIMEOUT_S:.0f} s: "
                           "is it a kit build of this version?")
        count, at = int(telemetry[SLICES_CHANNEL]), times[SLICES_CHANNEL]
        if not self.link.pump(lambda: times[SLICES_CHANNEL] >= at + SLICES_SAMPLE_S, REPLY_TIMEOUT_S):
            raise KitError(f"{SLICES_CHANNEL} did not move on the downlink in {REPLY_TIMEOUT_S:.0f} s")
        return max(1, math.floor((int(telemetry[SLICES_CHANNEL]) - count) / (times[SLICES_CHANNEL] - at) + 0.5))

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
        answered_before = self.link.events[self.noop_event]
        before = LinkCounts.of(self.link)
        pacer = Stopwatch(self.link)  # the offer paces itself, the line carries it
        line = Line(self.link, self.baud)
        # The request is a command like the traffic's, and the link loses
        # commands beyond its limits (LinkHealth's in-flight limit, the UART's
        # ring): the traffic pauses just before it, and it is sent again if
        # no segment followed
        request_at = SETTLE_S
        segment_ticks = self.clock.segment_ticks()
        # The segment starts at the next hyperperiod after its request
        segment_s = self.clock.seconds(self.clock.hyperperiod_ticks + segment_ticks)
        deadline = time.monotonic() + REPLY_TIMEOUT_S + segment_s
        while len(self.sweep_lines(axis, traffic.point)) < 3 or not offer.complete() or line.waiting():
            if time.monotonic() > deadline:
                raise KitError(f"no SWEEP lines for {axis.name} point {traffic.point}:\n"
                               f"{runner.halt_lines(self.qemu.lines) or self.qemu.text()[-2000:]}")
            elapsed = pacer.elapsed()
            if not request_at - REQUEST_QUIET_S <= elapsed < request_at:
                data = offer.due(traffic_time(elapsed), traffic)
                line.put(data)
                traffic.bytes_sent += len(data)
            line.feed()
            # Again only while no segment followed (a slow host's point outlasts the retry time)
            if elapsed >= request_at and not self.sweep_lines(axis, traffic.point):
                request = frame(command(self.opcodes["Kit.timing.MEASURE_SEGMENT"],
                                        SEGMENT_ARGUMENTS.pack(axis.code, traffic.point, traffic.level,
                                                               segment_ticks)))
                # On the line behind what it carries (a frame the line has
                # split must not be cut by another)
                line.put(request)
                traffic.bytes_sent += len(request)
                traffic.requests += 1
                request_at = elapsed + segment_s + REQUEST_RETRY_S
            self.link.pump(lambda: False, LINE_STEP_S)
            self.qemu.read_until(lambda _: False, CONSOLE_PEEK_S)
        if unload:
            self.link.send(unload)
            traffic.bytes_sent += len(unload)
        # Answers still on their way down; a lost one (the events queue
        # dropped it) shows as fewer answers than commands
        expected = answered_before + traffic.commands_sent
        last = self.link.now
        self.link.pump(lambda: self.link.events[self.noop_event] >= expected or self.link.now - last > SETTLE_S,
                       REPLY_TIMEOUT_S)
        traffic.noops_answered = self.link.events[self.noop_event] - answered_before
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
