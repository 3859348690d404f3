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
reason (LinkHealth telemetry); every bad command refused by the dispatcher
with an event (InvalidCommand, MalformedCommand or OpCodeError), and counted
in its CommandErrors channel where its form has one (F´'s CommandDispatcher:
fprime-baremetal's PassiveCmdDispatcher has no telemetry); and no assert or
halt on the console.
"""

from __future__ import annotations

import functools
import random
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from kittools.link.client import (
    DESCRIPTOR,
    FW_PACKET_LOG,
    FW_PACKET_TELEM,
    HEADER,
    NOISE_BYTES,
    START_WORD,
    TRAILER,
    Downlink,
    command,
    frame,
)
from kittools.link.dictionary import Dictionary
from kittools.workspace import KitError

# Closes every batch: a frame still waiting for its claimed length (a
# truncated one) is completed by these and rejected, never left pending
PADDING = bytes(80)
# Garbage is noise: no start word can form in it or across its edges
GARBAGE_BYTES = NOISE_BYTES

INVALID_KINDS = ("garbage", "bad_checksum", "truncated", "oversized", "length_wraps", "unknown_packet",
                 "bad_opcode", "bad_arguments")
# Valid frames (good start word, length and checksum) with a bad payload
FRAMED_KINDS = ("unknown_packet", "bad_opcode", "bad_arguments")


@dataclass(frozen=True)
class Deployment:
    """What the fuzzer needs from the build's dictionary."""

    noop: int
    #: The dispatcher's qualified instance name (kittools.link.dictionary)
    dispatcher: str
    #: A command with a U32 argument, in any deployment (the kit's load's
    #: SET_SLICE): any shorter argument is a format error
    with_argument: int
    opcodes: frozenset[int]
    accumulator_size: int
    #: The dispatcher counts errors in telemetry (F´'s CommandDispatcher; not the passive form)
    dispatcher_telemetry: bool = True

    @staticmethod
    def from_dictionary(path: Path) -> Deployment:
        names = Dictionary.read(path)
        return Deployment(names.noop_opcode, names.dispatcher, names.opcode(ARGUMENT_COMMAND),
                          frozenset(names.opcodes.values()), int(names.constant(ACCUMULATOR_CONSTANT)),
                          names.of_dispatcher(DISPATCHER_ERRORS) in names.channels)


def unknown_opcode(rng: random.Random, deployment: Deployment) -> int:
    """An opcode the deployment's dictionary does not have."""
    while True:
        opcode = rng.getrandbits(32)
        if opcode not in deployment.opcodes:
            return opcode


def invalid_frame(kind: str, rng: random.Random, deployment: Deployment) -> bytes:
    """One invalid frame of a kind, from the seeded generator."""
    def short_frame() -> bytes:
        # at most 26 bytes: the padding after the NO_OP completes any of them
        return frame(command(rng.choice(sorted(deployment.opcodes)), rng.randbytes(rng.randint(0, 8))))

    if kind == "garbage":
        return bytes(rng.choice(GARBAGE_BYTES) for _ in range(rng.randint(1, INVALID_FRAME_MAX)))
    if kind == "bad_checksum":
        corrupted = bytearray(short_frame())
        corrupted[-1 - rng.randrange(TRAILER.size)] ^= 1 << rng.randrange(8)
        return bytes(corrupted)
    if kind == "truncated":
        # Cut before the trailer: a frame that lacks only checksum bytes is
        # completed, as a valid frame, by a next frame that happens to start
        # with them (the start word's DE: one fuzzing run in 10,000 frames
        # turned an unknown packet into a bad command that way). With a body
        # byte missing too, what follows cannot complete it.
        whole = short_frame()
        return whole[:rng.randint(HEADER.size, len(whole) - TRAILER.size - 1)]
    if kind == "oversized":
        # A length the accumulator can never hold (it drops the candidate)
        length = rng.randint(deployment.accumulator_size, 0x7FFFFFFF)
        return HEADER.pack(START_WORD, length) + rng.randbytes(rng.randint(0, 16))
    if kind == "length_wraps":
        # header + length + trailer overflows F´'s 32-bit size to 0..11: F´'s
        # own detector asserted on these (app/Components/LinkHealth)
        return HEADER.pack(START_WORD, rng.randint(0xFFFFFFF4, 0xFFFFFFFF)) + rng.randbytes(rng.randint(0, 16))
    if kind == "unknown_packet":
        # Not a command, and not a file packet (3: the file uplink's where the
        # build has one, dropped silently by the router where it has not)
        descriptor = rng.choice([FW_PACKET_TELEM, FW_PACKET_LOG, rng.randint(4, 0xFFFF)])
        return frame(DESCRIPTOR.pack(descriptor) + rng.randbytes(rng.randint(0, 16)))
    if kind == "bad_opcode":
        return frame(command(unknown_opcode(rng, deployment), rng.randbytes(rng.randint(0, 8))))
    if kind == "bad_arguments":
        # SET_SLICE takes a U32; fewer bytes cannot be deserialized
        return frame(command(deployment.with_argument, rng.randbytes(rng.randint(0, 3))))
    raise ValueError(f"unknown kind {kind}")


@dataclass
class Outcome:
    seed: int
    sent: Counter[str] = field(default_factory=Counter)
    noops_sent: int = 0
    noops_answered: int = 0
    #: Every byte written to the link (frames, garbage, padding)
    bytes_sent: int = 0
    events: Counter[str] = field(default_factory=Counter)
    telemetry: dict[str, int] = field(default_factory=dict)
    #: The console lines that show the deployment halted ("" while it runs)
    halt: str = ""
    #: NO_OPs (their number in the run) not answered within REPLY_TIMEOUT_S
    missed: list[int] = field(default_factory=list)
    #: The dispatcher's qualified instance name (Deployment.dispatcher)
    dispatcher: str = ""
    #: The dispatcher's form counts errors in telemetry (Deployment.dispatcher_telemetry)
    dispatcher_telemetry: bool = True
    #: Unknown opcodes sent after the fuzzing to write the dispatcher's counts again
    read_out_commands: int = 0
    #: The downlink overflowed during every read-out: CommandErrors may not
    #: have come down, and the dispatcher's refusal events alone count
    #: (file_fuzz.Outcome says why a cooperative model loses the same
    #: channels in every read-out)
    read_out_overflowed: bool = False

    @property
    def invalid_sent(self) -> int:
        return sum(self.sent.values())

    def failures(self) -> list[str]:
        found = []
        framed = self.noops_sent + self.read_out_commands + sum(self.sent[kind] for kind in FRAMED_KINDS)
        bad_commands = self.sent["bad_opcode"] + self.sent["bad_arguments"] + self.read_out_commands
        checks = [
            ("NO_OPs answered", self.noops_answered, self.noops_sent),
            ("LinkHealth.FramesDetected (valid frames)", self.telemetry.get("Kit.linkHealth.FramesDetected"), framed),
            ("LinkHealth.Oversized", self.telemetry.get("Kit.linkHealth.Oversized"),
             self.sent["oversized"] + self.sent["length_wraps"]),
            ("LinkHealth.UnknownPackets", self.telemetry.get("Kit.linkHealth.UnknownPackets"),
             self.sent["unknown_packet"]),
            (f"{self.dispatcher}'s refusal events ({', '.join(DISPATCHER_REFUSALS)})",
             sum(self.events[f"{self.dispatcher}.{e}"] for e in DISPATCHER_REFUSALS), bad_commands),
            # Paced by its NO_OPs, the fuzzer never has more commands in flight than the link lets through,
            # nor fills the event service's queue (LinkHealth sheds commands then)
            ("LinkHealth.CommandsDropped", self.telemetry.get("Kit.linkHealth.CommandsDropped"), 0),
            # Each batch fits the UART driver's ring, and waits for its NO_OP's answer
            ("LinkHealth.UartRingDrops", self.telemetry.get("Kit.linkHealth.UartRingDrops"), 0),
            # QEMU's UART holds back what it cannot take: the UART reads every byte sent
            ("LinkHealth.UartBytesReceived", self.telemetry.get("Kit.linkHealth.UartBytesReceived"), self.bytes_sent),
        ]
        if self.dispatcher_telemetry and not self.read_out_overflowed:
            errors = f"{self.dispatcher}.{DISPATCHER_ERRORS}"
            checks.append((errors, self.telemetry.get(errors), bad_commands))
        for name, got, expected in checks:
            if got != expected:
                found.append(f"{name}: {got}, expected {expected}")
        bad = self.telemetry.get("Kit.linkHealth.BadChecksums", 0)
        if bad < self.sent["bad_checksum"]:
            found.append(f"LinkHealth.BadChecksums: {bad}, expected at least {self.sent['bad_checksum']}")
        if self.halt:
            found.append(f"the deployment asserted or halted:\n{self.halt}")
        if self.missed:
            found.append(f"no answer within {REPLY_TIMEOUT_S:.0f} s to NO_OPs {self.missed}")
        return found

    def to_json(self) -> dict[str, Any]:
        return {"seed": self.seed, "invalid_sent": self.invalid_sent, "sent": dict(sorted(self.sent.items())),
                "noops_sent": self.noops_sent, "read_out_commands": self.read_out_commands,
                "read_out_overflowed": self.read_out_overflowed,
                "noops_answered": self.noops_answered, "bytes_sent": self.bytes_sent,
                "rejected": {name.split(".", 1)[-1]: value for name, value in sorted(self.telemetry.items())},
                "events": dict(sorted(self.events.items())),
                "downlink_overflows": self.events[DOWNLINK_OVERFLOW_EVENT], "halt": self.halt, "missed": self.missed,
                "failures": self.failures()}


#: The command whose arguments the fuzzer gets wrong: the kit's own, so that
#: it is in every deployment's dictionary
ARGUMENT_COMMAND = "Kit.load.SET_SLICE"
#: The link's frame accumulator (Kit.GroundLink): the longest frame it takes
ACCUMULATOR_CONSTANT = "Kit.Link.accumulatorSize"
# How the dispatcher refuses a command, in either form: an unknown opcode, a
# packet it cannot read, a command its handler failed (bad arguments); the
# dispatcher's own names (Dictionary.of_dispatcher)
DISPATCHER_REFUSALS = ("InvalidCommand", "MalformedCommand", "OpCodeError")
DISPATCHER_ERRORS = "CommandErrors"
REPLY_TIMEOUT_S = 20.0
# Unanswered NO_OPs after which the run stops (it has failed already)
MISSED_ANSWERS_MAX = 3
# LinkHealth writes every 100 ms of virtual time, changed or not
HEARTBEAT_CHANNEL = "Kit.linkHealth.FramesDetected"
# Three 10 Hz cycles: the dispatcher's call, then the telemetry service's
SETTLE_S = 0.3
# Telemetry read at the end: the link's, then the dispatcher's own (count_channels)
LINK_COUNT_CHANNELS = ("Kit.linkHealth.FramesDetected", "Kit.linkHealth.BadChecksums", "Kit.linkHealth.BytesDiscarded",
                       "Kit.linkHealth.Oversized", "Kit.linkHealth.UnknownPackets", "Kit.linkHealth.CommandsDropped",
                       # where the bytes went before frame detection: the UART read them all, its ring kept them
                       # (the fuzzer's batches fit the ring: a drop here is a failure)
                       "Kit.linkHealth.UartBytesReceived", "Kit.linkHealth.UartRingDrops")
DISPATCHER_COUNT_CHANNELS = (DISPATCHER_ERRORS, "CommandsDispatched")


def count_channels(names: Dictionary) -> tuple[str, ...]:
    return LINK_COUNT_CHANNELS + tuple(names.of_dispatcher(c) for c in DISPATCHER_COUNT_CHANNELS)


def answered(link: Downlink, noops: int) -> bool:
    return link.events[link.dictionary.noop_event] >= noops


# The boot's own events fill the downlink's event queue for a while after
# the link is up; a fuzzer that started inside that burst had the answer to
# its first NO_OP dropped with them (CI, qemu_cortex_m3 baremetal_budgeted:
# every later NO_OP then looked unanswered). ComQueue sends events before
# telemetry, so a telemetry sample taken this far into the deployment's time
# comes down only after the events queued before it.
BOOT_SETTLE_S = 1.0
# Where ComQueue says it dropped a downlink buffer (its argument: which queue)
DOWNLINK_OVERFLOW_EVENT = "Kit.comQueue.QueueOverflow"


def settle(link: Downlink, seed: int) -> None:
    """Wait, by the deployment's own time tags, for a telemetry sample taken
    SETTLE_S after the last NO_OP's answer."""
    settled = link.event_time.get(link.dictionary.noop_event, 0.0) + SETTLE_S
    if not link.pump(lambda: link.telemetry_time.get(HEARTBEAT_CHANNEL, 0.0) >= settled, REPLY_TIMEOUT_S):
        raise KitError(f"no {HEARTBEAT_CHANNEL} telemetry after the last batch (seed {seed})")


#: A read-out (a few packets that make the deployment write its on-change
#: counts again, once the downlink has drained) during which the downlink
#: overflowed again may have lost the very writes it was for
#: (mps2/an385 baremetal_passive: FilesReceived 169 beside 170 FileReceived
#: events, 32 overflows under the fuzzing): it is played again, at most this
#: many read-outs in all. A count the deployment got wrong stays wrong in
#: every read-out; a lost write does not
READ_OUTS_MAX = 3


class NoopClosed(Protocol):
    """What a fuzzer's outcome keeps of the NO_OPs closing its batches."""

    noops_sent: int
    missed: list[int]
    halt: str


def send_closed_by_noop(link: Downlink, batch: bytes, noop: bytes, outcome: NoopClosed,
                        halted: Callable[[], str]) -> bool:
    """Send `batch` closed by a NO_OP and wait for its answer: the NO_OP is
    counted, an answer missed within REPLY_TIMEOUT_S is recorded, and
    `halted` is asked. Whether it was answered with the deployment running."""
    link.send(batch + noop + PADDING)
    outcome.noops_sent += 1
    replied = link.pump(functools.partial(answered, link, outcome.noops_sent), REPLY_TIMEOUT_S)
    if not replied:
        outcome.missed.append(outcome.noops_sent)
    outcome.halt = halted()
    return replied and not outcome.halt


@dataclass(frozen=True)
class ReadOut:
    played: int
    #: The downlink overflowed during the last one too: a count written in
    #: it may not have come down
    overflowed: bool


def read_out(link: Downlink, play: Callable[[], bool], seed: int) -> ReadOut:
    """Play one read-out (`play`: its packets and a NO_OP; False where the
    NO_OP went unanswered or the deployment halted), then settle; again
    while the downlink overflowed during it (READ_OUTS_MAX in all)."""
    for played in range(1, READ_OUTS_MAX + 1):
        overflows = link.events[DOWNLINK_OVERFLOW_EVENT]
        if not play():
            return ReadOut(played, overflowed=False)
        settle(link, seed)
        if link.events[DOWNLINK_OVERFLOW_EVENT] == overflows:
            return ReadOut(played, overflowed=False)
    return ReadOut(READ_OUTS_MAX, overflowed=True)


def after_boot_burst(link: Downlink, seed: int) -> None:
    """Wait for the boot's events to have come down (BOOT_SETTLE_S)."""
    if not link.pump(lambda: link.telemetry_time.get(HEARTBEAT_CHANNEL, 0.0) >= BOOT_SETTLE_S, REPLY_TIMEOUT_S):
        raise KitError(f"no {HEARTBEAT_CHANNEL} telemetry {BOOT_SETTLE_S:.0f} s into the deployment's time "
                       f"(seed {seed})")


# The longest invalid frame of any kind (garbage; the framed kinds are at
# most 32 bytes)
INVALID_FRAME_MAX = 48
# fprime-zephyr's ZephyrUartDriver receive ring (RING_BUF_SIZE), drained at
# each 100 Hz call: a batch lands in it whole, so the worst batch must fit,
# or the NO_OP closing it could be dropped
UART_RING_BYTES = 1024
# Invalid frames per batch: at most 4 x 48 + NO_OP + padding = 292 bytes.
# 12 a batch cut the reference board's 10,000 frames from 34 to 21 s, but a
# fresh-clone run then saw one qemu_cortex_m3 baremetal NO_OP answered only
# after the next batch (seed 20261201, NO_OP 259 of 261), never seen in many
# runs at 4: back to 4 until the late uplink (README, the ground link) is
# understood
PER_BATCH = 4


def run(socket_path: Path, dictionary: Path, seed: int, invalid_frames: int, per_batch: int = PER_BATCH,
        halted: Callable[[], str] = lambda: "") -> Outcome:
    """Send `invalid_frames` invalid frames in batches of `per_batch`, each
    batch closed by a NO_OP, and return what the deployment answered.
    `halted` is asked after every batch (it also drains the console): the
    console lines that show a halt, or ""."""
    deployment = Deployment.from_dictionary(dictionary)
    rng = random.Random(seed)
    outcome = Outcome(seed, dispatcher=deployment.dispatcher, dispatcher_telemetry=deployment.dispatcher_telemetry)
    noop = frame(command(deployment.noop))
    if per_batch * INVALID_FRAME_MAX + len(noop) + len(PADDING) > UART_RING_BYTES:
        raise ValueError(f"{per_batch} invalid frames a batch could overrun the UART's {UART_RING_BYTES}-byte ring")
    link = Downlink(socket_path, dictionary)
    try:
        after_boot_burst(link, seed)
        while outcome.invalid_sent < invalid_frames and not outcome.halt:
            batch = b""
            for _ in range(min(per_batch, invalid_frames - outcome.invalid_sent)):
                kind = rng.choice(INVALID_KINDS)
                invalid = invalid_frame(kind, rng, deployment)
                assert len(invalid) <= INVALID_FRAME_MAX, f"{kind}: {len(invalid)} bytes"
                batch += invalid
                outcome.sent[kind] += 1
            outcome.bytes_sent += len(batch) + len(noop) + len(PADDING)
            # A missed answer fails the run (Outcome.failures); go on, since
            # the next batch's bytes may free what holds it up, but not forever
            send_closed_by_noop(link, batch, noop, outcome, halted)
            if len(outcome.missed) >= MISSED_ANSWERS_MAX:
                break
        if outcome.halt:
            outcome.noops_answered = link.events[link.dictionary.noop_event]
            outcome.events = link.events
            return outcome
        # The counters after the last batch: the last NO_OP's answer means
        # every byte before it was processed. Telemetry waits behind events
        # in the downlink queue, so samples arriving after that answer can
        # be older than it: wait, by the deployment's own time tags, for a
        # LinkHealth sample taken SETTLE_S after it (settle). The
        # dispatcher's channels are sent on change only, and a write lost
        # where the downlink's telemetry queue overflowed would leave the
        # ground an old count: once the downlink has drained, one more
        # unknown opcode and a NO_OP write both again (READ_OUT_COMMANDS).
        settle(link, seed)
        if not outcome.missed and deployment.dispatcher_telemetry:

            def play() -> bool:
                bad = frame(command(unknown_opcode(rng, deployment)))
                outcome.bytes_sent += len(bad) + len(noop) + len(PADDING)
                outcome.read_out_commands += 1
                return send_closed_by_noop(link, bad, noop, outcome, halted)

            outcome.read_out_overflowed = read_out(link, play, seed).overflowed
        outcome.noops_answered = link.events[link.dictionary.noop_event]
        outcome.events = link.events
        outcome.telemetry = {name: int(link.telemetry[name]) for name in count_channels(link.dictionary)
                             if name in link.telemetry}
    finally:
        link.close()
    return outcome
