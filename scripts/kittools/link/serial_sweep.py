# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep: what traffic on the ground link costs the rate groups.

Five axes, each driven from outside through the real link (a build of the
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
  sequence  commands a sequence runs (cmd/s), where the build has F´'s
            command sequencer: an operator's sequence of NO_OPs uplinked
            once, then run by the ground's CS_RUN at the level's rate
            (kittools.link.sequence_load).

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

This module plays the sweep on a booted build (run, an axis at a time);
what a point does on the link is kittools.link.serial_driver; its plan (the
axes, levels and each point's traffic, the outcome and its records) is
kittools.link.serial_points, LinkHealth's counts kittools.link.health.
"""

from __future__ import annotations

import contextlib
import struct
from collections.abc import Callable, Collection, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from kittools.link import ground, sequence_load
from kittools.link.client import (
    Downlink,
    bytes_per_second,
    command,
    frame,
    line_rate,
)
from kittools.link.dictionary import Dictionary
from kittools.link.health import REPLY_TIMEOUT_S
from kittools.link.serial_driver import DOWNLINK_PACKET_EVENT, Driver
from kittools.link.serial_points import (
    DOWNLINK,
    FILE,
    NOISE,
    NOISE_NOOP_RATE,
    NOISE_SEED,
    REPEATS,
    SEQUENCE,
    UPLINK,
    Axis,
    Offer,
    Outcome,
    PointTraffic,
    downlink_levels,
    file_request,
    full_line_commands,
    last_stacks,
    noise_per_second,
)
from kittools.link.services import ping_enable, routine_events, string_argument
from kittools.workspace import KitError

U32 = struct.Struct(">I")
# The file axis' bulk file (Kit.RamFs.bulkFile), filled by the driver first
BULK_FILE_CONSTANT = "Kit.RamFs.bulkFile"
# F´'s FileDownlink command the file axis sends (it names the instance)
FILE_DOWNLINK_COMMAND = "SendPartial"
# The ground's name for what the file axis downlinks (fprime-gds is not on
# the link during the sweep: nothing writes it)
SWEEP_FILE_DESTINATION = "kit-sweep.bin"


@dataclass
class Sweeping:
    """A sweep under way on a booted build: its driver, its dictionary, its
    plays a level, the points so far and what they recorded."""

    driver: Driver
    names: Dictionary
    repeats: int
    outcome: Outcome = field(default_factory=Outcome)
    points: Iterator[int] = field(default_factory=lambda: iter(range(1 << 30)))
    #: The load's slices a second, measured before any axis (Driver.slice_hz)
    slice_hz: int = 0

    def plays(self, axis: Axis, level: int) -> Iterator[PointTraffic]:
        """Each play of a level, its traffic recorded once played."""
        for repeat in range(self.repeats):
            traffic = PointTraffic(axis.name, next(self.points), level, repeat)
            yield traffic
            self.outcome.traffic.append(traffic)

    def measure(self, axis: Axis, traffic: PointTraffic, offer: Offer, unload: bytes = b"") -> None:
        self.outcome.lines += self.driver.measure(axis, traffic, offer, unload)

    @contextlib.contextmanager
    def meanwhile(self, before: bytes, after: bytes) -> Iterator[None]:
        """Commands sent before and after what runs within (none where empty)."""
        if before:
            self.driver.link.send(before)
        yield
        if after:
            self.driver.link.send(after)

    def without_event_pings(self) -> contextlib.AbstractContextManager[None]:
        """Health stops pinging the event service meanwhile (services.ping_enable)."""
        return self.meanwhile(ping_enable(self.names, enabled=False), ping_enable(self.names, enabled=True))

    def without_routine_events(self) -> contextlib.AbstractContextManager[None]:
        """The event service sends no routine events meanwhile (services.routine_events)."""
        return self.meanwhile(routine_events(self.names, sent=False), routine_events(self.names, sent=True))


def uplink_axis(sweeping: Sweeping) -> None:
    driver = sweeping.driver
    for level in (*UPLINK.levels, full_line_commands(driver.baud, driver.noop)):
        for traffic in sweeping.plays(UPLINK, level):
            sweeping.measure(UPLINK, traffic, driver.offer(driver.noop, float(level)))


def downlink_axis(sweeping: Sweeping) -> None:
    driver, link, opcodes = sweeping.driver, sweeping.driver.link, sweeping.driver.opcodes
    # The dispatcher runs commands in order: the new level is set before the
    # segment is requested (no wait for its event, which a flooded events
    # queue may drop)
    unload = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(0)))
    with sweeping.without_event_pings():
        for level, per_slice in downlink_levels(sweeping.slice_hz):
            for traffic in sweeping.plays(DOWNLINK, level):
                received_before = link.events[DOWNLINK_PACKET_EVENT]
                newest_before = driver.newest_packet()
                load = frame(command(opcodes["Kit.load.SET_DOWNLINK"], U32.pack(per_slice)))
                link.send(load)
                traffic.bytes_sent += len(load)
                sweeping.measure(DOWNLINK, traffic, driver.offer(driver.noop, 0.0), unload)
                traffic.packets_received = link.events[DOWNLINK_PACKET_EVENT] - received_before
                # Packets are numbered: those between the newest before the
                # point and the newest after it that never arrived were lost
                traffic.packets_lost = driver.newest_packet() - newest_before - traffic.packets_received


def noise_axis(sweeping: Sweeping) -> None:
    driver = sweeping.driver
    for level in NOISE.levels:
        for traffic in sweeping.plays(NOISE, level):
            offer = driver.offer(driver.noop, NOISE_NOOP_RATE, noise_per_second(driver.baud, driver.noop, level),
                                 NOISE_SEED + traffic.point)
            sweeping.measure(NOISE, traffic, offer)


def file_axis(sweeping: Sweeping) -> None:
    """Where the build has F´'s FileDownlink, whatever its instance's name."""
    driver, link, names = sweeping.driver, sweeping.driver.link, sweeping.names
    file_downlink = names.owner_of(FILE_DOWNLINK_COMMAND)
    if file_downlink is None:
        return
    send_partial = names.opcodes[f"{file_downlink}.SendPartial"]
    bulk = str(names.constant(BULK_FILE_CONSTANT))
    file_bytes = driver.fill_bulk_file(bulk)
    for level in (*FILE.levels, int(bytes_per_second(driver.baud))):
        part, per_s = file_request(level, file_bytes)
        request = frame(command(send_partial, string_argument(bulk) + string_argument(SWEEP_FILE_DESTINATION)
                                + U32.pack(0) + U32.pack(part)))
        for traffic in sweeping.plays(FILE, level):
            received_before = link.file_bytes
            sweeping.measure(FILE, traffic, driver.offer(request, per_s))
            driver.quiet(lambda: link.file_bytes, "the file downlink was still sending")
            traffic.file_bytes_asked = traffic.commands_sent * part
            traffic.file_bytes_received = link.file_bytes - received_before


def sequence_axis(sweeping: Sweeping) -> None:
    """Where the build has F´'s CmdSequencer, whatever its instance's name
    (kittools.link.sequence_load): the sequence uplinked and run once, then
    each level. Each command a sequence runs is four events (dispatched,
    answered, completed, and the sequencer's own), which at the top level
    overflowed the downlink's queues and lost writes of the sequencer's
    count (mps2/an385 baremetal_passive, 80 cmd/s: plays counted 56, 56 and
    144 of 96): meanwhile, as an operator does before a busy sequence, the
    event service filters the routine severities out and, as for the
    downlink axis, health stops pinging it. A command the sequence ran is
    counted by its answer (the dispatcher's NoOpReceived, an event still
    sent: the ground's own traffic on this axis has no NO_OP), whose
    queue kept up where the sequencer's count, telemetry, still lost writes
    (the same build: 16, 152 and 104 of 96, every NO_OP answered)."""
    driver, names = sweeping.driver, sweeping.names
    sequencer = names.owner_of(sequence_load.RUN_COMMAND)
    if sequencer is None:
        return
    load = sequence_load.SequenceLoad(driver.link, names, sequencer)
    with sweeping.without_event_pings(), sweeping.without_routine_events():
        load.load()
        for level in SEQUENCE.levels:
            for traffic in sweeping.plays(SEQUENCE, level):
                before = load.answered()
                sweeping.measure(SEQUENCE, traffic,
                                 driver.offer(load.run_frame, level / sequence_load.SEQUENCE_RECORDS))
                traffic.sequence_commands_asked = traffic.commands_sent * sequence_load.SEQUENCE_RECORDS
                driver.quiet(load.answered, f"{sequencer} was still running its sequence",
                             reached=before + traffic.sequence_commands_asked)
                traffic.sequence_commands_run = load.answered() - before


#: Each axis' play, in the order a sweep plays them
AXIS_PLAYS: dict[str, Callable[[Sweeping], None]] = {
    UPLINK.name: uplink_axis, DOWNLINK.name: downlink_axis, NOISE.name: noise_axis, FILE.name: file_axis,
    SEQUENCE.name: sequence_axis,
}


#: The axes that play an F´ service the build may leave out: the service, and a command that names its instance
AXIS_SERVICES: dict[str, tuple[str, str]] = {
    FILE.name: ("F´'s file downlink", FILE_DOWNLINK_COMMAND),
    SEQUENCE.name: ("F´'s command sequencer", sequence_load.RUN_COMMAND),
}


def run(build: Path, repeats: int = REPEATS, axes: Collection[str] | None = None) -> Outcome:
    """Boot a ground build and sweep its link, each level `repeats` times:
    every axis (one the build lacks the service for is left out), or those
    named in `axes` (KitError when the build lacks one's service)."""
    unknown = sorted(set(axes or ()) - set(AXIS_PLAYS))
    if unknown:
        raise KitError(f"no serial axis {', '.join(unknown)}: the axes are {', '.join(AXIS_PLAYS)}")
    link_info = ground.link_of(build)
    names = Dictionary.read(link_info.dictionary)
    lacking = [f"{axis} (it plays {service}, which this build leaves out: no {command} in its dictionary)"
               for axis, (service, command) in AXIS_SERVICES.items()
               if axes is not None and axis in axes and names.owner_of(command) is None]
    if lacking:
        raise KitError(f"{build}: no serial axis {'; '.join(lacking)}")
    # In real time: the line's writes stay small and even (client.Line)
    with ground.boot(link_info, realtime=True) as qemu:
        baud = line_rate(ground.link_line(qemu))
        link = Downlink(link_info.socket, link_info.dictionary)
        try:
            sweeping = Sweeping(Driver(qemu, link, names.opcodes, baud), names, repeats)
            sweeping.outcome.lines.append(f"KIT LINE baud={baud} bytes_per_s={int(bytes_per_second(baud))}")
            # The deployment's clock reaches the host with its first telemetry
            if not link.pump(lambda: link.now > 0, REPLY_TIMEOUT_S):
                raise KitError(f"{build}: no downlink within {REPLY_TIMEOUT_S:.0f} s")
            chosen = [play for name, play in AXIS_PLAYS.items() if axes is None or name in axes]
            if downlink_axis in chosen:  # on the idle deployment
                sweeping.slice_hz = sweeping.driver.slice_hz()
            for play in chosen:
                play(sweeping)
            sweeping.outcome.stacks = last_stacks(qemu.lines)
            sweeping.outcome.events = dict(sorted(link.events.items()))
            sweeping.outcome.telemetry = dict(sorted(link.telemetry.items()))
        except KitError as error:
            # What the deployment said before it stopped answering
            raise KitError(f"{error}\nevents: {dict(sorted(link.events.items()))}\n"
                           f"telemetry: {dict(sorted(link.telemetry.items()))}") from None
        finally:
            link.close()
    return sweeping.outcome
