# SPDX-License-Identifier: Apache-2.0
"""kit compare: every variant built and run under QEMU through twister, each board's results file, the report."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from kittools import deployment
from kittools.deployment import Deployment
from kittools.log import say
from kittools.report import writer
from kittools.suite import budget, platforms, results, twister, verdict
from kittools.workspace import KIT_ROOT, check_board, check_provisioned, one_at_a_time

#: What `kit compare` plays: the comparison run and the load sweep
COMPARISON_SCENARIOS = ("nominal", "load")

#: Where `kit compare` keeps its builds, logs and results (a deployment's: with its name)
DEFAULT_OUTPUT = str(KIT_ROOT / "build" / "compare")

#: The suite's footprint profiles' builds are left out: the comparison is the kit profile's
PROFILE_TAG = twister.PROFILE_TAG


def compare_boards(boards: list[str], out_dir: Path, models: tuple[str, ...] = (),
                   deployment: Deployment | None = None) -> tuple[list[Path], bool]:
    """The comparison's scenarios (each model's nominal run and load sweep,
    played on the suite's builds of tests/deployment) on every board, of
    every variant or `models`, of the reference deployment or `deployment`,
    through twister; returns each board's results file and whether every
    run passed."""
    out_dir.mkdir(parents=True, exist_ok=True)
    twister_out = out_dir / "twister"
    cmake_args = tuple(deployment.cmake_args()) if deployment else ()
    tally = twister.run_twister(boards, out_dir, twister_out, scenarios=COMPARISON_SCENARIOS,
                                exclude_tags=(PROFILE_TAG,), models=models, cmake_args=cmake_args)
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
    chosen = deployment.resolve(args.deployment, boards)
    # A deployment's builds are its own: never the reference's folders
    out_dir = Path(args.output or DEFAULT_OUTPUT + chosen.output_suffix()).resolve()
    say(f"deployment: {chosen.name}")
    with one_at_a_time("compare"):
        files, passed = compare_boards(boards, out_dir, tuple(args.model or ()), chosen)
        outcome = writer.write_from_files(files, out_dir, None, budget.Budget(), say)
    print()
    print((out_dir / "report.md").read_text())
    say(f"results: {', '.join(str(f) for f in files)}")
    say(f"report: {', '.join(str(f) for f in outcome.files[:4])}")
    return 0 if passed else 1
