# SPDX-License-Identifier: Apache-2.0
"""The results model: what a results file holds (docs/results.md), typed.

Metrics are keyed by structured identifiers (MetricId, written in the file as
dotted keys such as ``rg.rg1kHz.latency.p99_us``); what a reader sees for one
is its label, from the one table here (LABELS). Nothing parses a label.

No plotting or templating library is imported here (the budget gate uses it).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

SCHEMA_VERSION = 2

#: Units of a metric, and how a label names them
UNITS = {"bytes": "bytes", "us": "us", "count": "", "pct": "%", "x": "x"}
#: Statistics of a distribution metric
STATS = ("p50", "p99", "max")
#: Per-rate-group quantities measured as distributions (RG records' field prefixes)
RG_QUANTITIES = ("latency", "exec", "jitter")


@dataclass(frozen=True, order=True)
class MetricId:
    """One metric: `group` (footprint, heap, stacks, rg, task), `name` (what
    in the group: rom, ram, … or a rate group), `quantity` (latency, exec,
    jitter, slips, cpu; empty when the name says it all), `stat` (p50, p99,
    max; empty for a single value) and `unit` (bytes, us, count, pct)."""

    group: str
    name: str
    quantity: str = ""
    stat: str = ""
    unit: str = "count"

    @property
    def key(self) -> str:
        """The metric's key in a results file: group.name[.quantity].[stat_]unit"""
        parts = [self.group, self.name] + ([self.quantity] if self.quantity else [])
        return ".".join(parts + [f"{self.stat}_{self.unit}" if self.stat else self.unit])

    @classmethod
    def parse(cls, key: str) -> MetricId:
        parts = key.split(".")
        if len(parts) not in (3, 4) or not all(parts):
            raise ValueError(f"not a metric key: {key!r}")
        stat, _, unit = parts[-1].rpartition("_")
        if unit not in UNITS or (stat and stat not in STATS):
            raise ValueError(f"not a metric key: {key!r} (unit '{unit}', stat '{stat}')")
        return cls(parts[0], parts[1], parts[2] if len(parts) == 4 else "", stat, unit)

    @property
    def label(self) -> str:
        return label(self)

    def __str__(self) -> str:
        return self.key


ROM = MetricId("footprint", "rom", unit="bytes")
RAM = MetricId("footprint", "ram", unit="bytes")
HEAP_FPRIME_PEAK = MetricId("heap", "fprime_peak", unit="bytes")
HEAP_REQUESTED = MetricId("heap", "requested", unit="bytes")
HEAP_LINK = MetricId("heap", "link_buffers", unit="bytes")
HEAP_ARENA_LEFT = MetricId("heap", "arena_left", unit="bytes")
#: QueueOverflow events of the ground link's ComQueue in the run (throttled:
#: one per spell of a full queue, not one per packet lost)
LINK_QUEUE_OVERFLOWS = MetricId("link", "queue_overflows")
STACKS_RESERVED = MetricId("stacks", "reserved", unit="bytes")
STACKS_USED = MetricId("stacks", "used_peak", unit="bytes")


def rg_metric(rate_group: str, quantity: str, stat: str) -> MetricId:
    """A rate group's latency, exec or jitter (period error) statistic, in µs."""
    return MetricId("rg", rate_group, quantity, stat, "us")


def slips(rate_group: str) -> MetricId:
    return MetricId("rg", rate_group, "slips", unit="count")


def cpu_share(task: str) -> MetricId:
    return MetricId("task", task, "cpu", unit="pct")


def floor_latency(stat: str) -> MetricId:
    """The kernel floor of the model's dispatch path (kittools.suite.floor), in µs."""
    return MetricId("floor", "kernel", "latency", stat, "us")


def stage_latency(stage: str, stat: str) -> MetricId:
    """One stage of the fastest rate group's dispatch (KIT STAGE, net of the
    probe's own cost), in µs."""
    return MetricId("stage", stage, "", stat, "us")


