# SPDX-License-Identifier: Apache-2.0
"""Run a kit build under QEMU (its own `run` target) until its end line."""

from __future__ import annotations

import os
import re
import selectors
import signal
import subprocess
import time
from pathlib import Path

from .workspace import KIT_ROOT, KitError, environment

RUN_TIMEOUT_S = 180.0


def _tail(text: str, lines: int = 25) -> str:
    return "\n".join(text.splitlines()[-lines:])


def run_command(build_dir: Path) -> list[str]:
    """The build's own `run` target: QEMU exactly as the build (and twister)
    runs it, machine, icount and console included."""
    return ["cmake", "--build", str(build_dir), "--target", "run"]


def qemu_pipe(build_dir: Path) -> Path | None:
    """The FIFO a twister build sends its console to (QEMU_PIPE in its CMake
    cache: QEMU reads <pipe>.in and writes <pipe>.out), or None: a plain
    build's console is on stdio."""
    cache = build_dir / "CMakeCache.txt"
    if not cache.is_file():
        raise KitError(f"{build_dir} is not a configured build (no CMakeCache.txt)")
    match = re.search(r"^QEMU_PIPE:[A-Z]+=(.+)$", cache.read_text(), re.MULTILINE)
    return Path(match.group(1)) if match else None


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


def run(build_dir: Path, log: Path, timeout_s: float = RUN_TIMEOUT_S) -> str:
    """Run the build's `run` target (QEMU) until the firmware's end line or a
    fatal report, then stop QEMU. The console is read from the build's QEMU
    pipe (a twister build) or from stdio. Returns the console text."""
    pipe = qemu_pipe(build_dir)
    pipe_fds = _open_pipe(pipe) if pipe is not None else None
    process = subprocess.Popen(run_command(build_dir), cwd=KIT_ROOT, env=environment(), stdin=subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL if pipe_fds else subprocess.PIPE,
                               stderr=subprocess.STDOUT, start_new_session=True)
    if pipe_fds is not None:
        fd = pipe_fds[0]
    else:
        assert process.stdout is not None
        fd = process.stdout.fileno()
    lines: list[str] = []
    partial = b""
    finished = False
    deadline = time.monotonic() + timeout_s
    selector = selectors.DefaultSelector()
    selector.register(fd, selectors.EVENT_READ)
    try:
        # Raw reads, not readline(): a buffered reader can hold the end line
        # in its buffer while select() waits on a pipe that stays empty.
        while time.monotonic() < deadline and not finished:
            if not selector.select(timeout=1.0):
                if process.poll() is not None:
                    break
                continue
            try:
                chunk = os.read(fd, 65536)
            except BlockingIOError:
                continue
            if not chunk:
                break
            *complete, partial = (partial + chunk).split(b"\n")
            for raw in complete:
                line = raw.decode(errors="replace").rstrip("\r")
                lines.append(line)
                finished = finished or ends_run(line)
    finally:
        selector.close()
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGTERM)
            process.wait(timeout=10)
        for pipe_fd in pipe_fds or ():
            os.close(pipe_fd)
    text = "\n".join(lines)
    log.write_text(text + "\n")
    if not finished:
        raise KitError(f"the run in {build_dir} did not reach its end line within {timeout_s:.0f} s; log {log}:\n"
                       f"{_tail(text)}")
    return text
