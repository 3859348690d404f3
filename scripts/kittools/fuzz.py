# SPDX-License-Identifier: Apache-2.0
"""Uplink fuzzing: seeded bad input on the ground link, interleaved with NO_OPs.

The fuzzer is the only client of a build's link socket (no fprime-gds: it
must send bytes no ground station would frame). It sends batches of a few
invalid frames of every kind below, each batch closed by a valid NO_OP and a
few zero bytes, and waits for that NO_OP's event before the next batch: the
uplink is paced by the deployment itself, whatever the speed of QEMU's
virtual time, and no batch outruns the UART driver's ring buffer. The
downlink is decoded with fprime-gds's own framing and decoders and the
build's dictionary.

What the deployment must show (`Outcome.failures`): every NO_OP answered;
every valid frame, and no invalid one, detected (LinkHealth.FramesDetected);
every oversized frame and every packet of an unknown type counted by its
reason (LinkHealth telemetry); every bad command counted by the dispatcher
(cmdDisp.CommandErrors); and no assert or halt on the console.
"""

from __future__ import annotations

import functools
import json
import random
import socket
import struct
import time
import zlib
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .workspace import KitError

START_WORD = 0xDEADBEEF
HEADER = struct.Struct(">II")  # start word, length (F´'s FprimeProtocol.FrameHeader)
TRAILER = struct.Struct(">I")  # CRC-32 of header and payload
DESCRIPTOR = struct.Struct(">H")  # FwPacketDescriptorType
OPCODE = struct.Struct(">I")  # FwOpcodeType
FW_PACKET_COMMAND = 0
FW_PACKET_TELEM = 1
FW_PACKET_LOG = 2
# Closes every batch: a frame still waiting for its claimed length (a
# truncated one) is completed by these and rejected, never left pending
PADDING = bytes(80)
# Bytes garbage never holds: no start word (DE AD BE EF) can form in it or
# across its edges with a neighbour
START_WORD_BYTES = frozenset(b"\xde\xad\xbe\xef")
GARBAGE_BYTES = bytes(value for value in range(256) if value not in START_WORD_BYTES)

INVALID_KINDS = ("garbage", "bad_checksum", "truncated", "oversized", "length_wraps", "unknown_packet",
                 "bad_opcode", "bad_arguments")
# Valid frames (good start word, length and checksum) with a bad payload
FRAMED_KINDS = ("unknown_packet", "bad_opcode", "bad_arguments")


def frame(payload: bytes) -> bytes:
    header = HEADER.pack(START_WORD, len(payload))
    return header + payload + TRAILER.pack(zlib.crc32(header + payload) & 0xFFFFFFFF)


def command(opcode: int, arguments: bytes = b"") -> bytes:
    return DESCRIPTOR.pack(FW_PACKET_COMMAND) + OPCODE.pack(opcode) + arguments


@dataclass(frozen=True)
class Deployment:
    """What the fuzzer needs from the build's dictionary."""

    noop: int
    setpoint: int  # an I32 argument: any shorter argument is a format error
    opcodes: frozenset[int]
    accumulator_size: int

    @staticmethod
    def from_dictionary(path: Path) -> Deployment:
        data = json.loads(path.read_text())
        opcodes = {c["name"]: c["opcode"] for c in data["commands"]}
        constants = {c["qualifiedName"]: c["value"] for c in data.get("constants", [])}
        try:
            return Deployment(opcodes["Kit.cmdDisp.CMD_NO_OP"], opcodes["Kit.controller.SET_SETPOINT"],
                              frozenset(opcodes.values()), int(constants["Kit.Link.accumulatorSize"]))
        except KeyError as missing:
            raise KitError(f"{path} lacks {missing}: is it this kit's dictionary?") from None


def invalid_frame(kind: str, rng: random.Random, deployment: Deployment) -> bytes:
    """One invalid frame of a kind, from the seeded generator."""
    def short_frame() -> bytes:
        # at most 26 bytes: the padding after the NO_OP completes any of them
        return frame(command(rng.choice(sorted(deployment.opcodes)), rng.randbytes(rng.randint(0, 8))))

    if kind == "garbage":
        return bytes(rng.choice(GARBAGE_BYTES) for _ in range(rng.randint(1, 48)))
    if kind == "bad_checksum":
        corrupted = bytearray(short_frame())
        corrupted[-1 - rng.randrange(TRAILER.size)] ^= 1 << rng.randrange(8)
        return bytes(corrupted)
    if kind == "truncated":
        whole = short_frame()
        return whole[:rng.randint(HEADER.size, len(whole) - 1)]
    if kind == "oversized":
        # A length the accumulator can never hold (it drops the candidate)
        length = rng.randint(deployment.accumulator_size, 0x7FFFFFFF)
        return HEADER.pack(START_WORD, length) + rng.randbytes(rng.randint(0, 16))
    if kind == "length_wraps":
        # header + length + trailer overflows F´'s 32-bit size to 0..11: F´'s
        # own detector asserted on these (app/Components/LinkHealth)
        return HEADER.pack(START_WORD, rng.randint(0xFFFFFFF4, 0xFFFFFFFF)) + rng.randbytes(rng.randint(0, 16))
    if kind == "unknown_packet":
        # Not a command, and not a file packet (3): the router drops those
        # silently when, as here, there is no file uplink
        descriptor = rng.choice([FW_PACKET_TELEM, FW_PACKET_LOG, rng.randint(4, 0xFFFF)])
        return frame(DESCRIPTOR.pack(descriptor) + rng.randbytes(rng.randint(0, 16)))
    if kind == "bad_opcode":
        while True:
            opcode = rng.getrandbits(32)
            if opcode not in deployment.opcodes:
                return frame(command(opcode, rng.randbytes(rng.randint(0, 8))))
    if kind == "bad_arguments":
        # SET_SETPOINT takes an I32; fewer bytes cannot be deserialized
        return frame(command(deployment.setpoint, rng.randbytes(rng.randint(0, 3))))
    raise ValueError(f"unknown kind {kind}")


