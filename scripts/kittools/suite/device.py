# SPDX-License-Identifier: Apache-2.0
"""Device testing: the suite on a board twister flashes and reads, and a
QEMU board standing in for one, so that CI exercises that path without
hardware.

Twister's device testing (`--device-testing --hardware-map FILE`) hands each
test to its pytest harness, which opens the device's console (a serial port,
or a command on a pty: the map's `serial_pty`), flashes the build with
`west flash --runner <map's runner> -- <runner_params>` and reads the
console: tests/deployment/pytest/test_scenarios.py, unchanged. On a real
board the runner and the port are the board's own.

A QEMU board has no flash runner; modules/qemu gives it Zephyr's
misc-flasher, whose command is scripts/qemu-device, the two halves here:

- `qemu-device BUILD DEVICE` (misc-flasher passes the build folder first,
  then the map's runner_params): "flashing" records the build as the
  image of the device folder DEVICE;
- `qemu-device --serial DEVICE` (the map's serial_pty): the device's
  console on stdin and stdout. Like a board, it runs what was flashed: each
  image flashed while the console is open resets it, that is, boots the
  build's own `run` target (QEMU, icount and all) on it. The console's
  bytes go both ways until twister closes the port (SIGTERM), which stops
  QEMU.
"""

from __future__ import annotations

import os
import selectors
import signal
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from kittools.build.folder import ELF, BuildFolder
from kittools.build.runner import Qemu
from kittools.workspace import KIT_ROOT, KitError

#: The runner modules/qemu adds to the QEMU boards (Zephyr's own)
QEMU_DEVICE_RUNNER = "misc-flasher"
QEMU_DEVICE_SCRIPT = KIT_ROOT / "scripts" / "qemu-device"
#: The file of a device folder that holds the flashed build's folder
FLASHED = "flashed"
#: How long the console waits for a first image (twister flashes right
#: after it opens the console; a flash that never comes is an error)
FIRST_IMAGE_WAIT_S = 120.0
_POLL_S = 0.1


def flash(build_dir: Path, device_dir: Path) -> Path:
    """Record a QEMU board's build as the image of a device folder (made if
    missing); returns its ELF. Refuses a build that is not one."""
    build_dir = build_dir.resolve()
    folder = BuildFolder(build_dir)
    if not folder.elf.is_file():
        raise KitError(f"{build_dir} has no {ELF}: nothing to flash (build it first)")
    config = folder.kconfig(missing_ok=True)
    if config.get("CONFIG_QEMU_TARGET") != "y":
        board = config.get("CONFIG_BOARD_TARGET", "?").strip('"')
        raise KitError(f"{build_dir} is a build for {board}, not a QEMU board: flash a real board with its own "
                       f"runner (its board.cmake; the hardware map's `runner`)")
    device_dir.mkdir(parents=True, exist_ok=True)
    staged = device_dir / (FLASHED + ".tmp")
    staged.write_text(f"{build_dir}\n")
    staged.replace(device_dir / FLASHED)  # the console sees a whole image or none
    return folder.elf


def take_flashed(device_dir: Path) -> Path | None:
    """The build last flashed to a device folder, taken (a second call gives
    None until the next flash), or None."""
    image = device_dir / FLASHED
    try:
        build = Path(image.read_text().strip())
    except FileNotFoundError:
        return None
    image.unlink(missing_ok=True)
    return build


class _Stop(Exception):
    """SIGTERM: twister closes the port."""


def _on_sigterm(signum: int, frame: object) -> None:
    raise _Stop


def serve_console(device_dir: Path, stdin_fd: int = 0, stdout_fd: int = 1,
                  first_image_wait_s: float = FIRST_IMAGE_WAIT_S) -> int:
    """The console of a device folder on two file descriptors, until its
    input closes or SIGTERM; each image flashed meanwhile boots under QEMU
    (a reset). Returns an exit status: 1 when no image came in time."""
    signal.signal(signal.SIGTERM, _on_sigterm)
    qemu: Qemu | None = None
    started = time.monotonic()
    selector = selectors.DefaultSelector()
    selector.register(stdin_fd, selectors.EVENT_READ, "host")
    try:
        while True:
            build = take_flashed(device_dir)
            if build is not None:
                if qemu is not None:
                    selector.unregister(qemu.console_fd())
                    qemu.stop()
                qemu = Qemu(build, scenario=None)
                selector.register(qemu.console_fd(), selectors.EVENT_READ, "device")
            elif qemu is None and time.monotonic() - started > first_image_wait_s:
                print(f"qemu-device: nothing was flashed to {device_dir} within {first_image_wait_s:.0f} s",
                      file=sys.stderr)
                return 1
            for key, _ in selector.select(timeout=_POLL_S):
                if key.data == "host":
                    data = os.read(stdin_fd, 4096)
                    if not data:
                        return 0  # the port was closed
                    if qemu is not None:  # a board that is not running drops its input
                        qemu.send(data)
                elif qemu is not None:
                    output = qemu.read_raw()
                    if output:
                        os.write(stdout_fd, output)
                    elif output is not None:  # the device halted: quiet until flashed again
                        selector.unregister(qemu.console_fd())
                        qemu.stop()
                        qemu = None
    except _Stop:
        return 0
    finally:
        selector.close()
        if qemu is not None:
            qemu.stop()


