# SPDX-License-Identifier: Apache-2.0
"""The kit's test suite: twister under QEMU, host unit tests (googletest),
and the tooling's own pytest, with one closing count."""

from __future__ import annotations

import concurrent.futures
import hashlib
import json
import re
import shutil
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol, TypeVar

from kittools import console, sweep, variants
from kittools.boards.scaffold import BUILD_ONLY_SUITE as BOARDS_SUITE_FILE
from kittools.boards.scaffold import REFERENCE_BOARD
from kittools.build import runner
from kittools.link import flood, fuzz, ground, serial_sweep
from kittools.model import Results
from kittools.sizes import by_layer, memory, sizing, symbols
from kittools.suite import budget, device, floor, results, shards
from kittools.workspace import KIT_ROOT, KitError, board_dir_name, check_board, environment

HOST_BUILD = KIT_ROOT / "build" / "host-ut"
SUITE = KIT_ROOT / "tests" / "deployment" / "testcase.yaml"
#: Real boards, built and not run (no emulator): every model's build
BUILD_ONLY_SUITE = KIT_ROOT / BOARDS_SUITE_FILE
TWISTER_OUT = KIT_ROOT / "twister-out"


@dataclass
class Tally:
    passed: int = 0
    failed: int = 0

    def add(self, other: Tally) -> None:
        self.passed += other.passed
        self.failed += other.failed


def _run(command: list[str], log: Path, cwd: Path = KIT_ROOT) -> int:
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("w") as out:
        return subprocess.run(command, cwd=cwd, env=environment(), stdout=out, stderr=subprocess.STDOUT).returncode


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


def _built_only(suite: dict[str, Any]) -> bool:
    return str(suite.get("name", "")).rsplit("/", 1)[-1].startswith(results.BUILD_ONLY_PREFIX)


def suite_boards(suite: Path = SUITE) -> list[str]:
    """The boards the suite runs on: its common platform_allow list (with
    BUILD_ONLY_SUITE, the real boards built and not run)."""
    import yaml  # Zephyr's requirements bring PyYAML into the venv

    try:
        platforms = yaml.safe_load(suite.read_text())["common"]["platform_allow"]
    except (OSError, KeyError, TypeError, yaml.YAMLError) as error:
        raise KitError(f"{suite} names no platforms (common: platform_allow): {error}") from error
    if not platforms:
        raise KitError(f"{suite}: common: platform_allow is empty")
    return [str(p) for p in platforms]


_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")
# Twister 4.0's announcements and, with -v, its line per finished configuration
# (twisterlib/runner.py: TwisterRunner.run, show_brief, ProjectBuilder.report_out)
_JOBS = re.compile(r"^INFO\s+-\s+JOBS: (?P<jobs>\d+)\s*$")
_SELECTED = re.compile(r"^INFO\s+-\s+(?P<scenarios>\d+) test scenarios \((?P<configurations>\d+) configurations\) "
                       r"selected, (?P<filtered>\d+) configurations filtered \((?P<static>\d+) by static filter")
_DONE = re.compile(r"^INFO\s+-\s+(?P<done>\d+)/(?P<total>\d+)\s+(?P<platform>\S+)\s+(?P<suite>\S+)\s+"
                   r"(?P<status>NOT RUN|[A-Z_]+)(?:\s+(?P<reason>.*?))?\s+\((?P<info>[^()]*)\)\s*$")
_SECONDS = re.compile(r"(?P<s>\d+(?:\.\d+)?)s\b")


@dataclass
class TwisterProgress:
    """Reads twister's console output line by line; says one line per
    finished configuration, and how many are left."""

    total: int | None = None
    jobs: int | None = None

    def line(self, text: str) -> str | None:
        """What to print for this line of twister's output, or None."""
        text = _ANSI.sub("", text).rstrip()
        if match := _JOBS.match(text):
            self.jobs = int(match["jobs"])
            return None
        if match := _SELECTED.match(text):
            self.total = int(match["configurations"]) - int(match["static"])
            jobs = f", {self.jobs} at a time" if self.jobs else ""
            return f"[kit]   twister: {self.total} configurations to build and run{jobs}"
        match = _DONE.match(text)
        if match is None:
            return None
        done = int(match["done"])
        total = self.total if self.total is not None else int(match["total"])
        seconds = _SECONDS.search(match["info"])
        info = f"{float(seconds['s']):.1f} s" if seconds else match["info"]
        reason = f" {match['reason']}" if match["reason"] else ""
        suite = match["suite"].rsplit("/", 1)[-1]
        return (f"[kit]   {done}/{total} {match['platform']} {suite} {match['status']}{reason} {info} "
                f"({max(total - done, 0)} left)")


