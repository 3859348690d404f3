# SPDX-License-Identifier: Apache-2.0
"""kit test: the full run (or a share of it, --subset K/N), the quick run,
or device testing, each as a plan of named steps in two lanes
(kittools.suite.plan)."""

from __future__ import annotations

import argparse
import concurrent.futures
import functools
import threading
from pathlib import Path

from kittools import deployment, variants
from kittools.boards.scaffold import REFERENCE_BOARD
from kittools.build.folder import BuildFolder
from kittools.link import serial_points
from kittools.log import LOG
from kittools.suite import (
    budget,
    deployment_run,
    determinism,
    device_runs,
    ground_checks,
    host,
    imported,
    platforms,
    porting,
    results,
    shards,
    style,
    template_deployment,
    twister,
    verdict,
)
from kittools.suite.counts import Tally
from kittools.suite.plan import Plan, settle
from kittools.workspace import KIT_ROOT, KitError, check_committed, check_provisioned

#: The deployment unlike the reference one that CI measures through the seam,
#: in an F´ project of its own as a team's repository holds one
#: (docs/your-deployment.md)
SECOND_DEPLOYMENT = KIT_ROOT / "tests" / "team" / "Thermal"

#: kit test --quick: the scenarios every model plays on the reference board
QUICK_SCENARIOS = ("nominal", "faults", "load")
#: ... and the integration suite's test each ground station runs (pytest -k)
QUICK_GROUND_TEST = "test_noop_completes_with_its_events"


def last_share(subset: tuple[int, int] | None) -> bool:
    """This run is the whole run, or the last share of a split one."""
    return subset is None or subset[0] == subset[1]


def subset_of(text: str | None) -> tuple[int, int] | None:
    """K/N of kit test --subset as (K, N); KitError unless 1 <= K <= N."""
    if text is None:
        return None
    try:
        k, n = (int(x) for x in text.split("/"))
    except ValueError:
        k = n = 0
    if not 1 <= k <= n:
        raise KitError(f"--subset {text}: expected K/N with 1 <= K <= N (this machine's share K of N, as "
                       "twister's --subset takes it), e.g. --subset 1/2 and --subset 2/2 on two machines")
    return k, n


def serial_plays(args: argparse.Namespace) -> int:
    """Plays of each serial-load level: once in CI's run, as often as the
    report's median and spread want in the full run and in the run that
    writes a baseline (which keeps the serial axes as the full run plays them)."""
    return serial_points.REPEATS if args.full or args.update_baseline else ground_checks.SERIAL_PLAYS_CI


def run(args: argparse.Namespace) -> int:
    if args.device_testing or args.hardware_map:
        return device_plan(args).run()
    if args.deployment:
        return deployment_plan(args).run()
    if args.quick:
        return quick_plan(args).run()
    return FullRun(args).plan().run()


