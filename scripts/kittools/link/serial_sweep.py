# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep: what traffic on the ground link costs the rate groups.

Four axes, each driven from outside through the real link (a build of the
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
  file      file data down (B/s), where the build has F´'s file downlink:
            the bulk file filled with the kit's pattern, then parts of it
            asked for with FileDownlink's SendPartial at a steady rate, up
            to a full line; what came down is the data bytes of the file
            packets the host received (every play waits until the downlink
            has gone quiet, so nothing spills into the next).

At each level the deployment measures a segment on request
(Timing.MEASURE_SEGMENT) and prints one SWEEP line per rate group, the
record the load scenario writes for its axes; breaking points come from them
as for those axes (kittools.sweep). Every level is played REPEATS times: the
host's bytes reach QEMU at host-timed moments, so a serial point's latencies
differ from run to run (the report gives their median and spread), as do
the commands lost past the link's delivery breaking point; the breaking
points, taken from the median play, do not. The bytes go up a client.Line
at the line rate, in real time (docs/ground.md says why). The host adds what only it
sees: what it sent and what came back, and LinkHealth's counts of where
every byte went (received by the UART, dropped by its ring, discarded by the
frame detector).

This module plays the sweep on a booted build (Driver, run); its plan (the
axes, levels and each point's traffic, the outcome and its records) is
kittools.link.serial_points, LinkHealth's counts kittools.link.health.
"""

from __future__ import annotations

import math
import struct
import time
from pathlib import Path

from kittools.build import runner
from kittools.link import ground
from kittools.link.client import (
    CONSOLE_PEEK_S,
    LINE_STEP_S,
    Downlink,
    Line,
    Stopwatch,
    bytes_per_second,
    command,
    frame,
    line_rate,
)
from kittools.link.dictionary import Dictionary
from kittools.link.health import REPLY_TIMEOUT_S, LinkCounts, settled_counts
from kittools.link.serial_points import (
    DOWNLINK,
    FILE,
    NOISE,
    NOISE_NOOP_RATE,
    NOISE_SEED,
    REPEATS,
    REQUEST_QUIET_S,
    SEGMENT_ARGUMENTS,
    SETTLE_S,
    UPLINK,
    Axis,
    Offer,
    Outcome,
    PointTraffic,
    SegmentClock,
    downlink_levels,
    file_request,
    full_line_commands,
    noise_per_second,
    traffic_time,
)
from kittools.workspace import KitError

DOWNLINK_PACKET_EVENT = "Kit.load.DownlinkLoadPacket"
# Written at every slice the load runs (no burst in the ground scenario):
# its count over the deployment's time is the slices' rate
SLICES_CHANNEL = "Kit.load.Processed"
SLICES_SAMPLE_S = 1.0
# The wait for a segment after a request, before it is sent again
REQUEST_RETRY_S = 1.0
U32 = struct.Struct(">I")
# The file axis: the bulk file (Kit.RamFs.bulkFile) is filled with the
# kit's pattern first (Load.FILL_FILE, asked for more than any bulk file
# holds; its FileFilled event says how much it took)
BULK_FILE_CONSTANT = "Kit.RamFs.bulkFile"
FILE_FILLED_EVENT = "Kit.load.FileFilled"
FILL_ASK_BYTES = 1 << 20
FILL_SEED = 20261205
# The ground's name for what the file axis downlinks (fprime-gds is not on
# the link during the sweep: nothing writes it)
SWEEP_FILE_DESTINATION = "kit-sweep.bin"
# A play of the file axis ends when no file data has come down for this
# long in the deployment's time: longer than FileDownlink's pause between
# files and its Run period together
FILE_QUIET_S = 0.5


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

    def file_quiet(self) -> None:
        """Read the downlink until no file data has come for FILE_QUIET_S
        of the deployment's time (the file downlink has sent what it was asked)."""
        last_bytes, last_change = self.link.file_bytes, self.link.now

        def quiet() -> bool:
            nonlocal last_bytes, last_change
            if self.link.file_bytes != last_bytes:
                last_bytes, last_change = self.link.file_bytes, self.link.now
            return self.link.now - last_change > FILE_QUIET_S

        if not self.link.pump(quiet, REPLY_TIMEOUT_S):
            raise KitError(f"the file downlink was still sending {REPLY_TIMEOUT_S:.0f} s after a file point")

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


# F´'s EventManager asserts when a health ping finds its queue full (its
# pingIn is an asserting async port; its LogRecv drops what a full queue
# cannot take). The downlink axis floods that queue by design, and on the
# models that serve one message per task per tick (baremetal, its budgeted
# policy) the ping then stopped the deployment (qemu_cortex_m3, 2026-12-04:
# EventManagerComponentAc.cpp's queue-full assert in the axis' first play of
# point 33, both models). So, as an operator would before flooding the event service, the
# sweep has health stop pinging it for the axis (F´'s HLTH_PING_ENABLE) and
# ping it again after; docs/design.md says why.
#: Svc.EventManager's command: its owner is the event service
EVENTS_COMMAND = "SET_ID_FILTER"
ENTRY_LENGTH = struct.Struct(">H")  # FwSizeStoreType, a string argument's length
ENABLED = struct.Struct(">B")  # Fw.Enabled


def string_argument(text: str) -> bytes:
    """A command's string argument: its length (FwSizeStoreType), then its bytes."""
    data = text.encode()
    return ENTRY_LENGTH.pack(len(data)) + data


def ping_enable(names: Dictionary, enabled: bool) -> bytes:
    """The frames of health's HLTH_PING_ENABLE for the event service's ping
    entries, or nothing where the build has no health (its deployment, or
    its board's profile, leaves it out). An entry is named after the
    instance health pings, F´'s way ("CdhCore_events" for CdhCore.events);
    the reference deployment pings its event service through a probe (the
    entry "Kit_eventsPing"). Health refuses the name it does not have with
    its lookup-error event, and pings on."""
    health = names.owner_of("HLTH_PING_ENABLE")
    events = names.owner_of(EVENTS_COMMAND)
    if health is None or events is None:
        return b""
    entry = events.replace(".", "_")
    return b"".join(frame(command(names.opcodes[f"{health}.HLTH_PING_ENABLE"],
                                  string_argument(name) + ENABLED.pack(int(enabled))))
                    for name in (entry, f"{entry}Ping"))


def run(build: Path, repeats: int = REPEATS) -> Outcome:
    """Boot a ground build and sweep every axis on its link, each level `repeats` times."""
    link_info = ground.link_of(build)
    names = Dictionary.read(link_info.dictionary)
    opcodes = names.opcodes
    outcome = Outcome()
    # In real time: the line's writes stay small and even (client.Line)
    with ground.boot(link_info, realtime=True) as qemu:
        baud = line_rate(ground.link_line(qemu))
        outcome.lines.append(f"KIT LINE baud={baud} bytes_per_s={int(bytes_per_second(baud))}")
        link = Downlink(link_info.socket, link_info.dictionary)
        try:
            driver = Driver(qemu, link, opcodes, baud)
            # The deployment's clock reaches the host with its first telemetry
            if not link.pump(lambda: link.now > 0, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: no downlink within {REPLY_TIMEOUT_S:.0f} s")
            points = iter(range(1 << 30))
            slice_hz = driver.slice_hz()
            uplink_levels = (*UPLINK.levels, full_line_commands(baud, driver.noop))
            for level in uplink_levels:
                for repeat in range(repeats):
                    traffic = PointTraffic(UPLINK.name, next(points), level, repeat)
                    outcome.lines += driver.measure(UPLINK, traffic, driver.offer(driver.noop, float(level)))
                    outcome.traffic.append(traffic)
            # The dispatcher runs commands in order: the new level is set
            # before the segment is requested (no wait for its event, which a
            # flooded events queue may drop)
            unload = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(0)))
            stop_pinging = ping_enable(names, enabled=False)
            if stop_pinging:
                link.send(stop_pinging)
            for level, per_slice in downlink_levels(slice_hz):
                for repeat in range(repeats):
                    traffic = PointTraffic(DOWNLINK.name, next(points), level, repeat)
                    received_before = link.events[DOWNLINK_PACKET_EVENT]
                    newest_before = driver.newest_packet()
                    load = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(per_slice)))
                    link.send(load)
                    traffic.bytes_sent += len(load)
                    outcome.lines += driver.measure(DOWNLINK, traffic, driver.offer(driver.noop, 0.0), unload)
                    traffic.packets_received = link.events[DOWNLINK_PACKET_EVENT] - received_before
                    # Packets are numbered: those between the newest before the
                    # point and the newest after it that never arrived were lost
                    traffic.packets_lost = driver.newest_packet() - newest_before - traffic.packets_received
                    outcome.traffic.append(traffic)
            ping_again = ping_enable(names, enabled=True)
            if ping_again:
                link.send(ping_again)
            for level in NOISE.levels:
                for repeat in range(repeats):
                    traffic = PointTraffic(NOISE.name, next(points), level, repeat)
                    offer = driver.offer(driver.noop, NOISE_NOOP_RATE, noise_per_second(baud, driver.noop, level),
                                  NOISE_SEED + traffic.point)
                    outcome.lines += driver.measure(NOISE, traffic, offer)
                    outcome.traffic.append(traffic)
            file_downlink = names.owner_of("SendPartial")  # F´'s FileDownlink, whatever its instance's name
            if file_downlink is not None:
                send_partial = opcodes[f"{file_downlink}.SendPartial"]
                bulk = str(names.constant(BULK_FILE_CONSTANT))
                file_bytes = driver.fill_bulk_file(bulk)
                for level in (*FILE.levels, int(bytes_per_second(baud))):
                    part, per_s = file_request(level, file_bytes)
                    request = frame(command(send_partial, string_argument(bulk)
                                            + string_argument(SWEEP_FILE_DESTINATION) + U32.pack(0) + U32.pack(part)))
                    for repeat in range(repeats):
                        traffic = PointTraffic(FILE.name, next(points), level, repeat)
                        received_before = link.file_bytes
                        outcome.lines += driver.measure(FILE, traffic, driver.offer(request, per_s))
                        driver.file_quiet()
                        traffic.file_bytes_asked = traffic.commands_sent * part
                        traffic.file_bytes_received = link.file_bytes - received_before
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
