"""The design-review report: one results file in, Markdown, self-contained
HTML (plots inline), JSON and CSV out, with an optional baseline diff and
budget check. Every sentence in it is generated from the numbers."""

from __future__ import annotations

import base64
import csv
import io
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Union

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402
from jinja2 import Environment, FileSystemLoader, select_autoescape  # noqa: E402

from . import results  # noqa: E402

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


Section = Union[Table, Text, Image]


@dataclass
class Budget:
    """Allowed growth against a baseline, per variant."""

    rom_pct: float = 2.0
    ram_pct: float = 2.0
    p99_pct: float = 10.0
    p99_floor_us: float = 2.0  # smaller changes of a p99 are never a regression


@dataclass
class Outcome:
    files: list[Path] = field(default_factory=list)
    violations: list[str] = field(default_factory=list)


def _fmt(value: Any) -> str:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    return f"{value:,.0f}" if float(value).is_integer() else f"{value:,.1f}"


def _variants(data: dict[str, Any]) -> list[str]:
    return sorted(data["variants"])


def _metric(data: dict[str, Any], variant: str, name: str) -> float | None:
    value = data["variants"][variant]["metrics"].get(name)
    return float(value) if isinstance(value, (int, float)) else None


def _kib(value: float) -> str:
    return f"{value / 1024:.1f} KiB"


def conditions_text(data: dict[str, Any]) -> Text:
    c = data["conditions"]
    lines = [f"Board {c.get('board')}; kit {c.get('kit')}; Zephyr {c.get('zephyr')}; F´ {c.get('fprime')}.",
             f"Rate-group tick {c.get('tick_hz')} Hz, system clock {c.get('sys_tick_hz')} Hz, cycle counter "
             f"{c.get('cycles_hz')} Hz, QEMU icount shift {c.get('icount_shift')}, run of {c.get('run_ticks')} ticks."]
    for variant in _variants(data):
        build = data["variants"][variant].get("build", {})
        if build.get("toolchain"):
            lines.append(f"{variant}: {build['toolchain']}.")
    lines.append(CAVEAT)
    return Text("Conditions", lines)


def findings(data: dict[str, Any]) -> Text:
    """'What the numbers say', generated from them."""
    names = _variants(data)
    lines: list[str] = []
    if len(names) == 2:
        a, b = names
        for label, key in (("ROM", "ROM (bytes)"), ("static RAM", "RAM, static (bytes)")):
            va, vb = _metric(data, a, key), _metric(data, b, key)
            if va and vb is not None:
                delta = vb - va
                more = "more" if delta >= 0 else "less"
                lines.append(f"{b} uses {_kib(abs(delta))} ({abs(delta) / va * 100:.1f}%) {more} {label} than {a} "
                             f"({_kib(vb)} vs {_kib(va)}).")
        sa, sb = _metric(data, a, "stacks reserved (bytes)"), _metric(data, b, "stacks reserved (bytes)")
        if sa is not None and sb is not None:
            lines.append(f"Stacks reserved: {a} {_fmt(sa)} B, {b} {_fmt(sb)} B.")
        rate_groups = sorted({k.split(" ")[0] for k in data["variants"][a]["metrics"] if k.endswith("slips")})
        for rg in rate_groups:
            la = _metric(data, a, f"{rg} latency p99 (us)")
            lb = _metric(data, b, f"{rg} latency p99 (us)")
            slips = {v: _metric(data, v, f"{rg} slips") for v in names}
            if la is None or lb is None:
                continue
            lower = a if la <= lb else b
            lines.append(f"{rg}: p99 dispatch latency {a} {la:.1f} µs, {b} {lb:.1f} µs: {lower} is lower by "
                         f"{abs(la - lb):.1f} µs; slips {a} {_fmt(slips[a])}, {b} {_fmt(slips[b])}.")
        for v in names:
            idle = [r for r in data["variants"][v]["records"] if r.get("kind") == "CPU" and r.get("name") == "idle"]
            if idle:
                lines.append(f"{v} idles {int(idle[0]['cpu_permille']) / 10:.1f}% of the run.")
    verdicts = ", ".join(f"{v} {'PASS' if data['variants'][v].get('passed') else 'FAIL'}" for v in names)
    lines.append(f"Run verdicts: {verdicts}.")
    return Text("What the numbers say", lines)