#: The fastest rate group's latency p50 over its path's kernel floor p50
FLOOR_RATIO = MetricId("floor", "fastest_rg", "ratio", "p50", "x")


# The labels, all in one place: fixed metrics by id, per-group ones by quantity
LABELS: dict[MetricId, str] = {
    ROM: "ROM (bytes)",
    RAM: "RAM, static (bytes)",
    HEAP_FPRIME_PEAK: "heap, F´ allocator peak (bytes)",
    HEAP_REQUESTED: "heap, all users (bytes requested)",
    HEAP_LINK: "heap, ground link's buffers and queues (bytes, part of the F´ allocator's)",
    HEAP_ARENA_LEFT: "heap, arena left after start-up (bytes, largest free block)",
    LINK_QUEUE_OVERFLOWS: "ground link's downlink queue overflows (F´'s ComQueue events)",
    STACKS_RESERVED: "stacks reserved (bytes)",
    STACKS_USED: "stacks used, peak (bytes)",
    **{floor_latency(stat): f"kernel floor of its dispatch path, latency {stat} (us)" for stat in STATS},
    FLOOR_RATIO: "fastest rate group's latency p50 over that floor's p50 (x)",
}
QUANTITY_LABELS = {"latency": "latency", "exec": "exec", "jitter": "period error", "slips": "slips",
                   "cpu": "CPU share"}


def label(metric: MetricId) -> str:
    """What a reader sees for a metric: 'ROM (bytes)', 'rg1kHz latency p99 (us)'."""
    if metric in LABELS:
        return LABELS[metric]
    if metric.group == "stage":
        return f"fastest rate group's dispatch, stage {metric.name.replace('_', ' ')}, {metric.stat} (us)"
    words = [metric.name, QUANTITY_LABELS.get(metric.quantity, metric.quantity), metric.stat]
    unit = UNITS.get(metric.unit, metric.unit)
    return " ".join(w for w in words if w) + (f" ({unit})" if unit else "")


#: What a baseline keeps of a variant's records: the load sweep's points and
#: breaks (SWEEP and BREAK on the load scenario's axes, app/scenarios/load.cpp),
#: which the budget's breaking points are read from (budget.earlier_breaks).
#: Played under icount, they repeat exactly. The ground link's serial axes
#: do not: QEMU's UART takes the host's bytes at the host's pace, so what a
#: level delivers and where a group slips move from run to run; the report
#: shows them, the budget does not hold them.
BASELINE_AXES = ("slice", "burst")
BASELINE_RECORD_KINDS = ("SWEEP", "BREAK")


def held_by_baseline(record: dict[str, str]) -> bool:
    return record.get("kind") in BASELINE_RECORD_KINDS and record.get("axis") in BASELINE_AXES


@dataclass
class Variant:
    """One variant's results on one board."""

    passed: bool
    metrics: dict[MetricId, float]
    records: list[dict[str, str]] = field(default_factory=list)
    build: dict[str, Any] = field(default_factory=dict)
    modules: dict[str, dict[str, int]] = field(default_factory=dict)
    footprint: dict[str, int] = field(default_factory=dict)
    #: rom/ram -> symbol -> bytes (kittools.sizes.symbols; smaller symbols summed per layer)
    symbols: dict[str, dict[str, int]] = field(default_factory=dict)
    #: kittools.sizes.sizing: tables against the dictionary and the run, and the ports' cost
    sizing: dict[str, Any] = field(default_factory=dict)

    def metric(self, metric: MetricId) -> float | None:
        value = self.metrics.get(metric)
        return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else None

    def of_kind(self, kind: str) -> list[dict[str, str]]:
        return [r for r in self.records if r.get("kind") == kind]

    def rate_groups(self) -> list[str]:
        """The rate groups the metrics cover, fastest first (as measured)."""
        return list(dict.fromkeys(m.name for m in self.metrics if m.group == "rg"))

    def context_kind(self) -> str | None:
        """How the variant runs its tasks, as its TASK records say (`context`):
        'thread' (each task a thread, switched by the scheduler) or 'slice'
        (cooperative slices of one loop); None when they do not say."""
        kinds = {r["context"] for r in self.of_kind("TASK") if r.get("context")}
        return kinds.pop() if len(kinds) == 1 else None

    def to_json(self, with_records: bool = True) -> dict[str, Any]:
        """Its JSON; without records, a baseline's: only the records the
        budget's breaking points come from (held_by_baseline)."""
        out: dict[str, Any] = {"passed": self.passed, "build": self.build, "modules": self.modules,
                               "footprint": self.footprint, "metrics": {m.key: v for m, v in self.metrics.items()}}
        if self.sizing:
            out["sizing"] = self.sizing
        if self.symbols:
            out["symbols"] = self.symbols
        if with_records:
            out["records"] = self.records
        else:
            out["records"] = [r for r in self.records if held_by_baseline(r)]
        return out


