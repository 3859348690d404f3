"""The variants' runs as comparable numbers (metrics) and as the results file
(as_json, docs/results.md); kittools.report renders them."""

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


def conditions(data: VariantData) -> dict[str, str]:
    banner = data.run.one("BANNER").fields
    keys = ("board", "kit", "zephyr", "fprime", "tick_hz", "sys_tick_hz", "cycles_hz", "icount_shift", "run_ticks")
    return {k: banner[k] for k in keys if k in banner}


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
