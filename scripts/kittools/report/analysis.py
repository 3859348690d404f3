# SPDX-License-Identifier: Apache-2.0
"""What the numbers say: findings, the load sweep's breaking points and
knees, and the guidance drawn from them. Every sentence is generated from
the results; nothing here draws or renders."""

from __future__ import annotations

from collections.abc import Callable

from kittools import model, sweep
from kittools.model import Results
from kittools.report.document import Table, Text, fmt, kib

#: The knee of a sweep: the first load at which the fastest group's p99 is this much over its zero-load value
KNEE_FACTOR = 1.1


def _against_first(values: dict[str, float], unit: str = "") -> str:
    """Each variant's value, the others with their difference to the first."""
    first = next(iter(values))
    parts = []
    for v, value in values.items():
        if v == first:
            parts.append(f"{v} {value:,.1f}{unit}")
        else:
            delta = value - values[first]
            parts.append(f"{v} {value:,.1f}{unit} ({delta:+,.1f}{unit})")
    return ", ".join(parts)


def findings(data: Results) -> Text:
    """'What the numbers say', generated from them: every variant, the others
    against the first (in name order)."""
    names = data.names()
    lines: list[str] = []
    if len(names) >= 2:
        first = names[0]
        for what, metric in (("ROM", model.ROM), ("static RAM", model.RAM)):
            values = {v: data.variants[v].metric(metric) for v in names}
            base = values[first]
            if base and all(x is not None for x in values.values()):
                for v in names[1:]:
                    delta = float(values[v] or 0) - base
                    more = "more" if delta >= 0 else "less"
                    lines.append(f"{v} uses {kib(abs(delta))} ({abs(delta) / base * 100:.1f}%) {more} {what} "
                                 f"than {first} ({kib(values[v] or 0)} vs {kib(base)}).")
        stacks = {v: data.variants[v].metric(model.STACKS_RESERVED) for v in names}
        if all(x is not None for x in stacks.values()):
            lines.append("Stacks reserved: " + ", ".join(f"{v} {fmt(x)} B" for v, x in stacks.items()) + ".")
        rate_groups = sorted({m.name for m in data.variants[first].metrics if m.quantity == "slips"})
        for rg in rate_groups:
            p99 = model.rg_metric(rg, "latency", "p99")
            latency = {v: data.variants[v].metric(p99) for v in names}
            if any(x is None for x in latency.values()):
                continue
            known = {v: float(x) for v, x in latency.items() if x is not None}
            lowest = min(known, key=lambda v: known[v])
            slipped = ", ".join(f"{v} {fmt(data.variants[v].metric(model.slips(rg)))}" for v in names)
            lines.append(f"{rg}: p99 dispatch latency {_against_first(known, ' µs')}: {lowest} is lowest; "
                         f"slips {slipped}.")
        for v in names:
            idle = [r for r in data.variants[v].of_kind("CPU") if r.get("name") == "idle"]
            if idle:
                lines.append(f"{v} idles {int(idle[0]['cpu_permille']) / 10:.1f}% of the run.")
    if data.conditions.get("run"):  # a board only built: no run, no verdict
        lines.append(f"{data.board}: {data.conditions['run']}.")
    else:
        verdicts = ", ".join(f"{v} {'PASS' if data.variants[v].passed else 'FAIL'}" for v in names)
        lines.append(f"Run verdicts: {verdicts}.")
    return Text("What the numbers say", lines)


def sweeps(data: Results) -> dict[str, sweep.Sweep]:
    """Each variant's background-load sweep, for those that have one."""
    found = {}
    for name in data.names():
        parsed = sweep.of_records(data.variants[name].records)
        if parsed is not None:
            found[name] = parsed
    return found


def fastest_period_us(data: Results) -> float:
    """Period of the fastest rate group, in µs: from its RG records (rate
    `hz`), so that any deployment's is its own (tests/team/Thermal's 50 Hz
    group: 20,000 µs); the tick's where a run has none."""
    rates = [float(r["hz"]) for name in data.names() for r in data.variants[name].of_kind("RG")
             if float(r.get("hz", 0) or 0) > 0]
    if rates:
        return 1e6 / max(rates)
    tick_hz = data.condition("tick_hz")
    return 1e6 / tick_hz if tick_hz > 0 else 0.0


def break_text(value: int | None, most: int, unit: str) -> str:
    """A breaking point, or how far the axis went without one."""
    if value is not None:
        return sweep.level_text(value, unit)
    return f"none up to {sweep.level_text(most, unit)}"


def knee(p99_us: list[float], series: list[sweep.Point]) -> int | None:
    """The first load at which the p99 is KNEE_FACTOR over its zero-load value."""
    return next((p.level for q, p in zip(p99_us, series, strict=True) if q > p99_us[0] * KNEE_FACTOR), None)


