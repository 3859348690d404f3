# SPDX-License-Identifier: Apache-2.0
"""A deployment's whole run through the seam (docs/your-deployment.md): every
model on a board, its scenarios under twister, its ground link's checks, its
results and report. `kit test` runs it on the second deployment
(tests/team/Thermal); `kit test --deployment DIR` on a team's own."""

from __future__ import annotations

import json
from pathlib import Path

from kittools import variants
from kittools.deployment import Deployment
from kittools.log import say
from kittools.suite import ground_checks, results, twister, verdict
from kittools.suite.counts import Tally
from kittools.suite.platforms import TWISTER_OUT
from kittools.workspace import check_board

#: What a deployment plays: the comparison run, the load sweep and the
#: ground-commanded faults (the soak, the stack overflow and the assert are
#: the kit's own checks of its models: the reference's run has them)
SCENARIOS = ("nominal", "load", "faults")


def run_deployment(chosen: Deployment, board: str, out_dir: Path, floors_from: Path = TWISTER_OUT,
                   serial_plays: int = 0) -> Tally:
    """Every model of `chosen` on `board`: SCENARIOS through twister, then
    the ground link's checks (ground_checks.run_deployment_link; the
    serial-load sweep where `serial_plays`, each level that many times),
    then its results (<out_dir>/<board folder>/results.json) and report
    (.../report/).
    The kernel floor is the board's, not the deployment's: it is taken from
    the suite's twister run in `floors_from` where that has it, else measured."""
    twister_out = out_dir / "twister"
    # The board's floor is measured here only where the suite's run has none
    suite_floors = results.floors_of(floors_from, board)
    tally = twister.run_twister([board], out_dir, twister_out, scenarios=SCENARIOS,
                                exclude_tags=(twister.PROFILE_TAG,), models=tuple(variants.names()),
                                with_floor=not suite_floors.paths, cmake_args=tuple(chosen.cmake_args()))
    tally.add(ground_checks.run_deployment_link(out_dir, twister_out, serial_plays))
    verdict.make_size_reports(twister_out)
    found, floors = results.collect(twister_out, board, out_dir)
    floors.add(suite_floors)
    data = results.assemble(found, floors, board)
    board_dir = out_dir / check_board(board)
    board_dir.mkdir(parents=True, exist_ok=True)
    (board_dir / "results.json").write_text(json.dumps(data.to_json(), indent=2) + "\n")
    from kittools.report import writer  # for the reader; kept out of the budget gate's imports

    writer.write(data, board_dir / "report")
    say(f"  {chosen.name} on {board}: report {board_dir / 'report' / 'report.html'}")
    tally.add(Tally(passed=1))
    return tally
