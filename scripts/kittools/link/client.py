# SPDX-License-Identifier: Apache-2.0
"""A raw client of a build's ground link: F´ frames up, the downlink decoded.

The kit's own tools that must control every byte on the link (the uplink
fuzzer, the serial-load sweep) use it instead of fprime-gds; the downlink is
decoded with fprime-gds's own framing and decoders and the build's
dictionary, so both read the deployment as the GDS does.
"""

from __future__ import annotations

import random
import re
import socket
import struct
import threading
import time
import zlib
from collections import Counter, deque
from collections.abc import Callable
from pathlib import Path

from kittools.link.dictionary import Dictionary
from kittools.workspace import KitError

_GDS_CONFIG = threading.Lock()


def gds_config_made() -> None:
    """fprime-gds's ConfigManager, made whole before any of its readers.
    It is a singleton whose first construction is not thread-safe: a
    thread that gets it between its creation and its defaults finds no
    types (a CI run's fuzzer, its decoder made while another build's checks
    made theirs: "Unknown type name: FwEventIdType"). Call it before
    anything of fprime-gds's that decodes or loads a dictionary."""
    from fprime_gds.common.utils.config_manager import ConfigManager

    with _GDS_CONFIG:
        ConfigManager()

START_WORD = 0xDEADBEEF
HEADER = struct.Struct(">II")  # start word, length (F´'s FprimeProtocol.FrameHeader)
TRAILER = struct.Struct(">I")  # CRC-32 of header and payload
DESCRIPTOR = struct.Struct(">H")  # FwPacketDescriptorType
OPCODE = struct.Struct(">I")  # FwOpcodeType
FW_PACKET_COMMAND = 0
FW_PACKET_TELEM = 1
FW_PACKET_LOG = 2
FW_PACKET_FILE = 3
# Fw::FilePacket (Fw/FilePacket/FilePacket.hpp): its types, its header and a
# data packet's fields
T_START, T_DATA, T_END, T_CANCEL = 0, 1, 2, 3
FILE_PACKET_HEADER = struct.Struct(">BI")  # type, sequence index
FILE_DATA_FIELDS = struct.Struct(">IH")  # byte offset, data size


#: A UART character on the line: start bit, 8 data bits, stop bit
BITS_PER_BYTE = 10
# The firmware's LINK line names its line rate (app/src/Report.cpp: the link
# UART's devicetree current-speed)
LINK_BAUD = re.compile(r"\bbaud=(\d+)")
# Bytes noise never holds: no start word (DE AD BE EF) can form in it or
# across its edges with a neighbour, so noise never frames a command
START_WORD_BYTES = frozenset(b"\xde\xad\xbe\xef")
NOISE_BYTES = bytes(value for value in range(256) if value not in START_WORD_BYTES)
# LinkHealth writes its telemetry every 100 ms: the ground's view of the
# deployment's clock moves in steps of about this much
CLOCK_STEP_S = 0.1


def line_rate(link_line: str) -> int:
    """The line rate (bits/s) a LINK line names."""
    found = LINK_BAUD.search(link_line)
    if found is None:
        raise KitError(f"the firmware's LINK line names no line rate (baud=): {link_line!r}; is it a kit build "
                       "of this version?")
    return int(found.group(1))


def bytes_per_second(baud: int) -> float:
    """What a line carries at most, in bytes per second."""
    return baud / BITS_PER_BYTE


def noise(rng: random.Random, count: int) -> bytes:
    """`count` random bytes that frame nothing (no start-word byte)."""
    return bytes(rng.choices(NOISE_BYTES, k=count))


def frame(payload: bytes) -> bytes:
    header = HEADER.pack(START_WORD, len(payload))
    return header + payload + TRAILER.pack(zlib.crc32(header + payload) & 0xFFFFFFFF)


def command(opcode: int, arguments: bytes = b"") -> bytes:
    return DESCRIPTOR.pack(FW_PACKET_COMMAND) + OPCODE.pack(opcode) + arguments


def file_path_field(path: str) -> bytes:
    """A path in a file packet (a start packet's source and destination):
    Fw::FilePacket's one length byte, then the bytes."""
    encoded = path.encode()
    return bytes([len(encoded)]) + encoded


