# SPDX-License-Identifier: Apache-2.0
"""The report's renderers: its sections as Markdown, self-contained HTML
(plots inline, a Jinja2 template), and its results as JSON and CSV."""

from __future__ import annotations

import base64
import csv
import io
import json
from pathlib import Path
from typing import Any

from kittools.model import Results
from kittools.report.analysis import sweeps
from kittools.report.document import Image, Section, Table, Text, fmt

TITLE = "F´ on Zephyr: baremetal vs RTOS"


def to_markdown(sections: list[Section], image_names: dict[int, str]) -> str:
    out = [f"# {TITLE}", ""]
    for index, section in enumerate(sections):
        out += [f"## {section.title}", ""]
        if isinstance(section, Text):
            out += [f"- {line}" for line in section.lines]
        elif isinstance(section, Table):
            numeric = [isinstance(v, (int, float)) and not isinstance(v, bool) for v in section.rows[0]] \
                if section.rows else []
            out.append("| " + " | ".join(section.columns) + " |")
            out.append("|" + "|".join("---:" if n else "---" for n in numeric) + "|" if numeric else
                       "|" + "|".join("---" for _ in section.columns) + "|")
            out += ["| " + " | ".join(fmt(v) for v in row) + " |" for row in section.rows]
        else:
            out.append(f"![{section.title}]({image_names[index]})")
        out.append("")
    return "\n".join(out)


def to_html(sections: list[Section]) -> str:
    from jinja2 import Environment, FileSystemLoader, select_autoescape

    env = Environment(loader=FileSystemLoader(Path(__file__).parent / "templates"),
                      autoescape=select_autoescape(["html"]))
    items: list[dict[str, Any]] = []
    for section in sections:
        if isinstance(section, Image):
            items.append({"kind": "image", "title": section.title,
                          "src": "data:image/png;base64," + base64.b64encode(section.png).decode()})
        elif isinstance(section, Table):
            items.append({"kind": "table", "title": section.title, "columns": section.columns,
                          "rows": [[(fmt(v), isinstance(v, (int, float))) for v in row] for row in section.rows]})
        else:
            items.append({"kind": "text", "title": section.title, "lines": section.lines})
    return env.get_template("report.html.j2").render(items=items)


def to_json(datas: list[Results], violations: list[str]) -> str:
    """The results reported (one board's, or {"boards": [...]}) and the budget's violations."""
    summary = datas[0].to_json() if len(datas) == 1 else {"boards": [d.to_json() for d in datas]}
    return json.dumps({**summary, "budget_violations": violations}, indent=2) + "\n"


def to_csv(datas: list[Results]) -> str:
    """One row per variant and metric (label and key), plus one per sweep point."""
    several = len(datas) > 1
    stream = io.StringIO()
    writer = csv.writer(stream)
    writer.writerow(["variant", "metric", "value", "key"])
    for data in datas:
        found = sweeps(data)
        for v in data.names():
            name = f"{data.board} {v}" if several else v
            for metric, value in data.variants[v].metrics.items():
                writer.writerow([name, metric.label, value, metric.key])
            sw = found.get(v)
            for point in sw.points if sw else []:
                writer.writerow([name, f"sweep {point.axis} {point.rate_group} load {point.level} {point.unit} "
                                       "latency p99 (cycles)", point.latency_p99,
                                 f"sweep.{point.axis}.{point.rate_group}.{point.level}.p99_cycles"])
    return stream.getvalue()
