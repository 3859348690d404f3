# SPDX-License-Identifier: Apache-2.0
"""The report's tables, built from the results (labels from kittools.model)."""

from __future__ import annotations

from typing import Any

from kittools import model, sweep
from kittools.build.conditions import SERVICES
from kittools.model import Results
from kittools.report.analysis import break_text, sweeps
from kittools.report.document import Table, Text, fmt
from kittools.sizes import by_layer, symbols
from kittools.suite.budget import Budget, Verdict

#: Symbols shown per variant and kind in the report's size diff (largest changes)
SYMBOL_ROWS = 25

#: The metrics of the boards-side-by-side table, before every rate group's p99 latency and slips
BOARD_METRICS = (model.ROM, model.RAM, model.STACKS_RESERVED, model.STACKS_USED, model.HEAP_FPRIME_PEAK,
                 model.FLOOR_RATIO)


def metrics_table(data: Results) -> Table:
    names = data.names()
    rows = []
    for metric in data.variants[names[0]].metrics:
        values = [data.variants[v].metric(metric) for v in names]
        row: list[Any] = [metric.label] + [v if v is not None else "" for v in values]
        if len(names) == 2 and values[0] is not None and values[1] is not None:
            row.append(values[1] - values[0])
        rows.append(row)
    columns = ["metric"] + names + ([f"{names[1]} − {names[0]}"] if len(names) == 2 else [])
    return Table("Side by side", columns, rows)


def modules_table(data: Results) -> Table | None:
    names = data.names()
    rom = {v: data.variants[v].modules.get("rom", {}) for v in names}
    ram = {v: data.variants[v].modules.get("ram", {}) for v in names}
    if not all(rom.values()):
        return None
    layers = list(rom[names[0]])
    rows: list[list[Any]] = [[layer] + [rom[v].get(layer, 0) for v in names] + [ram[v].get(layer, 0) for v in names]
                             for layer in layers]
    rows.append(["total"] + [sum(rom[v].values()) for v in names] + [sum(ram[v].values()) for v in names])
    return Table("ROM and RAM by module (bytes; Zephyr rom_report / ram_report, sorted into layers)",
                 ["module"] + [f"ROM {v}" for v in names] + [f"RAM {v}" for v in names], rows)


#: The layer of the ROM and RAM by module each of F´'s optional services is in
_SERVICE_LAYERS = {
    "CONFIG_KIT_SERVICE_CDH": by_layer.HEALTH_VERSION,
    "CONFIG_KIT_SERVICE_PARAMS": by_layer.FILE_HANDLING,
    "CONFIG_KIT_SERVICE_FILES": by_layer.FILE_HANDLING,
    "CONFIG_KIT_SERVICE_FILE_UPLINK": by_layer.FILE_HANDLING,
    "CONFIG_KIT_SERVICE_SEQUENCER": by_layer.SEQUENCER,
}


def services_sections(data: Results) -> list[Table | Text]:
    """Which of F´'s optional services each model carries, and for a model
    its board's profile leaves some out, why, in the run's numbers: its
    static RAM against the board's, and the RAM their layers take in a model
    that carries them. None for results recorded before the services were."""
    names = data.names()
    carried: dict[str, dict[str, bool]] = {v: data.variants[v].build.get("services") or {} for v in names}
    if not all(carried.values()):
        return []
    rows: list[list[Any]] = [[label] + ["yes" if carried[v].get(key) else "left out" for v in names]
                             for key, label in SERVICES]
    table = Table("F´'s services per model (a board's profile, boards/<board>/Kconfig.defconfig, leaves out what "
                  "its RAM cannot hold beside a model)", ["service"] + names, rows)
    why: list[str] = []
    for v in names:
        missing = [key for key, _ in SERVICES if not carried[v].get(key)]
        footprint = data.variants[v].footprint
        if not missing or not footprint.get("ram_size"):
            continue
        labels = ", ".join(label for key, label in SERVICES if key in missing)
        text = (f"{v} leaves out the {labels}: its static RAM is {footprint['ram']:,} B of {footprint['ram_size']:,} "
                f"({footprint['ram_size'] - footprint['ram']:,} B free).")
        # The model that carries the most of them, its layers' RAM against this one's
        others = [w for w in names if w != v and carried[w].get(missing[0])]
        if others:
            other = max(others, key=lambda w: sum(carried[w].get(key, False) for key in missing))
            layers = list(dict.fromkeys(_SERVICE_LAYERS[key] for key in missing))
            ram = {w: data.variants[w].modules.get("ram", {}) for w in (v, other)}
            more = [f"{layer} {ram[other].get(layer, 0) - ram[v].get(layer, 0):,} B" for layer in layers]
            text += (f" In {other}, which carries them, their layers take this much more RAM ({'; '.join(more)}), "
                     f"before what {v} adds for each: its thread's stack (app/Top/Tables.fpp) and its queue in "
                     f"the heap.")
        why.append(text)
    return [table, Text("Why a model leaves services out", why)] if why else [table]


