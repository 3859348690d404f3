# SPDX-License-Identifier: Apache-2.0
"""kit: the kit's command line (also `west kit`).

  kit compare   build every variant, run them under QEMU, write the comparison and its report
  kit report    turn a results file into report.md / .html / .json / .csv (optionally against a baseline)
  kit test      twister suite under QEMU, determinism, budget, ground-link integration, host and tooling tests
  kit gds       boot a board and model under QEMU with fprime-gds on its ground link
  kit serial-sweep  the serial-load sweep of a board and model through its ground link
  kit sizediff  symbols added, removed, grown and shrunk between two builds (or a results file and its baseline)
  kit footprint what each F´ knob costs: one build per knob from a footprint profile, ROM/RAM by layer, nominal run
  kit sizing    a build's fixed tables against its dictionary and run, and what its ports cost
  kit new-board scaffold a new board's folder (checks Zephyr knows it and that the deployment fits)
"""

from __future__ import annotations

import argparse
import concurrent.futures
import functools
import json
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path

from kittools import console, sweep, variants
from kittools.boards.scaffold import REFERENCE_BOARD, new_board
from kittools.link import ground, serial_sweep
from kittools.report import writer
from kittools.sizes import ablation, sizing, symbols
from kittools.suite import budget, results, shards, style, testing
from kittools.workspace import KIT_ROOT, KitError, check_board, check_provisioned, one_at_a_time


def _say(message: str) -> None:
    # One write per line: `kit test` says things from two lanes at once
    sys.stdout.write(f"[kit] {message}\n")
    sys.stdout.flush()


#: What `kit compare` plays: the comparison run and the load sweep
COMPARISON_SCENARIOS = ("nominal", "load")
#: The suite's tag for its footprint profiles' builds (tests/deployment/testcase.yaml),
#: which `kit compare` leaves out: the comparison is the kit profile's
PROFILE_TAG = "profile"


def compare_boards(boards: list[str], out_dir: Path, models: tuple[str, ...] = ()) -> tuple[list[Path], bool]:
    """The comparison's scenarios (each model's nominal run and load sweep,
    played on the suite's builds of tests/deployment) on every board, of
    every variant or `models`, through twister; returns each board's results
    file and whether every run passed."""
    out_dir.mkdir(parents=True, exist_ok=True)
    twister_out = out_dir / "twister"
    tally = testing.run_twister(boards, out_dir, twister_out, scenarios=COMPARISON_SCENARIOS,
                                exclude_tags=(PROFILE_TAG,), models=models)
    testing.make_size_reports(twister_out)  # every board's at once, two builds at a time
    files = []
    for board in boards:
        data = results.from_twister(twister_out, board)
        results_file = out_dir / check_board(board) / "comparison.json"
        results_file.parent.mkdir(parents=True, exist_ok=True)
        results_file.write_text(json.dumps(data.to_json(), indent=2) + "\n")
        files.append(results_file)
    return files, tally.failed == 0


def is_real_board(board: str) -> bool:
    """A board the kit builds and does not run (tests/boards), however the
    board target is spelled (nucleo_f401re, nucleo_f401re/stm32f401xe)."""
    return check_board(board) in {check_board(real) for real in testing.suite_boards(testing.BUILD_ONLY_SUITE)}


def check_runs_here(board: str) -> None:
    """Refuse a real board where the command must run the deployment under
    QEMU: the kit builds it (tests/boards) and runs the suite on it only
    through device testing (kit test --device-testing)."""
    if is_real_board(board):
        raise KitError(f"{board} is a real board: the kit builds it (kit test, tests/boards) but cannot run it "
                       f"here (no emulator; on the board itself: kit test --device-testing --hardware-map FILE). "
                       f"Boards it runs on: {', '.join(testing.suite_boards())}")


def cmd_compare(args: argparse.Namespace) -> int:
    boards = args.board or testing.suite_boards()
    for board in boards:
        check_runs_here(board)
    check_provisioned()
    out_dir = Path(args.output).resolve()
    with one_at_a_time("compare"):
        files, passed = compare_boards(boards, out_dir, tuple(args.model or ()))
        outcome = writer.write_from_files(files, out_dir, None, budget.Budget(), _say)
    print()
    print((out_dir / "report.md").read_text())
    _say(f"results: {', '.join(str(f) for f in files)}")
    _say(f"report: {', '.join(str(f) for f in outcome.files[:4])}")
    return 0 if passed else 1