def _run_streamed(command: list[str], log: Path, say: Callable[[str], str | None]) -> int:
    """Run `command`, its whole output into `log`; each line (ended by a
    newline or a carriage return) is also given to `say`, which returns what
    to print, if anything."""
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("wb") as out:
        # Unbuffered: a Python tool writing to a pipe would otherwise hand its
        # progress over in blocks, minutes late
        env = {**environment(), "PYTHONUNBUFFERED": "1"}
        process = subprocess.Popen(command, cwd=KIT_ROOT, env=env, stdin=subprocess.DEVNULL,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        assert process.stdout is not None
        for raw in process.stdout:
            out.write(raw)
            out.flush()
            for piece in raw.decode(errors="replace").replace("\r", "\n").splitlines():
                shown = say(piece)
                if shown is not None:
                    print(shown, flush=True)
        return process.wait()


class RunWatcher:
    """While twister runs, one line per scenario a build finished playing (its
    console log appearing in <build>/kit-runs/): a configuration plays for
    minutes, and twister says nothing until all its scenarios are done."""

    def __init__(self, out_dir: Path, period_s: float = 2.0) -> None:
        self._out_dir = out_dir
        self._period_s = period_s
        self._started = time.time()
        self._seen: set[Path] = set()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._watch, daemon=True)

    def __enter__(self) -> RunWatcher:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join()

    def _watch(self) -> None:
        while not self._stop.wait(self._period_s):
            for log in sorted(self._out_dir.glob(f"*/**/{results.RUNS_DIR}/*.log")):
                if log in self._seen or log.stat().st_mtime < self._started:
                    continue
                self._seen.add(log)
                lines = log.read_text(errors="replace").splitlines()
                build = log.parent.parent
                platform = build.relative_to(self._out_dir).parts[0]
                print(f"[kit]     {platform} {build.name} {log.stem}: {lines[-1] if lines else '(no output)'} "
                      f"({len(self._seen)} runs played)", flush=True)


def run_twister(platforms: list[str], log_dir: Path, out_dir: Path = TWISTER_OUT,
                scenarios: tuple[str, ...] = (), exclude_tags: tuple[str, ...] = (),
                models: tuple[str, ...] = (), with_floor: bool = True, subset: str | None = None) -> Tally:
    """The suite (tests/) on every board: one build per execution model and
    board, each playing every scenario, or only `scenarios` (pytest's -k),
    but for the test suites tagged with one of `exclude_tags`; with
    `models`, only those variants' builds (and the kernel floor's, unless
    not `with_floor`); with `subset` (K/N), twister's own share K of N of
    the configurations (kit test --subset); two builds or QEMU runs at a time (icount timing does not depend on the
    host's load). Twister's whole output goes to <log_dir>/twister.log; one
    line per finished configuration is printed."""
    for console_log in out_dir.glob(f"*/**/{floor.PREFIX}*/{floor.CONSOLE_LOG}"):  # the kernel floor's records
        console_log.unlink()
    command = ["west", "twister", "-T", "tests", "-j", "2", "--overflow-as-errors"]
    for platform in platforms:
        command += ["-p", platform]
    if scenarios:
        command += ["--pytest-args=-k", "--pytest-args=" + " or ".join(scenarios)]
    for tag in exclude_tags:
        command += ["--exclude-tag", tag]
    # Twister's -s takes a scenario by its name alone
    for scenario in [f"kit.{model}" for model in models] + (floor.scenarios(KIT_ROOT) if models and with_floor
                                                             else []):
        command += ["-s", scenario]
    if subset:
        command += ["--subset", subset]
    tally = _play(command, log_dir / "twister.log", out_dir)
    say_built_only(out_dir)
    say_profiles(out_dir)
    return tally


#: In a twister outdir: what the last clean run configured its builds from
CONFIGURED_FROM = "kit-configured-from.sha256"
#: The environment a build's configuration depends on beyond its files (the toolchain)
_CONFIGURE_ENVIRONMENT = ("ZEPHYR_TOOLCHAIN_VARIANT", "GNUARMEMB_TOOLCHAIN_PATH", "ZEPHYR_SDK_INSTALL_DIR")


def configured_from() -> str:
    """What twister configures the kit's builds from that their own build
    files do not track: every test suite's testcase.yaml (twister hands its
    extra_args to CMake once) and the toolchain's environment. Everything
    else a configuration reads (CMake and Kconfig files, .conf fragments,
    snippets, F´'s FPP files) is a configure dependency ninja checks itself."""
    digest = hashlib.sha256()
    for suite in sorted(KIT_ROOT.glob("tests/**/testcase.yaml")):
        digest.update(f"{suite.relative_to(KIT_ROOT)}\0".encode() + suite.read_bytes() + b"\0")
    env = environment()
    for name in _CONFIGURE_ENVIRONMENT:
        digest.update(f"{name}={env.get(name, '')}\0".encode())
    return digest.hexdigest()


