# SPDX-License-Identifier: Apache-2.0
"""The ground link's checks of `kit test`: the integration suite through
fprime-gds, the raw link, fuzzing, the flood and the serial-load sweep."""

from __future__ import annotations

import concurrent.futures
import functools
import json
import sys
import time
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import Any, Protocol, TypeVar

from kittools import sweep
from kittools.boards.scaffold import REFERENCE_BOARD
from kittools.build import runner
from kittools.link import file_fuzz, flood, fuzz, ground, serial_sweep
from kittools.link.dictionary import Dictionary
from kittools.link.sequence_load import RUN_COMMAND
from kittools.link.serial_points import SEQUENCE, SegmentClock
from kittools.log import LOG, say
from kittools.suite import platforms, results
from kittools.suite.counts import Tally, junit_failures, junit_tally, run_logged
from kittools.suite.platforms import TWISTER_OUT
from kittools.suite.stack_marks import STACKS_FILE, stack_summary, stacks_after_the_suite
from kittools.workspace import KIT_ROOT, KitError, check_board

INTEGRATION = KIT_ROOT / "tests" / "integration"


# The checks through fprime-gds run two builds at a time. The integration
# API's time-outs are the host's, and while a station's QEMU skipped idle
# time two at once missed a first NO_OP's 10 s; in real time (GroundStation)
# each sends fprime-gds its deployment's own telemetry rate, and nine
# stations two at a time took 55 s, against 98 s one at a time, all passed
# (twice). Fuzzing, the flood, the serial-load sweep and the foreign
# dictionary wait for the deployment's answers and pace on its own clock,
# however long the host takes: two builds at a time, one QEMU per core (the
# sweep's latencies are host-timed anyway: the report gives the median and
# spread of its plays; what it offers does not depend on the host, and its
# breaking points are the median play's).
INTEGRATION_JOBS = 2
RAW_LINK_JOBS = 2

#: The serial axes are swept on the reference board, every model (a
#: minute or more per build): what a level delivers is
#: bound by the line rate and the link driver, the same code on every board;
#: the other boards get the flood and the fuzzing, which check the link's
#: accounting and its halt-free recovery (CI time: issue 31)
SERIAL_SWEEP_BOARD = REFERENCE_BOARD
#: The sweep runs in real time (QEMU's UART takes the host's bytes at the
#: host's pace), so each play of a level costs its seconds: CI's run plays
#: each level once (about 60 s a build instead of 185), the full run and a
#: baseline's run three times (serial_points.REPEATS: median and spread).
#: What a level offers is the same in every play; what it delivers and the
#: latencies move from play to play, and the budget holds none of them
SERIAL_PLAYS_CI = 1
#: Elsewhere, a build with F´'s command sequencer plays the sequence axis
#: alone (issue 32: a sequence as a further load; qemu_cortex_m3's profile
#: leaves the sequencer out), about 10 s a play of its levels
SEQUENCE_AXES = (SEQUENCE.name,)


def ground_builds(required: bool = True, twister_out: Path = TWISTER_OUT) -> list[tuple[str, Path]]:
    """(platform, build) of every build of the last twister run (in
    `twister_out`) that can play the ground scenario; none is an error where
    `required`."""
    # The comparison's builds, and on a small part the profile's that fit it
    candidates = results.suite_builds(twister_out) + [
        (platform, build) for platform, build in results.suite_builds(twister_out, prefix=results.PROFILE_PREFIX)
        if platforms.is_small_part(platform)]
    builds = [(platform, build) for platform, build in candidates if ground.serves_ground(build)]
    if not builds and required:
        raise KitError(f"twister made no build of the suite that can play the ground scenario under {twister_out}")
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
                    required: bool = True, serial_plays: int = SERIAL_PLAYS_CI) -> Tally:
    """The ground-link checks of every build of the suite, each booted under
    QEMU into its ground scenario: first tests/integration (F´'s
    integration-test API, through fprime-gds's pytest plugin, with
    fprime-gds on the build's link: kittools.link.ground), `jobs` builds at a
    time; then the foreign dictionary, uplink fuzzing, the flood and the
    serial-load sweep, `raw_link_jobs` builds at a time. Two builds never share a QEMU
    pipe, a link socket or a GDS transport (each station's is its own). The
    kit's own runner, not twister's pytest harness: that harness owns one
    console and knows nothing of a second serial port or a GDS. Not
    `required` (a shard of a split run): a run that made none checks none.
    The serial-load sweep plays each level `serial_plays` times."""
    builds = ground_builds(required)
    raw_link = functools.partial(raw_link_checks, serial_plays=serial_plays)
    return _each_build(builds, log_dir, ((station_checks, jobs), (raw_link, raw_link_jobs)))


