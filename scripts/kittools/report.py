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

from . import results, sweep  # noqa: E402

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


def _sweeps(data: dict[str, Any]) -> dict[str, sweep.Sweep]:
    found = {}
    for v in _variants(data):
        parsed = sweep.of_records(data["variants"][v]["records"])
        if parsed is not None:
            found[v] = parsed
    return found


def _fastest_period_us(data: dict[str, Any]) -> float:
    """Period of the fastest rate group, in µs (the tick's)."""
    tick_hz = float(data["conditions"].get("tick_hz", 0) or 0)
    return 1e6 / tick_hz if tick_hz > 0 else 0.0


def _break_text(value: int | None, max_us: int) -> str:
    return f"{value} µs" if value is not None else f"none up to {max_us} µs"


def breaking_points_table(sweeps: dict[str, sweep.Sweep]) -> Table:
    names = sorted(sweeps)
    first = sweeps[names[0]]
    rows = []
    for axis in first.axes():
        for rg in first.rate_groups():
            rows.append([axis, rg] + [_break_text(sweeps[v].breaking_point(axis, rg), sweeps[v].max_load(axis))
                                      for v in names])
    return Table("Background load: breaking points (smallest load at which a rate group missed a deadline)",
                 ["load axis", "rate group"] + names, rows)


def sweep_table(sweeps: dict[str, sweep.Sweep], cycles_hz: float, axis: str) -> Table:
    names = sorted(sweeps)
    fastest = sweeps[names[0]].rate_groups()[0]
    loads = sorted({p.load_us for v in names for p in sweeps[v].points if p.axis == axis})
    rows = []
    for load in loads:
        row: list[Any] = [load]
        for v in names:
            at = {p.rate_group: p for p in sweeps[v].points if p.axis == axis and p.load_us == load}
            point = at.get(fastest)
            row += [point.latency_p99 * 1e6 / cycles_hz if point else "",
                    point.latency_max * 1e6 / cycles_hz if point else "",
                    ", ".join(rg for rg, p in at.items() if p.missed) or "-"]
        rows.append(row)
    columns = ["load (µs)"]
    for v in names:
        columns += [f"{v} {fastest} p99 (µs)", f"{v} {fastest} max (µs)", f"{v} missed deadlines"]
    return Table(f"Background load sweep, axis '{axis}'", columns, rows)


def sweep_chart(sweeps: dict[str, sweep.Sweep], cycles_hz: float, axis: str) -> Image:
    names = sorted(sweeps)
    rate_groups = sweeps[names[0]].rate_groups()

    def draw(figure: Any) -> None:
        for index, rg in enumerate(rate_groups):
            axes = figure.add_subplot(1, len(rate_groups), index + 1)
            for v in names:
                points = sweeps[v].series(axis, rg)
                x = [p.load_us for p in points]
                (line,) = axes.plot(x, [p.latency_p99 * 1e6 / cycles_hz for p in points], "-o", markersize=3,
                                    label=f"{v} p99")
                axes.plot(x, [p.latency_max * 1e6 / cycles_hz for p in points], "--", color=line.get_color(),
                          label=f"{v} max")
                missed = [p for p in points if p.missed]
                if missed:
                    axes.plot([p.load_us for p in missed], [p.latency_max * 1e6 / cycles_hz for p in missed], "x",
                              color="red", markersize=7, label=f"{v} missed deadline")
                broke = sweeps[v].breaking_point(axis, rg)
                if broke is not None:
                    axes.axvline(broke, linestyle=":", color=line.get_color())
            axes.set_title(f"{rg}: dispatch latency vs load ({axis})", fontsize=9)
            axes.set_xlabel("load (µs)", fontsize=8)
            axes.set_ylabel("latency (µs)", fontsize=8)
            axes.legend(fontsize=7)

    return Image(f"Latency versus background load, axis '{axis}'", _png(draw, (4.2 * len(rate_groups), 3.4)))