def _play(command: list[str], log: Path, out_dir: Path) -> Tally:
    """Run a twister command that plays the suite into `out_dir`, a line
    per finished configuration and per scenario played; its tally."""
    # -n: build in the last run's folders, so that a second run rebuilds only
    # what changed (ccache does the rest). Twister configures each build
    # again (about 20 s of a core with F´'s sub-build), unless told not to
    # (--aggressive-no-clean): done when the last run passed and what
    # twister configures from is as it was then (configured_from); ninja
    # configures again whatever else changed.
    stamp = out_dir / CONFIGURED_FROM
    fingerprint = configured_from()
    reuse = stamp.is_file() and stamp.read_text().strip() == fingerprint
    stamp.unlink(missing_ok=True)
    if not reuse:
        # The Kconfig file twister wrote for an earlier suite's extra_configs:
        # twister hands any it finds to CMake, whatever the suite says now
        # (the kit's suites set Kconfig through extra_args: testcase.yaml).
        # Its build folder is configured from scratch: its CMake cache names
        # the file (OVERLAY_CONFIG) and twister no longer passes it.
        for overlay in out_dir.glob("*/**/twister/testsuite_extra.conf"):
            overlay.unlink()
            (overlay.parent.parent / "CMakeCache.txt").unlink(missing_ok=True)
    # The last run's consoles go first: a scenario this run does not play (or
    # a build that fails) must not lend its old log to the results.
    for runs in out_dir.glob(f"*/**/{results.RUNS_DIR}"):
        shutil.rmtree(runs)
    # ... and so does the last run's report: a twister that dies before
    # writing its own must not be counted by the last one's
    (out_dir / "twister.json").unlink(missing_ok=True)
    command = [*command, "--aggressive-no-clean" if reuse else "-n", "-v", "--inline-logs", "--outdir", str(out_dir)]
    with RunWatcher(out_dir):
        code = _run_streamed(command, log, TwisterProgress().line)
    tally = twister_tally(out_dir / "twister.json")
    if code != 0 and tally.failed == 0:
        tally.failed += 1  # twister itself failed (for example a configuration error)
    if code == 0 and tally.failed == 0:
        stamp.write_text(fingerprint + "\n")
    return tally


# --- Device testing ----------------------------------------------------
DEVICE_OUT = KIT_ROOT / "build" / "device-out"
#: CI's device path: a QEMU board standing in for one on a probe (its device
#: folder and hardware map), one model: the path is under test here, the
#: models are in the QEMU run
QEMU_DEVICE = KIT_ROOT / "build" / "qemu-device"
STAND_IN_BOARD = REFERENCE_BOARD
STAND_IN_MODEL = "baremetal"
#: ... and two scenarios: a run to its end line and one commanded from the
#: uplink (every scenario is the QEMU run's; this checks the path, in CI time)
STAND_IN_SCENARIOS = ("nominal", "faults")


def check_device_run(hardware_map: Path, models: tuple[str, ...] = ()) -> list[device.Device]:
    """The connected boards of a hardware map, refused (KitError) where the
    kit has no port for one or a model is no variant (app/variants.yaml)."""
    devices = device.read_map(hardware_map)
    for connected in devices:
        check_board(connected.platform)
    for model in models:
        variants.get(model)  # the suite plays every variant (scripts/tests/test_variants.py)
    return devices


def run_device_testing(hardware_map: Path, log_dir: Path, models: tuple[str, ...] = (),
                       out_dir: Path = DEVICE_OUT, scenarios: tuple[str, ...] = ()) -> Tally:
    """The deployment suite (tests/deployment, every variant or `models`) on
    each connected board of a twister hardware map, through twister's device
    testing: each scenario flashes the board with its runner, reads its
    console (its port or serial_pty) and asserts what the QEMU run asserts
    (pytest/test_scenarios.py); only `scenarios` where given."""
    devices = check_device_run(hardware_map, models)
    # --force-platform: a real board is not in the suite's platform_allow,
    # which lists where the QEMU run plays
    command = ["west", "twister", "--device-testing", "--hardware-map", str(hardware_map.resolve()),
               "-T", str(SUITE.parent), "--force-platform"]
    for platform in dict.fromkeys(connected.platform for connected in devices):
        command += ["-p", platform]
    for model in models:
        command += ["-s", f"kit.{model}"]
    if scenarios:
        command += ["--pytest-args=-k", "--pytest-args=" + " or ".join(scenarios)]
    return _play(command, log_dir / "twister-device.log", out_dir)


def run_qemu_device(log_dir: Path) -> Tally:
    """The device path without hardware: STAND_IN_BOARD under QEMU as the
    flashed board of a hardware map (device.stand_in_map), STAND_IN_MODEL's
    suite played through twister's device testing."""
    folder = check_board(STAND_IN_BOARD)
    hardware_map = QEMU_DEVICE / "hardware-map.yaml"
    device.stand_in_map(hardware_map, STAND_IN_BOARD, QEMU_DEVICE / folder)
    return run_device_testing(hardware_map, log_dir, (STAND_IN_MODEL,), scenarios=STAND_IN_SCENARIOS)


def say_built_only(out_dir: Path = TWISTER_OUT) -> None:
    """A line per real board's build (tests/boards): its ROM and RAM, as
    built; nothing ran on it."""
    try:
        builds = results.suite_builds(out_dir, prefix=results.BUILD_ONLY_PREFIX)
    except KitError:
        return  # a build that failed: twister's tally counts it
    for platform, build in builds:
        size = memory.measure(build)
        print(f"[kit]   {platform} {build.name}: built, not run (no emulator; docs/porting.md): "
              f"ROM {size.rom:,} of {size.rom_size:,} B, RAM {size.ram:,} of {size.ram_size:,} B", flush=True)


