# SPDX-License-Identifier: Apache-2.0
"""Figures quoted in README.md and docs/ are the baselines' (tests/baselines),
so they cannot go stale; and every relative link in them resolves.

A quoted figure carries a marker right after it:

    151,587<!-- figure qemu_cortex_m3 baremetal footprint.rom.bytes -->

board folder, variant, and a metric key of the baseline (or
`break:AXIS:RATE_GROUP`, the load sweep's breaking point of that group on
that axis: its BREAK record). The text must show the baseline's value as
written: bytes and counts with thousands separators, microseconds to the
decimals the text shows. A marker with no figure right before it fails
too, and the pages quote a few figures (10 to 36: a few per board the
pages discuss), not the whole report.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
MARKER = re.compile(r"(?P<text>[0-9][0-9,]*(?:\.[0-9]+)?|none)<!-- figure (?P<board>\S+) (?P<variant>\S+) "
                    r"(?P<key>\S+) -->")
LINK = re.compile(r"\]\((?P<target>[^)#\s]+)(?:#[^)]*)?\)")


def _baseline(board: str) -> dict[str, Any]:
    path = ROOT / "tests" / "baselines" / f"{board}.json"
    if not path.is_file():
        raise AssertionError(f"no baseline {path.relative_to(ROOT)}")
    data: dict[str, Any] = json.loads(path.read_text())
    return data


def expected(board: str, variant: str, key: str, shown: str) -> str:
    """The baseline's value, written as the text writes it (`shown`)."""
    found = _baseline(board)["variants"].get(variant)
    if found is None:
        raise AssertionError(f"{board} has no variant {variant}")
    if key.startswith("break:"):
        _, axis, rate_group = key.split(":")
        levels = [r["level"] for r in found.get("records", [])
                  if r["kind"] == "BREAK" and r["axis"] == axis and r["rg"] == rate_group]
        if len(levels) != 1:
            raise AssertionError(f"{board} {variant}: {len(levels)} BREAK records for {axis} {rate_group}")
        return str(levels[0])
    if key not in found["metrics"]:
        raise AssertionError(f"{board} {variant} has no metric {key}")
    value = float(found["metrics"][key])
    decimals = len(shown.split(".", 1)[1]) if "." in shown else 0
    return f"{value:,.{decimals}f}"


def mismatches(text: str, where: str) -> list[str]:
    """Every marked figure of `text` that is not its baseline's value."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        if line.count("<!-- figure") != len(MARKER.findall(line)):
            found.append(f"{where}:{number}: a figure marker without its figure right before it, or malformed "
                         "(NUMBER<!-- figure BOARD VARIANT KEY -->)")
        for match in MARKER.finditer(line):
            try:
                want = expected(match["board"], match["variant"], match["key"], match["text"])
            except AssertionError as error:
                found.append(f"{where}:{number}: {error}")
                continue
            if match["text"] != want:
                found.append(f"{where}:{number}: {match['text']} where the baseline says {want} "
                             f"({match['board']} {match['variant']} {match['key']})")
    return found


def test_every_marked_figure_is_the_baselines() -> None:
    problems = [p for page in PAGES for p in mismatches(page.read_text(), str(page.relative_to(ROOT)))]
    assert not problems, "\n".join(problems)
    count = sum(len(MARKER.findall(page.read_text())) for page in PAGES)
    assert 10 <= count <= 36, f"{count} figures: a few well-chosen ones, not every number of the report"


def test_a_wrong_figure_or_an_unknown_key_is_found() -> None:
    board = "qemu_cortex_m3"
    rom = _baseline(board)["variants"]["rtos"]["metrics"]["footprint.rom.bytes"]
    right = f"{int(rom):,}<!-- figure {board} rtos footprint.rom.bytes -->"
    wrong = f"{int(rom) + 1:,}<!-- figure {board} rtos footprint.rom.bytes -->"
    assert mismatches(right, "t") == []
    assert "where the baseline says" in mismatches(wrong, "t")[0]
    assert "has no metric" in mismatches(f"1<!-- figure {board} rtos no.such.metric -->", "t")[0]
    assert "no baseline" in mismatches("1<!-- figure no_such_board rtos rom -->", "t")[0]
    assert "without its figure" in mismatches(f"1.5 ms<!-- figure {board} rtos footprint.rom.bytes -->", "t")[0]
    assert mismatches(f"{int(rom)}<!-- figure {board} rtos footprint.rom.bytes -->", "t"), "thousands separators"


def test_decimals_and_breaking_points_are_read_as_the_text_shows_them() -> None:
    board = "qemu_cortex_m3"
    variant = _baseline(board)["variants"]["baremetal"]
    p99 = float(variant["metrics"]["rg.rg1kHz.latency.p99_us"])
    for decimals in (0, 1, 2):
        shown = f"{p99:,.{decimals}f}"
        assert mismatches(f"{shown}<!-- figure {board} baremetal rg.rg1kHz.latency.p99_us -->", "t") == []
    assert mismatches(f"{p99 + 1:.1f}<!-- figure {board} baremetal rg.rg1kHz.latency.p99_us -->", "t")
    level = next(r["level"] for r in variant["records"]
                 if r["kind"] == "BREAK" and r["axis"] == "slice" and r["rg"] == "rg1kHz")
    other = "none" if level != "none" else "0"
    assert mismatches(f"{level}<!-- figure {board} baremetal break:slice:rg1kHz -->", "t") == []
    assert "where the baseline says" in mismatches(f"{other}<!-- figure {board} baremetal break:slice:rg1kHz -->",
                                                   "t")[0]
    assert "BREAK records" in mismatches(f"1<!-- figure {board} baremetal break:nosuchaxis:rg1kHz -->", "t")[0]


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_relative_link_resolves(page: Path) -> None:
    broken = [m["target"] for m in LINK.finditer(page.read_text())
              if "://" not in m["target"] and not m["target"].startswith("mailto:")
              and not (page.parent / m["target"]).exists()]
    assert not broken, f"{page.relative_to(ROOT)}: broken links {broken}"