@dataclass
class Outcome:
    seed: int
    sent: Counter[str] = field(default_factory=Counter)
    noops_sent: int = 0
    noops_answered: int = 0
    events: Counter[str] = field(default_factory=Counter)
    telemetry: dict[str, int] = field(default_factory=dict)
    halted: bool = False
    #: NO_OPs (their number in the run) not answered within REPLY_TIMEOUT_S
    missed: list[int] = field(default_factory=list)

    @property
    def invalid_sent(self) -> int:
        return sum(self.sent.values())

    def failures(self) -> list[str]:
        found = []
        framed = self.noops_sent + sum(self.sent[kind] for kind in FRAMED_KINDS)
        checks = (
            ("NO_OPs answered", self.noops_answered, self.noops_sent),
            ("LinkHealth.FramesDetected (valid frames)", self.telemetry.get("Kit.linkHealth.FramesDetected"), framed),
            ("LinkHealth.Oversized", self.telemetry.get("Kit.linkHealth.Oversized"),
             self.sent["oversized"] + self.sent["length_wraps"]),
            ("LinkHealth.UnknownPackets", self.telemetry.get("Kit.linkHealth.UnknownPackets"),
             self.sent["unknown_packet"]),
            ("cmdDisp.CommandErrors", self.telemetry.get("Kit.cmdDisp.CommandErrors"),
             self.sent["bad_opcode"] + self.sent["bad_arguments"]),
        )
        for name, got, expected in checks:
            if got != expected:
                found.append(f"{name}: {got}, expected {expected}")
        bad = self.telemetry.get("Kit.linkHealth.BadChecksums", 0)
        if bad < self.sent["bad_checksum"]:
            found.append(f"LinkHealth.BadChecksums: {bad}, expected at least {self.sent['bad_checksum']}")
        if self.halted:
            found.append("the deployment asserted or halted")
        if self.missed:
            found.append(f"no answer within {REPLY_TIMEOUT_S:.0f} s to NO_OPs {self.missed}")
        return found

    def to_json(self) -> dict[str, Any]:
        return {"seed": self.seed, "invalid_sent": self.invalid_sent, "sent": dict(sorted(self.sent.items())),
                "noops_sent": self.noops_sent, "noops_answered": self.noops_answered,
                "rejected": {name.removeprefix("Kit."): value for name, value in sorted(self.telemetry.items())},
                "events": dict(sorted(self.events.items())), "halted": self.halted, "missed": self.missed,
                "failures": self.failures()}


class Downlink:
    """The link socket: bytes up, and the downlink decoded into events (by
    name) and the latest value of every telemetry channel."""

    def __init__(self, socket_path: Path, dictionary: Path) -> None:
        from fprime_gds.common.communication.framing import FpFramerDeframer
        from fprime_gds.common.decoders.ch_decoder import ChDecoder
        from fprime_gds.common.decoders.event_decoder import EventDecoder
        from fprime_gds.common.models.dictionaries import Dictionaries

        dictionaries = Dictionaries()
        dictionaries.load_dictionaries(str(dictionary), None, None)
        self._events = EventDecoder(dictionaries.event_id)
        self._channels = ChDecoder(dictionaries.channel_id)
        FpFramerDeframer.set_constants()
        self._deframer = FpFramerDeframer()
        self._pending = b""
        self.events: Counter[str] = Counter()
        self.telemetry: dict[str, int] = {}
        # The deployment's time (F´ time tags, s) of the newest sample of each
        # channel and the newest event of each name
        self.telemetry_time: dict[str, float] = {}
        self.event_time: dict[str, float] = {}
        self._socket = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            self._socket.connect(str(socket_path))
        except OSError as error:
            raise KitError(f"cannot connect to the link {socket_path}: {error} (is QEMU running it?)") from None

    def close(self) -> None:
        self._socket.close()

    def send(self, data: bytes) -> None:
        self._socket.sendall(data)

    def pump(self, until: Callable[[], bool], timeout_s: float) -> bool:
        """Read and decode the downlink until `until()` holds or the time-out."""
        deadline = time.monotonic() + timeout_s
        while not until():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            self._socket.settimeout(min(remaining, 0.5))
            try:
                chunk = self._socket.recv(65536)
            except TimeoutError:
                continue
            if not chunk:
                raise KitError("the link closed: QEMU stopped")
            self._decode(chunk)
        return True

    def _decode(self, chunk: bytes) -> None:
        packets, self._pending, _ = self._deframer.deframe_all(self._pending + chunk, no_copy=False)
        for packet in packets:
            (descriptor,) = DESCRIPTOR.unpack_from(packet)
            body = packet[DESCRIPTOR.size:]
            if descriptor == FW_PACKET_LOG:
                for event in self._events.decode_api(body):
                    self.events[event.template.get_full_name()] += 1
                    self.event_time[event.template.get_full_name()] = event.get_time().get_float()
            elif descriptor == FW_PACKET_TELEM:
                for sample in self._channels.decode_api(body):
                    self.telemetry[sample.template.get_full_name()] = sample.get_val()
                    self.telemetry_time[sample.template.get_full_name()] = sample.get_time().get_float()