def say_profiles(out_dir: Path = TWISTER_OUT) -> None:
    """A line per footprint profile's build of the suite (its `profile.`
    scenarios): ROM and RAM, and their change from the same model's build
    with the kit's profile on the same board."""
    try:
        profiles = results.suite_builds(out_dir, prefix=results.PROFILE_PREFIX)
        kit_builds = {(platform, build.name): build for platform, build in results.suite_builds(out_dir)}
    except KitError:
        return  # a build that failed: twister's tally counts it
    for platform, build in profiles:
        profile, model = build.name.removeprefix(results.PROFILE_PREFIX).split(".", 1)
        size = memory.measure(build)
        kit_build = kit_builds.get((platform, f"kit.{model}"))
        if kit_build is None:
            print(f"[kit]   {platform} {model} with fprime-{profile}: ROM {size.rom:,} B, RAM {size.ram:,} B",
                  flush=True)
            continue
        kit = memory.measure(kit_build)
        print(f"[kit]   {platform} {model} with fprime-{profile}: ROM {size.rom:,} B ({size.rom - kit.rom:+,} from "
              f"the kit profile's {kit.rom:,}), RAM {size.ram:,} B ({size.ram - kit.ram:+,} from {kit.ram:,})",
              flush=True)


def recorded_hashes(twister_out: Path) -> dict[tuple[str, Path, str], str]:
    """(platform, build, scenario) -> the sample hash (KIT HASH line) of each
    scenario the suite played, from its console log (results.run_log)."""
    hashes: dict[tuple[str, Path, str], str] = {}
    for platform, build in results.suite_builds(twister_out):
        for log in sorted((build / results.RUNS_DIR).glob("*.log")):
            run = results.played(build, log.stem)
            if run is not None and run.of_kind("HASH") and "fnv" in run.one("HASH").fields:
                hashes[(platform, build, log.stem)] = run.one("HASH").fields["fnv"]
    return hashes


def check_determinism(log_dir: Path, jobs: int = 2, required: bool = True) -> Tally:
    """Play each scenario that printed a sample hash once more on its build
    under QEMU, `jobs` at a time, through the build's own run target (the
    console from its QEMU pipe): under icount the raw timing samples, and so
    their hash, must be identical to the suite's run. Not `required` (a
    shard of a split run): a run that played none checks none."""
    runs = [(platform, build, scenario, expected)
            for (platform, build, scenario), expected in sorted(recorded_hashes(TWISTER_OUT).items())
            # the soak: ten more virtual minutes per board; it checks itself
            if scenario != "soak"]
    if not runs:
        if not required:
            return Tally()
        raise KitError("the suite recorded no sample hash: nothing to compare")

    def rerun(platform: str, build: Path, scenario: str) -> str | None:
        log = log_dir / f"{platform.replace('/', '_')}.{build.name}.{scenario}.rerun.log"
        text = runner.run(build, log, scenario=scenario)
        return console.parse(text).one("HASH").fields.get("fnv")

    def rerun_build(platform: str, build: Path) -> dict[str, str | None]:
        # One build's scenarios one after another: two QEMUs of one build
        # would share its console FIFOs and its link socket
        return {scenario: rerun(platform, build, scenario) for p, b, scenario, _ in runs if (p, b) == (platform, build)}

    builds = sorted({(platform, build) for platform, build, _, _ in runs})
    tally = Tally()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {key: pool.submit(rerun_build, *key) for key in builds}
        for platform, build, scenario, expected in runs:
            again = futures[(platform, build)].result()[scenario]
            same = again == expected
            print(f"[kit]   {platform} {build.name} {scenario}: sample hash {expected}, then {again}: "
                  f"{'identical' if same else 'DIFFERENT'}", flush=True)
            tally.add(Tally(passed=1) if same else Tally(failed=1))
    return tally


INTEGRATION = KIT_ROOT / "tests" / "integration"


# The checks through fprime-gds run one build at a time: the integration
# API's time-outs are the host's (two stations at once once missed a first
# NO_OP's 10 s). Fuzzing, the flood, the serial-load sweep and the foreign
# dictionary wait for the deployment's answers and pace on its own clock,
# however long the host takes: two builds at a time, one QEMU per core (the
# sweep's latencies are host-timed anyway: played three times, median and
# spread; what it offers and delivers does not depend on the host).
INTEGRATION_JOBS = 1
RAW_LINK_JOBS = 2


def ground_builds(required: bool = True) -> list[tuple[str, Path]]:
    """(platform, build) of every build of the last twister run that can
    play the ground scenario; none is an error where `required`."""
    builds = [(platform, build) for platform, build in results.suite_builds(TWISTER_OUT)
              if ground.serves_ground(build)]
    if not builds and required:
        raise KitError(f"twister made no build of the suite that can play the ground scenario under {TWISTER_OUT}")
    return builds