class FullRun:
    """The full run's steps. The QEMU lane: twister, then what reads its
    builds. The host lane needs none of them; it runs beside twister, and
    the ground link's checks wait for it to end: their time-outs are the
    host's, and they keep it to themselves."""

    def __init__(self, args: argparse.Namespace) -> None:
        self.args = args
        self.subset = subset_of(args.subset)
        if self.subset and args.update_baseline:
            raise KitError("--update-baseline needs the whole run on one machine: a shard holds part of each board")
        if args.update_baseline:
            # Measured: a '-dirty' commit in the image (app/provenance.cmake,
            # F´'s version strings) moved mps2/an385 baremetal_passive's rg10Hz
            # period error p99 by 14 us under icount, against a clean clone's
            check_committed("a baseline is compared with runs of committed trees, and the commit strings in the "
                            "image ('-dirty' lengthens them) move the code after them, which moves icount's "
                            "timing figures")
        # The real boards are built and not run (tests/boards): no budget, no
        # ground link, nothing to play
        self.boards = ([b for b in args.board if not platforms.is_real_board(b) and not platforms.is_small_part(b)]
                       if args.board else platforms.suite_boards())
        # The small parts play the builds that fit them (the fprime-small
        # profile's) and the ground link: no comparison, so no budget
        self.small = ([b for b in args.board if platforms.is_small_part(b)] if args.board
                      else platforms.small_parts())
        self.built_only = ([b for b in args.board if platforms.is_real_board(b)] if args.board
                           else platforms.real_boards())
        check_provisioned()
        self.log_dir = Path(args.output).resolve()
        shards.start(self.log_dir, args.subset)
        self.steps = Plan()
        # Every board's size reports at once, in the background (lowest CPU
        # priority) from the determinism runs on, through the ground link's
        # checks; done before the first budget, which reads them
        self.size_reports: concurrent.futures.Future[None] = concurrent.futures.Future()
        self._size_reports_lock = threading.Lock()
        self._size_reports_started = False

    def twister(self) -> Tally:
        return twister.run_twister(self.boards + self.small + self.built_only, self.log_dir,
                                   subset=self.args.subset,
                                   exclude_tags=() if self.args.full else (twister.FULL_RUN_TAG,))

    def start_size_reports(self) -> None:
        """Once, from the first step that reads twister's runs (the
        determinism runs, or on a small part alone the ground link's)."""
        with self._size_reports_lock:
            if self._size_reports_started:
                return
            self._size_reports_started = True
        threading.Thread(target=settle, args=(self.size_reports, functools.partial(
            verdict.make_size_reports, background=True)), daemon=True).start()

    def determinism(self) -> Tally:
        self.start_size_reports()
        return determinism.check_determinism(self.log_dir, required=not self.subset)

    def ground(self) -> Tally:
        self.start_size_reports()
        self.steps.host_done.wait()
        return ground_checks.run_integration(self.log_dir, required=not self.subset,
                                             serial_plays=serial_plays(self.args))

    def second_deployment(self) -> Tally:
        """The second deployment (tests/team/Thermal) as a team runs it: its
        F´ project (tests/team) copied into a repository whose west.yml
        imports the kit, outside the clone (kittools.suite.imported); there,
        every model on the reference board, its whole run and report
        (kittools.suite.deployment_run), and `west kit sizing` of one of
        its builds from that repository."""
        with imported.importing_workspace(SECOND_DEPLOYMENT.parent, self.log_dir) as team:
            chosen = deployment.resolve(team / SECOND_DEPLOYMENT.name, [REFERENCE_BOARD])
            out_dir = deployment_log_dir(self.log_dir, chosen)
            # Its serial-load sweep in the full run only: about 50 s a model,
            # and the link it measures is the kit's, which CI's run sweeps on
            # the reference deployment's builds
            tally = deployment_run.run_deployment(chosen, REFERENCE_BOARD, out_dir,
                                                  serial_plays=ground_checks.SERIAL_PLAYS_CI if self.args.full else 0)
            builds = sorted(BuildFolder.built_under(out_dir / "twister"), key=lambda build: build.path)
            if not builds:
                LOG.error(f"  no build of {chosen.name} under {out_dir / 'twister'} for west kit sizing")
                tally.add(Tally(0, 1))
            else:
                tally.add(imported.west_kit(team, ["sizing", str(builds[0].path)], out_dir / "west-kit-sizing.log",
                                            expect="command dispatch table"))
        return tally

    def budget(self, board: str) -> Tally:
        self.size_reports.result()
        return verdict.check_budget(board, self.log_dir, budget.of_options(self.args), self.args.update_baseline)

    def shard(self, board: str, built: bool, prefix: str = results.BUILD_ONLY_PREFIX) -> Tally:
        self.size_reports.result()
        return verdict.write_shard(board, self.log_dir, built, prefix)

    def small_report(self, board: str) -> Tally:
        self.size_reports.result()
        return verdict.report_small_part(board, self.log_dir, self.args.update_baseline)

    def built_report(self, board: str) -> Tally:
        if self.boards:  # their size reports are made beside the determinism runs
            self.size_reports.result()
        return verdict.report_built_only(board, self.log_dir)

    def plan(self) -> Plan:
        args, steps, boards, subset = self.args, self.steps, self.boards, self.subset
        if not args.skip_twister:
            where = [", ".join(boards)] if boards else []
            where += [f"small parts, fprime-small: {', '.join(self.small)}"] if self.small else []
            where += [f"built only: {', '.join(self.built_only)}"] if self.built_only else []
            share = f", twister's share {args.subset}" if subset else ""
            steps.add_qemu(f"twister suite under QEMU ({'; '.join(where)}{share})", self.twister)
            if boards:  # the comparison's builds, played again
                steps.add_qemu("determinism: twister's binaries run again (size reports in the background)",
                               self.determinism)
            if boards or self.small:  # what reads the runs: none on a board only built
                # Before the budget: the board's report takes the serial-load sweep from it
                steps.add_qemu("ground link: integration suite through fprime-gds, fuzzing, serial-load sweep",
                               self.ground)
            if REFERENCE_BOARD in boards and last_share(subset):
                # Beside the budgets and reports, which read what is done and
                # leave the second core idle; after the ground link's checks,
                # whose time-outs are the host's, as are its own
                steps.add_qemu(f"second deployment: {deployment.label(SECOND_DEPLOYMENT)} through the seam, from a "
                               f"repository whose west.yml imports the kit, every model on {REFERENCE_BOARD}: "
                               f"{', '.join(deployment_run.SCENARIOS)}, ground link, report, west kit",
                               self.second_deployment, beside=True)
            for board in boards:
                if subset:  # judged once the shards are joined (kit report --merge)
                    steps.add_qemu(f"shard: {board}, this share's part", functools.partial(self.shard, board, False))
                else:
                    steps.add_qemu(f"budget: {board} results against its baseline",
                                   functools.partial(self.budget, board))
            for board in self.small:
                if subset:
                    steps.add_qemu(f"shard: {board}, small part, this share's part", functools.partial(
                        self.shard, board, True, results.PROFILE_PREFIX))
                else:
                    steps.add_qemu(f"report: {board}, small part (fprime-small)",
                                   functools.partial(self.small_report, board))
            for board in self.built_only:
                if subset:
                    steps.add_qemu(f"shard: {board}, built only, this share's part",
                                   functools.partial(self.shard, board, True))
                else:
                    steps.add_qemu(f"report: {board}, built only", functools.partial(self.built_report, board))
            if not subset:
                steps.add_qemu("report: every board side by side (what fits where)", functools.partial(
                    verdict.report_side_by_side, boards + self.small + self.built_only, self.log_dir))
        # A split run shares out the steps beside twister: the porting check (the
        # longest) to the first shard, the host's and the device path to the
        # last (measured on two shares of today's suite: the porting check took
        # 547 s, host and device 300 s; twister's sorted share put
        # qemu_cortex_m3, whose serial sweeps lengthen the ground link, last)
        first, last = (subset[0] == 1, subset[0] == subset[1]) if subset else (True, True)
        if last:
            host_steps(args, self.log_dir, steps)
        # The device path (twister's device testing, QEMU standing in for a
        # flashed board): its own build and QEMU runs, in the lane beside twister
        if not args.skip_twister and device_runs.STAND_IN_BOARD in boards and last:
            steps.add_host(f"device testing: twister's device harness, QEMU standing in for a flashed "
                           f"{device_runs.STAND_IN_BOARD} ({device_runs.STAND_IN_MODEL})",
                           functools.partial(device_runs.run_qemu_device, self.log_dir))
        # The porting path and the new-deployment path: the full run's (--full),
        # each several builds of its own (about 10 minutes each on CI's two
        # cores), which kept CI's run near 50 minutes; CI's run keeps the paths
        # every change goes through. Their own twister and west builds, in the
        # lane beside the suite's twister, done before the ground link's
        # checks start (their time-outs are the host's). A run for chosen
        # boards (--board) is about those: it leaves them out.
        if not args.skip_twister and not args.skip_porting and not args.board and args.full and first:
            steps.add_host(f"porting: a new QEMU board and a console-only real board scaffolded into a scratch "
                           f"copy ({', '.join(porting.PORTING_MODELS)})",
                           functools.partial(porting.run_porting_check, self.log_dir, args.full))
        # A deployment as F´'s tools make one, through kit new-deployment: in
        # the same lane, after the porting check (both end before the ground
        # link's checks start, which wait for this lane)
        if not args.skip_twister and not args.board and args.full and last:
            steps.add_host(f"new deployment: fprime-util new --deployment, kit new-deployment, kit compare on "
                           f"{template_deployment.BOARD} ({', '.join(template_deployment.compared_models(args.full))}"
                           f"), the fit on {template_deployment.SMALL_BOARD}",
                           functools.partial(template_deployment.run, self.log_dir, args.full))
        return steps


