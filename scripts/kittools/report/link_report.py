# SPDX-License-Identifier: Apache-2.0
"""The report's ground-link sections: the line rate, what each serial level
delivered (every play), where delivery breaks, and the flood, from the
records kit test's ground checks add to a variant (LINE, SERIAL, FLOOD,
FLOODRG: kittools.link.serial_sweep, kittools.link.flood)."""

from __future__ import annotations

import statistics
from typing import Any

from kittools import sweep
from kittools.model import Results, Variant
from kittools.report.document import Table, Text, fmt

#: Axes whose delivery is NO_OPs the link passed to the dispatcher: the
#: baseline gate holds their delivery breaking points (kittools.suite.budget)
COMMAND_AXES = ("uplink", "noise")
#: Every axis whose delivery has a breaking point, with its unit. The file
#: axis' is reported, not gated: it is where FileDownlink's own cadence (a
#: file started at its 10 Hz Run, 100 ms between files, one queued) stops
#: keeping up, and which Run a host-timed SendPartial lands before moves it
DELIVERY_UNITS = {"uplink": "cmd/s", "noise": "%", "file": "B/s", "sequence": "cmd/s"}


def serial_plays(variant: Variant) -> dict[tuple[str, int], list[dict[str, Any]]]:
    """A variant's SERIAL records by (axis, level), every play of the level."""
    found: dict[tuple[str, int], list[dict[str, Any]]] = {}
    for record in variant.of_kind("SERIAL"):
        found.setdefault((str(record["axis"]), int(record["level"])), []).append(record)
    return found


def _plays(data: Results, variant: str) -> dict[tuple[str, int], list[dict[str, Any]]]:
    return serial_plays(data.variants[variant])


def line_text(data: Results) -> Text | None:
    """The line rate the serial axes and the flood were paced to."""
    lines = {(int(r["baud"]), int(r["bytes_per_s"])) for v in data.names() for r in data.variants[v].of_kind("LINE")}
    if not lines:
        return None
    said = ", ".join(f"{baud:,} baud ({per_s:,} B/s)" for baud, per_s in sorted(lines))
    return Text("The ground link's line rate", [
        f"Line rate: {said}, the link UART's devicetree current-speed. QEMU's UART takes host bytes with no baud "
        "timing: the kit paces what it sends by the deployment's own clock (its downlink's time tags), so the "
        "serial axes and the flood offer the line rate in the deployment's time. QEMU hands the bytes to the "
        "firmware only as fast as its emulated UART goes: the flood table gives the rate the UART read.",
        "Each serial level is played several times (host-timed bytes land at other instants each play): "
        "latencies are the median play with the spread of the plays; what a level offered is the same in every "
        "play, what it delivered is shown play by play."])


def serial_link_table(data: Results) -> Table | None:
    """Per serial level and variant: what each play delivered of what it
    offered, and the bytes the UART driver's ring dropped."""
    names = data.names()
    found = {v: _plays(data, v) for v in names}
    keys = sorted({k for v in names for k in found[v]}, key=lambda k: (k[0], k[1]))
    if not keys:
        return None
    rows: list[list[Any]] = []
    for axis, level in keys:
        row: list[Any] = [axis, level]
        for v in names:
            plays = found[v].get((axis, level), [])
            offered = {int(p["offered"]) for p in plays}
            row += [f"{'/'.join(str(p['delivered']) for p in plays)} of {'/'.join(map(str, sorted(offered)))}"
                    if plays else "",
                    "/".join(str(p.get("ring_drops", 0)) for p in plays)]
        rows.append(row)
    columns = ["axis", "level"]
    for v in names:
        columns += [f"{v} delivered (each play)", f"{v} ring drops (B)"]
    return Table("Serial load: what the link delivered, play by play (uplink, noise: NO_OPs the link passed to the "
                 "dispatcher; downlink: packets the ground received, by their numbers; file: file data bytes the "
                 "ground received of those SendPartial asked for; sequence: commands the sequencer ran of those "
                 "in the runs the ground asked for; ring drops: bytes the UART driver's receive ring had no room "
                 "for)", columns, rows)


