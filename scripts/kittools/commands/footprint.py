# SPDX-License-Identifier: Apache-2.0
"""kit footprint: what each F´ knob costs (kittools.sizes.ablation)."""

from __future__ import annotations

import argparse

from kittools import deployment, variants
from kittools.log import say
from kittools.sizes import ablation
from kittools.suite import platforms
from kittools.workspace import check_provisioned


def run(args: argparse.Namespace) -> int:
    platforms.check_runs_here(args.board)
    profile, toward = ablation.check_profile(args.profile), ablation.check_profile(args.toward)
    models = args.model or list(variants.names())
    for model in models:
        variants.get(model)  # as in ground_build
    chosen = deployment.resolve(args.deployment, [args.board])
    suffix = chosen.output_suffix()
    if not args.report_only:
        check_provisioned()
        for model in models:
            ablation.run(args.board, model, profile, toward, ablation.out_dir_of(args.board, model, profile, suffix),
                         say, args.knob, chosen)
    tables = []
    for model in models:
        conditions, rows = ablation.load(ablation.out_dir_of(args.board, model, profile, suffix) / "footprint.json")
        tables.append(ablation.table(rows, conditions["board"], model, conditions["profile"], conditions["toward"]))
    files = ablation.write_report(tables, ablation.report_dir_of(args.board, profile, suffix))
    print(files[0].read_text())
    say(f"footprint report: {', '.join(str(f) for f in files)}")
    return 0