def _budget(args: argparse.Namespace) -> budget.Budget:
    return budget.Budget(rom_pct=args.rom_budget, ram_pct=args.ram_budget, p99_pct=args.p99_budget)


def cmd_report(args: argparse.Namespace) -> int:
    if args.merge:
        return _merge(args)
    if not args.results:
        raise KitError("kit report needs results files, or --merge DIR... (the output folders of kit test --subset)")
    sources = [Path(r).resolve() for r in args.results]
    out_dir = Path(args.output).resolve() if args.output else sources[0].parent
    baseline = Path(args.baseline).resolve() if args.baseline else None
    outcome = writer.write_from_files(sources, out_dir, baseline, _budget(args), _say)
    for path in outcome.files[:4]:
        _say(f"written: {path}")
    if baseline is not None:
        if outcome.violations:
            for violation in outcome.violations:
                _say(f"budget: {violation}")
            _say(f"budget check against {baseline}: FAIL")
            return 1
        _say(f"budget check against {baseline}: PASS")
    return 0


#: kit test --quick: the scenarios every model plays on the reference board
QUICK_SCENARIOS = ("nominal", "faults", "load")
#: ... and the integration suite's test each ground station runs (pytest -k)
QUICK_GROUND_TEST = "test_noop_completes_with_its_events"


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


def _merge(args: argparse.Namespace) -> int:
    """kit report --merge DIR...: the shards of one split run (kit test
    --subset K/N, each K once) joined per board into its results file and
    report, judged against its baseline as a single run is."""
    if args.results or args.baseline:
        raise KitError("--merge takes the shards' output folders only: each board is judged against its "
                       "baseline in tests/baselines")
    joined = shards.merge([Path(d).resolve() for d in args.merge])
    out_dir = Path(args.output).resolve() if args.output else KIT_ROOT / "build" / "merged"
    total = testing.Tally()
    for board, shard in sorted(joined.items()):
        data = shard.results()
        if shard.built_only is not None:
            total.add(testing.write_built_only(data, board, out_dir))
        else:
            total.add(testing.judge(data, board, out_dir, _budget(args)))
    print(f"total: {total.passed} passed, {total.failed} failed")
    return 0 if total.failed == 0 and total.passed > 0 else 1


