# SPDX-License-Identifier: Apache-2.0
"""File-uplink fuzzing: seeded file packets, most of them invalid, on the link.

Like the frame fuzzer (kittools.link.fuzz), this is the only client of a
build's link socket and paces itself by the deployment's answers: a few file
packets at a time, each batch closed by a valid NO_OP whose answer it waits
for. Every packet is a well-framed F´ file packet (descriptor 3) that the
router hands to Svc.FileUplink; what the packet is worth is decided by a
model of FileUplink's own rules (F´ 6c80056, Svc/FileUplink/FileUplink.cpp):
its receive mode, the last sequence index, the declared size, and the CFDP
checksum of what it wrote. A packet is invalid when FileUplink must refuse
it: a decode error (a type byte that names no packet, a header cut short, a
data size the packet does not hold) or a warning (data or an end with no
file open, a start while one is, an out-of-order or duplicate sequence
index, data past the declared size, a bad checksum, a destination the RAM
file system does not have). Files that start and never complete are among
them: a start while a file is open is the warning F´ gives.

What the deployment must show (`Outcome.failures`): every NO_OP answered, no
halt, and FileUplink's counts exactly the model's: packets received,
warnings, files received (telemetry) and decode errors (events).
"""

from __future__ import annotations

import random
import struct
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from kittools.link.client import (
    DESCRIPTOR,
    FILE_DATA_FIELDS,
    FILE_PACKET_HEADER,
    FW_PACKET_FILE,
    T_CANCEL,
    T_DATA,
    T_END,
    T_START,
    Downlink,
    command,
    file_path_field,
    frame,
)
from kittools.link.dictionary import FILE_UPLINK_CHANNELS, Dictionary
from kittools.link.fuzz import (
    DOWNLINK_OVERFLOW_EVENT,
    MISSED_ANSWERS_MAX,
    REPLY_TIMEOUT_S,
    after_boot_burst,
    read_out,
    send_closed_by_noop,
    settle,
)
from kittools.workspace import KitError

START_FIELDS = struct.Struct(">I")  # file size; then the two length-prefixed paths
END_FIELDS = struct.Struct(">I")  # CFDP checksum

# Where the fuzzer writes: the scratch file (a sequence's place; the
# parameter file is never touched), so declared sizes stay within it
SCRATCH_CONSTANT = "Kit.RamFs.scratchFile"
FILE_CAPACITY_BYTES = 256  # CONFIG_KIT_RAMFS_FILE_SIZE's default: a bin-0 file
DATA_MAX_BYTES = 32
# Names the RAM file system has no file for (MicroFs: /bin<n>/file<m> only),
# a negative bin and file among them
BAD_DESTINATIONS = ("/bin9/file0", "/bin0/file9", "/bin-1/file0", "/bin0/file-1", "/bin0/file1.crc", "/tmp/kit",
                    "", "bin0/file1", "/bin0/", "/bin1/file1")

# Packets a batch holds: each holds one of the link's six buffers
# (GroundLink.fpp's Link.bufferCount) until FileUplink has written it,
# beside the UART's, the accumulator's and the downlink frame on the wire.
# The NO_OP's answer does not say FileUplink is done (the dispatcher,
# beside it at one priority, may answer first), so the next batch can meet
# part of this one still held: with three a batch, a fresh-clone run of
# 05e28b8 had one valid file packet refused for want of a buffer
# (router.AllocationError, linkBuffers.NoBuffsAvailable: mps2/an385 rtos,
# FilesReceived 169 of 170). Two leave a buffer for that.
PER_BATCH = 2

KINDS = ("start", "start_bad_destination", "data_next", "data_out_of_order", "data_duplicate", "data_out_of_bounds",
         "end_good", "end_bad_checksum", "cancel", "bad_type", "truncated", "data_size_mismatch")
# The fuzzer's weights: mostly what FileUplink must refuse, enough valid
# packets that files open, grow and complete between them
WEIGHTS = (3, 1, 4, 2, 1, 2, 1, 2, 1, 1, 1, 1)

# The file uplink's events, by their own names (the instance's name is the
# deployment's: Dictionary.file_uplink; its counts are FILE_UPLINK_CHANNELS),
# and the link's ring
RING_DROPS_CHANNEL = "Kit.linkHealth.UartRingDrops"
DECODE_ERROR = "DecodeError"
FILE_RECEIVED = "FileReceived"
# Where a file packet is lost before FileUplink sees it: the link's buffers ran out
BUFFER_EVENTS = ("Kit.router.AllocationError", "Kit.frameAccumulator.NoBufferAvailable",
                 "Kit.linkBuffers.NoBuffsAvailable")


