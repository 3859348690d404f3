# SPDX-License-Identifier: Apache-2.0
"""The file-uplink fuzzer's oracle without QEMU: its CFDP checksum against
fprime-gds's, its model of Svc.FileUplink's rules, and the packets it builds."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from fprime_gds.common.files.helpers import CFDPChecksum

from kittools.build.folder import CONFIG, KCONFIG_STAMP, BuildFolder
from kittools.link import file_fuzz
from kittools.link.file_fuzz import FileUplinkModel

SCRATCH = "/bin0/file1"


def test_the_checksum_is_fprime_gds_s():
    rng = random.Random(7)
    theirs = CFDPChecksum()
    ours = 0
    offset = 0
    for _ in range(50):
        data = rng.randbytes(rng.randint(1, 37))
        theirs.update(data, offset)
        ours = file_fuzz.cfdp_checksum(data, offset, ours)
        offset += len(data)
    assert ours == theirs.value


def test_a_whole_file_is_received_without_a_warning():
    model = FileUplinkModel()
    model.start(8, opens=True)
    model.data(1, 0, b"abcd")
    model.data(2, 4, b"efgh")
    model.end(3, file_fuzz.cfdp_checksum(b"abcdefgh", 0))
    assert (model.packets, model.warnings, model.files, model.receiving) == (4, 0, 1, False)


def test_each_refusal_is_one_warning():
    model = FileUplinkModel()
    model.data(1, 0, b"x")  # no file open
    model.end(1, 0)  # no file open
    model.start(8, opens=False)  # a file the RAM file system does not have
    assert model.warnings == 3 and not model.receiving
    model.start(8, opens=True)
    model.data(1, 0, b"ab")
    model.data(1, 2, b"cd")  # duplicate: not written
    model.data(2, 6, b"xyz")  # past the declared size: not written
    model.start(8, opens=True)  # while receiving: a file that never completed
    assert model.warnings == 6 and model.written == 0
    model.data(5, 0, b"ab")  # out of order: written all the same
    model.end(6, 0)  # bad checksum
    assert model.warnings == 8 and model.files == 1


def test_generated_packets_agree_with_the_model():
    rng = random.Random(20261201)
    model = FileUplinkModel()
    for kind in file_fuzz.KINDS * 20:
        before = (model.packets, model.decode_errors)
        packet = file_fuzz.file_packet(kind, rng, model, SCRATCH)
        assert packet[:2] == bytes([0, file_fuzz.FW_PACKET_FILE])
        if kind == "bad_type":
            assert file_fuzz.T_CANCEL < packet[2] < 0xFF
        decoded = model.decode_errors - before[1]
        assert decoded == (kind in ("bad_type", "truncated", "data_size_mismatch"))
        assert model.packets - before[0] == (0 if decoded else 1)
        if kind == "start_bad_destination":
            assert not packet.endswith(bytes([len(SCRATCH)]) + SCRATCH.encode())


@pytest.mark.parametrize("opened", [False, True])
def test_the_read_out_writes_every_count_again(opened: bool):
    """Each count FileUplink sends on change moves during the read-out,
    whether the fuzzing left a file open or not: the ground's last sample
    of each is then one written after the downlink drained."""
    rng = random.Random(3)
    model = FileUplinkModel()
    if opened:
        model.start(8, opens=True)
        model.data(1, 0, b"ab")
    before = (model.packets, model.warnings, model.files)
    for kind in file_fuzz.READ_OUT:
        file_fuzz.file_packet(kind, rng, model, SCRATCH)
    after = (model.packets, model.warnings, model.files)
    assert all(now > then for now, then in zip(after, before, strict=True))
    assert not model.receiving and model.decode_errors == 0


def test_a_build_configured_under_other_kconfig_defaults_drops_its_config(tmp_path: Path):
    folder = BuildFolder(tmp_path)
    (tmp_path / CONFIG).parent.mkdir(parents=True)
    (tmp_path / CONFIG).write_text("CONFIG_X=y\n")
    folder.mark_kconfig("today")
    folder.take_kconfig_defaults("today")
    assert (tmp_path / CONFIG).is_file()
    folder.take_kconfig_defaults("tomorrow")
    assert not (tmp_path / CONFIG).exists()
    (tmp_path / CONFIG).write_text("CONFIG_X=y\n")
    (tmp_path / KCONFIG_STAMP).unlink()
    folder.take_kconfig_defaults("today")  # a folder from before the stamp
    assert not (tmp_path / CONFIG).exists()


def test_files_count_from_events_only_where_every_read_out_overflowed_the_downlink():
    """FilesReceived is the check, unless the last read-out's writes may not
    have come down; then the FileReceived events (one with each count) are,
    and a count that differs from the model fails either way."""
    # A deployment's own name for it (F´'s FileHandling subtopology's)
    outcome = file_fuzz.Outcome(seed=1, file_uplink="FileHandling.fileUplink", noops_sent=1, noops_answered=1)
    outcome.model.files = 3
    outcome.telemetry = {"FileHandling.fileUplink.PacketsReceived": 0, "FileHandling.fileUplink.Warnings": 0,
                         "FileHandling.fileUplink.FilesReceived": 2, "Kit.linkHealth.UartRingDrops": 0}
    outcome.events["FileHandling.fileUplink.FileReceived"] = 3
    assert outcome.failures() == ["FileUplink.FilesReceived: 2, expected 3"]
    outcome.read_out_overflowed = True
    assert outcome.failures() == []
    outcome.events["FileHandling.fileUplink.FileReceived"] = 4
    assert outcome.failures() == ["FileUplink's FileReceived events: 4, expected 3"]
    assert outcome.to_json()["read_out_overflowed"] is True
