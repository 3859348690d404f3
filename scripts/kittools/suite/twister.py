# SPDX-License-Identifier: Apache-2.0
"""Twister's runs of the suite: its command, its progress as lines, and what
a clean run was configured from."""

from __future__ import annotations

import hashlib
import re
import shutil
import subprocess
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from kittools.build.folder import CONSOLE_LOG, BuildFolder, kit_kconfig_digest
from kittools.deployment import CACHE_ENTRY, REFERENCE
from kittools.log import LOG, say
from kittools.sizes import memory
from kittools.suite import fit, floor, results
from kittools.suite.counts import Tally, twister_tally
from kittools.suite.platforms import TWISTER_OUT
from kittools.workspace import KIT_ROOT, KitError, commit_label, environment

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
        """What to say (a progress line) for this line of twister's output, or None."""
        text = _ANSI.sub("", text).rstrip()
        if match := _JOBS.match(text):
            self.jobs = int(match["jobs"])
            return None
        if match := _SELECTED.match(text):
            self.total = int(match["configurations"]) - int(match["static"])
            jobs = f", {self.jobs} at a time" if self.jobs else ""
            return f"  twister: {self.total} configurations to build and run{jobs}"
        match = _DONE.match(text)
        if match is None:
            return None
        done = int(match["done"])
        total = self.total if self.total is not None else int(match["total"])
        seconds = _SECONDS.search(match["info"])
        info = f"{float(seconds['s']):.1f} s" if seconds else match["info"]
        reason = f" {match['reason']}" if match["reason"] else ""
        suite = match["suite"].rsplit("/", 1)[-1]
        return (f"  {done}/{total} {match['platform']} {suite} {match['status']}{reason} {info} "
                f"({max(total - done, 0)} left)")


def _run_streamed(command: list[str], log: Path, progress: Callable[[str], str | None]) -> int:
    """Run `command`, its whole output into `log`; each line (ended by a
    newline or a carriage return) is also given to `progress`, which returns
    what to say (a progress line), if anything."""
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
                shown = progress(piece)
                if shown is not None:
                    say(shown)
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
            try:
                logs = sorted(self._out_dir.glob(f"*/**/{results.RUNS_DIR}/*.log"))
            except OSError:
                # CMake's try-compiles make and remove folders while the
                # glob walks them: look again next period
                continue
            for log in logs:
                if log in self._seen or log.stat().st_mtime < self._started:
                    continue
                self._seen.add(log)
                lines = log.read_text(errors="replace").splitlines()
                build = log.parent.parent
                platform = build.relative_to(self._out_dir).parts[0]
                say(f"    {platform} {build.name} {log.stem}: {lines[-1] if lines else '(no output)'} "
                    f"({len(self._seen)} runs played)")


def run_twister(platforms: list[str], log_dir: Path, out_dir: Path = TWISTER_OUT,
                scenarios: tuple[str, ...] = (), exclude_tags: tuple[str, ...] = (),
                models: tuple[str, ...] = (), with_floor: bool = True, subset: str | None = None,
                cmake_args: tuple[str, ...] = ()) -> Tally:
    """The suite (tests/) on every board: one build per execution model and
    board, each playing every scenario, or only `scenarios` (pytest's -k),
    but for the test suites tagged with one of `exclude_tags`; with
    `models`, only those variants' builds (and the kernel floor's, unless
    not `with_floor`); with `subset` (K/N), twister's own share K of N of
    the configurations (kit test --subset); `cmake_args` (-DNAME=value) to
    every build (a deployment's: kittools.deployment); two builds or QEMU
    runs at a time (icount timing does not depend on the host's load).
    Twister's whole output goes to <log_dir>/twister.log; one line per
    finished configuration is printed."""
    for console_log in out_dir.glob(f"*/**/{floor.PREFIX}*/{CONSOLE_LOG}"):  # the kernel floor's records
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
    for argument in cmake_args:
        command.append("-x=" + argument.removeprefix("-D"))
    tally = play(command, log_dir / "twister.log", out_dir)
    for overflow in fit.overflows(out_dir):
        LOG.error(f"  {overflow.text()}")
    say_built_only(out_dir)
    say_profiles(out_dir)
    return tally


#: The suite's tag for its footprint profiles' builds (tests/deployment/testcase.yaml),
#: which a comparison leaves out (kit compare, the second deployment's run)
PROFILE_TAG = "profile"

#: The twister tag of the builds only the full run makes (kit test --full):
#: the real boards' builds of a baremetal policy, whose port is the model's
FULL_RUN_TAG = "full"

#: In a twister outdir: what the last clean run configured its builds from
CONFIGURED_FROM = "kit-configured-from.sha256"
#: The environment a build's configuration depends on beyond its files (the toolchain)
_CONFIGURE_ENVIRONMENT = ("ZEPHYR_TOOLCHAIN_VARIANT", "GNUARMEMB_TOOLCHAIN_PATH", "ZEPHYR_SDK_INSTALL_DIR")