def switches_per_second(data: Results, variant: str) -> float | None:
    """Scheduling windows per second of the threads (KIT CPU runs, idle left
    out), when the variant's tasks are threads (TASK context=thread):
    cooperative slices of one loop are not context switches."""
    found = data.variants[variant]
    # A shared thread's members are in its own line's runs already
    records = [r for r in found.of_kind("CPU") if r.get("name") != "idle" and r.get("context") != "shared"]
    ticks, tick_hz = data.condition("run_ticks"), data.condition("tick_hz")
    if not records or ticks <= 0 or tick_hz <= 0 or found.context_kind() != "thread":
        return None
    return sum(int(r["runs"]) for r in records) / (ticks / tick_hz)


def sweep_guidance(data: Results, found: dict[str, sweep.Sweep]) -> Text:
    """What the sweep says, generated from its points."""
    cycles_hz = data.condition("cycles_hz")
    period = fastest_period_us(data)
    lines: list[str] = []
    for v in sorted(found):
        sw = found[v]
        fastest = sw.rate_groups()[0]
        for axis in sw.axes():
            unit = sw.unit(axis)
            # A load in µs of computation compares with the fastest period; a
            # traffic rate does not
            timed = unit == "us" and period > 0
            breaks = [(at_us, rg) for rg in sw.rate_groups() if (at_us := sw.breaking_point(axis, rg)) is not None]
            series = sw.series(axis, fastest)
            p99 = [p.latency_p99 * 1e6 / cycles_hz for p in series]
            at = knee(p99, series)
            grows = f"; its p99 latency starts to grow at {sweep.level_text(at, unit)}" if at is not None else ""
            if breaks:
                load, rg = min(breaks)
                before = [q for q, p in zip(p99, series, strict=True) if p.level < load]
                grow = (f", from {before[0]:.1f} µs to {before[-1]:.1f} µs just below the break"
                        if before and at is not None else "")
                share = f" ({load / period * 100:.0f}% of the {period:.0f} µs period)" if timed else ""
                lines.append(f"{v}, {axis} load: {rg} misses deadlines from {sweep.level_text(load, unit)}"
                             f"{share}{grows}{grow}.")
            else:
                most = sw.max_load(axis)
                times = f" ({most / period:.1f}x the fastest period)" if timed else ""
                lines.append(f"{v}, {axis} load: no rate group missed a deadline up to "
                             f"{sweep.level_text(most, unit)}{times}; "
                             f"{fastest} p99 latency stayed within {min(p99):.1f}-{max(p99):.1f} µs{grows}.")
        lines += [f"{v}: inconsistent sweep record: {text}" for text in sw.inconsistencies()]
    lines += policy_guidance(data, found)
    names = data.names()
    a = names[0] if names else ""
    for b in names[1:]:
        costs = []
        for what, metric in (("ROM", model.ROM), ("static RAM", model.RAM), ("reserved stack", model.STACKS_RESERVED)):
            va, vb = data.variants[a].metric(metric), data.variants[b].metric(metric)
            if va is not None and vb is not None:
                costs.append(f"{what} {vb - va:+,.0f} B")
        switches = switches_per_second(data, b)
        if switches is not None:
            costs.append(f"{switches:,.0f} context switches per second")
        if costs:
            lines.append(f"What {b} costs against {a} at zero load: {', '.join(costs)}.")
    return Text("Background load: what the sweep says", lines)


def policy_pairs(names: list[str]) -> list[tuple[str, str]]:
    """(model, the same model under another policy): a variant named
    <model>_<policy> (baremetal_budgeted) beside its model's."""
    return [(base, v) for v in names for base in names if v.startswith(base + "_")]


def policy_guidance(data: Results, found: dict[str, sweep.Sweep]) -> list[str]:
    """What a policy changes against its model's plain one, per load axis in
    µs, at the fastest rate group: where each breaks, what the policy shed
    to get there, and where no cooperative policy can help (a slice that
    does not fit the period)."""
    period = fastest_period_us(data)
    lines: list[str] = []
    for base, policy in policy_pairs(data.names()):
        if base not in found or policy not in found:
            continue
        plain, budgeted = found[base], found[policy]
        fastest = budgeted.rate_groups()[0]
        for axis in budgeted.axes():
            if axis not in plain.axes():
                continue
            unit = budgeted.unit(axis)
            at_plain, at_policy = plain.breaking_point(axis, fastest), budgeted.breaking_point(axis, fastest)
            most = budgeted.max_load(axis)
            if at_plain == at_policy and at_plain is None:
                moved = f"neither misses a deadline up to {sweep.level_text(most, unit)}"
            elif at_plain == at_policy:
                moved = f"both break at {sweep.level_text(at_plain, unit)}"
            else:
                moved = (f"{policy} holds it up to {break_text(at_policy, most, unit)} where {base} breaks at "
                         f"{break_text(at_plain, plain.max_load(axis), unit)}")
            shed = budgeted.shed(axis, fastest, at_policy)
            trade = ""
            if shed:
                trade = f"; to do so it shed {shed} load messages (its queue overflowed while it deferred them)"
            elif at_plain != at_policy:
                trade = "; it shed no load"
            limit = ""
            if unit == "us" and period > 0 and at_policy is not None and at_policy > period:
                limit = (f"; a slice of {period:.0f} µs or more fits no tick: a cooperative policy can only "
                         f"postpone it, and {policy} misses deadlines from {sweep.level_text(at_policy, unit)}")
            lines.append(f"{policy} against {base}, {axis} load, {fastest}: {moved}{trade}{limit}.")
    return lines