class Downlink:
    """The link socket: bytes up, and the downlink decoded into events (by
    name) and the latest value of every telemetry channel."""

    def __init__(self, socket_path: Path, dictionary: Path) -> None:
        from fprime_gds.common.communication.framing import FpFramerDeframer
        from fprime_gds.common.decoders.ch_decoder import ChDecoder
        from fprime_gds.common.decoders.event_decoder import EventDecoder
        from fprime_gds.common.models.dictionaries import Dictionaries

        gds_config_made()

        #: The dictionary's names: the dispatcher's NO_OP and its events
        self.dictionary = Dictionary.read(dictionary)
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
        # The arguments of the newest event of each name
        self.event_args: dict[str, tuple[object, ...]] = {}
        # File packets (Svc.FileDownlink's): the data bytes of every data
        # packet, and the files whose end packet came down
        self.file_bytes = 0
        self.files_ended = 0
        # The newest time tag of anything decoded: the deployment's clock, as
        # far as the ground knows it
        self.now = 0.0
        # (host clock, deployment clock) at each step of `now`: the pace at
        # which the deployment's time passes in the host's
        self._steps: deque[tuple[float, float]] = deque(maxlen=20)
        self._outbox = bytearray()
        #: Every byte given to send(), taken by the link or not yet
        self.bytes_sent = 0
        self._socket = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            self._socket.connect(str(socket_path))
        except OSError as error:
            raise KitError(f"cannot connect to the link {socket_path}: {error} (is QEMU running it?)") from None

    def close(self) -> None:
        self._socket.close()

    def send(self, data: bytes) -> None:
        """Queue bytes for the link and write what it takes now. Never
        blocks: QEMU writes the downlink synchronously from its main loop,
        so a host blocked writing while QEMU is blocked writing to the host
        would hold both for ever. What the link has not taken yet
        (`unsent`) goes while the downlink is pumped."""
        self._outbox += data
        self.bytes_sent += len(data)
        self._flush()

    def unsent(self) -> int:
        """Bytes queued that the link has not taken yet (QEMU's UART reads
        only as fast as the firmware empties it)."""
        return len(self._outbox)

    def _flush(self) -> None:
        # Non-blocking for the writes (pump sets its read time-out again)
        self._socket.settimeout(0.0)
        while self._outbox:
            try:
                taken = self._socket.send(self._outbox)
            except BlockingIOError:
                return
            except OSError as error:
                raise KitError(f"the link refused bytes: {error} (QEMU stopped?)") from None
            del self._outbox[:taken]

    def estimated_now(self) -> float:
        """The deployment's time now: its newest time tag, moved on by the
        host's clock at the pace its recent tags came, and never more than
        one clock step past the newest tag. QEMU's virtual time runs at no
        fixed pace against the host's (icount skips idle time): only the
        deployment's own tags say where it is."""
        if len(self._steps) < 2:
            return self.now
        (host_first, first), (host_last, last) = self._steps[0], self._steps[-1]
        if host_last <= host_first:
            return self.now
        pace = (last - first) / (host_last - host_first)
        return self.now + min(pace * (time.monotonic() - host_last), CLOCK_STEP_S)

    def pump(self, until: Callable[[], bool], timeout_s: float) -> bool:
        """Read and decode the downlink until `until()` holds or the time-out."""
        deadline = time.monotonic() + timeout_s
        while not until():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            self._flush()
            # Back soon to write while bytes wait to go
            self._socket.settimeout(min(remaining, 0.005 if self._outbox else 0.5))
            try:
                chunk = self._socket.recv(65536)
            except TimeoutError:
                continue
            if not chunk:
                raise KitError("the link closed: QEMU stopped")
            self._decode(chunk)
        return True

    def _decode(self, chunk: bytes) -> None:
        before = self.now
        self._decode_packets(chunk)
        if self.now > before:
            self._steps.append((time.monotonic(), self.now))

    def _decode_packets(self, chunk: bytes) -> None:
        packets, self._pending, _ = self._deframer.deframe_all(self._pending + chunk, no_copy=False)
        for packet in packets:
            (descriptor,) = DESCRIPTOR.unpack_from(packet)
            body = packet[DESCRIPTOR.size:]
            if descriptor == FW_PACKET_LOG:
                for event in self._events.decode_api(body):
                    name = event.template.get_full_name()
                    self.events[name] += 1
                    self.event_time[name] = event.get_time().get_float()
                    self.event_args[name] = tuple(arg.val for arg in event.get_args())
                    self.now = max(self.now, self.event_time[name])
            elif descriptor == FW_PACKET_TELEM:
                for sample in self._channels.decode_api(body):
                    name = sample.template.get_full_name()
                    self.telemetry[name] = sample.get_val()
                    self.telemetry_time[name] = sample.get_time().get_float()
                    self.now = max(self.now, self.telemetry_time[name])
            elif descriptor == FW_PACKET_FILE and len(body) >= FILE_PACKET_HEADER.size:
                self._count_file_packet(body)

    def _count_file_packet(self, body: bytes) -> None:
        (kind, _sequence) = FILE_PACKET_HEADER.unpack_from(body)
        if kind == T_DATA and len(body) >= FILE_PACKET_HEADER.size + FILE_DATA_FIELDS.size:
            (_offset, size) = FILE_DATA_FIELDS.unpack_from(body, FILE_PACKET_HEADER.size)
            self.file_bytes += size
        elif kind == T_END:
            self.files_ended += 1


