# SPDX-License-Identifier: Apache-2.0
"""A board's results against its baseline: the budget verdict (computed once,
then handed to the report), the results file, a shard of a split run."""

from __future__ import annotations

import json
from pathlib import Path

from kittools.log import LOG, say
from kittools.model import Results
from kittools.sizes import by_layer, sizing, symbols
from kittools.suite import budget, platforms, results, shards
from kittools.suite.counts import Tally
from kittools.suite.platforms import TWISTER_OUT
from kittools.workspace import KIT_ROOT, KitError, check_board


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
                         + results.suite_builds(twister_out, prefix=results.BUILD_ONLY_PREFIX)
                         + [(p, b) for p, b in results.suite_builds(twister_out, prefix=results.PROFILE_PREFIX)
                            if platforms.is_small_part(p)]],
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
        say(f"  baseline written: {baseline_path}")
    if not baseline_path.is_file():
        raise KitError(f"no baseline for {board} ({baseline_path}): run `scripts/kit test --board {board} "
                       "--update-baseline` once and commit the file")
    baseline = results.load(baseline_path)
    verdict = budget.check(data, baseline, limits)
    for violation in verdict.violations:
        LOG.error(f"  budget: {violation}")
    undersized = [f"{name}: {fault}" for name in data.names()
                  for fault in sizing.too_small([sizing.Advice.from_json(t)
                                                 for t in data.variants[name].sizing.get("tables", [])])]
    for fault in undersized:
        LOG.error(f"  sizing: {fault}")
    for variant, sizes in verdict.sizes:
        if variant in verdict.over_size:  # a failed size budget says which symbols grew
            for line in symbols.render(sizes, limit=15):
                LOG.error(f"  {variant}: {line}")
    tally = Tally(passed=1) if verdict.passed else Tally(failed=1)
    tally.add(Tally(failed=1) if undersized else Tally(passed=1))
    # The report is for the reader; the verdict above does not depend on it
    from kittools.report import writer

    writer.write(data, out_dir / "report", baseline, limits, verdict=verdict)
    say(f"  {board}: report against {baseline_path.name}: {out_dir / 'report' / 'report.html'}")
    return tally


def report_built_only(board: str, log_dir: Path) -> Tally:
    """A real board's results (its builds only: ROM and RAM, by layer) and
    their report, in <log_dir>/<board folder>/ like a QEMU board's; no
    baseline, no budget (nothing ran). One count: the results were made."""
    return write_built_only(results.built_only(TWISTER_OUT, board), board, log_dir)


def report_small_part(board: str, log_dir: Path, update_baseline: bool = False) -> Tally:
    """A small part's results (the sizes of its fprime-small builds, which
    twister and the ground link judged) and their report, as a real board's;
    with `update_baseline` also its baseline, which `kit new-board` reads to
    estimate what a small board can hold (kittools.boards.memory)."""
    data = results.built_only(TWISTER_OUT, board, results.PROFILE_PREFIX)
    tally = write_built_only(data, board, log_dir)
    if update_baseline:
        path = BASELINES / f"{check_board(board)}.json"
        write_baseline(data, path)
        say(f"  {board}: baseline written: {path.relative_to(KIT_ROOT)} (review and commit it)")
    return tally


def write_built_only(data: Results, board: str, log_dir: Path) -> Tally:
    """A real board's results file and report (see report_built_only)."""
    out_dir = log_dir / check_board(board)
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "results.json").write_text(json.dumps(data.to_json(), indent=2) + "\n")
    from kittools.report import writer  # for the reader; kept out of the budget gate's imports

    writer.write(data, out_dir / "report")
    say(f"  {board}: {data.conditions.get('run', '').split(':')[0]}, ROM and RAM by layer: "
        f"{out_dir / 'report' / 'report.html'}")
    return Tally(passed=1)


def write_shard(board: str, log_dir: Path, built_only: bool = False, prefix: str = results.BUILD_ONLY_PREFIX) -> Tally:
    """What this shard of a split run (kit test --subset) made of `board`:
    <log_dir>/<board folder>/shard.json for kit report --merge, which judges
    the board once every shard's parts are joined. One count where the
    shard made anything of the board; none where twister gave it nothing."""
    if built_only:
        if not results.suite_builds(TWISTER_OUT, board, prefix):
            return Tally()
        shard = shards.BoardShard(board, built_only=results.built_only(TWISTER_OUT, board, prefix))
    else:
        found, floors = results.collect(TWISTER_OUT, board, log_dir)
        if not found and not floors.paths and not floors.zephyr:
            return Tally()
        shard = shards.BoardShard(board, found, floors)
    path = shards.write(shard, log_dir)
    made = [p.variant for p in shard.played] + list(shard.built_only.variants if shard.built_only else ())
    say(f"  {board}: this shard's part ({', '.join(made) or 'kernel floor only'}): {path}")
    return Tally(passed=1)


def write_baseline(data: Results, path: Path) -> None:
    """A board's baseline: the conditions and every variant's metrics (with
    its build, modules and footprint) and its sweeps' records (the breaking
    points the budget holds), not the rest of the console records."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data.to_json(with_records=False), indent=2) + "\n")


def report_side_by_side(boards: list[str], log_dir: Path) -> Tally:
    """Every board's results of this run in one report (<log_dir>/boards/):
    the boards side by side and what fits where (each build against each
    board's memory). One count where two or more boards have results."""
    files = [log_dir / check_board(board) / "results.json" for board in boards]
    files = [f for f in files if f.is_file()]
    if len(files) < 2:
        return Tally()
    from kittools.report import writer

    writer.write_from_files(files, log_dir / "boards", None, budget.Budget(), lambda _m: None)
    say(f"  every board side by side, what fits where: {log_dir / 'boards' / 'report.html'}")
    return Tally(passed=1)