def deployment_log_dir(log_dir: Path, chosen: deployment.Deployment) -> Path:
    """Where a deployment's run keeps its builds, logs and report."""
    return log_dir / f"deployment{chosen.output_suffix()}"


def deployment_plan(args: argparse.Namespace) -> Plan:
    """kit test --deployment DIR: that deployment's whole run through the
    seam on each board (kittools.suite.deployment_run), nothing else."""
    if args.quick or args.subset or args.update_baseline or args.full or args.device_testing:
        raise KitError("--deployment is a deployment's own run: without --quick, --subset, --full, "
                       "--update-baseline or --device-testing (the baselines are the reference deployment's)")
    boards = args.board or [REFERENCE_BOARD]
    for board in boards:
        platforms.check_runs_here(board)
    check_provisioned()
    chosen = deployment.resolve(args.deployment, boards)
    log_dir = deployment_log_dir(Path(args.output).resolve(), chosen)
    steps = Plan()
    for board in boards:
        steps.add_qemu(f"{chosen.name} through the seam, every model on {board}: "
                       f"{', '.join(deployment_run.SCENARIOS)}, ground link, report",
                       functools.partial(deployment_run.run_deployment, chosen, board, log_dir,
                                         serial_plays=ground_checks.SERIAL_PLAYS_CI))
    return steps


