# SPDX-License-Identifier: Apache-2.0
"""Device testing's QEMU stand-in (kittools.suite.device): what "flashing" records,
what the console does before anything is flashed, and the hardware maps."""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest
import yaml

from kittools.suite import device
from kittools.workspace import KitError


def _build(folder: Path, config: str, elf: bool = True) -> Path:
    (folder / "zephyr").mkdir(parents=True)
    (folder / "zephyr" / ".config").write_text(config)
    if elf:
        (folder / "zephyr" / "zephyr.elf").write_bytes(b"\x7fELF")
    return folder


QEMU_CONFIG = 'CONFIG_BOARD_TARGET="qemu_cortex_m3/ti_lm3s6965"\nCONFIG_QEMU_TARGET=y\n'


def test_flash_records_the_build_once(tmp_path: Path) -> None:
    build = _build(tmp_path / "b", QEMU_CONFIG)
    elf = device.flash(build, tmp_path / "dev")
    assert elf == build.resolve() / "zephyr" / "zephyr.elf"
    assert device.take_flashed(tmp_path / "dev") == build.resolve()
    assert device.take_flashed(tmp_path / "dev") is None  # taken: the next boot needs the next flash


def test_flash_refuses_a_real_board_and_an_unbuilt_folder(tmp_path: Path) -> None:
    real = _build(tmp_path / "real", 'CONFIG_BOARD_TARGET="nucleo_f401re/stm32f401xe"\n')
    with pytest.raises(KitError, match="nucleo_f401re/stm32f401xe, not a QEMU board"):
        device.flash(real, tmp_path / "dev")
    with pytest.raises(KitError, match="no zephyr/zephyr.elf"):
        device.flash(_build(tmp_path / "unbuilt", QEMU_CONFIG, elf=False), tmp_path / "dev")
    assert not (tmp_path / "dev" / device.FLASHED).exists()


def test_console_without_a_flash_gives_up(tmp_path: Path) -> None:
    reader, writer = os.pipe()
    try:
        assert device.serve_console(tmp_path, reader, writer, first_image_wait_s=0.3) == 1
    finally:
        os.close(reader)
        os.close(writer)


def test_console_ends_when_the_port_closes(tmp_path: Path) -> None:
    reader, writer = os.pipe()
    out_reader, out_writer = os.pipe()
    threading.Timer(0.2, os.close, (writer,)).start()
    try:
        assert device.serve_console(tmp_path, reader, out_writer, first_image_wait_s=30) == 0
    finally:
        for fd in (reader, out_reader, out_writer):
            os.close(fd)


def test_stand_in_map_is_a_twister_hardware_map(tmp_path: Path) -> None:
    folder = tmp_path / "dev"
    folder.mkdir()
    (folder / device.FLASHED).write_text("/stale\n")  # a last run's flash must not boot
    devices = device.stand_in_map(tmp_path / "map.yaml", "qemu_cortex_m3", folder)
    assert devices == [device.Device("qemu_cortex_m3", "qemu-device-qemu_cortex_m3", "misc-flasher")]
    assert device.take_flashed(folder) is None
    entry = yaml.safe_load((tmp_path / "map.yaml").read_text())[0]
    assert entry["runner_params"] == [str(folder)]
    assert entry["serial_pty"].split() == [str(device.QEMU_DEVICE_SCRIPT), "--serial", str(folder)]
    # every key is one of twister's hardware map schema
    schema = Path(__file__).resolve().parents[2] / "deps/zephyr/scripts/schemas/twister/hwmap-schema.yaml"
    if schema.is_file():
        assert set(entry) <= set(yaml.safe_load(schema.read_text())["sequence"][0]["mapping"])


@pytest.mark.parametrize(("text", "reason"), [
    ("a: [", "is not YAML"),
    ("a: 1\n", "not a list of boards"),
    ("- platform: qemu_cortex_m3\n  id: x\n  connected: true\n", "has no runner"),
    ("- {platform: p, id: x, runner: r, connected: true}\n", "neither a serial port nor a serial_pty"),
    ("- {platform: p, id: x, runner: r, connected: false, serial: /dev/ttyACM0}\n", "no connected board"),
])
def test_a_bad_hardware_map_is_refused_with_its_reason(tmp_path: Path, text: str, reason: str) -> None:
    (tmp_path / "map.yaml").write_text(text)
    with pytest.raises(KitError, match=reason):
        device.read_map(tmp_path / "map.yaml")
    with pytest.raises(KitError, match="not found"):
        device.read_map(tmp_path / "none.yaml")