def cfdp_checksum(data: bytes, offset: int, start: int = 0) -> int:
    """F´'s CFDP::Checksum::update: each byte at file offset o adds
    byte << 8 * (3 - o % 4), modulo 2^32."""
    value = start
    for index, byte in enumerate(data):
        value += byte << (8 * (3 - (offset + index) % 4))
    return value & 0xFFFFFFFF


@dataclass
class FileUplinkModel:
    """Svc.FileUplink's state and counts, as its code decides them."""

    receiving: bool = False  # its DATA mode (a file open)
    last_sequence: int = 0
    last_write_ok: bool = False
    size: int = 0
    written: int = 0
    checksum: int = 0
    packets: int = 0
    warnings: int = 0
    files: int = 0
    decode_errors: int = 0

    def _sequence(self, index: int) -> None:
        if index != self.last_sequence + 1:
            self.warnings += 1
        self.last_sequence = index

    def _restart(self, receiving: bool) -> None:
        self.receiving = receiving
        self.last_sequence = 0
        self.last_write_ok = False

    def start(self, size: int, opens: bool) -> None:
        self.packets += 1
        if self.receiving:
            self.warnings += 1  # invalid receive mode: a file that never completed
        if opens:
            self.size, self.written, self.checksum = size, 0, 0
        else:
            self.warnings += 1  # file open error
        self._restart(opens)

    def data(self, index: int, offset: int, payload: bytes) -> None:
        self.packets += 1
        if not self.receiving:
            self.warnings += 1
            return
        if self.last_write_ok and index == self.last_sequence:
            self.warnings += 1  # duplicate
            return
        self._sequence(index)
        if offset + len(payload) > self.size:
            self.warnings += 1  # out of bounds
            return
        self.checksum = cfdp_checksum(payload, offset, self.checksum)
        self.written = max(self.written, offset + len(payload))
        self.last_write_ok = True

    def end(self, index: int, checksum: int) -> None:
        self.packets += 1
        if self.receiving:
            self.files += 1
            self._sequence(index)
            if checksum != self.checksum:
                self.warnings += 1
        else:
            self.warnings += 1
        self._restart(False)

    def cancel(self) -> None:
        self.packets += 1
        self._restart(False)


def file_packet(kind: str, rng: random.Random, model: FileUplinkModel, scratch: str) -> bytes:
    """One file packet of a kind (descriptor included), applied to the model."""
    sequence = model.last_sequence + 1
    if kind in ("start", "start_bad_destination"):
        size = rng.randint(1, FILE_CAPACITY_BYTES)
        good = kind == "start"
        destination = scratch if good else rng.choice(BAD_DESTINATIONS)
        model.start(size, good)
        body = (FILE_PACKET_HEADER.pack(T_START, 0) + START_FIELDS.pack(size) + file_path_field("kit-fuzz")
                + file_path_field(destination))
    elif kind.startswith("data_") and kind != "data_size_mismatch":
        room = max(0, model.size - model.written)
        payload = rng.randbytes(rng.randint(1, DATA_MAX_BYTES))
        offset = model.written
        if kind == "data_next":
            payload = payload[:room] or payload[:1]
        elif kind == "data_out_of_order":
            sequence += rng.randint(2, 1000)
            payload = payload[:room] or payload[:1]
        elif kind == "data_duplicate":
            sequence = model.last_sequence
        elif kind == "data_out_of_bounds":
            offset = model.size - len(payload) + rng.randint(1, 64)
            offset = max(offset, 0)
            if offset + len(payload) <= model.size:
                offset = model.size + 1
        model.data(sequence, offset, payload)
        body = FILE_PACKET_HEADER.pack(T_DATA, sequence) + FILE_DATA_FIELDS.pack(offset, len(payload)) + payload
    elif kind in ("end_good", "end_bad_checksum"):
        checksum = model.checksum if kind == "end_good" else (model.checksum + rng.randint(1, 0xFFFFFFFE)) & 0xFFFFFFFF
        model.end(sequence, checksum)
        body = FILE_PACKET_HEADER.pack(T_END, sequence) + END_FIELDS.pack(checksum)
    elif kind == "cancel":
        model.cancel()
        body = FILE_PACKET_HEADER.pack(T_CANCEL, sequence)
    elif kind == "bad_type":
        model.decode_errors += 1
        body = FILE_PACKET_HEADER.pack(rng.randint(T_CANCEL + 1, 0xFE), sequence) + rng.randbytes(rng.randint(0, 8))
    elif kind == "truncated":
        model.decode_errors += 1
        body = bytes([rng.choice((T_START, T_DATA, T_END))]) + rng.randbytes(rng.randint(0, 3))
    elif kind == "data_size_mismatch":
        model.decode_errors += 1
        payload = rng.randbytes(rng.randint(0, DATA_MAX_BYTES))
        claimed = len(payload) + rng.choice((-1, 1)) * rng.randint(1, 8)
        body = FILE_PACKET_HEADER.pack(T_DATA, sequence) + FILE_DATA_FIELDS.pack(0, max(claimed, 0) & 0xFFFF) + payload
        if claimed < 0:  # nothing to claim less than: claim more
            body = FILE_PACKET_HEADER.pack(T_DATA, sequence) + FILE_DATA_FIELDS.pack(0, len(payload) + 1) + payload
    else:
        raise ValueError(f"unknown kind {kind}")
    return DESCRIPTOR.pack(FW_PACKET_FILE) + body