def run_deployment_link(log_dir: Path, twister_out: Path, serial_plays: int = 0) -> Tally:
    """The ground link's checks of a deployment other than the reference
    (kit test --deployment, and kit test's second deployment), on every
    ground build of its twister run in `twister_out`: the integration suite
    through fprime-gds (its tests of the reference's own components skip
    themselves), then deployment_link_checks."""
    builds = ground_builds(twister_out=twister_out)
    raw_link = functools.partial(deployment_link_checks, serial_plays=serial_plays)
    return _each_build(builds, log_dir, ((station_checks, INTEGRATION_JOBS), (raw_link, RAW_LINK_JOBS)))


_Checks = Callable[[str, Path, Path], Tally]


def _each_build(builds: list[tuple[str, Path]], log_dir: Path, passes: tuple[tuple[_Checks, int], ...]) -> Tally:
    """Each pass's checks on every build, that many builds at a time, one pass after the other."""
    tally = Tally()
    for checks, workers in passes:
        with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
            for result in pool.map(checks, [p for p, _ in builds], [b for _, b in builds],
                                   [log_dir] * len(builds)):
                tally.add(result)
    return tally


def _ground_name(platform: str, build: Path) -> str:
    return f"{platform.replace('/', '_')}_{build.name}"


def station_checks(platform: str, build: Path, log_dir: Path, select: str | None = None) -> Tally:
    """One build's check through fprime-gds, whose time-outs are the
    host's: the integration suite (its tests matching `select`, pytest's
    -k), QEMU in real time (GroundStation)."""
    name = _ground_name(platform, build)
    logs = results.integration_logs(log_dir, platform, build.name)
    xml = logs / "pytest.xml"
    started = time.monotonic()
    with ground.GroundStation(build, logs) as station:
        # One hyperperiod's segment after the last test: its end prints the stacks (tests/integration/conftest.py)
        hyperperiod = SegmentClock.of_console(station.lines()).hyperperiod_ticks
        run_logged([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(INTEGRATION),
              *(["-k", select] if select else []), *station.client_arguments(), "--logs", str(logs / "api"),
              # the test client's own file downlinks (the station's are in its logs' files/)
              "--file-storage-directory", str(logs / "api-files"),
              f"--kit-stacks-ticks={hyperperiod}", f"--junitxml={xml}"],
             logs / "pytest.log")
        stacks = stacks_after_the_suite(station)
        console_text = station.console()
    (logs / "console.log").write_text(console_text + "\n")
    if not xml.is_file():
        raise KitError(f"the integration suite wrote no report for {build}; see {logs / 'pytest.log'}")
    tally = junit_tally(xml)
    say(f"  {name}: {tally.passed} passed, {tally.failed} failed "
        f"({time.monotonic() - started:.0f} s; logs {logs})")
    if stacks:
        (logs / STACKS_FILE).write_text("\n".join(stacks) + "\n")
        say(f"  {name}: stacks after the suite (used of size, B): {stack_summary(stacks)}")
    else:
        say(f"  {name}: the deployment printed no stacks after the suite (console.log)")
    if tally.failed:
        say(f"  {name}: FAIL: {'; '.join(junit_failures(xml))} (pytest.log: {logs / 'pytest.log'})")
    return tally


def raw_link_checks(platform: str, build: Path, log_dir: Path, serial_plays: int = SERIAL_PLAYS_CI) -> Tally:
    """One build's checks on the raw link, paced by the deployment's own
    answers and clock, one after the other (they share its QEMU pipe and
    link socket): another build's dictionary refused, uplink fuzzing of
    frames and of file packets, the flood, and on SERIAL_SWEEP_BOARD the
    serial-load sweep, each level played `serial_plays` times."""
    checks: list[_BuildCheck] = [fuzz_build, file_fuzz_build, flood_build]
    if check_board(platform) == check_board(SERIAL_SWEEP_BOARD):
        checks.append(functools.partial(serial_sweep_build, plays=serial_plays))
    elif serial_plays and Dictionary.read(ground.link_of(build).dictionary).owner_of(RUN_COMMAND) is not None:
        checks.append(functools.partial(serial_sweep_build, plays=serial_plays, axes=SEQUENCE_AXES))
    return _on_raw_link(platform, build, log_dir, checks)