def delivery_breaking_point(plays: dict[tuple[str, int], list[dict[str, Any]]], axis: str) -> int | None:
    """The lowest level of an axis where the median play lost more than
    sweep.HOST_TIMED_SHARE of what it offered (and at least one)."""
    for (found_axis, level), records in sorted(plays.items()):
        if found_axis != axis:
            continue
        lost = statistics.median_low(int(r["lost"]) for r in records)
        offered = max(int(r["offered"]) for r in records)
        if lost > sweep.HOST_TIMED_SHARE * offered:
            return level
    return None


def delivery_table(data: Results) -> Table | None:
    """Where each model's link starts to lose commands, per command axis."""
    names = data.names()
    found = {v: _plays(data, v) for v in names}
    axes = [a for a in DELIVERY_UNITS if any(k[0] == a for v in names for k in found[v])]
    if not axes:
        return None
    rows = []
    for axis in axes:
        points = [delivery_breaking_point(found[v], axis) for v in names]
        rows.append([axis] + [f"{p} {DELIVERY_UNITS[axis]}" if p is not None else "held" for p in points])
    return Table(f"Delivery breaking point: the lowest level where the median play lost more than "
                 f"{sweep.HOST_TIMED_SHARE:.0%} of what it offered (commands; the file axis: file bytes asked for; "
                 f"every play's count is below)", ["axis"] + names, rows)


def flood_table(data: Results) -> Table | None:
    """The flood, per variant: the line, where every byte went, the NO_OPs
    after it, and each rate group's slips and worst latency during it."""
    names = [v for v in data.names() if data.variants[v].of_kind("FLOOD")]
    if not names:
        return None
    cycles_hz = data.condition("cycles_hz")
    floods = {v: data.variants[v].of_kind("FLOOD")[0] for v in names}
    groups = {v: {str(r["rg"]): r for r in data.variants[v].of_kind("FLOODRG")} for v in names}
    fields = [("seconds of noise", "seconds"), ("line rate (baud)", "baud"),
              ("bytes a second the UART read", "received_per_s"), ("bytes sent", "bytes_sent"),
              ("read by the UART", "uart_received"), ("dropped by its ring", "ring_drops"),
              ("UART receive errors", "uart_errors"), ("discarded by the frame detector", "discarded"),
              ("bad checksums", "bad_checksums"), ("bytes of whole frames", "frame_bytes"),
              ("unaccounted", "unaccounted"), ("NO_OPs after the flood answered", "noops_answered")]
    rows: list[list[Any]] = [[label] + [_number(floods[v].get(key, "")) for v in names] for label, key in fields]
    for rg in dict.fromkeys(rg for v in names for rg in groups[v]):
        rows.append([f"{rg} slips (share of its cycles)"] + [_slips(groups[v][rg]) if rg in groups[v] else ""
                                                            for v in names])
        rows.append([f"{rg} latency max (µs)"] + [
            fmt(int(groups[v][rg]["latency_max"]) * 1e6 / cycles_hz) if rg in groups[v] and cycles_hz > 0 else ""
            for v in names])
    return Table("The flood: noise at the full line rate, then NO_OPs (every byte accounted for: read by the UART, "
                 "then dropped by its ring or decided on by the frame detector)", ["quantity"] + names, rows)


def _slips(record: dict[str, Any]) -> str:
    """A group's slips during the flood, with their share of the cycles it
    should have run (a 1 kHz group and a 10 Hz one compare by share)."""
    slips, expected = int(record["slips"]), int(record.get("expected", 0))
    return f"{slips} ({slips / expected:.2%})" if expected > 0 else str(slips)


def _number(value: Any) -> Any:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return value
    return int(number) if number.is_integer() else number


def sections(data: Results) -> list[Table | Text]:
    """Every ground-link section the results hold, in reading order."""
    found = [line_text(data), delivery_table(data), serial_link_table(data), flood_table(data)]
    return [s for s in found if s is not None]