def _cell(value: Any, key: str) -> Any:
    if value is None:
        return ""
    if key == "cpu_permille":
        return int(value) / 10
    try:
        return int(str(value), 0)
    except (TypeError, ValueError):
        return value


def record_table(data: Results, kind: str, title: str, columns: list[tuple[str, str]]) -> Table | None:
    rows = []
    for v in data.names():
        for r in data.variants[v].of_kind(kind):
            rows.append([v] + [_cell(r.get(key), key) for key, _ in columns])
    return Table(title, ["variant"] + [label for _, label in columns], rows) if rows else None


def record_tables(data: Results) -> list[Table]:
    """Tasks, CPU per execution context, stacks and the probe's cost, as recorded."""
    found = (
        record_table(data, "TASK", "Rate groups as tasks (counter cycles)",
                     [("name", "task"), ("context", "context"), ("runs", "runs"), ("exec_avg", "exec avg"),
                      ("exec_max", "exec max"), ("late", "late"), ("cpu_permille", "CPU %")]),
        record_table(data, "CPU", "CPU by execution context (threads, or cooperative slices of one loop, as the "
                                  "TASK context says)",
                     [("name", "context"), ("runs", "runs"), ("avg", "avg"), ("max", "max"),
                      ("cpu_permille", "CPU %")]),
        record_table(data, "STACK", "Stacks (bytes)", [("name", "stack"), ("size", "size"), ("used", "used")]),
        record_table(data, "PING", "Svc.Health's pings, round trip per entry (counter cycles, timed by the kit's "
                                   "probe on each connection; p50 and p99 over the last `held` pings, max over all; "
                                   "warn: health's WARNING_HI deadline, 3 of its 10 Hz cycles)",
                     [("name", "entry"), ("pings", "pings"), ("held", "held"), ("p50", "p50"), ("p99", "p99"),
                      ("max", "max"), ("warn", "warn")]),
        record_table(data, "SCHED", "The time-budgeted policy's task table (counter cycles; Betaflight's "
                                    "scheduler table: anticipated slice, turns deferred, slices run on an open tick "
                                    "though they did not fit, slices that ended after the next tick was due; the "
                                    "guard margin)",
                     [("name", "task"), ("critical", "critical"), ("anticipated", "anticipated"),
                      ("deferrals", "deferrals"), ("expedited", "expedited"), ("late", "late"), ("guard", "guard"),
                      ("guard_max", "guard max")]),
        record_table(data, "HEALTHBREAK", "Health's warning on the load axes: the first load at which a ping "
                                          "waited health's warning deadline for its answer (none: not on the "
                                          "axis), beside the rate groups' breaking points; the longest wait on "
                                          "the axis (counter cycles)",
                     [("axis", "axis"), ("level", "first level (us)"), ("ping_max", "longest wait"),
                      ("warn", "warning deadline")]),
        record_table(data, "PROBE", "Instrumentation cost (counter cycles per rate-group cycle)",
                     [("cycles_per_cycle", "cycles")]),
        record_table(data, "STAGE", "The fastest rate group's dispatch, stage by stage (counter cycles from the "
                                    "tick's stamp to its first member: the ISR's return and the loop or tick "
                                    "thread waking; the rate group driver and the group's port serializing the "
                                    "cycle; the queue's insert; the group's context picked, by a thread switch or "
                                    "the TaskRunner's pass; the queue's remove; deserializing and the group's "
                                    "handler up to its first member. Each stage is net of the probe mark that "
                                    "ends it; the STAGES line gives that cost)",
                     [("name", "stage"), ("cycles_min", "min"), ("cycles_p50", "p50"), ("cycles_p99", "p99"),
                      ("cycles_max", "max")]),
        record_table(data, "STAGES", "The stage probe (dispatches with every mark; marks per dispatch and one "
                                     "mark's measured cost, taken out of the stages and of the group's latency)",
                     [("rg", "rate group"), ("complete", "complete"), ("incomplete", "incomplete"),
                      ("marks", "marks"), ("mark_cycles", "cycles per mark")]),
        record_table(data, "FLOOR", "The kernel floor under each model's dispatch (tests/floor, counter cycles "
                                    "from the tick's stamp: wfi, a thread-less main loop waking from WFI; msgq, a "
                                    "thread woken by the tick handing it through a k_msgq to a less urgent one); "
                                    "the fastest rate group's latency over it is in the side-by-side table",
                     [("path", "path"), ("samples", "samples"), ("p50", "p50"), ("p99", "p99"), ("max", "max")]),
        record_table(data, "ZEPHYR", "Zephyr's own latency_measure benchmark, beside the threaded models (same "
                                     "board conditions; Zephyr's timing API over the same cycle counter, the "
                                     "benchmark's own timestamp overhead subtracted)",
                     [("metric", "metric"), ("description", "what"), ("cycles", "cycles"), ("ns", "ns")]),
    )
    return [t for t in found if t is not None]