def cmd_test(args: argparse.Namespace) -> int:
    if args.device_testing or args.hardware_map:
        return _device_test(args)
    if args.quick:
        return _quick_test(args)
    subset = subset_of(args.subset)
    if subset and args.update_baseline:
        raise KitError("--update-baseline needs the whole run on one machine: a shard holds part of each board")
    # The real boards are built and not run (tests/boards): no budget, no
    # ground link, nothing to play
    boards = [b for b in args.board if not is_real_board(b)] if args.board else testing.suite_boards()
    built_only = ([b for b in args.board if is_real_board(b)] if args.board
                  else testing.suite_boards(testing.BUILD_ONLY_SUITE))
    check_provisioned()
    log_dir = Path(args.output).resolve()
    shards.start(log_dir, args.subset)
    # Two lanes. The QEMU lane: twister, then what reads its builds. The host
    # lane needs none of them; it runs beside twister (whose start and last
    # runs leave a core idle), and the ground link's checks wait for it to
    # end: their time-outs are the host's, and they keep it to themselves.
    qemu_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    host_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    host_lane_done = threading.Event()
    # Every board's size reports at once, in the background (lowest CPU
    # priority) from the determinism runs on, through the ground link's
    # checks; done before the first budget, which reads them
    size_reports: concurrent.futures.Future[None] = concurrent.futures.Future()
    if not args.skip_twister:
        def budget(board: str) -> testing.Tally:
            size_reports.result()
            return testing.check_budget(board, log_dir, _budget(args), args.update_baseline)

        def shard(board: str, built: bool) -> testing.Tally:
            size_reports.result()
            return testing.write_shard(board, log_dir, built)

        def determinism() -> testing.Tally:
            threading.Thread(target=_settle, args=(size_reports, functools.partial(
                testing.make_size_reports, background=True)), daemon=True).start()
            return testing.check_determinism(log_dir, required=not subset)

        built = f"; built only: {', '.join(built_only)}" if built_only else ""
        share = f", twister's share {args.subset}" if subset else ""
        qemu_lane.append((f"twister suite under QEMU ({', '.join(boards)}{built}{share})",
                          lambda: testing.run_twister(boards + built_only, log_dir, subset=args.subset)))
        # Before the budget: the board's report takes the serial-load sweep from it
        def ground() -> testing.Tally:
            host_lane_done.wait()
            return testing.run_integration(log_dir, required=not subset)

        if boards:  # what reads the runs: none on a board only built
            qemu_lane.append(("determinism: twister's binaries run again (size reports in the background)",
                              determinism))
            qemu_lane.append(("ground link: integration suite through fprime-gds, fuzzing, serial-load sweep",
                              ground))
        for board in boards:
            if subset:  # judged once the shards are joined (kit report --merge)
                qemu_lane.append((f"shard: {board}, this share's part", functools.partial(shard, board, False)))
            else:
                qemu_lane.append((f"budget: {board} results against its baseline",
                                  functools.partial(budget, board)))

        def built_report(board: str) -> testing.Tally:
            if boards:  # their size reports are made beside the determinism runs
                size_reports.result()
            return testing.report_built_only(board, log_dir)

        for board in built_only:
            if subset:
                qemu_lane.append((f"shard: {board}, built only, this share's part",
                                  functools.partial(shard, board, True)))
            else:
                qemu_lane.append((f"report: {board}, built only", functools.partial(built_report, board)))
    # A split run shares out the steps beside twister: the porting check (the
    # longest) to the first shard, the host's and the device path to the
    # last (measured on two shares of today's suite: the porting check took
    # 547 s, host and device 300 s; twister's sorted share put
    # qemu_cortex_m3, whose serial sweeps lengthen the ground link, last)
    first, last = (subset[0] == 1, subset[0] == subset[1]) if subset else (True, True)
    if last:
        _host_steps(args, log_dir, host_lane)
    # The device path (twister's device testing, QEMU standing in for a
    # flashed board): its own build and QEMU runs, in the lane beside twister
    if not args.skip_twister and testing.STAND_IN_BOARD in boards and last:
        host_lane.append((f"device testing: twister's device harness, QEMU standing in for a flashed "
                          f"{testing.STAND_IN_BOARD} ({testing.STAND_IN_MODEL})",
                          lambda: testing.run_qemu_device(log_dir)))
    # The porting path: its own twister and west builds, in the lane beside
    # the suite's twister (which leaves a core idle at its start and between
    # its builds' runs), done before the ground link's checks start (their
    # time-outs are the host's). A run for chosen boards (--board) is about
    # those: it leaves it out.
    if not args.skip_twister and not args.skip_porting and not args.board and first:
        host_lane.append((f"porting: a new QEMU board and a console-only real board scaffolded into a scratch "
                          f"copy ({', '.join(testing.PORTING_MODELS)})", lambda: testing.run_porting_check(log_dir)))
    return _run_lanes(qemu_lane, host_lane, host_lane_done)


def _quick_test(args: argparse.Namespace) -> int:
    """kit test --quick: every model (or --model's) on the reference board,
    its nominal run, faults and load sweep, then one ground station per
    model answering a NO_OP; beside them, the host and tooling tests. No
    kernel floor, soak, determinism, fuzzing, serial sweep, porting or
    budget: those are the full run's."""
    if args.board or args.subset or args.update_baseline:
        raise KitError("--quick is the reference board's short run: without --board, --subset or "
                       "--update-baseline (those are the full run's)")
    check_provisioned()
    log_dir = Path(args.output).resolve()
    models = tuple(args.model or variants.names())
    host_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    host_lane_done = threading.Event()
    _host_steps(args, log_dir, host_lane)
    qemu_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    if not args.skip_twister:
        def stations() -> testing.Tally:
            host_lane_done.wait()  # the stations' time-outs are the host's
            return testing.run_stations(log_dir, QUICK_GROUND_TEST)

        qemu_lane.append((f"twister: {', '.join(models)} on {REFERENCE_BOARD} ({', '.join(QUICK_SCENARIOS)})",
                          lambda: testing.run_twister([REFERENCE_BOARD], log_dir, scenarios=QUICK_SCENARIOS,
                                                      models=models, with_floor=False)))
        qemu_lane.append(("ground link: a NO_OP through fprime-gds on each model", stations))
    return _run_lanes(qemu_lane, host_lane, host_lane_done)