def sweep_guidance(data: dict[str, Any], sweeps: dict[str, sweep.Sweep]) -> Text:
    """What the sweep says, generated from its points."""
    cycles_hz = float(data["conditions"].get("cycles_hz", 0) or 0)
    period = _fastest_period_us(data)
    lines: list[str] = []
    for v in sorted(sweeps):
        sw = sweeps[v]
        fastest = sw.rate_groups()[0]
        for axis in sw.axes():
            breaks = [(b, rg) for rg in sw.rate_groups() if (b := sw.breaking_point(axis, rg)) is not None]
            series = sw.series(axis, fastest)
            p99 = [p.latency_p99 * 1e6 / cycles_hz for p in series]
            # The knee: the first load at which the fastest group's p99 is 10% over its zero-load value
            knee = next((p.load_us for q, p in zip(p99, series) if q > p99[0] * 1.1), None)
            grows = f"; its p99 latency starts to grow at {knee} µs" if knee is not None else ""
            if breaks:
                load, rg = min(breaks)
                before = [q for q, p in zip(p99, series) if p.load_us < load]
                grow = (f", from {before[0]:.1f} µs to {before[-1]:.1f} µs just below the break"
                        if before and knee is not None else "")
                share = f" ({load / period * 100:.0f}% of the {period:.0f} µs period)" if period else ""
                lines.append(f"{v}, {axis} load: {rg} misses deadlines from {load} µs{share}{grows}{grow}.")
            else:
                most = sw.max_load(axis)
                times = f" ({most / period:.1f}x the fastest period)" if period else ""
                lines.append(f"{v}, {axis} load: no rate group missed a deadline up to {most} µs{times}; "
                             f"{fastest} p99 latency stayed within {min(p99):.1f}-{max(p99):.1f} µs{grows}.")
        lines += [f"{v}: inconsistent sweep record: {text}" for text in sw.inconsistencies()]
    names = _variants(data)
    if len(names) == 2:
        a, b = names
        costs = []
        for label, key in (("ROM", "ROM (bytes)"), ("static RAM", "RAM, static (bytes)"),
                           ("reserved stack", "stacks reserved (bytes)")):
            va, vb = _metric(data, a, key), _metric(data, b, key)
            if va is not None and vb is not None:
                costs.append(f"{label} {vb - va:+,.0f} B")
        switches = _switches_per_second(data, b)
        if switches is not None:
            costs.append(f"{switches:,.0f} context switches per second")
        if costs:
            lines.append(f"What {b} costs against {a} at zero load: {', '.join(costs)}.")
    return Text("Background load: what the sweep says", lines)


def _switches_per_second(data: dict[str, Any], variant: str) -> float | None:
    """Scheduling windows per second of the threads (KIT CPU runs, idle left out)."""
    records = [r for r in data["variants"][variant]["records"] if r.get("kind") == "CPU" and r.get("name") != "idle"]
    ticks = float(data["conditions"].get("run_ticks", 0) or 0)
    tick_hz = float(data["conditions"].get("tick_hz", 0) or 0)
    # Only threads switch context: baremetal's CPU records count cooperative
    # slices of one loop, not switches
    if not records or ticks <= 0 or tick_hz <= 0 or variant != "rtos":
        return None
    return sum(int(r["runs"]) for r in records) / (ticks / tick_hz)


def sweep_sections(data: dict[str, Any]) -> list[Section]:
    sweeps = _sweeps(data)
    cycles_hz = float(data["conditions"].get("cycles_hz", 0) or 0)
    if not sweeps or cycles_hz <= 0:
        return []
    sections: list[Section] = [breaking_points_table(sweeps), sweep_guidance(data, sweeps)]
    for axis in sweeps[sorted(sweeps)[0]].axes():
        sections += [sweep_chart(sweeps, cycles_hz, axis), sweep_table(sweeps, cycles_hz, axis)]
    return sections


def build_sections(data: dict[str, Any], baseline: dict[str, Any] | None, budget: Budget) -> tuple[list[Section], list[str]]:
    names = _variants(data)
    sections: list[Section] = [conditions_text(data), findings(data), metrics_table(data)]
    sections += sweep_sections(data)
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


def _board(data: dict[str, Any]) -> str:
    return str(data["conditions"].get("board", "?"))


BOARD_METRICS = ("ROM (bytes)", "RAM, static (bytes)", "stacks reserved (bytes)", "stacks used, peak (bytes)",
                 "heap, F´ allocator peak (bytes)")


