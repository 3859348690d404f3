# SPDX-License-Identifier: Apache-2.0
"""The design-review report: results files in; Markdown, self-contained HTML
(plots inline), JSON and CSV out, with an optional baseline diff and budget
check. This module assembles the sections; the budget gate (budget), what
the numbers say (analysis), the tables (tables), the plots (plots) and the
renderers (render) live apart."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from kittools.model import Results
from kittools.report import analysis, conditions, link_report, plots, render, tables
from kittools.report.document import Image, Section
from kittools.suite import budget, results
from kittools.suite.budget import Budget

__all__ = ["Budget", "Outcome", "build_sections", "write", "write_boards", "write_from_files"]


@dataclass
class Outcome:
    files: list[Path] = field(default_factory=list)
    violations: list[str] = field(default_factory=list)


def sweep_sections(data: Results) -> list[Section]:
    found = analysis.sweeps(data)
    cycles_hz = data.condition("cycles_hz")
    if not found or cycles_hz <= 0:
        return []
    sections: list[Section] = [tables.breaking_points_table(found), analysis.sweep_guidance(data, found)]
    for axis in dict.fromkeys(a for v in sorted(found) for a in found[v].axes()):
        sections += [plots.sweep_chart(found, cycles_hz, axis), tables.sweep_table(found, cycles_hz, axis)]
    return sections + link_report.sections(data)


def build_sections(data: Results, baseline: Results | None, limits: Budget,
                   verdict: budget.Verdict | None = None) -> tuple[list[Section], list[str]]:
    """A board's sections and its budget violations. The budget verdict is
    `verdict` when the caller has it already (kit test judged the board
    before it asks for the report), else checked here against `baseline`."""
    names = data.names()
    sections: list[Section] = [conditions.conditions_text(data), analysis.findings(data),
                               analysis.choosing(data, analysis.sweeps(data)), tables.metrics_table(data)]
    tasks = analysis.tasks_table(data)
    if tasks is not None:
        sections.append(tasks)
    sections += sweep_sections(data)
    violations: list[str] = []
    if verdict is None and baseline is not None:
        verdict = budget.check(data, baseline, limits)
    if verdict is not None:
        violations = verdict.violations
        sections += tables.budget_sections(verdict, limits)
    mods = tables.modules_table(data)
    if mods is not None:
        sections += [mods, plots.modules_chart(mods, names)]
    sections += tables.services_sections(data)
    sections += tables.sizing_tables(data)
    sections += tables.record_tables(data)
    rate_groups = sorted({r["name"] for v in names for r in data.variants[v].of_kind("RG")})
    for rg in rate_groups:
        image = plots.histogram_chart(data, rg)
        if image is not None:
            sections.append(image)
    return sections, violations


def write(data: Results, out_dir: Path, baseline: Results | None = None, limits: Budget | None = None,
          say: Callable[[str], None] = lambda _m: None, verdict: budget.Verdict | None = None) -> Outcome:
    """The report of one board's results; `verdict`: its budget verdict
    against `baseline`, when the caller has computed it (not computed again)."""
    return write_boards([data], out_dir, baseline, limits, say, verdict)


def write_boards(datas: list[Results], out_dir: Path, baseline: Results | None = None,
                 limits: Budget | None = None, say: Callable[[str], None] = lambda _m: None,
                 verdict: budget.Verdict | None = None) -> Outcome:
    """The report of one or more boards' results; the baseline (budget check)
    applies to the first, and so does `verdict` (the budget check's, already
    computed by the caller: kit test's)."""
    limits = limits or Budget()
    out_dir.mkdir(parents=True, exist_ok=True)
    say("report: building tables and plots")
    several = len(datas) > 1
    sections: list[Section] = [tables.boards_table(datas), plots.boards_chart(datas)] if several else []
    fits = tables.fits_table(datas) if several else None
    if fits is not None:
        sections.append(fits)
    violations: list[str] = []
    for index, data in enumerate(datas):
        first = index == 0
        board_sections, board_violations = build_sections(data, baseline if first else None, limits,
                                                          verdict if first else None)
        if several:
            for section in board_sections:
                section.title = f"{data.board}: {section.title}"
        sections += board_sections
        violations += board_violations
    outcome = Outcome(violations=violations)
    image_names: dict[int, str] = {}
    for index, section in enumerate(sections):
        if isinstance(section, Image):
            name = f"report-{len(image_names) + 1}.png"
            (out_dir / name).write_bytes(section.png)
            image_names[index] = name
            outcome.files.append(out_dir / name)
    say("report: writing Markdown, HTML, JSON and CSV")
    (out_dir / "report.md").write_text(render.to_markdown(sections, image_names))
    (out_dir / "report.html").write_text(render.to_html(sections))
    (out_dir / "report.json").write_text(render.to_json(datas, violations))
    (out_dir / "report.csv").write_text(render.to_csv(datas))
    outcome.files = [out_dir / n for n in ("report.md", "report.html", "report.json", "report.csv")] + outcome.files
    return outcome


def write_from_files(paths: list[Path], out_dir: Path, baseline_path: Path | None, limits: Budget,
                     say: Callable[[str], None]) -> Outcome:
    datas = []
    for path in paths:
        say(f"report: reading {path}")
        datas.append(results.load(path))
    baseline = results.load(baseline_path) if baseline_path is not None else None
    return write_boards(datas, out_dir, baseline, limits, say)
