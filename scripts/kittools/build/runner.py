# SPDX-License-Identifier: Apache-2.0
"""Run a kit build under QEMU (its own `run` target) until its end line."""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import time
from collections.abc import Callable
from pathlib import Path

from kittools.build.folder import BuildFolder
from kittools.workspace import KIT_ROOT, KitError, environment

RUN_TIMEOUT_S = 180.0
#: What asks scripts/kit-qemu (the QEMU of the kit's QEMU boards) for real time
REALTIME = "KIT_QEMU_REALTIME"


def _tail(text: str, lines: int = 25) -> str:
    return "\n".join(text.splitlines()[-lines:])


def run_command(build_dir: Path) -> list[str]:
    """The build's own `run` target: QEMU exactly as the build (and twister)
    runs it, machine, icount and console included."""
    return ["cmake", "--build", str(build_dir), "--target", "run"]


def asks_at_boot(build_dir: Path) -> bool:
    """The build asks for its scenario on the console at boot
    (CONFIG_KIT_SCENARIO_AT_BOOT: every build of the suite)."""
    return BuildFolder(build_dir).kconfig(missing_ok=True).get("CONFIG_KIT_SCENARIO_AT_BOOT") == "y"


#: The line a build that asks at boot prints before it reads the name
SELECT_PROMPT = "KIT SELECT scenarios="


def qemu_pipe(build_dir: Path) -> Path | None:
    """The FIFO a twister build sends its console to (QEMU_PIPE in its CMake
    cache: QEMU reads <pipe>.in and writes <pipe>.out), or None: a plain
    build's console is on stdio."""
    pipe = BuildFolder(build_dir).cache_value("QEMU_PIPE")
    return Path(pipe) if pipe else None


def _open_pipe(pipe: Path) -> tuple[int, int]:
    """Both FIFOs of a QEMU pipe chardev, opened read-write so that neither
    open blocks waiting for QEMU; returns (console fd, input fd)."""
    fds = []
    for suffix in (".out", ".in"):
        fifo = pipe.with_name(pipe.name + suffix)
        fifo.unlink(missing_ok=True)
        os.mkfifo(fifo)
        fds.append(os.open(fifo, os.O_RDWR | os.O_NONBLOCK))
    return fds[0], fds[1]


# A line that ends a run: the firmware's end line, or the halt marker every
# fatal path prints last (app/src/Fatal.cpp; twister fails on it at once).
HALT_MARKER = "PROJECT EXECUTION FAILED"


def ends_run(line: str) -> bool:
    return line.startswith(("KIT END", "KIT HALT")) or HALT_MARKER in line


# What a deployment that must never stop prints when it does: an F´ assert,
# Zephyr's or the kit's fatal report, or an end line
def _shows_halt(line: str) -> bool:
    return ends_run(line) or "Assert" in line or "FATAL" in line


def halt_lines(lines: list[str], most: int = 12) -> str:
    """The console from its first sign of a halt (at most `most` lines), or
    "" while the deployment runs."""
    for index, line in enumerate(lines):
        if _shows_halt(line):
            return "\n".join(lines[index:index + most])
    return ""