def _host_steps(args: argparse.Namespace, log_dir: Path, lane: list[tuple[str, Callable[[], testing.Tally]]]) -> None:
    """The steps that need no board: host unit tests and the tooling's checks."""
    if not args.skip_host:
        lane.append(("host unit tests (googletest)", lambda: testing.run_host_tests(log_dir)))
    if not args.skip_python:
        lane.append(("tooling tests (pytest)", lambda: testing.run_pytest(log_dir)))
        lane.append(("tooling lint and types (ruff, mypy)", lambda: testing.run_lint(log_dir)))
        lane.append(("C++ style (clang-format, F´ style)", style.run_style_check))


def _run_lanes(qemu_lane: list[tuple[str, Callable[[], testing.Tally]]],
               host_lane: list[tuple[str, Callable[[], testing.Tally]]],
               host_lane_done: threading.Event | None = None) -> int:
    """Both lanes at once, the closing count, the exit status."""
    done = host_lane_done or threading.Event()
    started = time.monotonic()
    with one_at_a_time("test"), concurrent.futures.ThreadPoolExecutor(max_workers=1) as beside:
        host = beside.submit(_run_steps, host_lane)
        host.add_done_callback(lambda _: done.set())
        total = _run_steps(qemu_lane)
        total.add(host.result())
    _say(f"all steps: {time.monotonic() - started:.0f} s")
    print(f"total: {total.passed} passed, {total.failed} failed")
    return 0 if total.failed == 0 and total.passed > 0 else 1


def _device_test(args: argparse.Namespace) -> int:
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
    boards = ", ".join(dict.fromkeys(d.platform for d in testing.check_device_run(hardware_map, models)))
    qemu_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    if not args.skip_twister:
        qemu_lane.append((f"device testing: {', '.join(models) or 'every model'} on {boards} ({hardware_map})",
                          lambda: testing.run_device_testing(hardware_map, log_dir, models)))
    host_lane: list[tuple[str, Callable[[], testing.Tally]]] = []
    _host_steps(args, log_dir, host_lane)
    return _run_lanes(qemu_lane, host_lane)


def _settle(future: concurrent.futures.Future[None], job: Callable[[], None]) -> None:
    """Run a job in this thread and settle its future with its outcome."""
    try:
        job()
    except BaseException as error:  # handed to whoever waits on the future
        future.set_exception(error)
    else:
        future.set_result(None)


def _run_steps(steps: list[tuple[str, Callable[[], testing.Tally]]]) -> testing.Tally:
    """Run steps in order, a line as each starts and ends; their added count."""
    total = testing.Tally()
    for name, step in steps:
        _say(f"{name} ...")
        step_started = time.monotonic()
        tally = step()
        _say(f"{name}: {tally.passed} passed, {tally.failed} failed ({time.monotonic() - step_started:.0f} s)")
        total.add(tally)
    return total


def _ground_build(args: argparse.Namespace) -> tuple[Path, Path]:
    """The ground scenario's build of --board and --model, built or brought
    up to date; returns it and its logs folder."""
    check_runs_here(args.board)
    variants.get(args.model)  # argparse checks the name only when it comes from the command line
    check_provisioned()
    build_dir = ground.ground_build_dir(args.board, args.model)
    logs = build_dir.with_name(build_dir.name + "-logs")
    _say(f"building {args.board} {args.model} (ground scenario) ...")
    ground.build_ground(args.board, args.model, logs / "build.log")
    return build_dir, logs