class Stopwatch:
    """The deployment's seconds since a start on its clock. The ground's only
    clock for the deployment is its downlink's time tags
    (Downlink.estimated_now); a Line carries bytes by it."""

    def __init__(self, link: Downlink) -> None:
        self.link = link
        self.started = link.estimated_now()

    def elapsed(self) -> float:
        return self.link.estimated_now() - self.started


#: The most of the line's time a write carries: QEMU's UART takes host bytes
#: with no baud timing of its own, so a write reaches the firmware as one
#: storm of receive interrupts. A real line brings a byte every 87 µs at
#: 115200 baud; with bytes the host wrote 256 at a time (a host that fell
#: behind catching up) the baremetal 1 kHz group saw 1.6 ms latencies, about
#: 256 receive interrupts' worth, and slipped in some plays and not others.
LINE_BURST_S = 0.002
# How often a line's bytes are written while they wait: often enough that
# LINE_BURST_S-sized writes keep up with a full line
LINE_STEP_S = 0.001
#: A loop that feeds a line looks at the console this long: a longer look
#: (it waits when QEMU prints nothing) slowed the loop below a full line
CONSOLE_PEEK_S = 0.0002


class Line:
    """The ground's end of a serial line: bytes queued here go up the link
    at no more than its line rate in the deployment's time, and at most
    LINE_BURST_S of it in one write. Bytes a late host owes wait their turn
    on the line instead of reaching the firmware faster than a line could
    bring them. Played in real time (ground.boot(realtime=True)) the
    deployment's clock runs with the host's, so writes are small and even;
    in skipped idle time one host step is several of the deployment's."""

    def __init__(self, link: Downlink, baud: int) -> None:
        self.link = link
        self.per_second = bytes_per_second(baud)
        self.burst = max(1, int(self.per_second * LINE_BURST_S))
        self._queue = bytearray()
        self._credit = float(self.burst)
        self._at = link.estimated_now()

    def put(self, data: bytes) -> None:
        self._queue += data

    def waiting(self) -> int:
        """Bytes queued that the line has not carried yet."""
        return len(self._queue)

    def feed(self) -> int:
        """Write what the line carries now; how many bytes that was."""
        now = self.link.estimated_now()
        # The estimate steps back when a late time tag corrects it: no credit then
        if now > self._at:
            self._credit = min(float(self.burst), self._credit + (now - self._at) * self.per_second)
            self._at = now
        count = min(int(self._credit), len(self._queue))
        # Nothing more while the link has bytes it has not taken (they would
        # go at once when it does)
        if count == 0 or self.link.unsent():
            return 0
        self.link.send(bytes(self._queue[:count]))
        del self._queue[:count]
        self._credit -= count
        return count
