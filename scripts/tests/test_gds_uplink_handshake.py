# SPDX-License-Identifier: Apache-2.0
"""fprime-gds's file uplinker, as the kit's setup patches it
(modules/fprime-gds/patches): a packet's handshake that comes back before
the send that caused it has returned is not lost.

fprime-gds sends a file one packet per handshake: the link's process sends
each packet's copy back once it has written it, and the uplinker, on the
thread that reads the link, sends the next packet when the copy matches
what it expects. It stored what it expects only after the send returned,
so a handshake that overtook that return was ignored and the upload
stalled until its 20 s time-out gave it up: a ground-link test saw a
file's start packet reach the deployment and nothing after it (CI's run of
63e0d34, mps2/an385 baremetal_passive, FileUplink's InvalidReceiveMode
when the next file started)."""

from __future__ import annotations

import threading
import time
from pathlib import Path

from fprime_gds.common.data_types.file_data import DataPacketData, EndPacketData, StartPacketData
from fprime_gds.common.files.helpers import TransmitFile
from fprime_gds.common.files.uplinker import FileStates, FileUplinker

from kittools.workspace import check_gds_patched

HEADER = b"\x00" * 8  # what the uplinker strips from the encoder's return
OVERTAKE_S = 0.2  # how long a send waits, holding its return, for the handshake


class OvertakingLink:
    """A file encoder whose link answers each packet before the send returns:
    the handshake is delivered on a thread of its own while data_callback is
    still running, which waits OVERTAKE_S for it."""

    def __init__(self) -> None:
        self.uplinker: FileUplinker | None = None
        self.sent: list[object] = []

    def data_callback(self, packet: object) -> bytes:
        self.sent.append(packet)
        payload = f"{len(self.sent)}:{type(packet).__name__}".encode()
        assert self.uplinker is not None
        answer = threading.Thread(target=self.uplinker.data_callback, args=(payload,))
        answer.start()
        answer.join(OVERTAKE_S)
        return HEADER + payload


def test_a_handshake_that_overtakes_its_send_is_kept(tmp_path: Path) -> None:
    source = tmp_path / "file.bin"
    source.write_bytes(b"0123456789")
    link = OvertakingLink()
    uplinker = FileUplinker(link, chunk=256)
    link.uplinker = uplinker
    try:
        upload = TransmitFile(str(source), "/file.bin")
        uplinker.start(upload)
        deadline = time.monotonic() + 10 * OVERTAKE_S * 3
        while uplinker.state != FileStates.IDLE and time.monotonic() < deadline:
            time.sleep(0.01)
        kinds = [type(packet) for packet in link.sent]
        assert kinds == [StartPacketData, DataPacketData, EndPacketData], (
            f"the upload stopped after {[k.__name__ for k in kinds]}: a handshake that came back before its send "
            "returned was ignored (is modules/fprime-gds/patches applied? scripts/setup.sh)")
        assert uplinker.state == FileStates.IDLE
        assert upload.state == "FINISHED"
    finally:
        uplinker.exit()


def test_the_installed_fprime_gds_carries_the_kits_patches() -> None:
    # What every ground station checks before it starts (kittools.link.ground)
    check_gds_patched()
