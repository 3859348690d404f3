# SPDX-License-Identifier: Apache-2.0
"""A deployment as F´'s tools make one, through `kit new-deployment`
(docs/your-deployment.md, "From fprime-util new --deployment"): in a
scratch F´ project outside the clone, `fprime-util new --deployment` with
fprime-tools' template, then `kit new-deployment` (twice: the second changes
nothing), then `kit compare --deployment` on mps2/an385 (the nominal run and the
load sweep of every model but CI_LEFT_OUT), and on qemu_cortex_m3, where the
template's buffers do not fit, the kit's one line that says by how much."""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

from kittools import variants, workspace
from kittools.log import LOG
from kittools.suite import imported
from kittools.suite.counts import Tally, run_logged
from kittools.workspace import KIT_ROOT

#: The scratch F´ project, one per machine (its path is on the compile
#: lines: ccache serves the next clone's run what this one compiled)
SCRATCH = Path(tempfile.gettempdir()) / "kit-template"
#: The deployment's name, and the answers fprime-util's wizard takes on
#: stdin: the name, the namespace (the name's), the driver (TcpClient), and
#: yes to adding it to the project's project.cmake
DEPLOYMENT = "MyDeployment"
WIZARD_ANSWERS = f"{DEPLOYMENT}\n\n1\nyes\n"
#: The fastest group's rate on the board (the template's 1 Hz base is the
#: host demo's; the kit's load reaches twice the fastest period, at most 50 ms)
FASTEST_HZ = "50"
#: The models CI's run leaves out of the comparison (the page's walk and
#: `kit test --full` have them all): baremetal_budgeted is baremetal's build with another scheduling
#: policy, which the reference suite plays in every run; what the template
#: brings (its task table, its active components on the cooperative loop) its
#: baremetal build plays. A build of this deployment is about 70 s of both
#: cores beside twister (CI's time: docs/tooling.md)
CI_LEFT_OUT = ("baremetal_budgeted",)
#: The board the whole comparison runs on, and the one it does not fit
BOARD = "mps2/an385"
SMALL_BOARD = "qemu_cortex_m3"
#: An F´ project as `fprime-bootstrap project` makes one: what fprime-util needs to find it
PROJECT_FILES = {
    # The framework fprime-util renders templates with: the kit's F´
    "settings.ini": f"[fprime]\nframework_path: {workspace.DEPS / 'fprime'}\nproject_root: .\n",
    "CMakeLists.txt": ('cmake_minimum_required(VERSION 3.16)\nproject(Proj C CXX)\n'
                       'include("${FPRIME_FRAMEWORK_PATH}/cmake/FPrime.cmake")\n'
                       'include("${CMAKE_CURRENT_LIST_DIR}/project.cmake")\n'),
    "project.cmake": "# The project's deployments and components\n",
}


#: Where `python -m kittools` finds the kit's package
SCRIPTS = KIT_ROOT / "scripts"


def kit_command(args: list[str]) -> list[str]:
    """`kit <args>`, as scripts/kit runs it, without its setup (CI's is done)."""
    return [sys.executable, "-m", "kittools", *args]


def walk(folder: str) -> dict[str, list[str]]:
    """The kit's commands of the page's walk (docs/your-deployment.md), by
    step: the page gives them for `MyDeployment`, CI for its scratch copy."""
    return {
        "new-deployment": ["new-deployment", folder, "--fastest-hz", FASTEST_HZ],
        "compare": ["compare", "--deployment", folder, "--board", BOARD],
        "compare-small": ["compare", "--deployment", folder, "--board", SMALL_BOARD, "--model", "rtos"],
    }


def _check(name: str, passed: bool, log: Path, tally: Tally) -> bool:
    if passed:
        LOG.info(f"  {name}: PASS")
        tally.add(Tally(1, 0))
    else:
        LOG.error(f"  {name}: FAIL; see {log}")
        tally.add(Tally(0, 1))
    return passed


def _text(log: Path) -> str:
    return log.read_text(errors="replace") if log.is_file() else ""


def compared_models(full: bool) -> list[str]:
    return [name for name in variants.names() if full or name not in CI_LEFT_OUT]


def run(log_dir: Path, full: bool = False) -> Tally:
    out = log_dir / "template-deployment"
    out.mkdir(parents=True, exist_ok=True)
    tally = Tally()
    with imported.scratch(SCRATCH) as project:
        for name, text in PROJECT_FILES.items():
            (project / name).write_text(text)
        fprime_util = shutil.which("fprime-util") or str(Path(sys.executable).with_name("fprime-util"))
        folder = project / DEPLOYMENT
        log = out / "fprime-util-new.log"
        code = run_logged([fprime_util, "new", "--deployment"], log, cwd=project, stdin=WIZARD_ANSWERS)
        if not _check("fprime-util new --deployment", code == 0 and (folder / "Top" / "topology.fpp").is_file(),
                      log, tally):
            return tally
        steps = walk(str(folder))
        log = out / "new-deployment.log"
        code = run_logged(kit_command(steps["new-deployment"]), log, cwd=SCRIPTS)
        if not _check("kit new-deployment", code == 0 and "changed:" in _text(log), log, tally):
            return tally
        log = out / "new-deployment-again.log"
        code = run_logged(kit_command(steps["new-deployment"][:2]), log, cwd=SCRIPTS)
        _check("kit new-deployment, run again: nothing to change", code == 0 and "nothing to change" in _text(log),
               log, tally)
        log = out / "compare.log"
        models = compared_models(full)
        code = run_logged(kit_command([*steps["compare"], *[arg for name in models for arg in ("--model", name)],
                                       "--output", str(out / "compare")]), log, cwd=SCRIPTS)
        _check(f"kit compare --deployment on {BOARD} ({', '.join(models)}): nominal and load sweep", code == 0, log,
               tally)
        log = out / "compare-small.log"
        run_logged(kit_command([*steps["compare-small"], "--output", str(out / "compare-small")]), log, cwd=SCRIPTS)
        _check(f"on {SMALL_BOARD}: the kit says what does not fit and by how much",
               "does not fit" in _text(log) and "overflowed by" in _text(log), log, tally)
    return tally
