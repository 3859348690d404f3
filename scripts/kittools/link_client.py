# SPDX-License-Identifier: Apache-2.0
"""A raw client of a build's ground link: F´ frames up, the downlink decoded.

The kit's own tools that must control every byte on the link (the uplink
fuzzer, the serial-load sweep) use it instead of fprime-gds; the downlink is
decoded with fprime-gds's own framing and decoders and the build's
dictionary, so both read the deployment as the GDS does.
"""

from __future__ import annotations

import socket
import struct
import time
import zlib
from collections import Counter
from collections.abc import Callable
from pathlib import Path

from .workspace import KitError

START_WORD = 0xDEADBEEF
HEADER = struct.Struct(">II")  # start word, length (F´'s FprimeProtocol.FrameHeader)
TRAILER = struct.Struct(">I")  # CRC-32 of header and payload
DESCRIPTOR = struct.Struct(">H")  # FwPacketDescriptorType
OPCODE = struct.Struct(">I")  # FwOpcodeType
FW_PACKET_COMMAND = 0
FW_PACKET_TELEM = 1
FW_PACKET_LOG = 2


def frame(payload: bytes) -> bytes:
    header = HEADER.pack(START_WORD, len(payload))
    return header + payload + TRAILER.pack(zlib.crc32(header + payload) & 0xFFFFFFFF)


def command(opcode: int, arguments: bytes = b"") -> bytes:
    return DESCRIPTOR.pack(FW_PACKET_COMMAND) + OPCODE.pack(opcode) + arguments


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
        # The arguments of the newest event of each name
        self.event_args: dict[str, tuple[object, ...]] = {}
        # The newest time tag of anything decoded: the deployment's clock, as
        # far as the ground knows it
        self.now = 0.0
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
