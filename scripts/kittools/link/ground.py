# SPDX-License-Identifier: Apache-2.0
"""The ground station: a kit build under QEMU with fprime-gds on its link.

`GroundStation` boots a build of the `ground` scenario (its `run` target),
waits for the firmware's LINK line, starts fprime-gds on the link's Unix
socket through the kit's adapter (kittools/link/gds_adapter.py) with the build's
own dictionary, and stops both on exit. Each station has its own ZeroMQ
endpoints, so stations never hear each other. `kit gds` and the integration
suite (tests/integration) use it.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import signal
import socket
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from kittools import variants
from kittools.build.folder import BuildFolder, kit_kconfig_digest
from kittools.build.runner import Qemu, asks_at_boot, ends_run
from kittools.deployment import Deployment
from kittools.link.client import line_rate
from kittools.workspace import GDS_MISSING, KIT_ROOT, KitError, board_dir_name, check_gds_patched, environment

BOOT_TIMEOUT_S = 60.0
GDS_TIMEOUT_S = 60.0
# fprime-gds prints this once its every application is up
GDS_READY = "F prime is now running"
# The firmware's line once its link is up (app/src/Report.cpp), with the id
# of the dictionary it was built with (app/dictionary_header.cmake)
LINK_READY = "KIT LINK ready"
LINK_DICTIONARY = re.compile(r"\bdictionary=([0-9a-f]+)")


@dataclass(frozen=True)
class Link:
    """What a build says about its ground link."""

    build_dir: Path
    socket: Path
    dictionary: Path
    board: str  # the board target the build is for


def dictionary_id(dictionary: Path) -> str:
    """A dictionary's id, as app/dictionary_header.cmake compiles it in."""
    return hashlib.sha256(dictionary.read_bytes()).hexdigest()[:16]


def link_of(build_dir: Path, dictionary: Path | None = None) -> Link:
    """The link socket and the dictionary of a built kit build; `dictionary`
    replaces the build's own (`boot` checks that it is the firmware's)."""
    folder = BuildFolder(build_dir)
    socket_path = folder.cache_value("KIT_LINK_SOCKET")
    if not socket_path:
        raise KitError(f"{build_dir} has no ground link (no KIT_LINK_SOCKET): is it a kit build of this version?")
    if dictionary is None:
        dictionary = folder.dictionary()
    elif not dictionary.is_file():
        raise KitError(f"no dictionary at {dictionary}")
    return Link(build_dir, Path(socket_path), dictionary, folder.cache_value("KIT_BOARD_TARGET") or "")


def boot(link: Link, realtime: bool = False) -> Qemu:
    """Boot a link's build in QEMU and wait for its LINK line; refuse a
    dictionary that is not the one the firmware was built with (a GDS would
    decode its packets as some other build's events and channels). On any
    error QEMU is stopped. `realtime`: idle time in host time (a station:
    GroundStation says why); the raw link's checks pace on the deployment's
    own answers and clock, and skip it."""
    _check_socket_free(link.socket)
    qemu = Qemu(link.build_dir, "ground", realtime=realtime)
    try:
        qemu.read_until(lambda line: line.startswith(LINK_READY) or ends_run(line), BOOT_TIMEOUT_S)
        if not any(line.startswith(LINK_READY) for line in qemu.lines):
            raise KitError(f"the firmware in {link.build_dir} did not bring its link up:\n{qemu.text()}")
        ready = link_line(qemu)
        built_with = LINK_DICTIONARY.search(ready)
        given = dictionary_id(link.dictionary)
        if built_with is None or built_with.group(1) != given:
            raise KitError(
                f"the dictionary {link.dictionary} (id {given}) is not the one the firmware in {link.build_dir} was "
                f"built with (id {built_with.group(1) if built_with else 'not printed'}): use that build's own "
                f"dictionary, or rebuild it (west build -d {link.build_dir})")
    except BaseException:
        qemu.stop()
        raise
    return qemu