NOOP_EVENT = "Kit.cmdDisp.NoOpReceived"
REPLY_TIMEOUT_S = 20.0
# Unanswered NO_OPs after which the run stops (it has failed already)
MISSED_ANSWERS_MAX = 3
# LinkHealth writes every 100 ms of virtual time, changed or not
HEARTBEAT_CHANNEL = "Kit.linkHealth.FramesDetected"
# Three 10 Hz cycles: the dispatcher's call, then the telemetry service's
SETTLE_S = 0.3
# Telemetry read at the end
COUNT_CHANNELS = ("Kit.linkHealth.FramesDetected", "Kit.linkHealth.BadChecksums", "Kit.linkHealth.BytesDiscarded",
                  "Kit.linkHealth.Oversized", "Kit.linkHealth.UnknownPackets", "Kit.cmdDisp.CommandErrors",
                  "Kit.cmdDisp.CommandsDispatched")


def answered(link: Downlink, noops: int) -> bool:
    return link.events[NOOP_EVENT] >= noops


def run(socket_path: Path, dictionary: Path, seed: int, invalid_frames: int, per_batch: int = 4,
        halted: Callable[[], bool] = lambda: False) -> Outcome:
    """Send `invalid_frames` invalid frames in batches of `per_batch`, each
    batch closed by a NO_OP, and return what the deployment answered.
    `halted` is asked after every batch (it also drains the console)."""
    deployment = Deployment.from_dictionary(dictionary)
    rng = random.Random(seed)
    outcome = Outcome(seed)
    noop = frame(command(deployment.noop))
    link = Downlink(socket_path, dictionary)
    try:
        while outcome.invalid_sent < invalid_frames and not outcome.halted:
            batch = b""
            for _ in range(min(per_batch, invalid_frames - outcome.invalid_sent)):
                kind = rng.choice(INVALID_KINDS)
                batch += invalid_frame(kind, rng, deployment)
                outcome.sent[kind] += 1
            link.send(batch + noop + PADDING)
            outcome.noops_sent += 1
            replied = link.pump(functools.partial(answered, link, outcome.noops_sent), REPLY_TIMEOUT_S)
            outcome.halted = halted()
            if not replied:
                # A missed answer fails the run (Outcome.failures); go on,
                # since the next batch's bytes may free what holds it up,
                # but not forever
                outcome.missed.append(outcome.noops_sent)
                if len(outcome.missed) >= MISSED_ANSWERS_MAX:
                    break
        if outcome.halted:
            outcome.noops_answered = link.events[NOOP_EVENT]
            outcome.events = link.events
            return outcome
        # The counters after the last batch: the last NO_OP's answer means
        # every byte before it was processed. Telemetry waits behind events
        # in the downlink queue, so samples arriving after that answer can
        # be older than it: wait, by the deployment's own time tags, for a
        # LinkHealth sample taken SETTLE_S after it. The dispatcher's
        # channels are sent on change only; their final values (written by
        # its 10 Hz call after the last command) were queued before that.
        settled = link.event_time.get(NOOP_EVENT, 0.0) + SETTLE_S
        if not link.pump(lambda: link.telemetry_time.get(HEARTBEAT_CHANNEL, 0.0) >= settled, REPLY_TIMEOUT_S):
            raise KitError(f"no {HEARTBEAT_CHANNEL} telemetry after the last batch (seed {seed})")
        outcome.noops_answered = link.events[NOOP_EVENT]
        outcome.events = link.events
        outcome.telemetry = {name: int(link.telemetry[name]) for name in COUNT_CHANNELS if name in link.telemetry}
    finally:
        link.close()
    return outcome
