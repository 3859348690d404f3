"""Side-by-side comparison of the variants' runs: a Markdown table (what a
reviewer pastes) and the same numbers as JSON."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .console import Run
from .footprint import Footprint


@dataclass(frozen=True)
class VariantData:
    """What the comparison needs of one variant's result."""

    variant: str
    footprint: Footprint
    run: Run
    rom_modules: dict[str, int] = field(default_factory=dict)
    ram_modules: dict[str, int] = field(default_factory=dict)
    build: dict[str, object] = field(default_factory=dict)  # conditions.read()


def _us(cycles: int, cycles_hz: int) -> float:
    return cycles * 1e6 / cycles_hz


def metrics(data: VariantData) -> dict[str, float]:
    """Flat metric name -> value for one variant (bytes, microseconds, counts)."""
    run = data.run
    cycles_hz = run.one("BANNER").int("cycles_hz")
    values: dict[str, float] = {
        "ROM (bytes)": data.footprint.rom,
        "RAM, static (bytes)": data.footprint.ram,
    }
    if run.of_kind("HEAP"):
        heap = run.one("HEAP")
        values["heap, F´ allocator peak (bytes)"] = heap.int("fprime_peak")
        values["heap, all users (bytes requested)"] = heap.int("bytes")
    stacks = run.of_kind("STACK")
    values["stacks reserved (bytes)"] = sum(s.int("size") for s in stacks)
    values["stacks used, peak (bytes)"] = sum(s.int("used") for s in stacks)
    for rg in run.of_kind("RG"):
        name = rg.fields["name"]
        for metric, label in (("latency", "latency"), ("exec", "exec"), ("jitter", "period error")):
            for stat in ("p50", "p99", "max"):
                values[f"{name} {label} {stat} (us)"] = _us(rg.int(f"{metric}_{stat}"), cycles_hz)
        values[f"{name} slips"] = rg.int("slips")
    for task in run.of_kind("TASK"):
        values[f"{task.fields['name']} CPU share (%)"] = task.int("cpu_permille") / 10
    return values


def _fmt(value: float) -> str:
    return f"{value:,.0f}" if float(value).is_integer() else f"{value:,.1f}"


def _table(title: str, columns: list[str], rows: list[list[Any]]) -> list[str]:
    """A titled Markdown table (nothing when there are no rows); numbers right-aligned."""
    if not rows:
        return []
    cells = [[_fmt(v) if isinstance(v, (int, float)) else str(v) for v in row] for row in rows]
    align = ["---" if isinstance(v, str) else "---:" for v in rows[0]]
    return ["", title, "", "| " + " | ".join(columns) + " |", "| " + " | ".join(align) + " |"] + [
        "| " + " | ".join(row) + " |" for row in cells]


def conditions(data: VariantData) -> dict[str, str]:
    banner = data.run.one("BANNER").fields
    keys = ("board", "kit", "zephyr", "fprime", "tick_hz", "sys_tick_hz", "cycles_hz", "icount_shift", "run_ticks")
    return {k: banner[k] for k in keys if k in banner}


def markdown(left: VariantData, right: VariantData) -> str:
    """The comparison table, conditions first."""
    cond = conditions(left)
    a, b = metrics(left), metrics(right)
    lines = [
        f"Conditions: board {cond.get('board')}, kit {cond.get('kit')}, Zephyr {cond.get('zephyr')}, "
        f"F´ {cond.get('fprime')}, tick {cond.get('tick_hz')} Hz, counter {cond.get('cycles_hz')} Hz, "
        f"QEMU icount shift {cond.get('icount_shift')}, {cond.get('run_ticks')} ticks. "
        "Times are QEMU virtual time: they compare software paths, not hardware latency.",
        "",
        f"| metric | {left.variant} | {right.variant} | {right.variant} − {left.variant} |",
        "|---|---:|---:|---:|",
    ]
    for name in a:
        if name in b:
            lines.append(f"| {name} | {_fmt(a[name])} | {_fmt(b[name])} | {_fmt(b[name] - a[name])} |")
    if left.rom_modules and right.rom_modules:
        rows = [[name, left.rom_modules[name], right.rom_modules.get(name, 0), left.ram_modules.get(name, 0),
                 right.ram_modules.get(name, 0)] for name in left.rom_modules]
        rows.append(["total"] + [sum(m.values()) for m in (left.rom_modules, right.rom_modules,
                                                           left.ram_modules, right.ram_modules)])
        lines += _table("ROM and RAM by module (bytes; Zephyr rom_report / ram_report, sorted into layers):",
                        ["module", f"ROM {left.variant}", f"ROM {right.variant}", f"RAM {left.variant}",
                         f"RAM {right.variant}"], rows)
    lines += _table("Rate groups as tasks (counter cycles):",
                    ["variant", "task", "runs", "exec avg", "exec max", "late", "CPU %"],
                    [[d.variant, t.fields["name"], t.int("runs"), t.int("exec_avg"), t.int("exec_max"), t.int("late"),
                      t.int("cpu_permille") / 10] for d in (left, right) for t in d.run.of_kind("TASK")])
    lines += _table("CPU by execution context (threads on rtos, TaskRunner slices on baremetal; counter cycles):",
                    ["variant", "context", "runs", "avg", "max", "CPU %"],
                    [[d.variant, c.fields["name"], c.int("runs"), c.int("avg"), c.int("max"),
                      c.int("cpu_permille") / 10] for d in (left, right) for c in d.run.of_kind("CPU")])
    probes = [f"{d.variant} {d.run.one('PROBE').fields.get('cycles_per_cycle')}" for d in (left, right)
              if d.run.of_kind("PROBE")]
    if probes:
        lines += ["", f"Instrumentation cost (counter cycles per rate-group cycle): {', '.join(probes)}."]
    verdicts = ", ".join(f"{d.variant} {'PASS' if d.run.passed else 'FAIL'}" for d in (left, right))
    lines += ["", f"Run verdicts: {verdicts}."]
    return "\n".join(lines)


SCHEMA_VERSION = 1


def as_json(results: list[VariantData]) -> dict[str, Any]:
    """The results file; its schema is documented in docs/results.md."""
    return {
        "schema_version": SCHEMA_VERSION,
        "conditions": conditions(results[0]),
        "variants": {
            d.variant: {
                "passed": d.run.passed,
                "build": d.build,
                "modules": {"rom": d.rom_modules, "ram": d.ram_modules},
                "footprint": {"rom": d.footprint.rom, "ram": d.footprint.ram,
                              "rom_size": d.footprint.rom_size, "ram_size": d.footprint.ram_size},
                "metrics": metrics(d),
                "records": [{"kind": r.kind, **r.fields} for r in d.run.records],
            }
            for d in results
        },
    }