def _known(data: Results, metric: model.MetricId) -> dict[str, float]:
    """Each variant's value of a metric, for those that have it."""
    return {v: x for v in data.names() if (x := data.variants[v].metric(metric)) is not None}


def _leader(values: dict[str, float], show: Callable[[float], str]) -> str:
    """The variant(s) with the lowest value, then every other's value."""
    low = min(values.values())
    best = [v for v, x in values.items() if x == low]
    others = ", ".join(f"{v} {show(x)}" for v, x in values.items() if x != low)
    return f"{', '.join(best)} ({show(low)}{'; ' + others if others else ''})"


def choosing(data: Results, found: dict[str, sweep.Sweep]) -> Text:
    """Every model at once, on each thing a team weighs when it chooses one:
    which leads on this board, and the others' figures. Generated from the
    numbers; a model without a figure is left out of that line."""
    names = data.names()
    lines: list[str] = []
    if len(names) < 2:
        return Text("Choosing a model", lines)
    for what, metric in (("the least ROM", model.ROM), ("the least static RAM", model.RAM),
                         ("the least stack reserved", model.STACKS_RESERVED)):
        values = _known(data, metric)
        if len(values) >= 2:
            lines.append(f"For {what}: {_leader(values, kib)}.")
    groups = [r["name"] for r in data.variants[names[0]].of_kind("RG")]
    fastest = groups[0] if groups else ""
    floor = _known(data, model.FLOOR_RATIO)
    for stat, what in (("p50", "the shortest typical dispatch"), ("p99", "the shortest dispatch tail"),
                       ("max", "the shortest worst dispatch")):
        values = _known(data, model.rg_metric(fastest, "latency", stat))
        if len(values) < 2:
            continue
        line = f"For {what} of {fastest} at zero load ({stat} latency): {_leader(values, lambda x: f'{x:.1f} µs')}"
        if stat == "p50" and len(floor) >= 2:
            line += "; over the kernel floor: " + ", ".join(f"{v} {x:.1f}x" for v, x in floor.items())
        lines.append(line + ".")
    for axis in dict.fromkeys(a for v in sorted(found) for a in found[v].axes()):
        swept = {v: found[v] for v in sorted(found) if axis in found[v].axes()}
        if len(swept) < 2:
            continue
        unit = next(iter(swept.values())).unit(axis)
        breaks = {v: sw.breaking_point(axis, fastest) for v, sw in swept.items()}
        held = [v for v, at in breaks.items() if at is None]
        broke = {v: at for v, at in breaks.items() if at is not None}
        most = max(sw.max_load(axis) for sw in swept.values())
        if not broke:
            lines.append(f"{axis} load: every model holds {fastest} up to {sweep.level_text(most, unit)}.")
            continue
        others = ", ".join(f"{v} {sweep.level_text(at, unit)}" for v, at in broke.items())
        if held:
            lines.append(f"{axis} load: only {', '.join(held)} held {fastest} to the end of the sweep "
                         f"({sweep.level_text(most, unit)}); the others break at: {others}.")
        else:
            best = max(broke, key=lambda v: broke[v])
            lines.append(f"{axis} load: {best} holds {fastest} longest; they break at: {others}.")
        at_rest = [v for v, at in broke.items() if at == swept[v].series(axis, fastest)[0].level]
        if at_rest:
            lines.append(f"{axis} load: {', '.join(at_rest)} already miss {fastest}'s deadlines at the sweep's "
                         f"lowest load on this board.")
    lines += pair_guidance(data, found)
    return Text("Choosing a model: every model on each axis", lines)


def _held_longest(breaking_point: int | None) -> float:
    """Sort key: the model that breaks later first, one that never breaks before all."""
    return -float("inf") if breaking_point is None else -breaking_point


