# SPDX-License-Identifier: Apache-2.0
"""An fprime-gds communication adapter for the kit's ground link under QEMU.

QEMU exposes the board's link UART as a Unix socket it listens on
(`KIT_LINK_SOCKET`, app/kit.cmake). fprime-gds speaks TCP and serial ports
only, so the kit adds this adapter through fprime-gds's own plugin system
(the `fprime_gds` entry point in scripts/pyproject.toml):

    fprime-gds --comm-adapter kit-unix --kit-socket /tmp/kit-link-….sock ...

It reconnects whenever QEMU restarts, as fprime-gds's own adapters do, and
never raises from read or write (fprime-gds's adapter contract).

QEMU's UART takes host bytes with no baud timing, and fprime-gds writes as
fast as its loop runs: its file uplinker sends the next 256 B packet as soon
as the last is written. A 16 KiB uplink unpaced lost 10,636 of 18,344 bytes
in the firmware's 1 KiB receive ring (mps2/an385). With `--kit-baud` the
adapter writes at the link's line rate, as a serial port would, in writes of
at most client.LINE_BURST_S of the line; the station plays QEMU in real
time, so the host's clock is the deployment's.
"""

from __future__ import annotations

import logging
import os
import socket
import stat
import threading
import time
from collections.abc import Iterator
from typing import Any

from fprime_gds.common.communication.adapters.base import BaseAdapter
from fprime_gds.plugin.definitions import gds_plugin_implementation

from kittools.link.client import LINE_BURST_S, bytes_per_second

LOGGER = logging.getLogger("kit.link")

# How long to wait between connection attempts while QEMU is not listening
RETRY_SECONDS = 0.5
READ_CHUNK = 4096


class UnixSocketAdapter(BaseAdapter):
    """Bytes to and from a Unix stream socket (QEMU's `-chardev socket,path=`)."""

    def __init__(self, socket_path: str, baud: int = 0) -> None:
        self.socket_path = socket_path
        self.pacer = HostLine(baud) if baud > 0 else None
        self._socket: socket.socket | None = None
        self._lock = threading.Lock()
        self._next_attempt = 0.0

    def __repr__(self) -> str:
        return f"kit-unix@{self.socket_path}"

    def open(self) -> None:
        self._connect()

    def close(self) -> None:
        with self._lock:
            if self._socket is not None:
                self._socket.close()
                self._socket = None

    def _connect(self) -> socket.socket | None:
        with self._lock:
            if self._socket is not None:
                return self._socket
            now = time.monotonic()
            if now < self._next_attempt:
                return None
            self._next_attempt = now + RETRY_SECONDS
            candidate = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            try:
                candidate.connect(self.socket_path)
            except OSError as error:
                candidate.close()
                LOGGER.debug("link %s not up yet: %s", self.socket_path, error)
                return None
            LOGGER.info("connected to the ground link at %s", self.socket_path)
            self._socket = candidate
            return candidate

    def _drop(self, dead: socket.socket) -> None:
        with self._lock:
            if self._socket is dead:
                dead.close()
                self._socket = None

    def read(self, timeout: float = 0.500) -> bytes:
        connection = self._connect()
        if connection is None:
            time.sleep(min(timeout, RETRY_SECONDS))
            return b""
        connection.settimeout(timeout)
        try:
            data = connection.recv(READ_CHUNK)
        except TimeoutError:
            return b""
        except OSError:
            self._drop(connection)
            return b""
        if not data:  # QEMU closed the link (it stopped)
            self._drop(connection)
        return data

    def write(self, frame: bytes) -> bool:
        connection = self._connect()
        if connection is None:
            return False
        try:
            if self.pacer is None:
                connection.sendall(frame)
            else:
                for piece in self.pacer.pieces(frame):
                    connection.sendall(piece)
        except OSError:
            self._drop(connection)
            return False
        return True

    @classmethod
    def get_name(cls) -> str:
        return "kit-unix"

    @classmethod
    def get_arguments(cls) -> dict[tuple[str, ...], dict[str, Any]]:
        return {
            ("--kit-socket",): {
                "dest": "socket_path",
                "type": str,
                "required": False,
                "default": None,
                "help": "Unix socket of the kit's ground link under QEMU (KIT_LINK_SOCKET, the build's CMakeCache)",
            },
            ("--kit-baud",): {
                "dest": "baud",
                "type": int,
                "required": False,
                "default": 0,
                "help": "the link's line rate (the firmware's LINK line): writes go no faster; 0 writes at once",
            },
        }

    @classmethod
    def check_arguments(cls, socket_path: str | None, baud: int = 0) -> None:
        if baud < 0:
            raise ValueError(f"--kit-baud must be a line rate or 0, not {baud}")
        if not socket_path:
            raise ValueError("--kit-socket is required with --comm-adapter kit-unix")
        if os.path.exists(socket_path) and not stat.S_ISSOCK(os.stat(socket_path).st_mode):
            raise ValueError(f"{socket_path} exists and is not a socket")

    @classmethod
    @gds_plugin_implementation
    def register_communication_plugin(cls) -> type[BaseAdapter]:
        return cls


class HostLine:
    """A serial line's pace on the host's clock: a write's bytes leave in
    pieces of at most LINE_BURST_S of the line, each when the line would
    have carried the ones before it."""

    def __init__(self, baud: int, clock: Any = time.monotonic, sleep: Any = time.sleep) -> None:
        self.per_second = bytes_per_second(baud)
        self.burst = max(1, int(self.per_second * LINE_BURST_S))
        self._clock = clock
        self._sleep = sleep
        self._free_at = 0.0

    def pieces(self, data: bytes) -> Iterator[bytes]:
        for start in range(0, len(data), self.burst):
            piece = data[start:start + self.burst]
            wait = self._free_at - self._clock()
            if wait > 0:
                self._sleep(wait)
            # An idle line does not bank time: it starts from now
            self._free_at = max(self._free_at, self._clock()) + len(piece) / self.per_second
            yield piece