# --- Hardware maps -----------------------------------------------------

@dataclass(frozen=True)
class Device:
    """One connected board of a hardware map."""

    platform: str
    id: str
    runner: str


def read_map(path: Path) -> list[Device]:
    """The connected boards of a twister hardware map (its schema:
    zephyr/scripts/schemas/twister/hwmap-schema.yaml), refused with the
    reason when it has none or is not one."""
    if not path.is_file():
        raise KitError(f"hardware map {path} not found (make one with `west twister --generate-hardware-map "
                       f"{path}`, then set each board's platform and runner)")
    try:
        entries: Any = yaml.safe_load(path.read_text())
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f" (line {mark.line + 1})" if mark is not None else ""
        raise KitError(f"hardware map {path} is not YAML{where}: {getattr(error, 'problem', None) or error}") from error
    if not isinstance(entries, list) or not all(isinstance(entry, dict) for entry in entries):
        raise KitError(f"hardware map {path} is not a list of boards (twister's hardware map format)")
    devices = []
    for number, entry in enumerate(entries, 1):
        missing = [key for key in ("platform", "id", "runner", "connected") if key not in entry]
        if missing:
            raise KitError(f"hardware map {path}: board {number} has no {', '.join(missing)}")
        if not entry.get("serial") and not entry.get("serial_pty"):
            raise KitError(f"hardware map {path}: board {number} ({entry['platform']}) has neither a serial "
                           f"port nor a serial_pty command: twister cannot read its console")
        if entry["connected"]:
            devices.append(Device(str(entry["platform"]), str(entry["id"]), str(entry["runner"])))
    if not devices:
        raise KitError(f"hardware map {path} has no connected board")
    return devices


def stand_in_map(path: Path, platform: str, device_dir: Path) -> list[Device]:
    """Write a hardware map in which a QEMU board stands in for one on a
    probe (QEMU_DEVICE_RUNNER; the console is `qemu-device --serial`), with
    an empty device folder; returns its devices (read_map)."""
    if " " in str(QEMU_DEVICE_SCRIPT) + str(device_dir):
        # twister splits serial_pty at spaces and commas
        raise KitError(f"the QEMU stand-in needs a path without spaces: {QEMU_DEVICE_SCRIPT}, {device_dir}")
    for stale in (device_dir / FLASHED, device_dir / (FLASHED + ".tmp")):
        stale.unlink(missing_ok=True)
    device_dir.mkdir(parents=True, exist_ok=True)
    entry = {
        "connected": True,
        "id": f"qemu-device-{platform.replace('/', '-')}",
        "platform": platform,
        "product": "QEMU standing in for a board on a probe (scripts/qemu-device)",
        "runner": QEMU_DEVICE_RUNNER,
        "runner_params": [str(device_dir)],
        "serial_pty": f"{QEMU_DEVICE_SCRIPT} --serial {device_dir}",
        "flash_timeout": 60,
    }
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump([entry], sort_keys=False))
    return read_map(path)


USAGE = ("usage: qemu-device BUILD_DIR DEVICE_DIR   flash a QEMU board's build (Zephyr's misc-flasher runner)\n"
         "       qemu-device --serial DEVICE_DIR    the device's console on stdio (twister's serial_pty)")


def main(argv: list[str]) -> int:
    """scripts/qemu-device."""
    try:
        if len(argv) == 2 and argv[0] == "--serial":
            return serve_console(Path(argv[1]))
        if len(argv) == 2 and not argv[0].startswith("-"):
            elf = flash(Path(argv[0]), Path(argv[1]))
            print(f"qemu-device: flashed {elf} to {argv[1]}")
            return 0
    except KitError as error:
        print(f"qemu-device: error: {error}", file=sys.stderr)
        return 1
    print(USAGE, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
