# SPDX-License-Identifier: Apache-2.0
"""The report as a document: titled sections (text, tables, images) that the
renderers (kittools.report.render) turn into Markdown, HTML, JSON and CSV."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

CAVEAT = ("Times are QEMU virtual time (icount): exact and repeatable, they compare software paths; "
          "they are not hardware latencies.")


@dataclass
class Table:
    title: str
    columns: list[str]
    rows: list[list[Any]]


@dataclass
class Text:
    title: str
    lines: list[str]


@dataclass
class Image:
    title: str
    png: bytes


Section = Table | Text | Image


def fmt(value: Any) -> str:
    """A number as the report shows it: thousands separated, one decimal unless whole."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    return f"{value:,.0f}" if float(value).is_integer() else f"{value:,.1f}"


def kib(value: float) -> str:
    return f"{value / 1024:.1f} KiB"