def metrics_table(data: dict[str, Any]) -> Table:
    names = _variants(data)
    keys = list(data["variants"][names[0]]["metrics"])
    rows = []
    for key in keys:
        values = [_metric(data, v, key) for v in names]
        row: list[Any] = [key] + [v if v is not None else "" for v in values]
        if len(names) == 2 and None not in values:
            row.append(values[1] - values[0])  # type: ignore[operator]
        rows.append(row)
    columns = ["metric"] + names + ([f"{names[1]} − {names[0]}"] if len(names) == 2 else [])
    return Table("Side by side", columns, rows)


def modules_table(data: dict[str, Any]) -> Table | None:
    names = _variants(data)
    rom = {v: data["variants"][v].get("modules", {}).get("rom", {}) for v in names}
    ram = {v: data["variants"][v].get("modules", {}).get("ram", {}) for v in names}
    if not all(rom.values()):
        return None
    layers = list(rom[names[0]])
    rows = [[layer] + [rom[v].get(layer, 0) for v in names] + [ram[v].get(layer, 0) for v in names] for layer in layers]
    rows.append(["total"] + [sum(rom[v].values()) for v in names] + [sum(ram[v].values()) for v in names])
    return Table("ROM and RAM by module (bytes; Zephyr rom_report / ram_report, sorted into layers)",
                 ["module"] + [f"ROM {v}" for v in names] + [f"RAM {v}" for v in names], rows)


def record_table(data: dict[str, Any], kind: str, title: str, columns: list[tuple[str, str]]) -> Table | None:
    rows = []
    for v in _variants(data):
        for r in data["variants"][v]["records"]:
            if r.get("kind") == kind:
                rows.append([v] + [_cell(r.get(key), key) for key, _ in columns])
    return Table(title, ["variant"] + [label for _, label in columns], rows) if rows else None


def _cell(value: Any, key: str) -> Any:
    if key == "cpu_permille":
        return int(value) / 10
    try:
        return int(str(value), 0)
    except (TypeError, ValueError):
        return value


def _png(draw: Callable[[Any], None], size: tuple[float, float]) -> bytes:
    figure = plt.figure(figsize=size, dpi=100)
    try:
        draw(figure)
        figure.tight_layout()
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png")
        return buffer.getvalue()
    finally:
        plt.close(figure)


def modules_chart(table: Table, names: list[str]) -> Image:
    layers = [row[0] for row in table.rows if row[0] != "total"]

    def draw(figure: Any) -> None:
        for index, (kind, offset) in enumerate((("ROM", 1), ("RAM", 1 + len(names)))):
            axes = figure.add_subplot(1, 2, index + 1)
            height = 0.8 / len(names)
            for n, variant in enumerate(names):
                values = [row[offset + n] / 1024 for row in table.rows if row[0] != "total"]
                axes.barh([i + n * height for i in range(len(layers))], values, height=height, label=variant)
            axes.set_yticks([i + height * (len(names) - 1) / 2 for i in range(len(layers))])
            axes.set_yticklabels(layers if index == 0 else [""] * len(layers), fontsize=8)
            axes.invert_yaxis()
            axes.set_xlabel(f"{kind} (KiB)")
            axes.legend(fontsize=8)

    return Image("ROM and RAM by module", _png(draw, (11, 4)))


