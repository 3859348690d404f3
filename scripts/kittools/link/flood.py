# SPDX-License-Identifier: Apache-2.0
"""The flood: a babbling line at its full rate, then the ground's commands.

A build of the ground scenario under QEMU gets FLOOD_S seconds of its own
time of noise (bytes that frame nothing) at the link's full line rate,
carried at the line rate of its clock as the downlink shows it, in real
time (kittools.link.client.Line),
while it measures that stretch as one segment (Timing.MEASURE_SEGMENT: its
SWEEP lines give each rate group's slips and latencies under the flood).
Then FLOOD_NOOPS NO_OPs, each sent when the one before is answered.

It passes when nothing asserted or halted, every NO_OP after the flood was
answered, and every byte sent is accounted for, from LinkHealth's counts:
read by the UART's receive interrupt (QEMU's UART holds back what it cannot
take, so nothing is lost before it), then either dropped by the UART
driver's ring or decided on by the frame detector (whole frames, discarded
bytes, bad checksums, oversized lengths). The slips are a result, not a
failure: the report shows them per model.
"""

from __future__ import annotations

import functools
import random
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from kittools.build import runner
from kittools.link import ground
from kittools.link.client import (
    CONSOLE_PEEK_S,
    LINE_STEP_S,
    Downlink,
    Line,
    Stopwatch,
    command,
    frame,
    line_rate,
    noise,
)
from kittools.link.dictionary import Dictionary
from kittools.link.fuzz import answered
from kittools.link.health import HEARTBEAT_CHANNEL, REPLY_TIMEOUT_S, LinkCounts, settled_counts
from kittools.link.serial_points import NOISE, REQUEST_QUIET_S, SEGMENT_ARGUMENTS, SETTLE_S, SegmentClock
from kittools.workspace import KitError

#: The deployment's seconds of noise at the full line rate
FLOOD_S = 10
#: NO_OPs after the flood, each one answered before the next
FLOOD_NOOPS = 20
FLOOD_SEED = 20261204
# The flood's segment, numbered apart from the sweep's points
FLOOD_POINT = 9000
# A NO_OP after the flood unanswered this long (the host's seconds: the
# deployment has drained the flood) is lost; after MISSED_ANSWERS_MAX of
# them the flood has failed and stops sending
NOOP_TIMEOUT_S = 10.0
MISSED_ANSWERS_MAX = 3
# The host's bound on the flood (virtual time runs slower than the host's
# when the deployment is busy; far slower than this is a stuck QEMU)
FLOOD_HOST_TIMEOUT_S = 300.0


@dataclass
class Outcome:
    baud: int = 0
    seconds: float = 0.0  # of the deployment's time the noise lasted
    #: What the UART read a second during the flood, by LinkHealth's
    #: samples: QEMU hands the firmware host bytes only as fast as its
    #: emulated UART and main loop go, which can be below the line rate
    received_per_s: float = 0.0
    bytes_sent: int = 0
    noops_sent: int = 0
    noops_answered: int = 0
    #: LinkHealth's counts over the flood and the NO_OPs after it
    counts: LinkCounts = field(default_factory=LinkCounts)
    #: ... over the flood alone (what the noise cost, before the NO_OPs)
    flood_counts: LinkCounts = field(default_factory=LinkCounts)
    #: The frames' sizes: the segment request's and a NO_OP's (the frame
    #: detector takes a detected frame whole: the request, then NO_OPs)
    request_bytes: int = 0
    noop_bytes: int = 0
    sweep_lines: list[str] = field(default_factory=list)
    halt: str = ""

    def frame_bytes(self) -> int:
        """Bytes of the frames the detector took whole: the request, then NO_OPs."""
        frames = self.counts.frames_detected
        return self.request_bytes + self.noop_bytes * (frames - 1) if frames > 0 else 0

    def unaccounted(self) -> int:
        """Bytes the ring kept that the frame detector did not decide on
        (with every NO_OP answered, nothing is left pending: 0)."""
        c = self.counts
        kept = c.uart_received - c.ring_drops
        return kept - (self.frame_bytes() + c.bytes_discarded + c.bad_checksums + c.oversized)

    def failures(self) -> list[str]:
        found = []
        if self.halt:
            found.append(f"the deployment asserted or halted:\n{self.halt}")
        if self.noops_answered != self.noops_sent:
            found.append(f"{self.noops_answered} of {self.noops_sent} NO_OPs after the flood answered")
        if self.counts.uart_received != self.bytes_sent:
            found.append(f"the UART read {self.counts.uart_received} bytes of the {self.bytes_sent} sent "
                         f"(receive errors: {self.counts.uart_errors})")
        # A NO_OP never answered may leave its bytes pending in the
        # accumulator (counted as failed above); more decided than kept never
        if self.unaccounted() < 0 or (self.unaccounted() != 0 and self.noops_answered == self.noops_sent):
            found.append(f"{self.unaccounted()} bytes the UART driver kept were not decided on by the frame "
                         f"detector (counts {asdict(self.counts)}, {self.frame_bytes()} bytes of whole frames)")
        if len(self.sweep_lines) < 3:
            found.append("the flood's segment printed no SWEEP lines")
        return found

    def record(self) -> str:
        """The flood as a console-style FLOOD record."""
        c = self.counts
        return (f"KIT FLOOD baud={self.baud} seconds={self.seconds:.2f} received_per_s={self.received_per_s:.0f} "
                f"bytes_sent={self.bytes_sent} "
                f"uart_received={c.uart_received} ring_drops={c.ring_drops} uart_errors={c.uart_errors} "
                f"discarded={c.bytes_discarded} bad_checksums={c.bad_checksums} oversized={c.oversized} "
                f"frame_bytes={self.frame_bytes()} unaccounted={self.unaccounted()} "
                f"noops_sent={self.noops_sent} noops_answered={self.noops_answered}")

    def to_json(self) -> dict[str, Any]:
        # The segment's SWEEP lines, renamed FLOODRG so that no sweep reads
        # them as a point of the noise axis
        lines = [line.replace("KIT SWEEP ", "KIT FLOODRG ", 1) for line in self.sweep_lines]
        return {"lines": [self.record(), *lines], "counts": asdict(self.counts),
                "flood_counts": asdict(self.flood_counts), "failures": self.failures()}