def deployment_link_checks(platform: str, build: Path, log_dir: Path, serial_plays: int = 0) -> Tally:
    """Another deployment's build on the raw link (run_deployment_link):
    another build's dictionary refused, uplink fuzzing
    (FUZZ_INVALID_FRAMES_OTHER_BOARDS frames: the dispatcher's refusals are
    the deployment's), file-uplink fuzzing where it has F´'s file uplink,
    the flood, and where `serial_plays` the serial-load sweep, each level
    played that many times (its file axis where it has F´'s file downlink)."""
    checks: list[_BuildCheck] = [functools.partial(fuzz_build, frames=FUZZ_INVALID_FRAMES_OTHER_BOARDS),
                                 file_fuzz_build, flood_build]
    if serial_plays:
        checks.append(functools.partial(serial_sweep_build, plays=serial_plays))
    return _on_raw_link(platform, build, log_dir, checks)


_BuildCheck = Callable[[Path, str, Path], Tally]


def _on_raw_link(platform: str, build: Path, log_dir: Path, checks: list[_BuildCheck]) -> Tally:
    """Another build's dictionary refused, then each check, one after the other."""
    name = _ground_name(platform, build)
    logs = results.integration_logs(log_dir, platform, build.name)
    # A record file an earlier run's check left would join this run's results
    for file_name in results.LINK_RECORD_FILES:
        (logs / file_name).unlink(missing_ok=True)
    tally = foreign_dictionary_build(build, name, logs)
    for check in checks:
        try:
            tally.add(check(build, name, logs))
        except Exception:  # noqa: BLE001 - one check's error is its failure; the build's other checks still run
            say(f"  {name}: {getattr(check, '__name__', check)}: FAIL, it raised:\n{traceback.format_exc()}")
            tally.add(Tally(failed=1))
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
    say(f"  {name}: another build's dictionary: {'refused' if failure is None else 'FAIL: ' + failure}")
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
        LOG.error(f"  {name}: {what}: FAIL: {error}")
        return None
    path.write_text(json.dumps(outcome.to_json(), indent=2) + "\n")
    return outcome


def serial_sweep_build(build: Path, name: str, logs: Path, plays: int = SERIAL_PLAYS_CI,
                       axes: tuple[str, ...] | None = None) -> Tally:
    """Boot a ground build and run the serial-load sweep on its link
    (kittools.link.serial_sweep), every axis or those named, each level
    `plays` times; the records go to serial.json beside the other logs,
    where the board's results (results.from_twister) take them."""
    started = time.monotonic()
    outcome = _recorded(name, "serial-load sweep", lambda: serial_sweep.run(build, plays, axes),
                        logs / results.SERIAL_SWEEP_FILE)
    if outcome is None:
        return Tally(failed=1)
    found = outcome.sweep()
    breaks = {f"{axis} {rg}": sweep.level_text(found.breaking_point(axis, rg), found.unit(axis))
              for axis in found.axes() for rg in found.rate_groups()} if found else {}
    which = f" ({', '.join(axes)} axis)" if axes else ""
    say(f"  {name}: serial-load sweep{which}, {plays} play(s) a level, {len(outcome.lines)} points x rate groups, "
        f"breaking points "
        f"{breaks} ({time.monotonic() - started:.0f} s)")
    return Tally(passed=1)


# Uplink fuzzing: a fixed seed, so two runs send the same bytes and must
# give the same counts (the seed is in every record). Each model gets its
# 10,000 invalid frames on the reference board; the other boards, where the
# deployment is the same code, a quarter of that.
FUZZ_SEED = 20261201
FUZZ_INVALID_FRAMES = 10_000
FUZZ_INVALID_FRAMES_OTHER_BOARDS = 2_500