def histogram_chart(data: dict[str, Any], rate_group: str) -> Image | None:
    cycles_hz = float(data["conditions"].get("cycles_hz", 0) or 0)
    if cycles_hz <= 0:
        return None
    series: dict[str, dict[str, list[tuple[float, int]]]] = {}
    for v in _variants(data):
        for r in data["variants"][v]["records"]:
            if r.get("kind") == "HIST" and r.get("rg") == rate_group and r.get("buckets"):
                points = [tuple(int(x) for x in pair.split(":")) for pair in str(r["buckets"]).split(",")]
                series.setdefault(r["metric"], {})[v] = [(lo * 1e6 / cycles_hz, count) for lo, count in points]
    if not series:
        return None
    labels = {"latency": "dispatch latency", "exec": "execution time", "jitter": "period error"}

    def draw(figure: Any) -> None:
        for index, metric in enumerate(("latency", "exec", "jitter")):
            axes = figure.add_subplot(1, 3, index + 1)
            for variant, points in sorted(series.get(metric, {}).items()):
                (line,) = axes.step([p[0] for p in points], [p[1] for p in points], where="post", label=variant)
                axes.plot([p[0] for p in points], [p[1] for p in points], "o", markersize=3, color=line.get_color())
            axes.set_title(f"{rate_group} {labels[metric]}", fontsize=9)
            axes.set_xlabel("µs (bucket lower bound)", fontsize=8)
            axes.set_ylabel("cycles", fontsize=8)
            axes.set_yscale("log")
            if series.get(metric):
                axes.legend(fontsize=8)

    return Image(f"{rate_group}: distributions", _png(draw, (12, 3.2)))


def baseline_diff(data: dict[str, Any], baseline: dict[str, Any], budget: Budget) -> tuple[Table, list[str]]:
    rows: list[list[Any]] = []
    violations: list[str] = []
    for v in _variants(data):
        if v not in baseline["variants"]:
            violations.append(f"{v}: not in the baseline")
            continue
        for key, now in data["variants"][v]["metrics"].items():
            before = baseline["variants"][v]["metrics"].get(key)
            if not isinstance(now, (int, float)) or not isinstance(before, (int, float)):
                continue
            delta = now - before
            pct = (delta / before * 100) if before else (0.0 if delta == 0 else float("inf"))
            verdict = ""
            if key in ("ROM (bytes)", "RAM, static (bytes)"):
                limit = budget.rom_pct if key.startswith("ROM") else budget.ram_pct
                if pct > limit:
                    verdict = f"over budget (+{pct:.1f}% > {limit}%)"
            elif " p99 (us)" in key and delta > budget.p99_floor_us and pct > budget.p99_pct:
                verdict = f"regressed (+{pct:.1f}% > {budget.p99_pct}%)"
            elif key.endswith(" slips") and now > before:
                verdict = "more slips"
            if verdict:
                violations.append(f"{v} {key}: {_fmt(before)} -> {_fmt(now)}, {verdict}")
            if delta != 0 or verdict:
                rows.append([v, key, before, now, delta, f"{pct:+.1f}%" if pct != float("inf") else "new", verdict])
    return Table("Against the baseline (changed metrics)",
                 ["variant", "metric", "baseline", "now", "delta", "change", "budget"], rows), violations