def link_line(qemu: Qemu) -> str:
    """The LINK line of a booted build (boot waited for it)."""
    line = next((line for line in qemu.lines if line.startswith(LINK_READY)), None)
    if line is None:
        raise KitError("the firmware has not printed its LINK line: boot it with kittools.link.ground.boot")
    return line


def scenario_of(build_dir: Path) -> str | None:
    """The scenario a build plays when the console does not choose one."""
    return BuildFolder(build_dir).kconfig(missing_ok=True).get("CONFIG_KIT_SCENARIO")


def socket_free(path: Path) -> bool:
    """No QEMU listens on a link socket (a stale file is free: QEMU unlinks
    and rebinds it)."""
    if not path.exists():
        return True
    probe = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        probe.connect(str(path))
    except OSError:
        return True
    finally:
        probe.close()
    return False


def _check_socket_free(path: Path) -> None:
    """A live socket at the link's path means another QEMU of this build is
    running: two would steal each other's link."""
    if not socket_free(path):
        raise KitError(f"the link socket {path} is in use: another QEMU of this build is running. Stop it first.")


def _check_port_free(port: int) -> None:
    """fprime-gds's web page needs its port; taken, fprime-gds would start
    and then fail in its log."""
    probe = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    try:
        probe.bind(("127.0.0.1", port))
    except OSError as error:
        raise KitError(f"the GDS web page's port {port} is taken ({error.strerror}): "
                       "stop what holds it or pick another with --port") from None
    finally:
        probe.close()


class GroundStation:
    """QEMU running a build, and fprime-gds connected to its link. QEMU
    runs in real time (virtual time keeps to the host's while the deployment
    idles), as the deployment would beside a real ground station: skipping
    idle time, a deployment that idles most of a second sent three to four
    seconds of telemetry per host second, fprime-gds on the same cores fell
    behind, and the commands it sent reached the deployment late (a fresh
    clone's full run on the small part: each one a command behind, its
    tests timed out)."""

    def __init__(self, build_dir: Path, logs: Path, gui: bool = False, gui_port: int = 5000,
                 dictionary: Path | None = None) -> None:
        self.link = link_of(build_dir, dictionary)
        if not serves_ground(build_dir):
            raise KitError(f"{build_dir} does not play the ground scenario (CONFIG_KIT_SCENARIO_GROUND=y, or "
                           "CONFIG_KIT_SCENARIO_AT_BOOT=y to choose it at boot): its firmware would not wait for "
                           "the ground")
        if shutil.which("fprime-gds", path=environment().get("PATH")) is None:
            raise KitError(GDS_MISSING)
        check_gds_patched()
        self.logs = logs
        self.gui = gui
        self.gui_port = gui_port
        self._transport_dir = Path(tempfile.mkdtemp(prefix="kit-gds-"))
        self.qemu: Qemu | None = None
        self._gds: subprocess.Popen[bytes] | None = None

    @property
    def transport(self) -> list[str]:
        """This station's ZeroMQ endpoints, for every client (fprime-cli, pytest)."""
        return ["--zmq-transport", f"ipc://{self._transport_dir}/in", f"ipc://{self._transport_dir}/out"]

    def client_arguments(self) -> list[str]:
        return ["--dictionary", str(self.link.dictionary), *self.transport]

    def __enter__(self) -> GroundStation:
        try:
            self.start()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def start(self) -> None:
        if self.gui:
            _check_port_free(self.gui_port)
        self.logs.mkdir(parents=True, exist_ok=True)
        self.qemu = boot(self.link, realtime=True)
        command = [
            "fprime-gds", "--no-app", "--dictionary", str(self.link.dictionary),
            "--communication-selection", "kit-unix", "--kit-socket", str(self.link.socket),
            "--kit-baud", str(line_rate(link_line(self.qemu))),
            "--framing-selection", "fprime", *self.transport, "--logs", str(self.logs),
            "--gui", "html" if self.gui else "none", "--gui-port", str(self.gui_port),
            "--file-storage-directory", str(self.logs / "files"),
        ]
        self.gds_output = self.logs / "fprime-gds.out"
        with self.gds_output.open("wb") as output:
            self._gds = subprocess.Popen(command, env=environment(), stdin=subprocess.DEVNULL, stdout=output,
                                         stderr=subprocess.STDOUT, start_new_session=True)
        self._wait_for_gds(command)

    def _wait_for_gds(self, command: list[str]) -> None:
        assert self._gds is not None
        deadline = time.monotonic() + GDS_TIMEOUT_S
        while time.monotonic() < deadline and self._gds.poll() is None:
            if GDS_READY in self.gds_output.read_text(errors="replace"):
                return
            time.sleep(0.2)
        tail = "\n".join(self.gds_output.read_text(errors="replace").splitlines()[-20:])
        raise KitError(f"fprime-gds did not start ({' '.join(command)}):\n{tail}")

    def console(self) -> str:
        return self.qemu.text() if self.qemu else ""

    def lines(self, read_s: float = 0.0) -> list[str]:
        """The console's lines so far, after reading what it prints in
        `read_s` (nothing reads it while clients talk to the deployment)."""
        if self.qemu is None:
            return []
        if read_s > 0:
            self.qemu.read_until(lambda _line: False, read_s)
        return list(self.qemu.lines)

    def stop(self) -> None:
        if self._gds is not None and self._gds.poll() is None:
            # fprime-gds stops its applications on SIGINT, as on Ctrl-C
            os.killpg(self._gds.pid, signal.SIGINT)
            try:
                self._gds.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(self._gds.pid, signal.SIGKILL)
                self._gds.wait()
        self._gds = None
        if self.qemu is not None:
            self.qemu.stop()
        shutil.rmtree(self._transport_dir, ignore_errors=True)


