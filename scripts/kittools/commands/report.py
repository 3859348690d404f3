# SPDX-License-Identifier: Apache-2.0
"""kit report: results files into report.md / .html / .json / .csv, judged against a baseline;
or the shards of a split run joined (--merge)."""

from __future__ import annotations

import argparse
from pathlib import Path

from kittools.log import say
from kittools.report import writer
from kittools.suite import budget, counts, shards, verdict
from kittools.workspace import KIT_ROOT, KitError


def run(args: argparse.Namespace) -> int:
    if args.merge:
        return merge(args)
    if not args.results:
        raise KitError("kit report needs results files, or --merge DIR... (the output folders of kit test --subset)")
    sources = [Path(r).resolve() for r in args.results]
    out_dir = Path(args.output).resolve() if args.output else sources[0].parent
    baseline = Path(args.baseline).resolve() if args.baseline else None
    outcome = writer.write_from_files(sources, out_dir, baseline, budget.of_options(args), say)
    for path in outcome.files[:4]:
        say(f"written: {path}")
    if baseline is not None:
        if outcome.violations:
            for violation in outcome.violations:
                say(f"budget: {violation}")
            say(f"budget check against {baseline}: FAIL")
            return 1
        say(f"budget check against {baseline}: PASS")
    return 0


def merge(args: argparse.Namespace) -> int:
    """kit report --merge DIR...: the shards of one split run (kit test
    --subset K/N, each K once) joined per board into its results file and
    report, judged against its baseline as a single run is; then every
    board side by side (<output>/boards/), as a single run writes it."""
    if args.results or args.baseline:
        raise KitError("--merge takes the shards' output folders only: each board is judged against its "
                       "baseline in tests/baselines")
    joined = shards.merge([Path(d).resolve() for d in args.merge])
    out_dir = Path(args.output).resolve() if args.output else KIT_ROOT / "build" / "merged"
    total = counts.Tally()
    for board, shard in sorted(joined.items()):
        data = shard.results()
        if shard.built_only is not None:
            total.add(verdict.write_built_only(data, board, out_dir))
        else:
            total.add(verdict.judge(data, board, out_dir, budget.of_options(args)))
    # ... and every board side by side, as a single run ends
    total.add(verdict.report_side_by_side(sorted(joined), out_dir))
    print(f"total: {total.passed} passed, {total.failed} failed")
    return 0 if total.failed == 0 and total.passed > 0 else 1