def build_sections(data: dict[str, Any], baseline: dict[str, Any] | None, budget: Budget) -> tuple[list[Section], list[str]]:
    names = _variants(data)
    sections: list[Section] = [conditions_text(data), findings(data), metrics_table(data)]
    violations: list[str] = []
    if baseline is not None:
        diff, violations = baseline_diff(data, baseline, budget)
        verdict = (["Budget check: PASS (ROM +{:.1f}%, RAM +{:.1f}%, p99 +{:.0f}% above {:.0f} µs allowed)."
                    .format(budget.rom_pct, budget.ram_pct, budget.p99_pct, budget.p99_floor_us)]
                   if not violations else ["Budget check: FAIL"] + violations)
        sections += [Text("Budget", verdict), diff]
    mods = modules_table(data)
    if mods is not None:
        sections += [mods, modules_chart(mods, names)]
    for table in (
        record_table(data, "TASK", "Rate groups as tasks (counter cycles)",
                     [("name", "task"), ("runs", "runs"), ("exec_avg", "exec avg"), ("exec_max", "exec max"),
                      ("late", "late"), ("cpu_permille", "CPU %")]),
        record_table(data, "CPU", "CPU by execution context (threads on rtos, TaskRunner slices on baremetal)",
                     [("name", "context"), ("runs", "runs"), ("avg", "avg"), ("max", "max"),
                      ("cpu_permille", "CPU %")]),
        record_table(data, "STACK", "Stacks (bytes)", [("name", "stack"), ("size", "size"), ("used", "used")]),
        record_table(data, "PROBE", "Instrumentation cost (counter cycles per rate-group cycle)",
                     [("cycles_per_cycle", "cycles")]),
    ):
        if table is not None:
            sections.append(table)
    rate_groups = sorted({r["name"] for v in names for r in data["variants"][v]["records"] if r.get("kind") == "RG"})
    for rg in rate_groups:
        image = histogram_chart(data, rg)
        if image is not None:
            sections.append(image)
    return sections, violations


def to_markdown(sections: list[Section], image_names: dict[int, str]) -> str:
    out = ["# F´ on Zephyr: baremetal vs RTOS", ""]
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
            out += ["| " + " | ".join(_fmt(v) for v in row) + " |" for row in section.rows]
        else:
            out.append(f"![{section.title}]({image_names[index]})")
        out.append("")
    return "\n".join(out)


def to_html(sections: list[Section]) -> str:
    env = Environment(loader=FileSystemLoader(Path(__file__).parent / "templates"),
                      autoescape=select_autoescape(["html"]))
    items = []
    for section in sections:
        if isinstance(section, Image):
            items.append({"kind": "image", "title": section.title,
                          "src": "data:image/png;base64," + base64.b64encode(section.png).decode()})
        elif isinstance(section, Table):
            items.append({"kind": "table", "title": section.title, "columns": section.columns,
                          "rows": [[(_fmt(v), isinstance(v, (int, float))) for v in row] for row in section.rows]})
        else:
            items.append({"kind": "text", "title": section.title, "lines": section.lines})
    return env.get_template("report.html.j2").render(items=items)


def write(data: dict[str, Any], out_dir: Path, baseline: dict[str, Any] | None = None,
          budget: Budget | None = None, say: Callable[[str], None] = lambda _m: None) -> Outcome:
    budget = budget or Budget()
    out_dir.mkdir(parents=True, exist_ok=True)
    say("report: building tables and plots")
    sections, violations = build_sections(data, baseline, budget)
    outcome = Outcome(violations=violations)
    image_names: dict[int, str] = {}
    for index, section in enumerate(sections):
        if isinstance(section, Image):
            name = f"report-{len(image_names) + 1}.png"
            (out_dir / name).write_bytes(section.png)
            image_names[index] = name
            outcome.files.append(out_dir / name)
    say("report: writing Markdown, HTML, JSON and CSV")
    (out_dir / "report.md").write_text(to_markdown(sections, image_names))
    (out_dir / "report.html").write_text(to_html(sections))
    (out_dir / "report.json").write_text(json.dumps({**data, "budget_violations": violations}, indent=2) + "\n")
    with (out_dir / "report.csv").open("w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["variant", "metric", "value"])
        for v in _variants(data):
            for key, value in data["variants"][v]["metrics"].items():
                writer.writerow([v, key, value])
    outcome.files = [out_dir / n for n in ("report.md", "report.html", "report.json", "report.csv")] + outcome.files
    return outcome


def write_from_file(path: Path, out_dir: Path, baseline_path: Path | None, budget: Budget,
                    say: Callable[[str], None]) -> Outcome:
    say(f"report: reading {path}")
    data = results.load(path)
    baseline = results.load(baseline_path) if baseline_path is not None else None
    return write(data, out_dir, baseline, budget, say)