@dataclass
class Results:
    """A results file: the conditions of the run and every variant's results."""

    conditions: dict[str, str]
    variants: dict[str, Variant]

    @property
    def board(self) -> str:
        return str(self.conditions.get("board", "?"))

    def names(self) -> list[str]:
        return sorted(self.variants)

    def condition(self, key: str) -> float:
        """A numeric condition (tick_hz, cycles_hz, run_ticks), 0 when absent."""
        try:
            return float(self.conditions.get(key, 0) or 0)
        except ValueError:
            return 0.0

    def to_json(self, with_records: bool = True) -> dict[str, Any]:
        """The results file (docs/results.md); without records: a baseline."""
        return {"schema_version": SCHEMA_VERSION, "conditions": self.conditions,
                "variants": {name: v.to_json(with_records) for name, v in self.variants.items()}}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Results:
        """From a results file's JSON of the current schema (results.load checks and upgrades)."""
        variants = {}
        for name, v in data["variants"].items():
            variants[name] = Variant(
                passed=bool(v.get("passed")),
                metrics={MetricId.parse(k): value for k, value in v["metrics"].items()},
                records=[{k: str(x) for k, x in r.items()} for r in v.get("records") or []],
                build=dict(v.get("build") or {}), modules=dict(v.get("modules") or {}),
                footprint=dict(v.get("footprint") or {}),
                symbols={kind: {str(k): int(n) for k, n in table.items()}
                         for kind, table in (v.get("symbols") or {}).items()},
                sizing=dict(v.get("sizing") or {}))
        return cls({k: str(x) for k, x in data["conditions"].items()}, variants)


# Schema 1 keyed metrics by their labels; an upgrade reads them back once
_V1_RG = re.compile(r"^(?P<rg>\S+) (?P<quantity>latency|exec|period error) (?P<stat>p50|p99|max) \(us\)$")
_V1_OTHER = re.compile(r"^(?P<name>\S+) (?:(?P<slips>slips)|CPU share \(%\))$")


def metric_of_v1_label(text: str) -> MetricId:
    """The metric a schema-1 results file named `text`; ValueError if none."""
    fixed = {v: k for k, v in LABELS.items()}
    if text in fixed:
        return fixed[text]
    match = _V1_RG.match(text)
    if match:
        quantity = "jitter" if match["quantity"] == "period error" else match["quantity"]
        return rg_metric(match["rg"], quantity, match["stat"])
    match = _V1_OTHER.match(text)
    if match:
        return slips(match["name"]) if match["slips"] else cpu_share(match["name"])
    raise ValueError(f"unknown schema-1 metric {text!r}")


def upgrade_v1(data: dict[str, Any]) -> dict[str, Any]:
    """A schema-1 results file's JSON in schema 2 (metric keys; values unchanged)."""
    out = {**data, "schema_version": SCHEMA_VERSION, "variants": {}}
    for name, variant in data["variants"].items():
        metrics = {metric_of_v1_label(k).key: v for k, v in variant["metrics"].items()}
        out["variants"][name] = {**variant, "metrics": metrics}
    return out