def quick_plan(args: argparse.Namespace) -> Plan:
    """kit test --quick: every model (or --model's) on the reference board,
    its nominal run, faults and load sweep, then one ground station per
    model answering a NO_OP; beside them, the host and tooling tests. No
    kernel floor, soak, determinism, fuzzing, serial sweep, porting or
    budget: those are the full run's."""
    if args.board or args.subset or args.update_baseline or args.full:
        raise KitError("--quick is the reference board's short run: without --board, --subset, --full or "
                       "--update-baseline")
    check_provisioned()
    log_dir = Path(args.output).resolve()
    models = tuple(args.model or variants.names())
    steps = Plan()
    host_steps(args, log_dir, steps)
    if not args.skip_twister:
        def stations() -> Tally:
            steps.host_done.wait()  # the stations' time-outs are the host's
            return ground_checks.run_stations(log_dir, QUICK_GROUND_TEST)

        steps.add_qemu(f"twister: {', '.join(models)} on {REFERENCE_BOARD} ({', '.join(QUICK_SCENARIOS)})",
                       functools.partial(twister.run_twister, [REFERENCE_BOARD], log_dir, scenarios=QUICK_SCENARIOS,
                                         models=models, with_floor=False))
        steps.add_qemu("ground link: a NO_OP through fprime-gds on each model", stations)
    return steps


def device_plan(args: argparse.Namespace) -> Plan:
    """kit test --device-testing --hardware-map FILE: the suite on the map's
    boards through twister's device testing, instead of under QEMU."""
    if not (args.device_testing and args.hardware_map):
        raise KitError("device testing needs both --device-testing and --hardware-map FILE (twister's hardware "
                       "map: each board's platform, runner and serial port; docs/porting.md, 'Device testing')")
    if args.board or args.update_baseline:
        raise KitError("--board and --update-baseline are for the QEMU run; with --device-testing the hardware "
                       "map names the boards")
    check_provisioned()
    log_dir = Path(args.output).resolve()
    hardware_map = Path(args.hardware_map)
    models = tuple(args.model or ())
    boards = ", ".join(dict.fromkeys(d.platform for d in device_runs.check_device_run(hardware_map, models)))
    steps = Plan()
    if not args.skip_twister:
        steps.add_qemu(f"device testing: {', '.join(models) or 'every model'} on {boards} ({hardware_map})",
                       functools.partial(device_runs.run_device_testing, hardware_map, log_dir, models))
    host_steps(args, log_dir, steps)
    return steps


def host_steps(args: argparse.Namespace, log_dir: Path, steps: Plan) -> None:
    """The steps that need no board: host unit tests and the tooling's checks."""
    if not args.skip_host:
        steps.add_host("host unit tests (googletest)", functools.partial(host.run_host_tests, log_dir))
    if not args.skip_python:
        steps.add_host("tooling tests (pytest)", functools.partial(host.run_pytest, log_dir))
        steps.add_host("tooling lint and types (ruff, mypy)", functools.partial(host.run_lint, log_dir))
        steps.add_host("C++ style (clang-format, F´ style)", style.run_style_check)