def run_stations(log_dir: Path, select: str) -> Tally:
    """The integration suite's tests matching `select` (pytest's -k)
    through fprime-gds on every ground build of the last twister run, one
    build at a time (kit test --quick: the NO_OP)."""
    tally = Tally()
    for platform, build in ground_builds():
        tally.add(station_checks(platform, build, log_dir, select))
    return tally


def run_integration(log_dir: Path, jobs: int = INTEGRATION_JOBS, raw_link_jobs: int = RAW_LINK_JOBS,
                    required: bool = True) -> Tally:
    """The ground-link checks of every build of the suite, each booted under
    QEMU into its ground scenario: first tests/integration (F´'s
    integration-test API, through fprime-gds's pytest plugin, with
    fprime-gds on the build's link: kittools.link.ground), `jobs` builds at a
    time; then the foreign dictionary, uplink fuzzing, the flood and the
    serial-load sweep, `raw_link_jobs` builds at a time. Two builds never share a QEMU
    pipe, a link socket or a GDS transport (each station's is its own). The
    kit's own runner, not twister's pytest harness: that harness owns one
    console and knows nothing of a second serial port or a GDS. Not
    `required` (a shard of a split run): a run that made none checks none."""
    builds = ground_builds(required)
    tally = Tally()
    for checks, workers in ((station_checks, jobs), (raw_link_checks, raw_link_jobs)):
        with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
            for result in pool.map(checks, [p for p, _ in builds], [b for _, b in builds],
                                   [log_dir] * len(builds)):
                tally.add(result)
    return tally


def _ground_name(platform: str, build: Path) -> str:
    return f"{platform.replace('/', '_')}_{build.name}"


def station_checks(platform: str, build: Path, log_dir: Path, select: str | None = None) -> Tally:
    """One build's check that needs the host to itself: the integration
    suite through fprime-gds (its tests matching `select`, pytest's -k)."""
    name = _ground_name(platform, build)
    logs = results.integration_logs(log_dir, platform, build.name)
    xml = logs / "pytest.xml"
    started = time.monotonic()
    with ground.GroundStation(build, logs) as station:
        _run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(INTEGRATION),
              *(["-k", select] if select else []), *station.client_arguments(), "--logs", str(logs / "api"),
              f"--junitxml={xml}"],
             logs / "pytest.log")
        console_text = station.console()
    (logs / "console.log").write_text(console_text + "\n")
    if not xml.is_file():
        raise KitError(f"the integration suite wrote no report for {build}; see {logs / 'pytest.log'}")
    tally = junit_tally(xml)
    print(f"[kit]   {name}: {tally.passed} passed, {tally.failed} failed "
          f"({time.monotonic() - started:.0f} s; logs {logs})", flush=True)
    return tally


def raw_link_checks(platform: str, build: Path, log_dir: Path) -> Tally:
    """One build's checks on the raw link, paced by the deployment's own
    answers and clock, one after the other (they share its QEMU pipe and
    link socket): another build's dictionary refused, uplink fuzzing, the
    flood, and on SERIAL_SWEEP_BOARD the serial-load sweep."""
    name = _ground_name(platform, build)
    logs = results.integration_logs(log_dir, platform, build.name)
    tally = foreign_dictionary_build(build, name, logs)
    checks = [fuzz_build, flood_build]
    if check_board(platform) == check_board(SERIAL_SWEEP_BOARD):
        checks.append(serial_sweep_build)
    for check in checks:
        tally.add(check(build, name, logs))
    return tally


def foreign_dictionary_build(build: Path, name: str, logs: Path) -> Tally:
    """Boot a ground build with a dictionary of another build (its own with
    another project version, as a build of another commit has): the ground
    tools must refuse it with their one message and leave no QEMU behind."""
    own = ground.link_of(build).dictionary
    foreign = logs / "foreign-dictionary.json"
    data = json.loads(own.read_text())
    data["metadata"]["projectVersion"] = f"{data['metadata']['projectVersion']}-another-build"
    foreign.write_text(json.dumps(data, indent=2) + "\n")
    link = ground.link_of(build, foreign)
    try:
        with ground.boot(link):
            failure: str | None = "booted with another build's dictionary"
    except KitError as error:
        failure = None if "is not the one the firmware" in str(error) else f"refused for another reason: {error}"
    if failure is None and not ground.socket_free(link.socket):
        failure = "QEMU still holds the link socket after the refusal"
    print(f"[kit]   {name}: another build's dictionary: {'refused' if failure is None else 'FAIL: ' + failure}",
          flush=True)
    return Tally(failed=1) if failure else Tally(passed=1)


class _Recorded(Protocol):
    def to_json(self) -> dict[str, Any]: ...


_R = TypeVar("_R", bound=_Recorded)


def _recorded(name: str, what: str, job: Callable[[], _R], path: Path) -> _R | None:
    """Run a ground-link check and write its record; None (said) when it
    could not run to its end."""
    try:
        outcome = job()
    except KitError as error:
        print(f"[kit]   {name}: {what}: FAIL: {error}", flush=True)
        return None
    path.write_text(json.dumps(outcome.to_json(), indent=2) + "\n")
    return outcome


