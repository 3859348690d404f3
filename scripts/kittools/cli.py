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
  kit new-deployment  give a deployment made by fprime-util new --deployment the kit's seam
"""


from __future__ import annotations

import argparse
import sys
from pathlib import Path

from kittools import variants
from kittools.boards.scaffold import REFERENCE_BOARD
from kittools.commands import (
    compare,
    footprint,
    gds,
    new_board,
    new_deployment,
    report,
    serial_sweep,
    sizediff,
    sizing,
    test,
)
from kittools.link.serial_points import AXES
from kittools.sizes import symbols
from kittools.suite import budget
from kittools.workspace import KIT_ROOT, KitError


def add_deployment_option(command: argparse.ArgumentParser, what: str) -> None:
    command.add_argument("--deployment", metavar="DIR",
                         help=f"{what} (default: the reference one, app/; docs/your-deployment.md)")


def parser() -> argparse.ArgumentParser:
    top = argparse.ArgumentParser(prog="kit", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = top.add_subparsers(dest="command", required=True)
    p = sub.add_parser("compare", help="build and run every variant, print the comparison")
    p.add_argument("--board", action="append",
                   help="board to compare on (repeatable; default: every platform of the suite)")
    p.add_argument("--output", help="build folders, logs, results (default: build/compare, or "
                   "build/compare-<folder> for --deployment)")
    add_deployment_option(p, "the F´ deployment to measure")
    variants.add_model_option(p, "the variants to compare (repeatable; default: every one)", repeatable=True)
    p.set_defaults(func=compare.run)
    r = sub.add_parser("report", help="report of results files (build/compare/<board>/comparison.json)")
    r.add_argument("results", nargs="*", help="results files (JSON, docs/results.md), one per board")
    r.add_argument("--merge", nargs="+", metavar="DIR",
                   help="join the shards of a split run (the --output folders of kit test --subset K/N, every K "
                        "once) into each board's results file and report, judged against its baseline "
                        "(default output: build/merged)")
    r.add_argument("--baseline", help="results file to diff the first against; with it, a budget check sets the "
                                      "exit code")
    r.add_argument("--output", help="folder for report.* (default: the results file's folder)")
    r.set_defaults(func=report.run)
    t = sub.add_parser("test", help="twister suite, host unit tests and tooling tests")
    t.add_argument("--board", action="append",
                   help="board to run the suite on (repeatable; default: every platform of the suite, "
                        "tests/deployment/testcase.yaml)")
    t.add_argument("--output", default=str(KIT_ROOT / "build" / "test-logs"), help="logs and reports")
    t.add_argument("--quick", action="store_true",
                   help=f"the short run: every model (or --model's) on {REFERENCE_BOARD}, nominal, faults and "
                        "load, a NO_OP through fprime-gds per model, host and tooling tests; no budget")
    t.add_argument("--full", action="store_true",
                   help="also what CI's run leaves out: the porting check (kit new-board's QEMU and real "
                        "boards), the new-deployment check (fprime-util's template through kit new-deployment), "
                        "the real boards' builds of each baremetal policy (tests/boards, tag 'full')")
    t.add_argument("--subset", metavar="K/N",
                   help="this machine's share K of a full run split across N (twister's --subset); join the "
                        "shards' --output folders with kit report --merge")
    add_deployment_option(t, "with it, that deployment's whole run alone: every model on --board (default: "
                             f"{REFERENCE_BOARD}), nominal, load sweep, faults, its ground link, its report; the F´ "
                             "deployment to test")
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
    t.set_defaults(func=test.run)
    g = sub.add_parser("gds", help="boot a board and model under QEMU with fprime-gds on its ground link")
    g.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(g, "default: rtos", default="rtos")
    add_deployment_option(g, "the F´ deployment to boot")
    g.add_argument("--port", type=int, default=5000, help="the GDS web page's port (default: 5000)")
    g.add_argument("--dictionary", type=Path, default=None,
                   help="the F´ dictionary to give fprime-gds (default: the build's own; refused unless it is "
                        "the one the firmware was built with)")
    g.set_defaults(func=gds.run)
    w = sub.add_parser("serial-sweep", help="the serial-load sweep (uplink commands, downlink packets) of a board "
                                            "and model, through its ground link under QEMU")
    w.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(w, "default: rtos", default="rtos")
    add_deployment_option(w, "the F´ deployment to sweep")
    w.add_argument("--axis", action="append", choices=[axis.name for axis in AXES], dest="axes",
                   help="sweep this axis only (again for more; default: every axis the build has the service for; "
                        "an axis named on a build without its service is refused)")
    w.set_defaults(func=serial_sweep.run)
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
    d.set_defaults(func=sizediff.run)
    f = sub.add_parser("footprint", help="what each F´ knob costs: from a footprint profile, one build per knob "
                                         "(ROM, RAM by layer, the nominal run)")
    f.add_argument("--board", default=REFERENCE_BOARD, help=f"board target (default: {REFERENCE_BOARD})")
    variants.add_model_option(f, "repeatable; default: every one", repeatable=True)
    f.add_argument("--profile", default="fprime-kit", help="the profile to start from (modules/fprime/snippets; "
                                                           "default: fprime-kit)")
    f.add_argument("--toward", default="fprime-default", help="the profile whose values the knobs move to "
                                                              "(default: fprime-default)")
    add_deployment_option(f, "the F´ deployment to measure")
    f.add_argument("--report-only", action="store_true",
                   help="write the report from the models' last ablations (build/footprint/), building nothing")
    f.add_argument("--knob", action="append", default=[], metavar="TEXT",
                   help="only the knobs whose name contains TEXT (repeatable; the profile's build always), "
                        "for example --knob optimization for the compiler's")
    f.set_defaults(func=footprint.run)
    z = sub.add_parser("sizing", help="a build's fixed tables (command dispatch, telemetry, TaskRunner, thread "
                                      "pool, queues) against what its dictionary and run need, and its ports")
    z.add_argument("build", help="a kit build folder (west build -d ...)")
    z.add_argument("--log", help="the console log of a run of that build, for its queues' high-water marks")
    z.set_defaults(func=sizing.run)
    n = sub.add_parser("new-board", help="scaffold boards/<board>/ for a new board and add it to the suite")
    n.add_argument("board", metavar="BOARD", help="board target as west build -b takes it (e.g. mps2/an385)")
    n.add_argument("--from", "--reference", dest="reference", metavar="REFERENCE", default=REFERENCE_BOARD,
                   help=f"ported board to copy the folder and the measured footprint of (default: {REFERENCE_BOARD})")
    n.add_argument("--force", action="store_true", help="write the board's folder again if it exists")
    n.set_defaults(func=new_board.run)
    e = sub.add_parser("new-deployment", help="give a deployment folder made by fprime-util new --deployment the "
                                              "kit's seam, replacing its host timer, link and clock")
    e.add_argument("folder", metavar="DIR", help="the deployment folder (inside its F´ project)")
    e.add_argument("--fastest-hz", metavar="HZ",
                   help="the fastest rate group's rate on the board; the others keep the template's ratios to it "
                        "(default: the template's rates, where F´'s rate group driver holds them at the kit's tick)")
    e.set_defaults(func=new_deployment.run)
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
