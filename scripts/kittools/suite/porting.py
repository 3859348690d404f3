# SPDX-License-Identifier: Apache-2.0
"""The porting check: a new QEMU board and a console-only real board
scaffolded into a scratch copy of the kit, then compared and built."""

from __future__ import annotations

import shutil
import subprocess
import sys
import time
from pathlib import Path

from kittools.boards.suites import BUILD_ONLY_SUITE as BOARDS_SUITE_FILE
from kittools.log import LOG, say
from kittools.suite.counts import Tally, twister_tally
from kittools.suite.platforms import suite_boards
from kittools.workspace import KIT_ROOT, KitError, board_dir_name, environment

#: A QEMU board Zephyr has and the kit has not ported (its platform file says
#: `simulation: qemu`): scaffolded, then compared with no edit
PORTING_QEMU_BOARD = "mps3/corstone300/an547"
#: A real board whose devicetree enables its console alone among the UARTs:
#: scaffolded (a UART of its SoC on the HAL's pins), then built with no edit
PORTING_REAL_BOARD = "nucleo_l152re"
#: The variants the porting step compares and builds: the execution models
#: (the folders with a Kconfig.model), not their policies: a board port is
#: the same for every policy of a model, and CI's time is shared
PORTING_MODELS = ("baremetal", "rtos")
#: The real board's builds in CI's run: the cooperative model alone. Its rtos
#: build is the full run's (kit test --full): the suite's own real board
#: builds rtos in every run (tests/boards), and a build costs CI about two
#: minutes of both cores (F´'s autocoder and configure, which ccache skips not)
PORTING_REAL_MODELS_CI = ("baremetal",)
#: Under the output folder; the same path every run, so that its builds hit
#: ccache (CCACHE_BASEDIR is the copy: paths hash relative to it)
PORTING_DIR = "porting"


def make_scratch(scratch: Path) -> None:
    """A copy of the clone in `scratch`: its tracked files as they are in
    the working tree (what is under test, committed or not), and its
    workspace: deps/ hard-linked (a second of work, no space; a symlink
    would not do: F´ resolves its paths, so its directories would have two
    names in one configuration), the venv by a symlink, .west/config."""
    shutil.rmtree(scratch, ignore_errors=True)
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=KIT_ROOT, capture_output=True, check=True).stdout
    for name in filter(None, listed.decode().split("\0")):
        source = KIT_ROOT / name
        if not source.exists() and not source.is_symlink():
            continue  # deleted in the working tree
        target = scratch / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target, follow_symlinks=False)
    if subprocess.run(["cp", "-al", str(KIT_ROOT / "deps"), str(scratch / "deps")]).returncode != 0:
        raise KitError(f"could not hard-link {KIT_ROOT / 'deps'} into {scratch}")
    (scratch / ".venv").symlink_to(KIT_ROOT / ".venv")
    (scratch / ".west").mkdir()
    shutil.copy2(KIT_ROOT / ".west" / "config", scratch / ".west" / "config")


def scratch_environment(scratch: Path) -> dict[str, str]:
    """environment() for the copy: its own Zephyr, its own tooling (the
    shared venv's editable install is this clone's), ccache relative to it."""
    env = environment()
    env.update(ZEPHYR_BASE=str(scratch / "deps" / "zephyr"), CCACHE_BASEDIR=str(scratch),
               PYTHONPATH=str(scratch / "scripts"), PYTHONUNBUFFERED="1")
    return env


def run_porting_check(log_dir: Path, full: bool = False) -> Tally:
    """`kit new-board` as a new user meets it, in a scratch copy of the
    clone (<log_dir>/porting/scratch): PORTING_QEMU_BOARD scaffolded, then
    `kit compare` on it (PORTING_MODELS, nominal and load) with no edit;
    PORTING_REAL_BOARD (its devicetree enables the console alone)
    scaffolded, then built for PORTING_MODELS with no edit (`full`; else
    PORTING_REAL_MODELS_CI). One count per scaffold, per compared scenario
    (twister's), per build."""
    out = log_dir / PORTING_DIR
    scratch = out / "scratch"
    make_scratch(scratch)
    env = scratch_environment(scratch)
    kit = [sys.executable, "-m", "kittools"]
    tally = Tally()

    def step(name: str, command: list[str], log: Path) -> bool:
        started = time.monotonic()
        with log.open("w") as to:
            code = subprocess.run(command, cwd=scratch, env=env, stdin=subprocess.DEVNULL, stdout=to,
                                  stderr=subprocess.STDOUT).returncode
        say(f"  porting: {name}: {'PASS' if code == 0 else f'FAIL (exit {code}; {log})'} "
            f"({time.monotonic() - started:.0f} s)")
        return code == 0

    def count(passed: bool) -> None:
        tally.add(Tally(passed=1) if passed else Tally(failed=1))

    # A QEMU board: the QEMU suites' lists, not the real boards' (kit compare refuses those)
    qemu_ok = step(f"kit new-board {PORTING_QEMU_BOARD}", [*kit, "new-board", PORTING_QEMU_BOARD],
                   out / "new-board-qemu.log")
    listed_real = PORTING_QEMU_BOARD in suite_boards(scratch / BOARDS_SUITE_FILE)
    if listed_real:
        LOG.error(f"  porting: {PORTING_QEMU_BOARD} was added to {BOARDS_SUITE_FILE}, the real boards' list")
    count(qemu_ok and not listed_real)
    if qemu_ok:
        compare_out = scratch / "build" / "compare"
        compared = step(f"kit compare --board {PORTING_QEMU_BOARD}",
                        [*kit, "compare", "--board", PORTING_QEMU_BOARD, "--output", str(compare_out),
                         *(f"--model={model}" for model in PORTING_MODELS)],
                        out / "compare.log")
        report = compare_out / "twister" / "twister.json"
        played = twister_tally(report) if report.is_file() else Tally()
        if not compared and played.failed == 0:
            played.failed += 1  # compare failed before or after twister's runs
        tally.add(played)
    # A real board whose devicetree enables its console alone
    real_ok = step(f"kit new-board {PORTING_REAL_BOARD}", [*kit, "new-board", PORTING_REAL_BOARD],
                   out / "new-board-real.log")
    count(real_ok)
    if real_ok:
        for model in PORTING_MODELS if full else PORTING_REAL_MODELS_CI:
            build = scratch / "build" / "porting" / f"{board_dir_name(PORTING_REAL_BOARD)}.{model}"
            count(step(f"west build -b {PORTING_REAL_BOARD} -T tests/boards/board.{model}",
                       ["west", "build", "-b", PORTING_REAL_BOARD, "-d", str(build), "-T",
                        f"tests/boards/board.{model}"], out / f"build-{model}.log"))
    return tally