def configured_from() -> str:
    """What twister configures the kit's builds from that their own build
    files do not track: every test suite's testcase.yaml (twister hands its
    extra_args to CMake once), the toolchain's environment, the kit's
    commit (app/provenance.cmake writes it into the image at configure
    time: a reused build kept an earlier commit's, '-dirty' and all, which
    moves icount's timing), and the kit's Kconfig files. Ninja configures again when a Kconfig file changes, but
    Zephyr then takes the build's last .config as input (its .conf
    fragments unchanged), which keeps every prompted symbol's old value: a
    changed default reaches a build only configured from scratch (play).
    Everything else a configuration reads (CMake files, .conf fragments,
    snippets, F´'s FPP files) is a configure dependency ninja checks itself."""
    digest = hashlib.sha256()
    for suite in sorted(KIT_ROOT.glob("tests/**/testcase.yaml")):
        digest.update(f"{suite.relative_to(KIT_ROOT)}\0".encode() + suite.read_bytes() + b"\0")
    digest.update(kit_kconfig_digest(KIT_ROOT).encode())
    digest.update(f"commit={commit_label(KIT_ROOT)}\0".encode())
    env = environment()
    for name in _CONFIGURE_ENVIRONMENT:
        digest.update(f"{name}={env.get(name, '')}\0".encode())
    return digest.hexdigest()


def forget_other_deployments(out_dir: Path, command: list[str]) -> None:
    """A build folder configured for another deployment than the command's
    (its -x=KIT_DEPLOYMENT_DIR, or the reference's) is configured from
    scratch: its CMake cache keeps the Kconfig fragments of that deployment
    (CONF_FILE: its deployment.conf), which a reconfigure does not replace.
    Two deployment folders of one name share an output folder
    (deployment-<name>)."""
    prefix = f"-x={CACHE_ENTRY}="
    wanted = next((arg.removeprefix(prefix) for arg in command if arg.startswith(prefix)), str(REFERENCE))
    for build in BuildFolder.configured_under(out_dir):
        built_for = build.cache_value(CACHE_ENTRY)
        if built_for is not None and Path(built_for) != Path(wanted):
            build.cmake_cache.unlink(missing_ok=True)


def play(command: list[str], log: Path, out_dir: Path) -> Tally:
    """Run a twister command that plays the suite into `out_dir`, a line
    per finished configuration and per scenario played; its tally."""
    # -n: build in the last run's folders, so that a second run rebuilds only
    # what changed (ccache does the rest). Twister configures each build
    # again (about 20 s of a core with F´'s sub-build), unless told not to
    # (--aggressive-no-clean): done when the last run passed and what
    # twister configures from is as it was then (configured_from); ninja
    # configures again whatever else changed.
    stamp = out_dir / CONFIGURED_FROM
    # ... and from the CMake entries the command adds (a deployment's folder)
    fingerprint = configured_from() + "".join(f" {arg}" for arg in command if arg.startswith("-x="))
    reuse = stamp.is_file() and stamp.read_text().strip() == fingerprint
    stamp.unlink(missing_ok=True)
    if not reuse:
        # Each build's Kconfig from its fragments and the kit's Kconfig
        # defaults as they are now, not from its last .config (configured_from)
        for build in BuildFolder.configured_under(out_dir):
            build.config.unlink(missing_ok=True)
        forget_other_deployments(out_dir, command)
        # The Kconfig file twister wrote for an earlier suite's extra_configs:
        # twister hands any it finds to CMake, whatever the suite says now
        # (the kit's suites set Kconfig through extra_args: testcase.yaml).
        # Its build folder is configured from scratch: its CMake cache names
        # the file (OVERLAY_CONFIG) and twister no longer passes it.
        for overlay in out_dir.glob("*/**/twister/testsuite_extra.conf"):
            overlay.unlink()
            BuildFolder(overlay.parent.parent).cmake_cache.unlink(missing_ok=True)
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


def say_built_only(out_dir: Path = TWISTER_OUT) -> None:
    """A line per real board's build (tests/boards): its ROM and RAM, as
    built; nothing ran on it."""
    try:
        builds = results.suite_builds(out_dir, prefix=results.BUILD_ONLY_PREFIX)
    except KitError:
        return  # a build that failed: twister's tally counts it
    for platform, build in builds:
        size = memory.measure(build)
        say(f"  {platform} {build.name}: built, not run (no emulator; docs/porting.md): "
            f"ROM {size.rom:,} of {size.rom_size:,} B, RAM {size.ram:,} of {size.ram_size:,} B")


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
            say(f"  {platform} {model} with fprime-{profile}: ROM {size.rom:,} B, RAM {size.ram:,} B")
            continue
        kit = memory.measure(kit_build)
        say(f"  {platform} {model} with fprime-{profile}: ROM {size.rom:,} B ({size.rom - kit.rom:+,} from "
            f"the kit profile's {kit.rom:,}), RAM {size.ram:,} B ({size.ram - kit.ram:+,} from {kit.ram:,})")
