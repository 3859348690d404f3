# SPDX-License-Identifier: Apache-2.0
"""What each step of `kit test` counts: passed and failed, read from twister's,
googletest's and pytest's reports; and the logged subprocess the steps run."""

from __future__ import annotations

import json
import subprocess
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kittools.suite import results
from kittools.workspace import KIT_ROOT, KitError, environment


@dataclass
class Tally:
    passed: int = 0
    failed: int = 0

    def add(self, other: Tally) -> None:
        self.passed += other.passed
        self.failed += other.failed


def run_logged(command: list[str], log: Path, cwd: Path = KIT_ROOT, unset: tuple[str, ...] = (),
               stdin: str = "") -> int:
    """`command` in the kit's environment (without the variables `unset`),
    `stdin` its input, its output to `log`; its exit code."""
    env = {name: value for name, value in environment().items() if name not in unset}
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("w") as out:
        return subprocess.run(command, cwd=cwd, env=env, input=stdin, text=True, stdout=out,
                              stderr=subprocess.STDOUT).returncode


def _built_only(suite: dict[str, Any]) -> bool:
    return str(suite.get("name", "")).rsplit("/", 1)[-1].startswith(results.BUILD_ONLY_PREFIX)


def twister_tally(path: Path) -> Tally:
    """Count twister's test cases (each scenario a build played, with the
    pytest harness): passed, or failed (failed, error, blocked). A
    configuration that reports no case counts once, by its own status."""
    if not path.is_file():
        raise KitError(f"twister wrote no report at {path}")
    tally = Tally()
    for suite in json.loads(path.read_text()).get("testsuites", []):
        if _built_only(suite):
            # A real board's build (tests/boards): twister builds what it
            # cannot run and says "not run"; a build that failed is an error
            status = suite.get("status")
            tally.passed += status == "not run"
            tally.failed += status in ("failed", "error", "blocked")
            continue
        statuses = [case.get("status") for case in suite.get("testcases") or []] or [suite.get("status")]
        for status in statuses:
            if status == "passed":
                tally.passed += 1
            elif status in ("failed", "error", "blocked"):
                tally.failed += 1
    return tally




def gtest_tally(path: Path) -> Tally:
    data = json.loads(path.read_text())
    return Tally(passed=data["tests"] - data["failures"] - data.get("errors", 0),
                 failed=data["failures"] + data.get("errors", 0))




def junit_tally(path: Path) -> Tally:
    root = ET.parse(path).getroot()
    suites = [root] if root.tag == "testsuite" else list(root)
    tests = sum(int(s.get("tests", 0)) for s in suites)
    bad = sum(int(s.get("failures", 0)) + int(s.get("errors", 0)) for s in suites)
    return Tally(passed=tests - bad - sum(int(s.get("skipped", 0)) for s in suites), failed=bad)


# How much of a failure's reason a summary line carries: its first line,
# enough for the assertion's message, the whole traceback is in the log
FAILURE_REASON_CHARS = 240


def junit_failures(path: Path) -> list[str]:
    """Each failed or erred test case of a JUnit report, named with the first
    line of its reason (pytest's message: the assertion and its values), so
    a run's summary says why without its log, which a CI run may not keep."""
    failures = []
    for case in ET.parse(path).getroot().iter("testcase"):
        outcome = case.find("failure")
        if outcome is None:
            outcome = case.find("error")
        if outcome is None:
            continue
        reason = (outcome.get("message") or outcome.text or "").strip().splitlines()
        first = reason[0][:FAILURE_REASON_CHARS] if reason else "no reason given"
        failures.append(f"{case.get('name')} ({first})")
    return failures
