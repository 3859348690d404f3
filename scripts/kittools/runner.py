"""Build a variant with west and run it under QEMU until its end line."""

from __future__ import annotations

import os
import re
import selectors
import shlex
import signal
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

from . import console
from .footprint import Footprint, measure
from .workspace import KIT_ROOT, KitError, check_board, check_variant, environment

RUN_TIMEOUT_S = 180.0


@dataclass
class VariantResult:
    variant: str
    board: str
    build_dir: Path
    footprint: Footprint
    run: console.Run
    console_text: str


def _tail(text: str, lines: int = 25) -> str:
    return "\n".join(text.splitlines()[-lines:])


def build(variant: str, board: str, build_dir: Path, log: Path, scenario: str = "") -> None:
    """`west build -b <board> -T app/kit.<variant>[.<scenario>]` into build_dir
    (app/sample.yaml names the scenarios)."""
    check_variant(variant)
    check_board(board)
    command = ["west", "build", "-b", board, "-d", str(build_dir), "-T",
               f"app/kit.{variant}" + (f".{scenario}" if scenario else "")]
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("w") as out:
        result = subprocess.run(command, cwd=KIT_ROOT, env=environment(), stdout=out, stderr=subprocess.STDOUT)
    if result.returncode != 0:
        raise KitError(f"build of {variant} failed ({' '.join(command)}); log {log}:\n{_tail(log.read_text())}")


def qemu_command(build_dir: Path) -> list[str]:
    """The QEMU command line the build's `run` target uses, with the console on
    stdio. Twister builds send the console to a FIFO instead; the binary and
    every other flag (machine, icount) stay exactly as built."""
    ninja = build_dir / "build.ninja"
    if not ninja.is_file():
        raise KitError(f"{build_dir} is not a finished build (no build.ninja)")
    for line in ninja.read_text().splitlines():
        start = line.find("qemu-system-")
        if start >= 0 and "-kernel" in line:
            words = shlex.split(line[start:].split("&&")[0])
            return [re.sub(r"^pipe,id=con,mux=on,path=\S+$", "stdio,id=con,mux=on", w) for w in words
                    if w != "-pidfile" and not w.endswith("qemu.pid")]
    raise KitError(f"no QEMU command in {ninja}: is this a QEMU board build?")


# A line that ends a run: the firmware's end line, or the halt marker every
# fatal path prints last (app/src/Fatal.cpp; twister fails on it at once).
HALT_MARKER = "PROJECT EXECUTION FAILED"


def ends_run(line: str) -> bool:
    return line.startswith(("KIT END", "KIT HALT")) or HALT_MARKER in line


def run(build_dir: Path, log: Path, timeout_s: float = RUN_TIMEOUT_S) -> str:
    """Run the build in QEMU, exactly as its `run` target would (qemu_command),
    until the firmware's end line or a fatal report, then stop QEMU. Returns
    the console text."""
    command = qemu_command(build_dir)
    process = subprocess.Popen(command, cwd=KIT_ROOT, env=environment(), stdin=subprocess.DEVNULL,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
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
            chunk = os.read(fd, 65536)
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
    text = "\n".join(lines)
    log.write_text(text + "\n")
    if not finished:
        raise KitError(f"the run in {build_dir} did not reach its end line within {timeout_s:.0f} s; log {log}:\n"
                       f"{_tail(text)}")
    return text


def build_and_run(variant: str, board: str, out_dir: Path, scenario: str = "") -> VariantResult:
    name = variant + (f".{scenario}" if scenario else "")
    build_dir = out_dir / f"{check_board(board)}-{name}"
    build(variant, board, build_dir, out_dir / f"{name}.build.log", scenario)
    text = run(build_dir, out_dir / f"{name}.console.log")
    parsed = console.parse(text)
    return VariantResult(variant, board, build_dir, measure(build_dir), parsed, text)
