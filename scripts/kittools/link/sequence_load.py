# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep's sequence axis: a sequence that runs as a further
load, where the build has F´'s command sequencer (Svc.CmdSequencer).

The sequence is one an operator writes: SEQUENCE_RECORDS NO_OPs with no
wait between them (`R00:00:00`), compiled by fprime-gds's fprime-seqgen
against the build's dictionary and uplinked once, through F´'s file uplink,
to the RAM file system's scratch file (Kit.RamFs.scratchFile). A level of
the axis is the sequencer's commands a second: the ground's `CS_RUN ...
NO_BLOCK` at level / SEQUENCE_RECORDS a second, each run opening, reading
and checking the file (its CRC) and then dispatching its commands one after
the other, each when the last one's answer is back. What the deployment ran
is counted by the NO_OPs' answers (kittools.link.serial_sweep.sequence_axis
says why not by the sequencer's own count); a run asked for while the last
one still runs is refused (CS_InvalidMode), and its commands count as not
delivered.
"""

from __future__ import annotations

import struct
import tempfile
from pathlib import Path

from kittools.link.client import (
    DESCRIPTOR,
    FILE_DATA_FIELDS,
    FILE_PACKET_HEADER,
    FW_PACKET_FILE,
    T_DATA,
    T_END,
    T_START,
    Downlink,
    command,
    file_path_field,
    frame,
    gds_config_made,
)
from kittools.link.dictionary import Dictionary
from kittools.link.file_fuzz import END_FIELDS, SCRATCH_CONSTANT, START_FIELDS, cfdp_checksum
from kittools.link.health import REPLY_TIMEOUT_S
from kittools.link.services import string_argument
from kittools.workspace import KitError

#: The sequence's commands: 8 NO_OPs take 165 B with F´'s header and CRC,
#: within the smallest RAM file system file the kit builds (256 B,
#: CONFIG_KIT_RAMFS_FILE_SIZE), which the sequencer's buffer is sized to
SEQUENCE_RECORDS = 8
#: Svc.CmdSequencer's command that runs a file: its owner is the sequencer
RUN_COMMAND = "CS_RUN"
#: Svc.CmdSequencer.BlockState (U8): NO_BLOCK answers CS_RUN once the run starts
NO_BLOCK = struct.Struct(">B").pack(1)
#: fprime-seqgen's time base for a sequence that runs on any clock (TB_DONT_CARE)
ANY_TIME_BASE = 0xFFFF
#: File data a packet carries: the link's buffers hold a frame of it with room to spare
DATA_BYTES = 64
SOURCE_NAME = "kit-sweep.seq"
#: Between two file packets: two of the UART driver's 100 Hz polls, so the
#: link's buffers (six) never hold more than a packet or two of them
PACKET_GAP_S = 0.02


def sequence_text(noop_command: str, records: int = SEQUENCE_RECORDS) -> str:
    """The sequence as an operator writes it (fprime-gds's .seq text)."""
    return "; The serial-load sweep's sequence: NO_OPs, one after the other\n" + "".join(
        f"R00:00:00 {noop_command}\n" for _ in range(records))


def compile_sequence(dictionary: Path, noop_command: str, records: int = SEQUENCE_RECORDS) -> bytes:
    """The sequence's binary, as fprime-seqgen writes it for this dictionary."""
    from fprime_gds.common.tools.seqgen import generateSequence  # the GDS's own compiler

    gds_config_made()
    with tempfile.TemporaryDirectory(prefix="kit-seq-") as folder:
        text, binary = Path(folder) / "sweep.seq", Path(folder) / "sweep.bin"
        text.write_text(sequence_text(noop_command, records))
        try:
            generateSequence(str(text), str(binary), str(dictionary), ANY_TIME_BASE)
        except Exception as error:  # the GDS's own exceptions, whatever their class
            raise KitError(f"fprime-seqgen could not compile the sweep's sequence against {dictionary}: "
                           f"{error}") from None
        return binary.read_bytes()


def file_frames(data: bytes, destination: str) -> list[bytes]:
    """The frames that uplink `data` to `destination` through F´'s file
    uplink: a start, the data in order, an end with its CFDP checksum."""
    packets = [FILE_PACKET_HEADER.pack(T_START, 0) + START_FIELDS.pack(len(data)) + file_path_field(SOURCE_NAME)
               + file_path_field(destination)]
    for index, offset in enumerate(range(0, len(data), DATA_BYTES), start=1):
        chunk = data[offset:offset + DATA_BYTES]
        packets.append(FILE_PACKET_HEADER.pack(T_DATA, index) + FILE_DATA_FIELDS.pack(offset, len(chunk)) + chunk)
    packets.append(FILE_PACKET_HEADER.pack(T_END, len(packets)) + END_FIELDS.pack(cfdp_checksum(data, 0)))
    return [frame(DESCRIPTOR.pack(FW_PACKET_FILE) + packet) for packet in packets]


class SequenceLoad:
    """The sweep's sequence on a booted build: uplinked, run once to show it
    runs, then run at each level's rate (`run_frame`)."""

    def __init__(self, link: Downlink, names: Dictionary, sequencer: str) -> None:
        if names.file_uplink is None:
            raise KitError(f"{names.path}: {sequencer} has no file uplink beside it to load a sequence through")
        self.link = link
        self.sequencer = sequencer
        self.files_received = f"{names.file_uplink}.FilesReceived"
        self.file_received = f"{names.file_uplink}.FileReceived"
        self.noop_event = names.noop_event
        scratch = str(names.constant(SCRATCH_CONSTANT))
        self.data = compile_sequence(names.path, names.noop_command)
        self.run_frame = frame(command(names.opcode(f"{sequencer}.{RUN_COMMAND}"), string_argument(scratch) + NO_BLOCK))
        self.scratch = scratch

    def load(self) -> None:
        """Uplink the sequence and run it once: every NO_OP of it answered,
        or KitError (a sequence its buffer cannot hold: CS_FileSizeError
        among the events). The file's arrival is the file uplink's event or
        its count (telemetry), whichever comes down: a cooperative model's
        downlink drops the channels a busy telemetry cycle sends last, and
        fprime-util's template deployment lost every write of the
        sequencer's counts (mps2/an385, every cooperative model); the run's
        answers are events, which the sweep keeps few (routine severities
        filtered out, as during the axis)."""
        counted, told = self._count(self.files_received), self.link.events[self.file_received]
        for data in file_frames(self.data, self.scratch):
            self.link.send(data)
            self.link.pump(lambda: False, PACKET_GAP_S)
        if not self.link.pump(lambda: self._count(self.files_received) > counted
                              or self.link.events[self.file_received] > told, REPLY_TIMEOUT_S):
            raise KitError(f"the sweep's sequence ({len(self.data)} B) was not received by the file uplink "
                           f"within {REPLY_TIMEOUT_S:.0f} s")
        answered = self.answered()
        self.link.send(self.run_frame)
        if not self.link.pump(lambda: self.answered() >= answered + SEQUENCE_RECORDS, REPLY_TIMEOUT_S):
            raise KitError(f"the sweep's sequence ({len(self.data)} B, {SEQUENCE_RECORDS} NO_OPs in "
                           f"{self.scratch}) had {self.answered() - answered} NO_OP(s) answered "
                           f"{REPLY_TIMEOUT_S:.0f} s after {RUN_COMMAND}")

    def answered(self) -> int:
        """The deployment's NO_OP answers so far: a command of the sequence
        ran (the ground's own traffic on the axis has no NO_OP)."""
        return self.link.events[self.noop_event]

    def _count(self, channel: str) -> int:
        return int(self.link.telemetry.get(channel, 0))
