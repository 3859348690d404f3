# SPDX-License-Identifier: Apache-2.0
"""kit sizediff: symbols added, removed, grown and shrunk between two builds or results files."""

from __future__ import annotations

import argparse
from pathlib import Path

from kittools.sizes import symbols
from kittools.suite import results
from kittools.workspace import KitError


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


def run(args: argparse.Namespace) -> int:
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