def pair_guidance(data: Results, found: dict[str, sweep.Sweep]) -> list[str]:
    """One sentence per pair of models: where each stops holding the fastest
    group on every load axis both swept, their tails at rest, and what the
    second costs against the first. A policy against its own model has its
    own sentences (policy_guidance)."""
    names = data.names()
    policies = set(policy_pairs(names))
    groups = [r["name"] for r in data.variants[names[0]].of_kind("RG")] if names else []
    fastest = groups[0] if groups else ""
    p99 = _known(data, model.rg_metric(fastest, "latency", "p99"))
    lines: list[str] = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if (a, b) in policies or (b, a) in policies:
                continue
            parts = []
            both = [x for x in found[a].axes() if x in found[b].axes()] if a in found and b in found else []
            for axis in both:
                unit = found[a].unit(axis)
                at = {v: found[v].breaking_point(axis, fastest) for v in (a, b)}
                most = max(found[a].max_load(axis), found[b].max_load(axis))
                if at[a] == at[b]:
                    same = (f"neither breaks up to {sweep.level_text(most, unit)}" if at[a] is None
                            else f"both break at {sweep.level_text(at[a], unit)}")
                    parts.append(f"{axis} load, {same}")
                    continue
                # the one that holds longer first: a missing break is the longest hold
                first, second = sorted((a, b), key=lambda v: _held_longest(at[v]))
                held = (f"through the sweep ({sweep.level_text(found[first].max_load(axis), unit)})"
                        if at[first] is None else f"up to {sweep.level_text(at[first], unit)}")
                parts.append(f"{axis} load, {first} holds {fastest} {held} where {second} breaks at "
                             f"{sweep.level_text(at[second] or 0, unit)}")
            if a in p99 and b in p99:
                parts.append(f"{fastest}'s p99 latency at rest {p99[b]:.1f} µs against {p99[a]:.1f} µs")
            costs = []
            for what, metric in (("ROM", model.ROM), ("static RAM", model.RAM),
                                 ("reserved stack", model.STACKS_RESERVED)):
                va, vb = data.variants[a].metric(metric), data.variants[b].metric(metric)
                if va is not None and vb is not None:
                    costs.append(f"{what} {vb - va:+,.0f} B")
            if costs:
                parts.append(f"{b} costs {', '.join(costs)}")
            if parts:
                lines.append(f"{b} against {a}: {'; '.join(parts)}.")
    return lines


#: Why an instance is a task (a thread or a cooperative task) in a model, or
#: what its passive form is: F´ 4.1's and fprime-baremetal's components as the
#: pinned versions have them (the kit's Kconfig help says the same)
TASK_REASONS = {
    "cmdDisp": "a passive form: fprime-baremetal's PassiveCmdDispatcher (baremetal_passive)",
    "events": "no passive form: F´'s EventManager is active only",
    "tlmSend": "no passive form: F´'s TlmChan and fprime-baremetal's TlmLinearChan are both active",
    "comQueue": "no passive form: F´'s ComQueue is active only",
    "load": "the kit's background load: a task by design",
}
#: ... and of every rate group, whatever the deployment names it (its RG records)
RATE_GROUP_REASON = "a passive form: F´'s PassiveRateGroup (baremetal_passive)"
#: CPU records that are not component tasks (rtos's "assert": rtos/AssertReport.cpp;
#: its "services" runs a band of levels' tasks, context=shared: rtos/Os/SharedThread.hpp)
NOT_COMPONENTS = ("idle", "main", "assert", "services")


def tasks_table(data: Results) -> Table | None:
    """Each component that is a task in some model, and what it is in each
    (a thread, a cooperative task, or passive: run in its caller), from the
    CPU records, with why it stays a task or what its passive form is."""
    names = data.names()
    kinds = {v: {r["name"]: r.get("context", "") for r in data.variants[v].of_kind("CPU")
                 if r.get("name") not in NOT_COMPONENTS} for v in names}
    components = sorted({c for found in kinds.values() for c in found})
    if not components:
        return None
    shown = {"thread": "thread", "slice": "cooperative task", "shared": "on the shared thread"}

    def cell(v: str, c: str) -> str:
        if not data.variants[v].of_kind("CPU"):
            return "-"  # no CPU records: nothing to say
        if c not in kinds[v]:
            return "passive (runs in its caller)"
        kind = kinds[v][c] or data.variants[v].context_kind() or "task"  # older records: the TASK lines say
        return shown.get(kind, kind)

    rate_groups = {r["name"] for v in names for r in data.variants[v].of_kind("RG")}

    def why(c: str) -> str:
        return RATE_GROUP_REASON if c in rate_groups else TASK_REASONS.get(c, "-")

    return Table("What runs as a task in each model, and why", ["component", *names, "why"],
                 [[c, *(cell(v, c) for v in names), why(c)] for c in components])