@dataclass
class Outcome:
    seed: int
    #: The file uplink's qualified instance name (Dictionary.file_uplink)
    file_uplink: str
    sent: Counter[str] = field(default_factory=Counter)
    invalid_sent: int = 0
    noops_sent: int = 0
    noops_answered: int = 0
    model: FileUplinkModel = field(default_factory=FileUplinkModel)
    events: Counter[str] = field(default_factory=Counter)
    telemetry: dict[str, int] = field(default_factory=dict)
    halt: str = ""
    missed: list[int] = field(default_factory=list)
    #: READ_OUT batches played at the end (fuzz.read_out)
    read_outs: int = 0
    #: The downlink overflowed during every read-out: the files are counted
    #: from FileReceived events
    read_out_overflowed: bool = False

    def of_uplink(self, name: str) -> str:
        """A channel or event of the file uplink, by its own name."""
        return f"{self.file_uplink}.{name}"

    def count_channels(self) -> tuple[str, ...]:
        return (*(self.of_uplink(name) for name in FILE_UPLINK_CHANNELS), RING_DROPS_CHANNEL)

    def failures(self) -> list[str]:
        found = []
        checks = [
            ("NO_OPs answered", self.noops_answered, self.noops_sent),
            ("FileUplink.PacketsReceived", self.telemetry.get(self.of_uplink("PacketsReceived")), self.model.packets),
            ("FileUplink.Warnings", self.telemetry.get(self.of_uplink("Warnings")), self.model.warnings),
            self._files_received(),
            ("FileUplink's DecodeError events", self.events[self.of_uplink(DECODE_ERROR)], self.model.decode_errors),
            # Each batch fits the link's buffers and the UART's ring: a loss here is a failure
            ("LinkHealth.UartRingDrops", self.telemetry.get(RING_DROPS_CHANNEL), 0),
        ]
        for name, got, expected in checks:
            if got != expected:
                found.append(f"{name}: {got}, expected {expected}")
        if self.halt:
            found.append(f"the deployment asserted or halted:\n{self.halt}")
        if self.missed:
            found.append(f"no answer within {REPLY_TIMEOUT_S:.0f} s to NO_OPs {self.missed}")
        return found

    def _files_received(self) -> tuple[str, int | None, int]:
        """FileUplink's files: its FilesReceived count, or where the
        downlink overflowed during every read-out, its FileReceived events
        (one with each count; the events' queue is not the one a
        cooperative model overflows: TlmChan sends a slice's packets at
        once, up to 7, into ComQueue's telemetry queue of 4, and the same
        channels come last each time: mps2/an385 baremetal_passive read
        FilesReceived 169 through three read-outs beside 172 events)."""
        if self.read_out_overflowed:
            return "FileUplink's FileReceived events", self.events[self.of_uplink(FILE_RECEIVED)], self.model.files
        return "FileUplink.FilesReceived", self.telemetry.get(self.of_uplink("FilesReceived")), self.model.files

    def to_json(self) -> dict[str, Any]:
        model = self.model
        decode_errors = self.of_uplink(DECODE_ERROR)
        return {"seed": self.seed, "invalid_sent": self.invalid_sent, "sent": dict(sorted(self.sent.items())),
                "noops_sent": self.noops_sent, "noops_answered": self.noops_answered, "read_outs": self.read_outs,
                "read_out_overflowed": self.read_out_overflowed,
                "expected": {"packets": model.packets, "warnings": model.warnings, "files": model.files,
                             "decode_errors": model.decode_errors},
                "counted": {name.removeprefix("Kit."): value for name, value in sorted(self.telemetry.items())}
                | {f"{decode_errors.removeprefix('Kit.')} events": self.events[decode_errors]},
                "buffer_events": {name.removeprefix("Kit."): self.events[name] for name in BUFFER_EVENTS},
                # every event that came down: a count that differs from the model names its cause here
                "events": {name.removeprefix("Kit."): count for name, count in sorted(self.events.items())},
                "downlink_overflows": self.events[DOWNLINK_OVERFLOW_EVENT],
                "halt": self.halt, "missed": self.missed, "failures": self.failures()}