def ground_build_dir(board: str, variant: str, chosen: Deployment | None = None) -> Path:
    """Where `kit gds` builds a board and variant's ground scenario, of the
    reference deployment or `chosen` (its logs go beside it, `<folder>-logs`)."""
    suffix = chosen.output_suffix() if chosen else ""
    return KIT_ROOT / "build" / f"gds-{board_dir_name(board)}-{variant}{suffix}"


def build_ground(board: str, variant: str, log: Path, chosen: Deployment | None = None) -> Path:
    """Build (or bring up to date) the ground scenario of a board and variant
    (app/variants.yaml), of the reference deployment or `chosen`, with west,
    as a user would; returns the build folder."""
    build_dir = ground_build_dir(board, variant, chosen)
    # A folder built before the kit's Kconfig defaults changed keeps its old
    # values (a heap arena too small for a new service faulted at boot)
    folder = BuildFolder(build_dir)
    kconfig = kit_kconfig_digest()
    folder.take_kconfig_defaults(kconfig)
    command = ["west", "build", "-b", board, "-d", str(build_dir), str(KIT_ROOT / "app"), "--",
               *variants.get(variant).cmake_args(), "-DCONFIG_KIT_SCENARIO_GROUND=y",
               *(chosen.cmake_args() if chosen else [])]
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("w") as output:
        code = subprocess.run(command, cwd=KIT_ROOT, env=environment(), stdout=output,
                              stderr=subprocess.STDOUT).returncode
    if code != 0:
        tail = "\n".join(log.read_text(errors="replace").splitlines()[-25:])
        raise KitError(f"building {board} {variant} failed ({' '.join(command)}); log {log}:\n{tail}")
    folder.mark_kconfig(kconfig)
    return build_dir


def serves_ground(build_dir: Path) -> bool:
    """The build can play the ground scenario: it asks for its scenario at
    boot (the suite's builds), or it was built for this one."""
    return asks_at_boot(build_dir) or scenario_of(build_dir) == "ground"
