# SPDX-License-Identifier: Apache-2.0
"""LinkHealth's counts as the host reads them from the downlink: where every
byte sent up the link went (read by the UART, dropped by its receive ring,
framed, discarded by the frame detector), and a sample of them taken once
the link has settled. The serial-load sweep (kittools.link.serial_sweep) and
the flood (kittools.link.flood) account for their traffic with them."""

from __future__ import annotations

from dataclasses import dataclass

from kittools.link.client import Downlink
from kittools.workspace import KitError

#: How long the host waits for the deployment's answer or telemetry
REPLY_TIMEOUT_S = 30.0


@dataclass(frozen=True)
class LinkCounts:
    """LinkHealth's counts, as its newest telemetry says (kittools reads
    deltas of them around a point or a flood)."""

    frames_detected: int = 0
    commands_dropped: int = 0
    uart_received: int = 0
    ring_drops: int = 0
    bytes_discarded: int = 0
    bad_checksums: int = 0
    oversized: int = 0
    #: The UART's receive errors, all kinds (written on change: none sent is none)
    uart_errors: int = 0

    CHANNELS = {"frames_detected": "FramesDetected", "commands_dropped": "CommandsDropped",
                "uart_received": "UartBytesReceived", "ring_drops": "UartRingDrops",
                "bytes_discarded": "BytesDiscarded", "bad_checksums": "BadChecksums", "oversized": "Oversized"}
    ERROR_CHANNELS = ("UartOverruns", "UartParityErrors", "UartFramingErrors", "UartBreaks")

    @staticmethod
    def of(link: Downlink) -> LinkCounts:
        values = {key: int(link.telemetry.get(f"Kit.linkHealth.{name}", 0))
                  for key, name in LinkCounts.CHANNELS.items()}
        errors = sum(int(link.telemetry.get(f"Kit.linkHealth.{name}", 0)) for name in LinkCounts.ERROR_CHANNELS)
        return LinkCounts(**values, uart_errors=errors)

    def since(self, before: LinkCounts) -> LinkCounts:
        return LinkCounts(**{key: getattr(self, key) - getattr(before, key)
                             for key in (*LinkCounts.CHANNELS, "uart_errors")})

    def positions(self, frame_size: int) -> int:
        """Byte positions the frame detector decided on: whole frames of
        `frame_size`, and one position per other decision."""
        return self.frames_detected * frame_size + self.bytes_discarded + self.bad_checksums + self.oversized


# LinkHealth writes its counts every 100 ms, changed or not
HEARTBEAT_CHANNEL = "Kit.linkHealth.UartBytesReceived"


def settled_counts(link: Downlink, after: float, what: str) -> LinkCounts:
    """LinkHealth's counts from a sample taken at least `after` (the
    deployment's time) that shows every byte this client sent read by the
    UART: QEMU takes host bytes only as fast as the firmware reads its UART,
    so some may still be on their way after the traffic stopped. The client
    is the link's only writer since boot (the UART counts from boot)."""
    def settled() -> bool:
        return (link.telemetry_time.get(HEARTBEAT_CHANNEL, 0.0) >= after and link.unsent() == 0
                and int(link.telemetry.get(HEARTBEAT_CHANNEL, 0)) >= link.bytes_sent)

    if not link.pump(settled, REPLY_TIMEOUT_S):
        raise KitError(f"no settled {HEARTBEAT_CHANNEL} telemetry after {what} (read "
                       f"{link.telemetry.get(HEARTBEAT_CHANNEL)} of {link.bytes_sent} bytes sent, "
                       f"{link.unsent()} not taken by the link)")
    return LinkCounts.of(link)