def boards_table(datas: list[dict[str, Any]]) -> Table:
    """The key metrics of every board and variant, side by side."""
    columns = [(d, v) for d in datas for v in _variants(d)]
    keys = list(BOARD_METRICS)
    for d in datas:
        for v in _variants(d):
            keys += [k for k in d["variants"][v]["metrics"] if (k.endswith("latency p99 (us)") or k.endswith(" slips"))
                     and k not in keys]
    rows: list[list[Any]] = []
    for key in keys:
        rows.append([key] + [_metric(d, v, key) if _metric(d, v, key) is not None else "" for d, v in columns])
    sweeps = [(_sweeps(d).get(v), d) for d, v in columns]
    axes = list(dict.fromkeys(a for sw, _ in sweeps if sw for a in sw.axes()))
    for axis in axes:
        for rg in next(sw for sw, _ in sweeps if sw).rate_groups():
            rows.append([f"breaking point, {axis} load, {rg}"] +
                        [_break_text(sw.breaking_point(axis, rg), sw.max_load(axis)) if sw else "" for sw, _ in sweeps])
    return Table("Boards side by side", ["metric"] + [f"{_board(d)} {v}" for d, v in columns], rows)


def boards_chart(datas: list[dict[str, Any]]) -> Image:
    columns = [(d, v) for d in datas for v in _variants(d)]

    def draw(figure: Any) -> None:
        for index, (label, key) in enumerate((("ROM", "ROM (bytes)"), ("static RAM", "RAM, static (bytes)"))):
            axes = figure.add_subplot(1, 2, index + 1)
            values = [(_metric(d, v, key) or 0) / 1024 for d, v in columns]
            axes.barh(range(len(columns)), values)
            axes.set_yticks(range(len(columns)))
            axes.set_yticklabels([f"{_board(d)} {v}" if index == 0 else "" for d, v in columns], fontsize=8)
            axes.invert_yaxis()
            axes.set_xlabel(f"{label} (KiB)")

    return Image("ROM and RAM per board and variant", _png(draw, (11, 0.5 * len(columns) + 1.5)))


def write(data: dict[str, Any], out_dir: Path, baseline: dict[str, Any] | None = None,
          budget: Budget | None = None, say: Callable[[str], None] = lambda _m: None) -> Outcome:
    """The report of one board's results."""
    return write_boards([data], out_dir, baseline, budget, say)


def write_boards(datas: list[dict[str, Any]], out_dir: Path, baseline: dict[str, Any] | None = None,
                 budget: Budget | None = None, say: Callable[[str], None] = lambda _m: None) -> Outcome:
    """The report of one or more boards' results; the baseline (budget check)
    applies to the first."""
    budget = budget or Budget()
    out_dir.mkdir(parents=True, exist_ok=True)
    say("report: building tables and plots")
    several = len(datas) > 1
    sections: list[Section] = [boards_table(datas), boards_chart(datas)] if several else []
    violations: list[str] = []
    for index, data in enumerate(datas):
        board_sections, board_violations = build_sections(data, baseline if index == 0 else None, budget)
        if several:
            for section in board_sections:
                section.title = f"{_board(data)}: {section.title}"
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
    (out_dir / "report.md").write_text(to_markdown(sections, image_names))
    (out_dir / "report.html").write_text(to_html(sections))
    summary = {**datas[0]} if not several else {"boards": datas}
    (out_dir / "report.json").write_text(json.dumps({**summary, "budget_violations": violations}, indent=2) + "\n")
    with (out_dir / "report.csv").open("w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["variant", "metric", "value"])
        for data in datas:
            for v in _variants(data):
                name = f"{_board(data)} {v}" if several else v
                for key, value in data["variants"][v]["metrics"].items():
                    writer.writerow([name, key, value])
                sw = _sweeps(data).get(v)
                for point in sw.points if sw else []:
                    writer.writerow([name, f"sweep {point.axis} {point.rate_group} load {point.load_us} us "
                                           "latency p99 (cycles)", point.latency_p99])
    outcome.files = [out_dir / n for n in ("report.md", "report.html", "report.json", "report.csv")] + outcome.files
    return outcome


def write_from_files(paths: list[Path], out_dir: Path, baseline_path: Path | None, budget: Budget,
                     say: Callable[[str], None]) -> Outcome:
    datas = []
    for path in paths:
        say(f"report: reading {path}")
        datas.append(results.load(path))
    baseline = results.load(baseline_path) if baseline_path is not None else None
    return write_boards(datas, out_dir, baseline, budget, say)

