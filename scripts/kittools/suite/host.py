# SPDX-License-Identifier: Apache-2.0
"""The steps that need no board: host unit tests (googletest) and the
tooling's tests, lint and types."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

from kittools.log import LOG
from kittools.suite.counts import Tally, gtest_tally, junit_tally, run_logged
from kittools.workspace import KIT_ROOT, KitError

HOST_BUILD = KIT_ROOT / "build" / "host-ut"


def run_host_tests(log_dir: Path) -> Tally:
    tests_dir = KIT_ROOT / "tests" / "host"
    # No coverage instrumentation (the kit reports none), so ccache can serve
    # a fresh clone's host build: with -ftest-coverage it hashes the build
    # folder's absolute path and never hits across clones (88 s cold, 7 s warm)
    configure = ["cmake", "-S", str(tests_dir), "-B", str(HOST_BUILD), "-G", "Ninja", "-DBUILD_TESTING=ON",
                 "-DFPRIME_ENABLE_UT_COVERAGE=OFF"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
    if run_logged(configure, log_dir / "host-configure.log") != 0:
        raise KitError(f"host test configuration failed; see {log_dir / 'host-configure.log'}")
    if run_logged(["cmake", "--build", str(HOST_BUILD), "--target", "kit_host_tests"], log_dir / "host-build.log") != 0:
        raise KitError(f"host test build failed; see {log_dir / 'host-build.log'}")
    tally = Tally()
    for exe in sorted((HOST_BUILD / "bin").glob("*/*")):
        if not (exe.name.startswith("app_") or exe.name.startswith("Kit_")):
            continue
        gtest_json = log_dir / f"{exe.name}.json"
        gtest_json.unlink(missing_ok=True)
        code = run_logged([str(exe), f"--gtest_output=json:{gtest_json}"], log_dir / f"{exe.name}.log")
        tests = gtest_tally(gtest_json) if gtest_json.is_file() else Tally()
        tally.add(tests)
        if code != 0 and tests.failed == 0:
            # Crashed before its report, or a sanitizer (leak, UB) failed it after
            # every test passed: one failure, its log says which
            LOG.error(f"  {exe.name} exited {code} with no failed test: see {log_dir / (exe.name + '.log')}")
            tally.failed += 1
    if tally.passed + tally.failed == 0:
        raise KitError(f"no host test executable found in {HOST_BUILD / 'bin'}")
    return tally




def run_pytest(log_dir: Path) -> Tally:
    xml = log_dir / "pytest.xml"
    code = run_logged(["python", "-m", "pytest", "-q", f"--junitxml={xml}"], log_dir / "pytest.log",
                cwd=KIT_ROOT / "scripts")
    if not xml.is_file():
        raise KitError(f"pytest wrote no report (exit {code}); see {log_dir / 'pytest.log'}")
    return junit_tally(xml)


#: The tooling's static checks, run from scripts/ (its pyproject.toml configures both)
LINTERS = (("ruff", ["check", "."]), ("mypy", ["kittools"]))


def run_lint(log_dir: Path) -> Tally:
    """ruff and mypy over the tooling, one pass or fail each."""
    tally = Tally()
    for tool, arguments in LINTERS:
        log = log_dir / f"{tool}.log"
        log.parent.mkdir(parents=True, exist_ok=True)
        with log.open("w") as out:
            code = subprocess.run([sys.executable, "-m", tool, *arguments], cwd=KIT_ROOT / "scripts",
                                  stdout=out, stderr=subprocess.STDOUT).returncode
        if code == 0:
            tally.passed += 1
        else:
            LOG.error(f"  {tool} found problems (exit {code}): see {log}")
            tally.failed += 1
    return tally


# --- Porting: the scaffolder on a scratch copy of the clone -------------
