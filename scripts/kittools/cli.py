"""kit: the kit's command line (also `west kit`).

  kit compare   build both variants, run them under QEMU, print the comparison
  kit test      twister suite under QEMU, host unit tests, tooling tests
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import compare, conditions, modules, runner, testing
from .workspace import KIT_ROOT, VARIANTS, KitError, check_board, check_provisioned

DEFAULT_BOARD = "qemu_cortex_m3"


def _say(message: str) -> None:
    print(f"[kit] {message}", flush=True)


def cmd_compare(args: argparse.Namespace) -> int:
    check_board(args.board)
    check_provisioned()
    out_dir = Path(args.output).resolve()
    out_dir.mkdir(parents=True, exist_ok=True)
    results = []
    for variant in VARIANTS:
        _say(f"{variant}: building for {args.board} (west build -T app/kit.{variant})")
        result = runner.build_and_run(variant, args.board, out_dir)
        fp = result.footprint
        _say(f"{variant}: ran to its end line: {'PASS' if result.run.passed else 'FAIL'}; "
             f"ROM {fp.rom} B, RAM {fp.ram} B")
        _say(f"{variant}: ROM/RAM by module (west build -t rom_report / ram_report)")
        rom = modules.breakdown(modules.report(result.build_dir, "rom"))
        ram = modules.breakdown(modules.report(result.build_dir, "ram"))
        results.append(compare.VariantData(variant, result.footprint, result.run, rom, ram,
                                           conditions.read(result.build_dir)))
    table = compare.markdown(results[0], results[1])
    (out_dir / "comparison.md").write_text(table + "\n")
    (out_dir / "comparison.json").write_text(json.dumps(compare.as_json(results), indent=2) + "\n")
    print()
    print(table)
    print()
    _say(f"written: {out_dir / 'comparison.md'}, {out_dir / 'comparison.json'}")
    return 0 if all(r.run.passed for r in results) else 1


def cmd_test(args: argparse.Namespace) -> int:
    check_board(args.board)
    check_provisioned()
    log_dir = Path(args.output).resolve()
    total = testing.Tally()
    steps = []
    if not args.skip_twister:
        steps.append(("twister suite under QEMU", lambda: testing.run_twister(args.board, log_dir)))
        steps.append(("determinism: twister's binaries run again", lambda: testing.check_determinism(log_dir)))
    if not args.skip_host:
        steps.append(("host unit tests (googletest)", lambda: testing.run_host_tests(log_dir)))
    if not args.skip_python:
        steps.append(("tooling tests (pytest)", lambda: testing.run_pytest(log_dir)))
    for name, step in steps:
        _say(f"{name} ...")
        tally = step()
        _say(f"{name}: {tally.passed} passed, {tally.failed} failed")
        total.add(tally)
    print(f"total: {total.passed} passed, {total.failed} failed")
    return 0 if total.failed == 0 and total.passed > 0 else 1


def parser() -> argparse.ArgumentParser:
    top = argparse.ArgumentParser(prog="kit", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = top.add_subparsers(dest="command", required=True)
    p = sub.add_parser("compare", help="build and run both variants, print the comparison")
    p.add_argument("--board", default=DEFAULT_BOARD)
    p.add_argument("--output", default=str(KIT_ROOT / "build" / "compare"), help="build folders, logs, results")
    p.set_defaults(func=cmd_compare)
    t = sub.add_parser("test", help="twister suite, host unit tests and tooling tests")
    t.add_argument("--board", default=DEFAULT_BOARD)
    t.add_argument("--output", default=str(KIT_ROOT / "build" / "test-logs"), help="logs and reports")
    t.add_argument("--skip-twister", action="store_true")
    t.add_argument("--skip-host", action="store_true")
    t.add_argument("--skip-python", action="store_true")
    t.set_defaults(func=cmd_test)
    return top


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        return int(args.func(args))
    except KitError as error:
        print(f"kit: error: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
