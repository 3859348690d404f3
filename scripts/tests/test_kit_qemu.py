# SPDX-License-Identifier: Apache-2.0
"""scripts/kit-qemu, the QEMU of the kit's QEMU boards: each run takes a
host CPU no other holds, until it exits; with none left it runs unpinned;
it runs the command it is given, status and all; asked for real time, it
turns icount's sleep on."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from kittools.build.runner import REALTIME
from kittools.workspace import KIT_ROOT

WRAPPER = KIT_ROOT / "scripts" / "kit-qemu"
# Stands in for QEMU: prints the CPUs it may run on, then waits for its stdin to close
SHOW_AFFINITY = "import os, sys; print(sorted(os.sched_getaffinity(0)), flush=True); sys.stdin.read()"
CPUS = sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else []


def _start(tmp_path: Path) -> tuple[subprocess.Popen[str], list[int]]:
    process = subprocess.Popen([str(WRAPPER), sys.executable, "-c", SHOW_AFFINITY], text=True, stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, env={**os.environ, "TMPDIR": str(tmp_path)})
    assert process.stdout is not None
    return process, [int(cpu) for cpu in process.stdout.readline().strip(" []\n").split(",")]


@pytest.mark.skipif(len(CPUS) < 2, reason="needs two host CPUs")
def test_each_run_takes_a_cpu_of_its_own_until_it_exits(tmp_path: Path) -> None:
    runs = [_start(tmp_path) for _ in CPUS]
    try:
        taken = [cpus for _, cpus in runs]
        assert taken == [[cpu] for cpu in CPUS]  # one each, in order
        extra, cpus = _start(tmp_path)  # none left: where the scheduler puts it
        assert cpus == CPUS
        extra.communicate("")
        first, _ = runs.pop(0)
        first.communicate("")  # its CPU is free again
        deadline = time.monotonic() + 5
        again, cpus = _start(tmp_path)
        runs.append((again, cpus))
        assert cpus == [CPUS[0]] and time.monotonic() < deadline
    finally:
        for process, _ in runs:
            process.communicate("")


def test_the_command_runs_as_given(tmp_path: Path) -> None:
    done = subprocess.run([str(WRAPPER), sys.executable, "-c", "import sys; print(sys.argv[1:]); sys.exit(3)",
                           "a b", "-c"], capture_output=True, text=True, env={**os.environ, "TMPDIR": str(tmp_path)})
    assert (done.returncode, done.stdout) == (3, "['a b', '-c']\n")


def test_a_missing_qemu_is_one_error(tmp_path: Path) -> None:
    done = subprocess.run([str(WRAPPER), str(tmp_path / "qemu-system-none")], capture_output=True, text=True)
    assert done.returncode == 1
    missing = tmp_path / "qemu-system-none"
    assert done.stderr == f"kit-qemu: error: cannot run {missing}: No such file or directory\n"


ICOUNT = ["-icount", "shift=4,align=off,sleep=off", "-rtc", "clock=vm"]
SHOW_ARGUMENTS = "import sys; print(sys.argv[1:])"


@pytest.mark.parametrize(("realtime", "expected"), [
    (None, "shift=4,align=off,sleep=off"),
    ("1", "shift=4,align=off,sleep=on"),
    ("0", "shift=4,align=off,sleep=off"),
])
def test_real_time_turns_icount_sleep_on_when_asked(tmp_path: Path, realtime: str | None, expected: str) -> None:
    # REALTIME: the name the kit's runner sets, so the two cannot drift apart
    env = {key: value for key, value in os.environ.items() if key != REALTIME}
    if realtime is not None:
        env[REALTIME] = realtime
    done = subprocess.run([str(WRAPPER), sys.executable, "-c", SHOW_ARGUMENTS, *ICOUNT], capture_output=True,
                          text=True, env={**env, "TMPDIR": str(tmp_path)}, check=True)
    assert done.stdout == f"{['-icount', expected, '-rtc', 'clock=vm']}\n"


def test_real_time_leaves_a_run_without_icount_as_it_is(tmp_path: Path) -> None:
    done = subprocess.run([str(WRAPPER), sys.executable, "-c", SHOW_ARGUMENTS, "-icount"], capture_output=True,
                          text=True, env={**os.environ, REALTIME: "1", "TMPDIR": str(tmp_path)}, check=True)
    assert done.stdout == "['-icount']\n"