def _played_booted(link: ground.Link, play: Callable[[Callable[[], str]], _R], console_log: Path,
                   what: str) -> _R | None:
    """Boot a ground build and play `play` on its link, given how to ask
    whether the deployment halted; its console goes to `console_log`.
    None where the play failed (a failed check, logged under `what`, not
    the end of `kit test`)."""
    with ground.boot(link) as qemu:

        def halted() -> str:
            qemu.read_until(lambda line: False, 0.001)
            return runner.halt_lines(qemu.lines)

        try:
            return play(halted)
        except KitError as error:
            LOG.error(f"{what}: FAIL: {error}")
            return None
        finally:
            console_log.write_text(qemu.text() + "\n")


def fuzz_build(build: Path, name: str, logs: Path, frames: int | None = None) -> Tally:
    """Boot a ground build and fuzz its uplink (kittools.link.fuzz) with
    `frames` invalid frames (by default the board's share); the outcome
    goes to fuzz.json beside the other logs."""
    link = ground.link_of(build)
    started = time.monotonic()
    if frames is None:
        reference = link.board.split("/")[0] == REFERENCE_BOARD
        frames = FUZZ_INVALID_FRAMES if reference else FUZZ_INVALID_FRAMES_OTHER_BOARDS
    outcome = _played_booted(
        link, lambda halted: fuzz.run(link.socket, link.dictionary, FUZZ_SEED, frames, halted=halted),
        logs / "fuzz.console.log", f"  {name}: fuzzing (seed {FUZZ_SEED})")
    if outcome is None:
        return Tally(failed=1)
    record = outcome.to_json()
    (logs / "fuzz.json").write_text(json.dumps(record, indent=2) + "\n")
    failures = outcome.failures()
    say(f"  {name}: fuzzing (seed {outcome.seed}): {outcome.invalid_sent} invalid frames "
        f"{dict(sorted(outcome.sent.items()))}, {outcome.noops_answered}/{outcome.noops_sent} NO_OPs answered, "
        f"rejected {record['rejected']} ({time.monotonic() - started:.0f} s): "
        f"{'PASS' if not failures else 'FAIL: ' + '; '.join(failures)}")
    return Tally(failed=1) if failures else Tally(passed=1)


# File-uplink fuzzing: the same seed; packets FileUplink must refuse, per
# model on every board that has the file uplink (issue 32: at least 2,500)
FILE_FUZZ_INVALID_PACKETS = 2_500


def file_fuzz_build(build: Path, name: str, logs: Path) -> Tally:
    """Boot a ground build and fuzz its file uplink (kittools.link.file_fuzz);
    the outcome goes to file-fuzz.json beside the other logs. A build whose
    board profile leaves the file uplink out is skipped, and said to be."""
    link = ground.link_of(build)
    if not file_fuzz.has_file_uplink(link.dictionary):
        say(f"  {name}: file-uplink fuzzing: skipped (this build has no F´ file uplink: its deployment, or its "
            "board's profile for this model, leaves it out)")
        return Tally()
    started = time.monotonic()
    outcome = _played_booted(
        link, lambda halted: file_fuzz.run(link.socket, link.dictionary, FUZZ_SEED, FILE_FUZZ_INVALID_PACKETS,
                                           halted=halted),
        logs / "file-fuzz.console.log", f"  {name}: file-uplink fuzzing (seed {FUZZ_SEED})")
    if outcome is None:
        return Tally(failed=1)
    record = outcome.to_json()
    (logs / "file-fuzz.json").write_text(json.dumps(record, indent=2) + "\n")
    failures = outcome.failures()
    say(f"  {name}: file-uplink fuzzing (seed {outcome.seed}): {outcome.invalid_sent} invalid file packets of "
        f"{sum(outcome.sent.values())} {dict(sorted(outcome.sent.items()))}, counted {record['counted']} "
        f"({time.monotonic() - started:.0f} s): {'PASS' if not failures else 'FAIL: ' + '; '.join(failures)}")
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
    say(f"  {name}: flood ({outcome.seconds:.1f} s at {outcome.baud} baud): {outcome.record()}, slips "
        f"{slips} ({time.monotonic() - started:.0f} s): {'PASS' if not failures else 'FAIL: ' + '; '.join(failures)}")
    return Tally(failed=1) if failures else Tally(passed=1)