def has_file_uplink(dictionary: Path) -> bool:
    """The build has F´'s file uplink (its deployment, or its board's
    profile, may leave it out), under whatever instance name its topology gives it."""
    return Dictionary.read(dictionary).file_uplink is not None


# FileUplink writes its counts (telemetry) when they change, and TlmChan
# sends a channel once per write: a write lost where the downlink's
# telemetry queue overflows under the fuzzer's bursts (ComQueue's
# QueueOverflow events) leaves the ground an old count for good (a
# fresh-clone run read FilesReceived 168 while 169 FileReceived events came
# down). After the downlink has drained, these packets write each count once
# more: a cancel (no file open after it), an end with no file open
# (Warnings), then a file of no bytes (FilesReceived), PacketsReceived with
# each. The model counts them as it counts every packet.
READ_OUT = ("cancel", "end_good", "start", "end_good")


def run(socket_path: Path, dictionary: Path, seed: int, invalid_packets: int,
        halted: Callable[[], str] = lambda: "") -> Outcome:
    """Send file packets until `invalid_packets` of them are ones FileUplink
    must refuse, PER_BATCH at a time, each batch closed by a NO_OP; return
    what the deployment counted beside what its model expects."""
    names = Dictionary.read(dictionary)
    if names.file_uplink is None:
        raise KitError(f"{dictionary}: the deployment has no F´ file uplink to fuzz")
    scratch = str(names.constant(SCRATCH_CONSTANT))
    rng = random.Random(seed)
    outcome = Outcome(seed, names.file_uplink)
    model = outcome.model
    noop = frame(command(names.noop_opcode))
    link = Downlink(socket_path, dictionary)
    try:
        after_boot_burst(link, seed)
        while outcome.invalid_sent < invalid_packets and not outcome.halt:
            batch = b""
            for _ in range(PER_BATCH):
                kind = rng.choices(KINDS, WEIGHTS)[0]
                before = (model.warnings, model.decode_errors)
                batch += frame(file_packet(kind, rng, model, scratch))
                outcome.sent[kind] += 1
                if (model.warnings, model.decode_errors) != before:
                    outcome.invalid_sent += 1
            send_closed_by_noop(link, batch, noop, outcome, halted)
            if len(outcome.missed) >= MISSED_ANSWERS_MAX:
                break
        if not outcome.halt and not outcome.missed:
            # The downlink drained, then FileUplink's counts written once more

            def play() -> bool:
                outcome.read_outs += 1
                answered = True
                for first in range(0, len(READ_OUT), PER_BATCH):  # PER_BATCH a batch, as above
                    kinds = READ_OUT[first:first + PER_BATCH]
                    batch = b"".join(frame(file_packet(kind, rng, model, scratch)) for kind in kinds)
                    answered = send_closed_by_noop(link, batch, noop, outcome, halted) and answered
                return answered

            settle(link, seed)
            ended = read_out(link, play, seed)
            outcome.read_out_overflowed = ended.overflowed
        outcome.noops_answered = link.events[link.dictionary.noop_event]
        outcome.events = link.events
        if outcome.halt:
            return outcome
        if outcome.missed:
            settle(link, seed)
        outcome.events = link.events
        outcome.telemetry = {name: int(link.telemetry[name]) for name in outcome.count_channels()
                             if name in link.telemetry}
    finally:
        link.close()
    return outcome
