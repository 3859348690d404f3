# SPDX-License-Identifier: Apache-2.0
"""The variants' runs as comparable numbers (metrics) and as the results file
(results(), docs/results.md); kittools.report renders them."""

from __future__ import annotations

from dataclasses import dataclass, field

from kittools import model
from kittools.console import Run
from kittools.model import MetricId
from kittools.sizes.memory import Footprint


@dataclass(frozen=True)
class VariantData:
    """What the comparison needs of one variant's result."""

    variant: str
    footprint: Footprint
    run: Run
    rom_modules: dict[str, int] = field(default_factory=dict)
    ram_modules: dict[str, int] = field(default_factory=dict)
    build: dict[str, object] = field(default_factory=dict)  # conditions.read()
    symbols: dict[str, dict[str, int]] = field(default_factory=dict)  # kittools.sizes.symbols, floored
    sizing: dict[str, object] = field(default_factory=dict)  # kittools.sizes.sizing, as JSON


def _us(cycles: int, cycles_hz: int) -> float:
    return cycles * 1e6 / cycles_hz


def metrics(data: VariantData) -> dict[MetricId, float]:
    """Metric -> value for one variant (bytes, microseconds, counts, percent)."""
    run = data.run
    cycles_hz = run.one("BANNER").int("cycles_hz")
    values: dict[MetricId, float] = {
        model.ROM: data.footprint.rom,
        model.RAM: data.footprint.ram,
    }
    if run.of_kind("HEAP"):
        heap = run.one("HEAP")
        values[model.HEAP_FPRIME_PEAK] = heap.int("fprime_peak")
        values[model.HEAP_REQUESTED] = heap.int("bytes")
        if "link_buffers" in heap.fields:
            values[model.HEAP_LINK] = heap.int("link_buffers")
        if "arena_left" in heap.fields:
            values[model.HEAP_ARENA_LEFT] = heap.int("arena_left")
    downlink = run.of_kind("DOWNLINK")
    if downlink and "queue_overflows" in downlink[0].fields:
        values[model.LINK_QUEUE_OVERFLOWS] = downlink[0].int("queue_overflows")
    stacks = run.of_kind("STACK")
    values[model.STACKS_RESERVED] = sum(s.int("size") for s in stacks)
    values[model.STACKS_USED] = sum(s.int("used") for s in stacks)
    for rg in run.of_kind("RG"):
        name = rg.fields["name"]
        for quantity in model.RG_QUANTITIES:
            for stat in model.STATS:
                values[model.rg_metric(name, quantity, stat)] = _us(rg.int(f"{quantity}_{stat}"), cycles_hz)
        values[model.slips(name)] = rg.int("slips")
    for task in run.of_kind("TASK"):
        values[model.cpu_share(task.fields["name"])] = task.int("cpu_permille") / 10
    stages = run.of_kind("STAGES")  # the fastest group's dispatch, stage by stage
    if len(stages) == 1 and stages[0].int("complete") > 0:
        for stage in run.of_kind("STAGE"):
            for stat in ("p50", "p99"):
                values[model.stage_latency(stage.fields["name"], stat)] = _us(stage.int(f"cycles_{stat}"), cycles_hz)
    floors = run.of_kind("FLOOR")  # kittools.suite.floor: the kernel floor of the model's path
    rate_groups = run.of_kind("RG")
    if len(floors) == 1:
        floor = floors[0]
        for stat in model.STATS:
            values[model.floor_latency(stat)] = _us(floor.int(stat), floor.int("cycles_hz"))
        if rate_groups and floor.int("p50") > 0:
            # Both in cycles of the same counter (the floor's stamp is the deployment's)
            values[model.FLOOR_RATIO] = round(rate_groups[0].int("latency_p50") / floor.int("p50"), 2)
    return values


def conditions(data: VariantData) -> dict[str, str]:
    banner = data.run.one("BANNER").fields
    keys = ("board", "kit", "zephyr", "fprime", "tick_hz", "sys_tick_hz", "cycles_hz", "icount_shift", "run_ticks",
            "timing_buckets")
    return {k: banner[k] for k in keys if k in banner}


SCHEMA_VERSION = model.SCHEMA_VERSION


def results(found: list[VariantData]) -> model.Results:
    """The results of the variants' runs on one board."""
    return model.Results(conditions(found[0]), {
        d.variant: model.Variant(
            passed=d.run.passed, metrics=metrics(d),
            records=[{"kind": r.kind, **r.fields} for r in d.run.records],
            build=dict(d.build), modules={"rom": d.rom_modules, "ram": d.ram_modules},
            footprint={"rom": d.footprint.rom, "ram": d.footprint.ram,
                       "rom_size": d.footprint.rom_size, "ram_size": d.footprint.ram_size},
            symbols=d.symbols, sizing=dict(d.sizing))
        for d in found
    })