def sizing_tables(data: Results) -> list[Table]:
    """Sizing advice and the ports' cost, per variant (kittools.sizes.sizing)."""
    names = [v for v in data.names() if data.variants[v].sizing]
    if not names:
        return []
    advice = [[v, t["table"], t["current"], t["needed"], t["unit_bytes"], t["spare_bytes"], t["verdict"],
               t["basis"], t["setting"]] for v in names for t in data.variants[v].sizing.get("tables", [])]
    port_rows = []
    for v in names:
        p = data.variants[v].sizing.get("ports") or {}
        if not p:
            continue
        port_rows.append([v, p["instances"], p["inputs"], p["input_bytes"], p["outputs"], p["output_bytes"],
                          round(p["input_bytes"] / p["inputs"], 1) if p["inputs"] else "",
                          round(p["output_bytes"] / p["outputs"], 1) if p["outputs"] else "",
                          p["object_bytes"],
                          f"{(p['input_bytes'] + p['output_bytes']) / p['object_bytes'] * 100:.1f}%"
                          if p["object_bytes"] else ""])
    return [
        Table("Sizing advice: fixed tables against what the dictionary and the run need (entries; bytes per entry "
              "and spare bytes cover every copy of a table; a queue's need is this run's high-water mark, not a "
              "bound)", ["variant", "table", "current", "needed", "B/entry", "spare B", "verdict", "basis",
                         "set in"], advice),
        Table("Ports: every declared port object of the topology's instances (static RAM, connected or not; "
              "sizes from the build's debug information)",
              ["variant", "instances", "input ports", "input B", "output ports", "output B", "B/input",
               "B/output", "instance objects B", "ports' share"], port_rows),
    ]


def budget_sections(verdict: Verdict, budget: Budget) -> list[Table | Text]:
    """The budget check's verdict and the changed metrics."""
    text = ([f"Budget check: PASS ({budget.describe()})."] if verdict.passed
            else ["Budget check: FAIL"] + verdict.violations)
    rows: list[list[Any]] = [[c.variant, c.metric.label, c.before, c.now, c.delta,
                              f"{c.pct:+.1f}%" if c.pct != float("inf") else "new", c.verdict]
                             for c in verdict.changes]
    sections: list[Table | Text] = [
        Text("Budget", text),
        Table("Against the baseline (changed metrics)",
              ["variant", "metric", "baseline", "now", "delta", "change", "budget"], rows)]
    for variant, sizes in verdict.sizes:
        changed = sizes.rows()
        names = symbols.demangle(d.key for d in changed[:SYMBOL_ROWS])
        sections.append(Table(
            f"{variant}: {sizes.kind.upper()} symbols against the baseline ({sizes.summary()}; symbols under "
            f"{symbols.SYMBOL_FLOOR} B summed per layer)",
            ["symbol", "baseline", "now", "delta"],
            [[names[d.key], d.before, d.now, d.delta] for d in changed[:SYMBOL_ROWS]]))
    return sections


def breaking_points_table(found: dict[str, sweep.Sweep]) -> Table:
    names = sorted(found)
    first = found[names[0]]
    rows = []
    for axis in dict.fromkeys(a for v in names for a in found[v].axes()):
        for rg in first.rate_groups():
            rows.append([axis, rg] + [break_text(found[v].breaking_point(axis, rg), found[v].max_load(axis),
                                                 found[v].unit(axis)) if axis in found[v].axes() else "not run"
                                      for v in names])
    return Table("Load sweeps: breaking points (smallest load at which a rate group missed a deadline)",
                 ["load axis", "rate group"] + names, rows)