#: The serial axes are swept on the reference board, every model (three
#: plays per level, a minute or more per build): what a level delivers is
#: bound by the line rate and the link driver, the same code on every board;
#: the other boards get the flood and the fuzzing, which check the link's
#: accounting and its halt-free recovery (CI time: issue 31)
SERIAL_SWEEP_BOARD = REFERENCE_BOARD


def serial_sweep_build(build: Path, name: str, logs: Path) -> Tally:
    """Boot a ground build and run the serial-load sweep on its link
    (kittools.link.serial_sweep); the records go to serial.json beside the other
    logs, where the board's results (results.from_twister) take them."""
    started = time.monotonic()
    outcome = _recorded(name, "serial-load sweep", lambda: serial_sweep.run(build),
                        logs / results.SERIAL_SWEEP_FILE)
    if outcome is None:
        return Tally(failed=1)
    found = outcome.sweep()
    breaks = {f"{axis} {rg}": sweep.level_text(found.breaking_point(axis, rg), found.unit(axis))
              for axis in found.axes() for rg in found.rate_groups()} if found else {}
    print(f"[kit]   {name}: serial-load sweep, {len(outcome.lines)} points x rate groups, breaking points "
          f"{breaks} ({time.monotonic() - started:.0f} s)", flush=True)
    return Tally(passed=1)


# Uplink fuzzing: a fixed seed, so two runs send the same bytes and must
# give the same counts (the seed is in every record). Each model gets its
# 10,000 invalid frames on the reference board; the other boards, where the
# deployment is the same code, a quarter of that.
FUZZ_SEED = 20261201
FUZZ_INVALID_FRAMES = 10_000
FUZZ_INVALID_FRAMES_OTHER_BOARDS = 2_500


def fuzz_build(build: Path, name: str, logs: Path) -> Tally:
    """Boot a ground build and fuzz its uplink (kittools.link.fuzz); the outcome
    goes to fuzz.json beside the other logs."""
    link = ground.link_of(build)
    started = time.monotonic()
    with ground.boot(link) as qemu:

        def halted() -> str:
            qemu.read_until(lambda line: False, 0.001)
            return runner.halt_lines(qemu.lines)

        reference = link.board.split("/")[0] == REFERENCE_BOARD
        frames = FUZZ_INVALID_FRAMES if reference else FUZZ_INVALID_FRAMES_OTHER_BOARDS
        try:
            outcome = fuzz.run(link.socket, link.dictionary, FUZZ_SEED, frames, halted=halted)
        except KitError as error:
            # A failed check, not the end of `kit test`
            (logs / "fuzz.console.log").write_text(qemu.text() + "\n")
            print(f"[kit]   {name}: fuzzing (seed {FUZZ_SEED}): FAIL: {error}", flush=True)
            return Tally(failed=1)
        (logs / "fuzz.console.log").write_text(qemu.text() + "\n")
    record = outcome.to_json()
    (logs / "fuzz.json").write_text(json.dumps(record, indent=2) + "\n")
    failures = outcome.failures()
    print(f"[kit]   {name}: fuzzing (seed {outcome.seed}): {outcome.invalid_sent} invalid frames "
          f"{dict(sorted(outcome.sent.items()))}, {outcome.noops_answered}/{outcome.noops_sent} NO_OPs answered, "
          f"rejected {record['rejected']} ({time.monotonic() - started:.0f} s): "
          f"{'PASS' if not failures else 'FAIL: ' + '; '.join(failures)}", flush=True)
    return Tally(failed=1) if failures else Tally(passed=1)


def flood_build(build: Path, name: str, logs: Path) -> Tally:
    """Boot a ground build and flood its link (kittools.link.flood); the records
    go to flood.json, where the board's results take them."""
    started = time.monotonic()
    outcome = _recorded(name, "flood", lambda: flood.run(build), logs / results.FLOOD_FILE)
    if outcome is None:
        return Tally(failed=1)
    failures = outcome.failures()
    slips = {line.split(" rg=")[1].split()[0]: line.split(" slips=")[1].split()[0] for line in outcome.sweep_lines}
    print(f"[kit]   {name}: flood ({outcome.seconds:.1f} s at {outcome.baud} baud): {outcome.record()}, slips "
          f"{slips} ({time.monotonic() - started:.0f} s): {'PASS' if not failures else 'FAIL: ' + '; '.join(failures)}",
          flush=True)
    return Tally(failed=1) if failures else Tally(passed=1)


def make_size_reports(twister_out: Path = TWISTER_OUT, background: bool = False) -> None:
    """Zephyr's rom and ram reports of every build of the suite, all boards'
    at once (kittools.sizes.by_layer: about 20 s of one core each, two builds at a
    time), before the budget steps read them board by board. `background`:
    at the lowest CPU priority, beside the determinism runs and the ground
    link's checks (`kit test`): those take the CPU they need first (QEMU
    counts virtual time; the checks' time-outs are the host's) and the
    reports the rest. A failure is left to the budget step, which makes the
    report again and says why."""
    try:
        by_layer.reports([build for _, build in results.suite_builds(twister_out)
                         + results.suite_builds(twister_out, prefix=results.BUILD_ONLY_PREFIX)],
                        background=background)
    except KitError:
        pass  # made again, and reported, by the budget step