def cmd_gds(args: argparse.Namespace) -> int:
    build_dir, logs = _ground_build(args)
    with ground.GroundStation(build_dir, logs, gui=True, gui_port=args.port, dictionary=args.dictionary) as station:
        _say(f"QEMU runs {build_dir}; its link: {station.link.socket}")
        _say(f"fprime-gds: http://127.0.0.1:{args.port} (dictionary {station.link.dictionary})")
        _say(f"from a shell: fprime-cli command-send Kit.cmdDisp.CMD_NO_OP {' '.join(station.client_arguments())}")
        _say("Ctrl-C stops both")
        try:
            while station.qemu is not None and station.qemu.running():
                time.sleep(0.5)
        except KeyboardInterrupt:
            _say("stopping")
            return 0
        raise KitError(f"QEMU stopped on its own; its console:\n{station.console()[-3000:]}")


def cmd_serial_sweep(args: argparse.Namespace) -> int:
    build_dir, logs = _ground_build(args)
    _say(f"serial-load sweep on {build_dir}'s link ...")
    outcome = serial_sweep.run(build_dir)
    out = logs / results.SERIAL_SWEEP_FILE
    out.write_text(json.dumps(outcome.to_json(), indent=2) + "\n")
    found = outcome.sweep()
    levels: dict[tuple[str, int], list[serial_sweep.PointTraffic]] = {}
    for traffic in outcome.traffic:
        levels.setdefault((traffic.axis, traffic.level), []).append(traffic)
    for (axis, level), plays in levels.items():
        if found is None:
            break
        at = {p.rate_group: p for p in found.points if p.axis == axis and p.level == level}
        spread = {rg: "-".join(map(str, found.spread.get((axis, level, rg), ()))) for rg in at}
        latency = ", ".join(f"{rg} p99/max {p.latency_p99}/{p.latency_max}"
                            f"{f' (max {spread[rg]})' if spread[rg] else ''} cycles{' MISSED' if p.missed else ''}"
                            for rg, p in at.items())
        print(f"{axis} {sweep.level_text(level, found.unit(axis))}: {latency} (median of {len(plays)} plays); "
              f"delivered {'/'.join(str(t.delivered()) for t in plays)} of {plays[0].offered()}, ring drops "
              f"{'/'.join(str(t.ring_drops) for t in plays)} B")
    _say(f"records: {out}")
    return 0


def _symbol_tables(source: Path, variant: str | None) -> dict[str, dict[str, int]]:
    """A build folder's full symbol tables, or a variant's (floored) from a results file or baseline."""
    if source.is_dir():
        return symbols.of_build(source)
    data = results.load(source)
    names = [variant] if variant else data.names()
    if len(names) != 1 or names[0] not in data.variants:
        raise KitError(f"{source} holds the variants {', '.join(data.names())}: name one with --model")
    tables = data.variants[names[0]].symbols
    if not tables:
        raise KitError(f"{source}: variant {names[0]} has no symbol tables (written by a kit before they existed)")
    return tables


def cmd_sizediff(args: argparse.Namespace) -> int:
    before, now = Path(args.before).resolve(), Path(args.now).resolve()
    if before.is_dir() != now.is_dir():
        # A results file keeps only symbols of SYMBOL_FLOOR bytes or more: floor the build's alike
        build = before if before.is_dir() else now
        floored = symbols.of_build(build, symbols.SYMBOL_FLOOR)
        tables = (floored, _symbol_tables(now, args.model)) if before.is_dir() \
            else (_symbol_tables(before, args.model), floored)
    else:
        tables = (_symbol_tables(before, args.model), _symbol_tables(now, args.model))
    for kind in args.kind or symbols.KINDS:
        for line in symbols.render(symbols.diff(tables[0].get(kind, {}), tables[1].get(kind, {}), kind),
                                   None if args.all else args.limit):
            print(line)
        print()
    return 0


def cmd_footprint(args: argparse.Namespace) -> int:
    check_runs_here(args.board)
    profile, toward = ablation.check_profile(args.profile), ablation.check_profile(args.toward)
    models = args.model or list(variants.names())
    for model in models:
        variants.get(model)  # as in _ground_build
    if not args.report_only:
        check_provisioned()
        for model in models:
            ablation.run(args.board, model, profile, toward, ablation.out_dir_of(args.board, model, profile), _say)
    tables = []
    for model in models:
        conditions, rows = ablation.load(ablation.out_dir_of(args.board, model, profile) / "footprint.json")
        tables.append(ablation.table(rows, conditions["board"], model, conditions["profile"], conditions["toward"]))
    files = ablation.write_report(tables, ablation.report_dir_of(args.board, profile))
    print(files[0].read_text())
    _say(f"footprint report: {', '.join(str(f) for f in files)}")
    return 0


