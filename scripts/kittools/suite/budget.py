# SPDX-License-Identifier: Apache-2.0
"""The budget gate: a board's results against its baseline.

ROM or static RAM more than +2%, a p99 more than +10% and over 2 µs, the
fastest rate group's latency over its kernel floor more than +10%, any new
slip, or a breaking point that comes earlier (a rate group's on any load or
serial axis, the link's delivery on its command axes) fails it (the limits
are options). It decides from the metrics and the sweep records alone (the
serial axes' latencies, host-timed, are not held: their breaking points and
deliveries are): no report is rendered, and no plotting or templating
library is imported here or by what it imports.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, field

from kittools import model, sweep
from kittools.model import MetricId, Results
from kittools.report import link_report
from kittools.sizes import symbols


@dataclass
class Budget:
    """Allowed growth against a baseline, per variant."""

    rom_pct: float = 2.0
    ram_pct: float = 2.0
    p99_pct: float = 10.0
    p99_floor_us: float = 2.0  # smaller changes of a p99 are never a regression
    floor_ratio_pct: float = 10.0  # the dispatch path against the kernel floor (kittools.suite.floor)

    def describe(self) -> str:
        return (f"ROM +{self.rom_pct:.1f}%, RAM +{self.ram_pct:.1f}%, p99 +{self.p99_pct:.0f}% above "
                f"{self.p99_floor_us:.0f} µs, latency over the kernel floor +{self.floor_ratio_pct:.0f}% allowed")


@dataclass(frozen=True)
class Change:
    """One metric of one variant that differs from the baseline (or breaks the budget)."""

    variant: str
    metric: MetricId
    before: float
    now: float
    verdict: str  # empty: within budget

    @property
    def delta(self) -> float:
        return self.now - self.before

    @property
    def pct(self) -> float:
        if self.before:
            return self.delta / self.before * 100
        return 0.0 if self.delta == 0 else float("inf")


@dataclass
class Verdict:
    changes: list[Change] = field(default_factory=list)
    violations: list[str] = field(default_factory=list)
    #: (variant, its symbols' diff against the baseline) where its ROM or RAM changed
    sizes: list[tuple[str, symbols.SizeDiff]] = field(default_factory=list)
    #: variants whose ROM or RAM broke the budget
    over_size: set[str] = field(default_factory=set)

    @property
    def passed(self) -> bool:
        return not self.violations


def _fmt(value: float) -> str:
    return f"{value:,.0f}" if float(value).is_integer() else f"{value:,.1f}"


def judge(metric: MetricId, before: float, now: float, budget: Budget) -> str:
    """Why this change breaks the budget, or '' if it does not."""
    delta = now - before
    pct = (delta / before * 100) if before else (0.0 if delta == 0 else float("inf"))
    if metric in (model.ROM, model.RAM):
        limit = budget.rom_pct if metric == model.ROM else budget.ram_pct
        if pct > limit:
            return f"over budget (+{pct:.1f}% > {limit}%)"
    elif metric.stat == "p99" and metric.unit == "us":
        if delta > budget.p99_floor_us and pct > budget.p99_pct:
            return f"regressed (+{pct:.1f}% > {budget.p99_pct}%)"
    elif metric == model.FLOOR_RATIO:
        if pct > budget.floor_ratio_pct:
            return f"dispatch slowed against the kernel floor (+{pct:.1f}% > {budget.floor_ratio_pct}%)"
    elif metric.quantity == "slips" and now > before:
        return "more slips"
    return ""


def check(data: Results, baseline: Results, budget: Budget | None = None) -> Verdict:
    """Every variant's metrics against the baseline's."""
    budget = budget or Budget()
    verdict = Verdict()
    for name in data.names():
        old = baseline.variants.get(name)
        if old is None:
            verdict.violations.append(f"{name}: not in the baseline")
            continue
        for metric in data.variants[name].metrics:
            now, before = data.variants[name].metric(metric), old.metric(metric)
            if now is None or before is None:
                continue
            why = judge(metric, before, now, budget)
            if why:
                verdict.violations.append(f"{name} {metric.label}: {_fmt(before)} -> {_fmt(now)}, {why}")
                if metric in (model.ROM, model.RAM):
                    verdict.over_size.add(name)
            if now != before or why:
                verdict.changes.append(Change(name, metric, before, now, why))
        verdict.violations += [f"{name} {v}" for v in earlier_breaks(data.variants[name], old)]
        # Which symbols moved: both tables floored alike (kittools.sizes.symbols)
        for kind in symbols.KINDS:
            table_now, table_before = data.variants[name].symbols.get(kind), old.symbols.get(kind)
            if table_now and table_before:
                sizes = symbols.diff(table_before, table_now, kind)
                if sizes.changed:
                    verdict.sizes.append((name, sizes))
    return verdict


def breaking_points(variant: model.Variant) -> dict[str, tuple[int | None, int]]:
    """Every breaking point a variant's records give, with the highest level
    swept: each rate group's on each sweep axis (the median play of a serial
    level), and the link's delivery on each command axis. None: it held
    through the sweep."""
    found: dict[str, tuple[int | None, int]] = {}
    parsed = sweep.of_records(variant.records)
    if parsed is not None:
        for axis in parsed.axes():
            for rg in parsed.rate_groups():
                found[f"{axis} load, {rg}"] = (parsed.breaking_point(axis, rg), parsed.max_load(axis))
    plays = link_report.serial_plays(variant)
    for axis in link_report.COMMAND_AXES:
        levels = [level for found_axis, level in plays if found_axis == axis]
        if levels:
            found[f"{axis} delivery"] = (link_report.delivery_breaking_point(plays, axis), max(levels))
    return found


def earlier_breaks(now: model.Variant, before: model.Variant) -> list[str]:
    """Where a breaking point comes at a lower level than in the baseline
    (a level the baseline's sweep did not reach cannot be earlier)."""
    found = []
    old = breaking_points(before)
    for name, (level, _) in breaking_points(now).items():
        if name not in old or level is None:
            continue
        was, swept = old[name]
        if (was is None and level <= swept) or (was is not None and level < was):
            said = f"held through the sweep to {swept}" if was is None else f"broke at {was}"
            found.append(f"breaking point, {name}: {level}, earlier than the baseline ({said})")
    return found


def of_options(args: argparse.Namespace) -> Budget:
    """The limits kit report and kit test were given (--rom-budget, --ram-budget, --p99-budget)."""
    return Budget(rom_pct=args.rom_budget, ram_pct=args.ram_budget, p99_pct=args.p99_budget)