def run(build: Path) -> Outcome:
    """Boot a ground build, flood its link and account for every byte."""
    link_info = ground.link_of(build)
    names = Dictionary.read(link_info.dictionary)
    opcodes = names.opcodes
    noop = frame(command(names.noop_opcode))
    outcome = Outcome()
    # In real time: the line's writes stay small and even (client.Line)
    with ground.boot(link_info, realtime=True) as qemu:
        outcome.baud = line_rate(ground.link_line(qemu))
        link = Downlink(link_info.socket, link_info.dictionary)
        try:
            if not link.pump(lambda: link.now > 0, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: no downlink within {REPLY_TIMEOUT_S:.0f} s")
            before = settled_counts(link, link.now + SETTLE_S, "boot")
            _flood(link, qemu, opcodes, outcome)
            # Every byte of the flood read by the UART (QEMU may still be
            # handing it over after the noise stopped), then the UART
            # driver's ring drained, before the NO_OPs: REQUEST_QUIET_S of
            # the deployment's time past the sample that showed them read
            # (measured from that sample: each new one moves the heartbeat's
            # time, and a wait on the newest never ended but by time-out,
            # 30 s of every flood)
            settled = settled_counts(link, link.now + SETTLE_S, "the noise")
            quiet_until = link.telemetry_time[HEARTBEAT_CHANNEL] + REQUEST_QUIET_S
            if not link.pump(lambda: link.now >= quiet_until, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: the deployment's clock did not move {REQUEST_QUIET_S} s past the flood "
                               f"in {REPLY_TIMEOUT_S:.0f} s")
            outcome.noop_bytes = len(noop)
            missed = 0
            for _ in range(FLOOD_NOOPS):
                link.send(noop)
                outcome.noops_sent += 1
                outcome.bytes_sent += len(noop)
                if not link.pump(functools.partial(answered, link, outcome.noops_sent), NOOP_TIMEOUT_S):
                    missed += 1
                    if missed >= MISSED_ANSWERS_MAX:
                        break
            outcome.noops_answered = link.events[names.noop_event]
            outcome.flood_counts = settled.since(before)
            outcome.counts = settled_counts(link, link.now + SETTLE_S, "the flood").since(before)
        finally:
            link.close()
            qemu.read_until(lambda line: False, 0.001)
            outcome.halt = runner.halt_lines(qemu.lines)
    return outcome


def _flood(link: Downlink, qemu: runner.Qemu, opcodes: dict[str, int], outcome: Outcome) -> None:
    """Request the flood's segment on a quiet link, then noise at the full
    line rate until its SWEEP lines are printed."""
    clock = SegmentClock.of_console(qemu.lines)
    segment_ticks = clock.ticks(FLOOD_S)  # whole hyperperiods of the deployment's rate groups
    request = frame(command(opcodes["Kit.timing.MEASURE_SEGMENT"],
                            SEGMENT_ARGUMENTS.pack(NOISE.code, FLOOD_POINT, 100, segment_ticks)))
    link.send(request)
    outcome.bytes_sent += len(request)
    outcome.request_bytes = len(request)
    rng = random.Random(FLOOD_SEED)
    pacer = Stopwatch(link)  # the line paces the noise
    line = Line(link, outcome.baud)
    prefix = f"KIT SWEEP axis={NOISE.name} point={FLOOD_POINT} "
    # The segment is about FLOOD_S long and starts at the next hyperperiod
    # after the request: twice that without its lines is a deployment that
    # stopped (its clock, or the host's when its clock stops)
    flood_s = clock.seconds(clock.hyperperiod_ticks + segment_ticks)
    host_deadline = time.monotonic() + FLOOD_HOST_TIMEOUT_S
    samples: list[tuple[float, int]] = []  # (deployment time, bytes the UART read)
    while pacer.elapsed() < 2 * flood_s and time.monotonic() < host_deadline:
        outcome.sweep_lines = [line for line in qemu.lines if line.startswith(prefix)]
        if len(outcome.sweep_lines) >= 3 or runner.halt_lines(qemu.lines):
            break
        sampled = link.telemetry_time.get(HEARTBEAT_CHANNEL)
        if sampled is not None and (not samples or sampled > samples[-1][0]):
            samples.append((sampled, int(link.telemetry[HEARTBEAT_CHANNEL])))
        # The line kept full: what it carries is the full line rate
        if not line.waiting():
            line.put(noise(rng, line.burst))
        outcome.bytes_sent += line.feed()
        link.pump(lambda: False, LINE_STEP_S)
        qemu.read_until(lambda _: False, CONSOLE_PEEK_S)
    outcome.seconds = pacer.elapsed()
    # The rate over the segment's second half: its start is the request's and
    # the first bytes' way in
    half_segment_s = clock.seconds(segment_ticks) / 2
    settled = [s for s in samples if s[0] >= samples[-1][0] - half_segment_s] if samples else []
    if len(settled) >= 2 and settled[-1][0] > settled[0][0]:
        outcome.received_per_s = (settled[-1][1] - settled[0][1]) / (settled[-1][0] - settled[0][0])
