# SPDX-License-Identifier: Apache-2.0
"""The serial-load sweep's sequence axis without QEMU: the file packets that
uplink its sequence (against the file fuzzer's model of Svc.FileUplink), the
sequence an operator would write, what a point offered and delivered, and
the axes a sweep may be asked for."""

from __future__ import annotations

import random
import zlib
from pathlib import Path

import pytest

from kittools.link import client, sequence_load, serial_sweep
from kittools.link.file_fuzz import END_FIELDS, START_FIELDS, FileUplinkModel, cfdp_checksum
from kittools.link.serial_points import AXES, SEQUENCE, PointTraffic
from kittools.workspace import KitError


def _packets(frames: list[bytes]) -> list[bytes]:
    """Each frame's file packet (its descriptor checked and taken off), its CRC checked."""
    packets = []
    for data in frames:
        start, length = client.HEADER.unpack_from(data)
        payload = data[client.HEADER.size:client.HEADER.size + length]
        (crc,) = client.TRAILER.unpack_from(data, client.HEADER.size + length)
        assert start == client.START_WORD and crc == zlib.crc32(data[:client.HEADER.size + length])
        assert client.DESCRIPTOR.unpack_from(payload) == (client.FW_PACKET_FILE,)
        packets.append(payload[client.DESCRIPTOR.size:])
    return packets


@pytest.mark.parametrize("size", [1, sequence_load.DATA_BYTES, sequence_load.DATA_BYTES + 1, 167, 256])
def test_the_sequence_uplinks_as_one_whole_file_file_uplink_accepts(size: int) -> None:
    data = random.Random(size).randbytes(size)
    model = FileUplinkModel()
    received = b""
    for packet in _packets(sequence_load.file_frames(data, "/bin0/file1")):
        kind, index = client.FILE_PACKET_HEADER.unpack_from(packet)
        body = packet[client.FILE_PACKET_HEADER.size:]
        if kind == client.T_START:
            (declared,) = START_FIELDS.unpack_from(body)
            source_length = body[START_FIELDS.size]
            destination = body[START_FIELDS.size + 1 + source_length + 1:].decode()
            assert (declared, destination) == (size, "/bin0/file1")
            model.start(declared, opens=True)
        elif kind == client.T_DATA:
            offset, length = client.FILE_DATA_FIELDS.unpack_from(body)
            chunk = body[client.FILE_DATA_FIELDS.size:]
            assert len(chunk) == length <= sequence_load.DATA_BYTES and offset == len(received)
            model.data(index, offset, chunk)
            received += chunk
        else:
            assert kind == client.T_END
            (checksum,) = END_FIELDS.unpack_from(body)
            assert checksum == cfdp_checksum(data, 0)
            model.end(index, checksum)
    assert received == data
    assert (model.warnings, model.files, model.decode_errors) == (0, 1, 0)


def test_the_sequence_is_an_operators_no_ops_with_no_wait() -> None:
    text = sequence_load.sequence_text("Kit.cmdDisp.CMD_NO_OP", 3)
    records = [line for line in text.splitlines() if not line.startswith(";")]
    assert records == ["R00:00:00 Kit.cmdDisp.CMD_NO_OP"] * 3


def test_a_sequence_point_offers_the_commands_of_its_runs_and_delivers_what_ran() -> None:
    traffic = PointTraffic(SEQUENCE.name, 7, 40, commands_sent=6, commands_dispatched=6,
                           sequence_commands_asked=6 * sequence_load.SEQUENCE_RECORDS, sequence_commands_run=40)
    assert (traffic.offered(), traffic.delivered()) == (48, 40)
    assert "axis=sequence point=7 level=40 repeat=0 offered=48 delivered=40 lost=8" in traffic.record()


def test_every_axis_has_its_play_and_an_unknown_one_is_refused_before_boot(tmp_path: Path) -> None:
    assert list(serial_sweep.AXIS_PLAYS) == [axis.name for axis in AXES]
    with pytest.raises(KitError, match="no serial axis sideways: the axes are uplink, downlink, noise, file, "
                                       "sequence"):
        serial_sweep.run(tmp_path / "no-build", axes=("sequence", "sideways"))


class _NoSequencer:
    """A dictionary with F´'s file downlink and no command sequencer."""

    def owner_of(self, command: str) -> str | None:
        return "Top.fileDownlink" if command == serial_sweep.FILE_DOWNLINK_COMMAND else None


def test_an_axis_named_on_a_build_without_its_service_is_refused_before_boot(tmp_path: Path,
                                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    """`kit serial-sweep --axis sequence` on a build whose profile leaves the
    sequencer out says so, where it played nothing and passed."""
    monkeypatch.setattr(serial_sweep.ground, "link_of", lambda build: type("Link", (), {"dictionary": build})())
    monkeypatch.setattr(serial_sweep.Dictionary, "read", lambda path: _NoSequencer())

    def boot(*args: object, **kwargs: object) -> None:
        raise AssertionError("booted a build that cannot play the axis")

    monkeypatch.setattr(serial_sweep.ground, "boot", boot)
    with pytest.raises(KitError, match=r"no serial axis sequence \(it plays F´'s command sequencer, which this "
                                       r"build leaves out: no CS_RUN in its dictionary\)"):
        serial_sweep.run(tmp_path, axes=("file", "sequence"))