BASELINES = KIT_ROOT / "tests" / "baselines"


def check_budget(board: str, log_dir: Path, limits: budget.Budget, update_baseline: bool = False) -> Tally:
    """Results of this twister run on `board` against its committed baseline
    (tests/baselines/<board folder>.json): ROM, RAM, p99 and slips budgets,
    decided by kittools.suite.budget from the metrics alone; and every variant's
    fixed tables against what its dictionary needs (kittools.sizes.sizing), each
    one count.
    update_baseline: make this run the baseline instead (conditions and
    metrics, no raw records; review the diff).
    Writes <log_dir>/<board folder>/results.json, then its report."""
    return judge(results.from_twister(TWISTER_OUT, board, log_dir), board, log_dir, limits, update_baseline)


def judge(data: Results, board: str, log_dir: Path, limits: budget.Budget, update_baseline: bool = False) -> Tally:
    """A QEMU board's results (of one run, or of a split run's shards
    joined: kit report --merge) against its baseline: see check_budget.
    Writes <log_dir>/<board folder>/results.json, then its report."""
    folder = check_board(board)
    baseline_path = BASELINES / f"{folder}.json"
    out_dir = log_dir / folder
    out_dir.mkdir(parents=True, exist_ok=True)
    current = out_dir / "results.json"
    current.write_text(json.dumps(data.to_json(), indent=2) + "\n")
    if update_baseline:
        write_baseline(data, baseline_path)
        print(f"[kit]   baseline written: {baseline_path}", flush=True)
    if not baseline_path.is_file():
        raise KitError(f"no baseline for {board} ({baseline_path}): run `scripts/kit test --board {board} "
                       "--update-baseline` once and commit the file")
    baseline = results.load(baseline_path)
    verdict = budget.check(data, baseline, limits)
    for violation in verdict.violations:
        print(f"[kit]   budget: {violation}", flush=True)
    undersized = [f"{name}: {fault}" for name in data.names()
                  for fault in sizing.too_small([sizing.Advice.from_json(t)
                                                 for t in data.variants[name].sizing.get("tables", [])])]
    for fault in undersized:
        print(f"[kit]   sizing: {fault}", flush=True)
    for variant, sizes in verdict.sizes:
        if variant in verdict.over_size:  # a failed size budget says which symbols grew
            for line in symbols.render(sizes, limit=15):
                print(f"[kit]   {variant}: {line}", flush=True)
    tally = Tally(passed=1) if verdict.passed else Tally(failed=1)
    tally.add(Tally(failed=1) if undersized else Tally(passed=1))
    # The report is for the reader; the verdict above does not depend on it
    from kittools.report import writer

    writer.write(data, out_dir / "report", baseline, limits)
    print(f"[kit]   {board}: report against {baseline_path.name}: {out_dir / 'report' / 'report.html'}", flush=True)
    return tally


def report_built_only(board: str, log_dir: Path) -> Tally:
    """A real board's results (its builds only: ROM and RAM, by layer) and
    their report, in <log_dir>/<board folder>/ like a QEMU board's; no
    baseline, no budget (nothing ran). One count: the results were made."""
    return write_built_only(results.built_only(TWISTER_OUT, board), board, log_dir)


def write_built_only(data: Results, board: str, log_dir: Path) -> Tally:
    """A real board's results file and report (see report_built_only)."""
    out_dir = log_dir / check_board(board)
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "results.json").write_text(json.dumps(data.to_json(), indent=2) + "\n")
    from kittools.report import writer  # for the reader; kept out of the budget gate's imports

    writer.write(data, out_dir / "report")
    print(f"[kit]   {board}: built only, ROM and RAM by layer: {out_dir / 'report' / 'report.html'}", flush=True)
    return Tally(passed=1)


def write_shard(board: str, log_dir: Path, built_only: bool = False) -> Tally:
    """What this shard of a split run (kit test --subset) made of `board`:
    <log_dir>/<board folder>/shard.json for kit report --merge, which judges
    the board once every shard's parts are joined. One count where the
    shard made anything of the board; none where twister gave it nothing."""
    if built_only:
        if not results.suite_builds(TWISTER_OUT, board, results.BUILD_ONLY_PREFIX):
            return Tally()
        shard = shards.BoardShard(board, built_only=results.built_only(TWISTER_OUT, board))
    else:
        found, floors = results.collect(TWISTER_OUT, board, log_dir)
        if not found and not floors.paths and not floors.zephyr:
            return Tally()
        shard = shards.BoardShard(board, found, floors)
    path = shards.write(shard, log_dir)
    made = [p.variant for p in shard.played] + list(shard.built_only.variants if shard.built_only else ())
    print(f"[kit]   {board}: this shard's part ({', '.join(made) or 'kernel floor only'}): {path}", flush=True)
    return Tally(passed=1)