def sweep_table(found: dict[str, sweep.Sweep], cycles_hz: float, axis: str) -> Table:
    names = sorted(found)
    fastest = found[names[0]].rate_groups()[0]
    loads = sorted({p.level for v in names for p in found[v].points if p.axis == axis})
    # A column of dropped load messages for a variant that dropped any here
    # (a policy that sheds load by design, or an overloaded queue)
    shedding = [v for v in names if found[v].shed(axis, fastest) > 0]
    rows = []
    for load in loads:
        row: list[Any] = [load]
        for v in names:
            at = {p.rate_group: p for p in found[v].points if p.axis == axis and p.level == load}
            point = at.get(fastest)
            spread = found[v].spread.get((axis, load, fastest))
            row += [point.latency_p99 * 1e6 / cycles_hz if point else "",
                    (f"{fmt(point.latency_max * 1e6 / cycles_hz)} ({fmt(spread[0] * 1e6 / cycles_hz)}–"
                     f"{fmt(spread[1] * 1e6 / cycles_hz)})" if point and spread else
                     point.latency_max * 1e6 / cycles_hz if point else ""),
                    ", ".join(rg for rg, p in at.items() if p.missed) or "-"]
            if v in shedding:
                row.append(point.shed if point else "")
        rows.append(row)
    unit = found[names[0]].unit(axis)
    columns = [f"load ({'µs' if unit == 'us' else unit})"]
    for v in names:
        plays = found[v].repeats(axis)
        columns += [f"{v} {fastest} p99 (µs)" + (f", median of {plays} plays" if plays > 1 else ""),
                    f"{v} {fastest} max (µs)" + (" (spread)" if plays > 1 else ""), f"{v} missed deadlines"]
        if v in shedding:
            columns.append(f"{v} load dropped")
    shape = next((text for v in names if (text := found[v].shape_text(axis))), "")
    return Table(f"Load sweep, axis '{axis}'" + (f" ({shape})" if shape else ""), columns, rows)


def boards_table(datas: list[Results]) -> Table:
    """The key metrics of every board and variant, side by side."""
    columns = [(d, v) for d in datas for v in d.names()]
    metrics = list(BOARD_METRICS)
    for d, v in columns:
        metrics += [m for m in d.variants[v].metrics
                    if ((m.quantity == "latency" and m.stat == "p99") or m.quantity == "slips") and m not in metrics]
    rows: list[list[Any]] = []
    for metric in metrics:
        values = [d.variants[v].metric(metric) for d, v in columns]
        rows.append([metric.label] + [value if value is not None else "" for value in values])
    found = [sweeps(d).get(v) for d, v in columns]
    axes = list(dict.fromkeys(a for sw in found if sw for a in sw.axes()))
    for axis in axes:
        for rg in next(sw for sw in found if sw).rate_groups():
            rows.append([f"breaking point, {axis} load, {rg}"] +
                        [break_text(sw.breaking_point(axis, rg), sw.max_load(axis), sw.unit(axis)) if sw else ""
                         for sw in found])
    return Table("Boards side by side", ["metric"] + [f"{d.board} {v}" for d, v in columns], rows)


def _profile_name(variant: str) -> str:
    """A variant as a results file names it, with its profile in words:
    small.baremetal_passive (a small part's build) is baremetal_passive with
    fprime-small; a plain name is the kit profile's."""
    profile, dot, name = variant.partition(".")
    return f"{name}, fprime-{profile}" if dot else f"{variant}, kit profile"


def fits_table(datas: list[Results]) -> Table | None:
    """What fits where: every build (model and profile) against every
    board's memory. A board that built it gives its own ROM and RAM (it
    linked: it fits); elsewhere the smallest measured build of it is set
    against the board's flash and RAM (an estimate: ROM differs a few %
    from board to board). None where no results file gives the memory."""
    capacity = {}
    for data in datas:
        sizes = [v.footprint for v in data.variants.values() if v.footprint.get("rom_size")]
        if sizes:
            capacity[data.board] = (sizes[0]["rom_size"], sizes[0]["ram_size"])
    if len(capacity) < 2:
        return None
    builds = list(dict.fromkeys(v for data in datas for v in data.variants))
    rows: list[list[Any]] = []
    for build in builds:
        measured = [(int(d.variants[build].metric(model.ROM) or 0), int(d.variants[build].metric(model.RAM) or 0))
                    for d in datas if build in d.variants]
        need_rom, need_ram = min(r for r, _ in measured), min(r for _, r in measured)
        row: list[Any] = [_profile_name(build)]
        for data in datas:
            if data.board not in capacity:
                continue
            rom_size, ram_size = capacity[data.board]
            own = data.variants.get(build)
            if own is not None:
                row.append(f"built: ROM {own.metric(model.ROM):,.0f} of {rom_size:,}, "
                           f"RAM {own.metric(model.RAM):,.0f} of {ram_size:,}")
                continue
            short = [f"{what} {need - have:,} B short" for what, need, have in
                     (("ROM", need_rom, rom_size), ("RAM", need_ram, ram_size)) if need > have]
            row.append("does not fit: " + ", ".join(short) if short else
                       f"fits (estimate: ROM {need_rom:,}, RAM {need_ram:,})")
        rows.append(row)
    return Table("What fits where (bytes; a build's ROM and RAM where the board built it, else the smallest "
                 "measured build against the board's memory)", ["build"] + [d.board for d in datas
                                                                         if d.board in capacity], rows)
