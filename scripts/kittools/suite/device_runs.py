# SPDX-License-Identifier: Apache-2.0
"""The suite on boards through twister's device testing, and CI's device path
(a QEMU board standing in for one on a probe)."""

from __future__ import annotations

from pathlib import Path

from kittools import variants
from kittools.boards.scaffold import REFERENCE_BOARD
from kittools.suite import device
from kittools.suite.counts import Tally
from kittools.suite.platforms import SUITE
from kittools.suite.twister import play
from kittools.workspace import KIT_ROOT, check_board

DEVICE_OUT = KIT_ROOT / "build" / "device-out"
#: CI's device path: a QEMU board standing in for one on a probe (its device
#: folder and hardware map), one model: the path is under test here, the
#: models are in the QEMU run
QEMU_DEVICE = KIT_ROOT / "build" / "qemu-device"
STAND_IN_BOARD = REFERENCE_BOARD
STAND_IN_MODEL = "baremetal"
#: ... and two scenarios: a run to its end line and one commanded from the
#: uplink (every scenario is the QEMU run's; this checks the path, in CI time)
STAND_IN_SCENARIOS = ("nominal", "faults")


def check_device_run(hardware_map: Path, models: tuple[str, ...] = ()) -> list[device.Device]:
    """The connected boards of a hardware map, refused (KitError) where the
    kit has no port for one or a model is no variant (app/variants.yaml)."""
    devices = device.read_map(hardware_map)
    for connected in devices:
        check_board(connected.platform)
    for model in models:
        variants.get(model)  # the suite plays every variant (scripts/tests/test_variants.py)
    return devices


def run_device_testing(hardware_map: Path, log_dir: Path, models: tuple[str, ...] = (),
                       out_dir: Path = DEVICE_OUT, scenarios: tuple[str, ...] = ()) -> Tally:
    """The deployment suite (tests/deployment, every variant or `models`) on
    each connected board of a twister hardware map, through twister's device
    testing: each scenario flashes the board with its runner, reads its
    console (its port or serial_pty) and asserts what the QEMU run asserts
    (pytest/test_scenarios.py); only `scenarios` where given."""
    devices = check_device_run(hardware_map, models)
    # --force-platform: a real board is not in the suite's platform_allow,
    # which lists where the QEMU run plays
    command = ["west", "twister", "--device-testing", "--hardware-map", str(hardware_map.resolve()),
               "-T", str(SUITE.parent), "--force-platform"]
    for platform in dict.fromkeys(connected.platform for connected in devices):
        command += ["-p", platform]
    for model in models:
        command += ["-s", f"kit.{model}"]
    if scenarios:
        command += ["--pytest-args=-k", "--pytest-args=" + " or ".join(scenarios)]
    return play(command, log_dir / "twister-device.log", out_dir)


def run_qemu_device(log_dir: Path) -> Tally:
    """The device path without hardware: STAND_IN_BOARD under QEMU as the
    flashed board of a hardware map (device.stand_in_map), STAND_IN_MODEL's
    suite played through twister's device testing."""
    folder = check_board(STAND_IN_BOARD)
    hardware_map = QEMU_DEVICE / "hardware-map.yaml"
    device.stand_in_map(hardware_map, STAND_IN_BOARD, QEMU_DEVICE / folder)
    return run_device_testing(hardware_map, log_dir, (STAND_IN_MODEL,), scenarios=STAND_IN_SCENARIOS)