class Qemu:
    """The build's `run` target (QEMU) in the background, its console read
    line by line from the build's QEMU pipe (a twister build) or from stdio.
    A build that asks for its scenario at boot is answered `scenario` at its
    prompt (None: left to whoever writes to the console, send()).
    `realtime`: virtual time keeps to the host's while the guest idles
    (scripts/kit-qemu, KIT_QEMU_REALTIME: a ground station's runs; every
    other run skips idle time). A context manager: leaving it stops QEMU
    (its whole process group)."""

    def __init__(self, build_dir: Path, scenario: str | None = "nominal", realtime: bool = False) -> None:
        self.build_dir = build_dir
        self.lines: list[str] = []
        self._partial = b""
        self._answer: str | None = scenario if scenario is not None and asks_at_boot(build_dir) else None
        pipe = qemu_pipe(build_dir)
        self._pipe_fds = _open_pipe(pipe) if pipe is not None else None
        self._process = subprocess.Popen(
            run_command(build_dir), cwd=KIT_ROOT, env={**environment(), REALTIME: "1" if realtime else "0"},
            stdin=subprocess.PIPE if self._pipe_fds is None else subprocess.DEVNULL,
            stdout=subprocess.DEVNULL if self._pipe_fds else subprocess.PIPE, stderr=subprocess.STDOUT,
            start_new_session=True)
        if self._pipe_fds is not None:
            self._fd = self._pipe_fds[0]
        else:
            assert self._process.stdout is not None
            self._fd = self._process.stdout.fileno()
        self._selector = selectors.DefaultSelector()
        self._selector.register(self._fd, selectors.EVENT_READ)

    def __enter__(self) -> Qemu:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def running(self) -> bool:
        return self._process.poll() is None

    def read_until(self, done: Callable[[str], bool], timeout_s: float) -> bool:
        """Read console lines until one satisfies `done` (True), QEMU exits
        or `timeout_s` passes (False)."""
        deadline = time.monotonic() + timeout_s
        # Raw reads, not readline(): a buffered reader can hold the end line
        # in its buffer while select() waits on a pipe that stays empty.
        while time.monotonic() < deadline:
            if not self._selector.select(timeout=min(1.0, max(0.0, deadline - time.monotonic()))):
                if not self.running():
                    return False
                continue
            try:
                chunk = os.read(self._fd, 65536)
            except BlockingIOError:
                continue
            if not chunk:
                return False
            *complete, self._partial = (self._partial + chunk).split(b"\n")
            found = False
            for raw in complete:
                line = raw.decode(errors="replace").rstrip("\r")
                self.lines.append(line)
                if self._answer is not None and line.startswith(SELECT_PROMPT):
                    self.send(f"{self._answer}\n".encode())
                    self._answer = None  # once: a refused name shows as a second prompt
                found = found or done(line)
            if found:
                return True
        return False

    def text(self) -> str:
        return "\n".join(self.lines)

    def console_fd(self) -> int:
        """The file descriptor the console's output is read from."""
        return self._fd

    def read_raw(self) -> bytes | None:
        """The console bytes ready now, unsplit, for a caller that only
        forwards them: None when there are none yet, b"" when QEMU has closed
        its console."""
        try:
            return os.read(self._fd, 65536)
        except BlockingIOError:
            return None

    def send(self, data: bytes) -> None:
        """Bytes to the console: the pipe's input FIFO, or QEMU's stdin."""
        if self._pipe_fds is not None:
            os.write(self._pipe_fds[1], data)
        elif self._process.stdin is not None:
            self._process.stdin.write(data)
            self._process.stdin.flush()

    def stop(self) -> None:
        self._selector.close()
        if self._process.poll() is None:
            os.killpg(self._process.pid, signal.SIGTERM)
            self._process.wait(timeout=10)
        _reap_group(self._process.pid)
        for pipe_fd in self._pipe_fds or ():
            os.close(pipe_fd)
        self._pipe_fds = None


def _reap_group(group: int, timeout_s: float = 5.0) -> None:
    """Wait until no process of a group is left: the run target's leader
    (ninja) exits before QEMU does, and a QEMU still holding the link
    socket would refuse the next boot."""
    deadline = time.monotonic() + timeout_s
    for _ in range(int(2 * timeout_s / 0.05)):  # a zombie nobody reaps must not hang us
        try:
            os.killpg(group, signal.SIGKILL if time.monotonic() > deadline else 0)
        except ProcessLookupError:
            return
        time.sleep(0.05)


def run(build_dir: Path, log: Path, timeout_s: float = RUN_TIMEOUT_S, scenario: str = "nominal") -> str:
    """Run the build's `run` target (QEMU) until the firmware's end line or a
    fatal report, then stop QEMU; a build that asks for its scenario at boot
    plays `scenario`. Returns the console text."""
    with Qemu(build_dir, scenario) as qemu:
        finished = qemu.read_until(ends_run, timeout_s)
    text = qemu.text()
    log.write_text(text + "\n")
    if not finished:
        raise KitError(f"the run in {build_dir} did not reach its end line within {timeout_s:.0f} s; log {log}:\n"
                       f"{_tail(text)}")
    return text