def write_baseline(data: Results, path: Path) -> None:
    """A board's baseline: the conditions and every variant's metrics (with
    its build, modules and footprint) and its sweeps' records (the breaking
    points the budget holds), not the rest of the console records."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data.to_json(with_records=False), indent=2) + "\n")


def gtest_tally(path: Path) -> Tally:
    data = json.loads(path.read_text())
    return Tally(passed=data["tests"] - data["failures"] - data.get("errors", 0),
                 failed=data["failures"] + data.get("errors", 0))


def run_host_tests(log_dir: Path) -> Tally:
    tests_dir = KIT_ROOT / "tests" / "host"
    # No coverage instrumentation (the kit reports none), so ccache can serve
    # a fresh clone's host build: with -ftest-coverage it hashes the build
    # folder's absolute path and never hits across clones (88 s cold, 7 s warm)
    configure = ["cmake", "-S", str(tests_dir), "-B", str(HOST_BUILD), "-G", "Ninja", "-DBUILD_TESTING=ON",
                 "-DFPRIME_ENABLE_UT_COVERAGE=OFF"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
    if _run(configure, log_dir / "host-configure.log") != 0:
        raise KitError(f"host test configuration failed; see {log_dir / 'host-configure.log'}")
    if _run(["cmake", "--build", str(HOST_BUILD), "--target", "kit_host_tests"], log_dir / "host-build.log") != 0:
        raise KitError(f"host test build failed; see {log_dir / 'host-build.log'}")
    tally = Tally()
    for exe in sorted((HOST_BUILD / "bin").glob("*/*")):
        if not (exe.name.startswith("app_") or exe.name.startswith("Kit_")):
            continue
        gtest_json = log_dir / f"{exe.name}.json"
        gtest_json.unlink(missing_ok=True)
        code = _run([str(exe), f"--gtest_output=json:{gtest_json}"], log_dir / f"{exe.name}.log")
        tests = gtest_tally(gtest_json) if gtest_json.is_file() else Tally()
        tally.add(tests)
        if code != 0 and tests.failed == 0:
            # Crashed before its report, or a sanitizer (leak, UB) failed it after
            # every test passed: one failure, its log says which
            print(f"[kit]   {exe.name} exited {code} with no failed test: see {log_dir / (exe.name + '.log')}",
                  flush=True)
            tally.failed += 1
    if tally.passed + tally.failed == 0:
        raise KitError(f"no host test executable found in {HOST_BUILD / 'bin'}")
    return tally


def junit_tally(path: Path) -> Tally:
    root = ET.parse(path).getroot()
    suites = [root] if root.tag == "testsuite" else list(root)
    tests = sum(int(s.get("tests", 0)) for s in suites)
    bad = sum(int(s.get("failures", 0)) + int(s.get("errors", 0)) for s in suites)
    return Tally(passed=tests - bad - sum(int(s.get("skipped", 0)) for s in suites), failed=bad)


def run_pytest(log_dir: Path) -> Tally:
    xml = log_dir / "pytest.xml"
    code = _run(["python", "-m", "pytest", "-q", f"--junitxml={xml}"], log_dir / "pytest.log",
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
            print(f"[kit]   {tool} found problems (exit {code}): see {log}", flush=True)
            tally.failed += 1
    return tally


# --- Porting: the scaffolder on a scratch copy of the clone -------------
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


def run_porting_check(log_dir: Path) -> Tally:
    """`kit new-board` as a new user meets it, in a scratch copy of the
    clone (<log_dir>/porting/scratch): PORTING_QEMU_BOARD scaffolded, then
    `kit compare` on it (PORTING_MODELS, nominal and load) with no edit;
    PORTING_REAL_BOARD (its devicetree enables the console alone)
    scaffolded, then built for PORTING_MODELS with no edit. One count
    per scaffold, per compared scenario (twister's), per build."""
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
        print(f"[kit]   porting: {name}: {'PASS' if code == 0 else f'FAIL (exit {code}; {log})'} "
              f"({time.monotonic() - started:.0f} s)", flush=True)
        return code == 0

    def count(passed: bool) -> None:
        tally.add(Tally(passed=1) if passed else Tally(failed=1))

    # A QEMU board: the QEMU suites' lists, not the real boards' (kit compare refuses those)
    qemu_ok = step(f"kit new-board {PORTING_QEMU_BOARD}", [*kit, "new-board", PORTING_QEMU_BOARD],
                   out / "new-board-qemu.log")
    listed_real = PORTING_QEMU_BOARD in suite_boards(scratch / BOARDS_SUITE_FILE)
    if listed_real:
        print(f"[kit]   porting: {PORTING_QEMU_BOARD} was added to {BOARDS_SUITE_FILE}, the real boards' list",
              flush=True)
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
        for model in PORTING_MODELS:
            build = scratch / "build" / "porting" / f"{board_dir_name(PORTING_REAL_BOARD)}.{model}"
            count(step(f"west build -b {PORTING_REAL_BOARD} -T tests/boards/board.{model}",
                       ["west", "build", "-b", PORTING_REAL_BOARD, "-d", str(build), "-T",
                        f"tests/boards/board.{model}"], out / f"build-{model}.log"))
    return tally
