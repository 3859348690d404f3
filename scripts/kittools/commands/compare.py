# SPDX-License-Identifier: Apache-2.0
"""kit compare: every variant built and run under QEMU through twister, each board's results file, the report."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from kittools.log import say
from kittools.report import writer
from kittools.suite import budget, platforms, results, twister, verdict
from kittools.workspace import check_board, check_provisioned, one_at_a_time

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
    tally = twister.run_twister(boards, out_dir, twister_out, scenarios=COMPARISON_SCENARIOS,
                                exclude_tags=(PROFILE_TAG,), models=models)
    verdict.make_size_reports(twister_out)  # every board's at once, two builds at a time
    files = []
    for board in boards:
        data = results.from_twister(twister_out, board)
        results_file = out_dir / check_board(board) / "comparison.json"
        results_file.parent.mkdir(parents=True, exist_ok=True)
        results_file.write_text(json.dumps(data.to_json(), indent=2) + "\n")
        files.append(results_file)
    return files, tally.failed == 0


def run(args: argparse.Namespace) -> int:
    boards = args.board or platforms.suite_boards()
    for board in boards:
        platforms.check_runs_here(board)
    check_provisioned()
    out_dir = Path(args.output).resolve()
    with one_at_a_time("compare"):
        files, passed = compare_boards(boards, out_dir, tuple(args.model or ()))
        outcome = writer.write_from_files(files, out_dir, None, budget.Budget(), say)
    print()
    print((out_dir / "report.md").read_text())
    say(f"results: {', '.join(str(f) for f in files)}")
    say(f"report: {', '.join(str(f) for f in outcome.files[:4])}")
    return 0 if passed else 1