def cmd_sizing(args: argparse.Namespace) -> int:
    build = Path(args.build).resolve()
    queues: list[dict[str, str]] = []
    if args.log:
        log = Path(args.log)
        if not log.is_file():
            raise KitError(f"no console log at {log}")
        # Any run that printed its queues will do, finished or halted
        records = (console.parse_line(line) for line in log.read_text(errors="replace").splitlines())
        queues = [r.fields for r in records if r is not None and r.kind == "QUEUE"]
        if not queues:
            raise KitError(f"{log} has no KIT QUEUE lines (a nominal, load, faults or soak run prints them)")
    found = sizing.measure(build, queues)
    for line in sizing.render(found):
        print(line)
    faults = sizing.too_small(found.advice)
    for fault in faults:
        print(f"kit: TOO SMALL: {fault}", file=sys.stderr)
    return 1 if faults else 0


def cmd_new_board(args: argparse.Namespace) -> int:
    # Only Zephyr's board tree is needed (new_board says so if it is missing):
    # no F´ checkout, so a port can be scaffolded before the rest is fetched
    new_board(args.board, args.reference, args.force, _say)
    return 0


def parser() -> argparse.ArgumentParser:
    top = argparse.ArgumentParser(prog="kit", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = top.add_subparsers(dest="command", required=True)
    p = sub.add_parser("compare", help="build and run every variant, print the comparison")
    p.add_argument("--board", action="append",
                   help="board to compare on (repeatable; default: every platform of the suite)")
    p.add_argument("--output", default=str(KIT_ROOT / "build" / "compare"), help="build folders, logs, results")
    variants.add_model_option(p, "the variants to compare (repeatable; default: every one)", repeatable=True)
    p.set_defaults(func=cmd_compare)
    r = sub.add_parser("report", help="report of results files (build/compare/<board>/comparison.json)")
    r.add_argument("results", nargs="*", help="results files (JSON, docs/results.md), one per board")
    r.add_argument("--merge", nargs="+", metavar="DIR",
                   help="join the shards of a split run (the --output folders of kit test --subset K/N, every K "
                        "once) into each board's results file and report, judged against its baseline "
                        "(default output: build/merged)")
    r.add_argument("--baseline", help="results file to diff the first against; with it, a budget check sets the "
                                      "exit code")
    r.add_argument("--output", help="folder for report.* (default: the results file's folder)")
    r.set_defaults(func=cmd_report)
    t = sub.add_parser("test", help="twister suite, host unit tests and tooling tests")
    t.add_argument("--board", action="append",
                   help="board to run the suite on (repeatable; default: every platform of the suite, "
                        "tests/deployment/testcase.yaml)")
    t.add_argument("--output", default=str(KIT_ROOT / "build" / "test-logs"), help="logs and reports")
    t.add_argument("--quick", action="store_true",
                   help=f"the short run: every model (or --model's) on {REFERENCE_BOARD}, nominal, faults and "
                        "load, a NO_OP through fprime-gds per model, host and tooling tests; no budget")
    t.add_argument("--subset", metavar="K/N",
                   help="this machine's share K of a full run split across N (twister's --subset); join the "
                        "shards' --output folders with kit report --merge")
    t.add_argument("--skip-twister", action="store_true")
    t.add_argument("--skip-host", action="store_true")
    t.add_argument("--skip-python", action="store_true")
    t.add_argument("--skip-porting", action="store_true",
                   help="leave out the porting step (kit new-board on a new QEMU board, then kit compare on it, and "
                        "on a real board, then its builds, in a scratch copy; left out with --board)")
    t.add_argument("--update-baseline", action="store_true",
                   help="make this run's results tests/baselines/<board>.json (review and commit the change)")
    t.add_argument("--device-testing", action="store_true",
                   help="run the suite on attached boards through twister's device testing instead of under QEMU "
                        "(with --hardware-map)")
    t.add_argument("--hardware-map", help="twister's hardware map of the attached boards (west twister "
                                          "--generate-hardware-map makes one)")
    variants.add_model_option(t, "with --device-testing, the one to play (repeatable; default: every one)",
                              repeatable=True)
    t.set_defaults(func=cmd_test)
    g = sub.add_parser("gds", help="boot a board and model under QEMU with fprime-gds on its ground link")
    g.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(g, "default: rtos", default="rtos")
    g.add_argument("--port", type=int, default=5000, help="the GDS web page's port (default: 5000)")
    g.add_argument("--dictionary", type=Path, default=None,
                   help="the F´ dictionary to give fprime-gds (default: the build's own; refused unless it is "
                        "the one the firmware was built with)")
    g.set_defaults(func=cmd_gds)
    w = sub.add_parser("serial-sweep", help="the serial-load sweep (uplink commands, downlink packets) of a board "
                                            "and model, through its ground link under QEMU")
    w.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(w, "default: rtos", default="rtos")
    w.set_defaults(func=cmd_serial_sweep)
    d = sub.add_parser("sizediff", help="symbols added, removed, grown and shrunk between two builds (as "
                                        "bloat-o-meter): build folders, or results files / baselines")
    d.add_argument("before", help="build folder, results file or baseline (tests/baselines/<board>.json)")
    d.add_argument("now", help="build folder, results file or baseline")
    variants.add_model_option(d, "the one to take from a results file that holds several")
    # The option's name before every command took --model; kept for scripts that use it
    d.add_argument("--variant", dest="model", choices=variants.names(), help=argparse.SUPPRESS)
    d.add_argument("--kind", action="append", choices=symbols.KINDS, help="rom or ram (default: both)")
    d.add_argument("--limit", type=int, default=40, help="symbols shown per kind, largest change first (default 40)")
    d.add_argument("--all", action="store_true", help="every changed symbol")
    d.set_defaults(func=cmd_sizediff)
    f = sub.add_parser("footprint", help="what each F´ knob costs: from a footprint profile, one build per knob "
                                         "(ROM, RAM by layer, the nominal run)")
    f.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(f, "repeatable; default: every one", repeatable=True)
    f.add_argument("--profile", default="fprime-kit", help="the profile to start from (modules/fprime/snippets; "
                                                           "default: fprime-kit)")
    f.add_argument("--toward", default="fprime-default", help="the profile whose values the knobs move to "
                                                              "(default: fprime-default)")
    f.add_argument("--report-only", action="store_true",
                   help="write the report from the models' last ablations (build/footprint/), building nothing")
    f.set_defaults(func=cmd_footprint)
    z = sub.add_parser("sizing", help="a build's fixed tables (command dispatch, telemetry, TaskRunner, thread "
                                      "pool, queues) against what its dictionary and run need, and its ports")
    z.add_argument("build", help="a kit build folder (west build -d ...)")
    z.add_argument("--log", help="the console log of a run of that build, for its queues' high-water marks")
    z.set_defaults(func=cmd_sizing)
    n = sub.add_parser("new-board", help="scaffold boards/<board>/ for a new board and add it to the suite")
    n.add_argument("board", metavar="BOARD", help="board target as west build -b takes it (e.g. mps2/an385)")
    n.add_argument("--from", "--reference", dest="reference", metavar="REFERENCE", default=REFERENCE_BOARD,
                   help=f"ported board to copy the folder and the measured footprint of (default: {REFERENCE_BOARD})")
    n.add_argument("--force", action="store_true", help="write the board's folder again if it exists")
    n.set_defaults(func=cmd_new_board)
    for command in (r, t):
        command.add_argument("--rom-budget", type=float, default=budget.Budget.rom_pct, help="allowed ROM growth, %%")
        command.add_argument("--ram-budget", type=float, default=budget.Budget.ram_pct, help="allowed RAM growth, %%")
        command.add_argument("--p99-budget", type=float, default=budget.Budget.p99_pct,
                             help="allowed p99 growth, %% (changes under 2 us never count)")
    return top


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        return int(args.func(args))
    except KitError as error:
        print(f"kit: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        # Whatever the command started (QEMU, fprime-gds) was stopped on the way out
        print("kit: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
