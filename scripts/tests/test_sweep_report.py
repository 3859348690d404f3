# SPDX-License-Identifier: Apache-2.0
"""The load sweep in the report: parsed from SWEEP/BREAK records, breaking
points computed and cross-checked, plots and guidance generated."""

import json
from pathlib import Path

import pytest

from kittools import console, metrics, model, sweep
from kittools.link import client, services
from kittools.link.dictionary import Dictionary
from kittools.report import analysis, conditions, link_report, writer
from kittools.sizes.memory import Footprint

from sample_console import console_log

CYCLES_PER_US = 12  # the sample console's 12 MHz counter


def sweep_lines(variant: str, breaks_at: int | None, say_break: int | None | str = "same") -> list[str]:
    """A slice sweep 0..2000 µs in 500 µs steps: the fast group's latency grows
    with the load in the cooperative variant and misses deadlines from
    `breaks_at`; the BREAK line says `say_break` ("same": the truth)."""
    lines = []
    for point, load in enumerate(range(0, 2001, 500)):
        for rg, hz in (("rg1kHz", 1000), ("rg100Hz", 100)):
            latency_us = 60 + (load // 2 if variant == "baremetal" and rg == "rg1kHz" else 0)
            missed = breaks_at is not None and rg == "rg1kHz" and load >= breaks_at
            lines.append(
                f"KIT SWEEP axis=slice point={point} level={load} unit=us burst=0 rg={rg} hz={hz} cycles=200 "
                f"expected=200 slips={20 if missed else 0} late_starts=0 latency_p99={latency_us * CYCLES_PER_US} "
                f"latency_max={(latency_us + 5) * CYCLES_PER_US} jitter_p99=12 jitter_max=24 exec_max=200 "
                "load_runs=20 load_dropped=0")
    said = breaks_at if say_break == "same" else say_break
    lines.append(f"KIT BREAK axis=slice rg=rg1kHz level={'none' if said is None else said} unit=us")
    lines.append("KIT BREAK axis=slice rg=rg100Hz level=none unit=us")
    return lines


def results(baremetal_says: int | None | str = "same", with_sweep: bool = True) -> model.Results:
    def data(variant: str, rom: int, ram: int, breaks_at: int | None, says: int | None | str) -> metrics.VariantData:
        text = console_log(variant)
        if with_sweep:
            text += "\n" + "\n".join(sweep_lines(variant, breaks_at, says))
        return metrics.VariantData(variant, Footprint(rom, ram, 262144, 65536), console.parse(text))
    return metrics.results([data("baremetal", 96000, 30000, 1000, baremetal_says),
                            data("rtos", 102000, 42000, None, "same")])


def test_points_and_breaking_points_come_from_the_records():
    data = results()
    parsed = sweep.of_records(data.variants["baremetal"].records)
    assert parsed is not None
    assert parsed.axes() == ["slice"] and parsed.rate_groups() == ["rg1kHz", "rg100Hz"]
    assert [p.level for p in parsed.series("slice", "rg1kHz")] == [0, 500, 1000, 1500, 2000]
    assert parsed.breaking_point("slice", "rg1kHz") == 1000
    assert parsed.breaking_point("slice", "rg100Hz") is None
    assert parsed.inconsistencies() == []


def test_a_break_line_that_disagrees_with_the_points_is_reported():
    data = results(baremetal_says=1500)
    parsed = sweep.of_records(data.variants["baremetal"].records)
    assert parsed.inconsistencies() == ["slice rg1kHz: BREAK says 1500 µs, the points say 1000 µs"]
    guidance = analysis.sweep_guidance(data, analysis.sweeps(data))
    assert "baremetal: inconsistent sweep record: slice rg1kHz: BREAK says 1500 µs, the points say 1000 µs" \
        in guidance.lines


def test_guidance_is_generated_from_the_numbers():
    data = results()
    lines = analysis.sweep_guidance(data, analysis.sweeps(data)).lines
    assert lines[0] == ("baremetal, slice load: rg1kHz misses deadlines from 1000 µs (100% of the 1000 µs period); "
                        "its p99 latency starts to grow at 500 µs, from 60.0 µs to 310.0 µs just below the break.")
    assert lines[1] == ("rtos, slice load: no rate group missed a deadline up to 2000 µs (2.0x the fastest "
                        "period); rg1kHz p99 latency stayed within 60.0-60.0 µs.")
    assert lines[-1] == ("What rtos costs against baremetal at zero load: ROM +6,000 B, static RAM +12,000 B, "
                         "reserved stack +0 B, 1,000 context switches per second.")


def test_choosing_puts_every_model_on_each_axis(tmp_path):
    data = results()
    lines = analysis.choosing(data, analysis.sweeps(data)).lines
    assert "For the least ROM: baremetal (93.8 KiB; rtos 99.6 KiB)." in lines
    assert "For the least stack reserved: baremetal, rtos (2.0 KiB)." in lines  # a tie names both
    assert ("slice load: only rtos held rg1kHz to the end of the sweep (2000 µs); the others break at: "
            "baremetal 1000 µs.") in lines
    writer.write(data, tmp_path)
    assert "## Choosing a model: every model on each axis" in (tmp_path / "report.md").read_text()


def test_choosing_compares_every_pair_of_models_from_the_numbers():
    data = results()
    lines = analysis.choosing(data, analysis.sweeps(data)).lines
    p99 = {v: data.variants[v].metric(model.rg_metric("rg1kHz", "latency", "p99")) for v in ("baremetal", "rtos")}
    assert (f"rtos against baremetal: slice load, rtos holds rg1kHz through the sweep (2000 µs) where baremetal "
            f"breaks at 1000 µs; rg1kHz's p99 latency at rest {p99['rtos']:.1f} µs against {p99['baremetal']:.1f} µs; "
            "rtos costs ROM +6,000 B, static RAM +12,000 B, reserved stack +0 B.") in lines


def test_a_policy_against_its_own_model_is_not_compared_twice():
    assert analysis.pair_guidance(results(), {}) != []  # two models: one pair
    data = results()
    data.variants["baremetal_budgeted"] = data.variants.pop("rtos")
    assert analysis.pair_guidance(data, {}) == []


def test_the_tasks_table_says_what_each_model_runs_as_a_task_and_why():
    data = results()
    table = analysis.tasks_table(data)
    assert table is not None and table.columns == ["component", "baremetal", "rtos", "why"]
    rows = {row[0]: row[1:] for row in table.rows}
    assert "idle" not in rows and "main" not in rows
    for component, (bare, rtos, why) in rows.items():
        assert bare == "cooperative task" and rtos == "thread", component
        expected = (analysis.RATE_GROUP_REASON if component.startswith("rg")
                    else analysis.TASK_REASONS.get(component, "-"))
        assert why == expected, component
    # rtos without its rate group's task: passive there
    data.variants["rtos"].records = [r for r in data.variants["rtos"].records
                                     if not (r["kind"] == "CPU" and r.get("name") == "rg1kHz")]
    rows = {row[0]: row[1:] for row in analysis.tasks_table(data).rows}
    assert rows["rg1kHz"][:2] == ["cooperative task", "passive (runs in its caller)"]


def test_a_task_on_the_shared_thread_says_so_and_counts_no_switches_of_its_own():
    data = results()
    found = data.variants["rtos"]
    switches = analysis.switches_per_second(data, "rtos")
    cpu = [r for r in found.records if r["kind"] == "CPU" and r.get("name") not in ("idle", "main")]
    assert cpu, "the fixture's rtos has component threads"
    member = dict(cpu[0], context="shared", runs="1000")
    found.records = [*found.records, dict(cpu[0], name="services"), member]
    found.records.remove(cpu[0])
    rows = {row[0]: row[1:] for row in analysis.tasks_table(data).rows}
    assert rows[member["name"]][1] == "on the shared thread"
    assert "services" not in rows  # the thread is not a component
    # The member's runs are in the shared thread's own line: counted once
    assert analysis.switches_per_second(data, "rtos") == switches


def test_choosing_says_which_model_misses_with_nothing_added():
    data = results()
    found = analysis.sweeps(data)
    text = console_log("rtos") + "\n" + "\n".join(sweep_lines("baremetal", 0))
    found["rtos"] = sweep.of_records([{"kind": r.kind, **r.fields} for r in console.parse(text).records])
    lines = analysis.choosing(data, found).lines
    assert "slice load: baremetal holds rg1kHz longest; they break at: baremetal 1000 µs, rtos 0 µs." in lines
    assert "slice load: rtos already miss rg1kHz's deadlines at the sweep's lowest load on this board." in lines


def test_the_report_has_the_breaking_points_the_plot_and_the_table(tmp_path):
    writer.write(results(), tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert "| slice | rg1kHz | 1000 µs | none up to 2000 µs |" in markdown
    assert "## Latency versus load, axis 'slice'" in markdown
    assert "| 1,000 | 560 | 565 | rg1kHz | 60 | 65 | - |" in markdown
    assert "sweep slice rg1kHz load 1000 us latency p99 (cycles)" in (tmp_path / "report.csv").read_text()
    assert "http" not in (tmp_path / "report.html").read_text().split("<body", 1)[1]


def test_no_sweep_section_without_sweep_records(tmp_path):
    writer.write(results(with_sweep=False), tmp_path)
    assert "Load sweep" not in (tmp_path / "report.md").read_text()


def test_several_boards_are_reported_side_by_side(tmp_path):
    first = results()
    second = results()
    second.conditions["board"] = "mps2/an385"
    outcome = writer.write_boards([first, second], tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert "| metric | qemu_cortex_m3 baremetal | qemu_cortex_m3 rtos | mps2/an385 baremetal | mps2/an385 rtos |" \
        in markdown
    assert "| breaking point, slice load, rg1kHz | 1000 µs | none up to 2000 µs | 1000 µs | none up to 2000 µs |" \
        in markdown
    assert "## mps2/an385: Background load: what the sweep says" in markdown
    assert (tmp_path / "report.csv").read_text().count("mps2/an385 rtos,ROM (bytes)") == 1
    assert outcome.violations == []


def test_a_serial_axis_is_reported_in_its_own_unit(tmp_path):
    """The ground link's axes (kittools.link.serial_sweep) share the records and
    the report with the load axes, each in its unit."""
    data = results()
    uplink = [f"KIT SWEEP axis=uplink point={point} level={rate} unit=cmd/s burst=0 rg={rg} hz={hz} cycles=1000 "
              f"expected=1000 slips={20 if rate >= 200 and rg == 'rg1kHz' else 0} late_starts=0 latency_p99=720 "
              "latency_max=900 jitter_p99=12 jitter_max=24 exec_max=200 load_runs=100 load_dropped=0"
              for point, rate in enumerate((0, 100, 200)) for rg, hz in (("rg1kHz", 1000), ("rg100Hz", 100))]
    uplink.append("KIT SERIAL axis=uplink point=2 level=200 repeat=0 offered=300 delivered=290 lost=10 "
                  "bytes_sent=5400 uart_received=5400 ring_drops=180 uart_errors=0")
    for variant in ("baremetal", "rtos"):
        data.variants[variant].records += [{"kind": r.kind, **r.fields} for line in uplink
                                           if (r := console.parse_line(line)) is not None]
    parsed = sweep.of_records(data.variants["rtos"].records)
    assert parsed is not None and parsed.axes() == ["slice", "uplink"]
    assert parsed.unit("uplink") == "cmd/s" and parsed.breaking_point("uplink", "rg1kHz") == 200
    writer.write(data, tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert "| uplink | rg1kHz | 200 cmd/s | 200 cmd/s |" in markdown
    assert "| uplink | rg100Hz | none up to 200 cmd/s | none up to 200 cmd/s |" in markdown
    assert "| load (cmd/s) |" in markdown
    assert "| uplink | 200 | 290 of 300 | 180 | 290 of 300 | 180 |" in markdown
    assert "| uplink | 200 cmd/s | 200 cmd/s |" in markdown  # where delivery breaks
    lines = analysis.sweep_guidance(data, analysis.sweeps(data)).lines
    assert "rtos, uplink load: rg1kHz misses deadlines from 200 cmd/s." in lines


def test_a_serial_level_played_three_times_is_its_median_with_the_spread(tmp_path):
    """Host-timed input: each play of a serial level has its own latencies.
    The report gives the median play and the spread; a level breaks when
    most plays missed; delivery is shown play by play."""
    data = results()
    lines = ["KIT LINE baud=115200 bytes_per_s=11520"]
    for play, (latency_max, slips, lost) in enumerate(((1200, 0, 0), (3600, 1, 2), (2400, 0, 0))):
        lines += [f"KIT SWEEP axis=noise point={play} level=75 unit=% burst=0 rg={rg} hz={hz} cycles=1000 "
                  f"expected=1000 slips={slips if rg == 'rg1kHz' else 0} late_starts=0 latency_p99=720 "
                  f"latency_max={latency_max} jitter_p99=12 jitter_max=24 exec_max=200 load_runs=0 load_dropped=0"
                  for rg, hz in (("rg1kHz", 1000), ("rg100Hz", 100))]
        lines.append(f"KIT SERIAL axis=noise point={play} level=75 repeat={play} offered=48 delivered={48 - lost} "
                     f"lost={lost} bytes_sent=10618 uart_received=10618 ring_drops={300 * lost} uart_errors=0")
    lines += ["KIT FLOOD baud=115200 seconds=10.20 received_per_s=6826 bytes_sent=117792 uart_received=117792 "
              "ring_drops=9048 uart_errors=0 discarded=108350 bad_checksums=0 oversized=0 frame_bytes=394 "
              "unaccounted=0 noops_sent=20 noops_answered=20",
              "KIT FLOODRG axis=noise point=9000 level=100 unit=% burst=0 rg=rg1kHz hz=1000 cycles=10000 "
              "expected=10000 slips=3 late_starts=0 latency_p99=6655 latency_max=12000 jitter_p99=1 jitter_max=2"]
    for variant in ("baremetal", "rtos"):
        data.variants[variant].records += [{"kind": r.kind, **r.fields} for line in lines
                                           if (r := console.parse_line(line)) is not None]
    parsed = sweep.of_records(data.variants["rtos"].records)
    assert parsed is not None and parsed.repeats("noise") == 3
    assert parsed.spread[("noise", 75, "rg1kHz")] == (1200, 3600)
    assert parsed.series("noise", "rg1kHz")[0].latency_max == 2400  # the median play
    assert parsed.breaking_point("noise", "rg1kHz") is None  # one play of three missed
    writer.write(data, tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert "115,200 baud (11,520 B/s)" in markdown
    assert "| noise | 75 | 48/46/48 of 48 | 0/600/0 |" in markdown
    assert "| noise | held | held |" in markdown  # the median play lost nothing
    assert "max (µs) (spread)" in markdown and "| 200 (100–300) |" in markdown  # cycles at 12 MHz
    assert "| rg1kHz slips (share of its cycles) | 3 (0.03%) | 3 (0.03%) |" in markdown
    assert "| NO_OPs after the flood answered | 20 | 20 |" in markdown


def test_an_axis_one_variant_did_not_run_says_so(tmp_path):
    data = results()
    line = ("KIT SWEEP axis=downlink point=0 level=0 unit=pkt/s burst=0 rg=rg1kHz hz=1000 cycles=1000 "
            "expected=1000 slips=0 late_starts=0 latency_p99=720 latency_max=900 jitter_p99=12 jitter_max=24 "
            "exec_max=200 load_runs=100 load_dropped=0")
    record = console.parse_line(line)
    assert record is not None
    data.variants["rtos"].records.append({"kind": record.kind, **record.fields})
    writer.write(data, tmp_path)
    assert "| downlink | rg1kHz | not run | none up to 0 pkt/s |" in (tmp_path / "report.md").read_text()


def test_a_policy_is_compared_with_its_model_and_its_shed_load_shown(tmp_path):
    """baremetal_budgeted (the baremetal model under its time-budgeted
    policy) beside baremetal: where each breaks, what the policy shed, and
    where no cooperative policy can help; its SCHED table in the report."""
    def budgeted_lines() -> list[str]:
        lines = []
        for point, load in enumerate(range(0, 2001, 500)):
            for rg, hz in (("rg1kHz", 1000), ("rg100Hz", 100)):
                missed = rg == "rg1kHz" and load >= 1500
                shed = 4 if load >= 1000 else 0
                lines.append(
                    f"KIT SWEEP axis=slice point={point} level={load} unit=us burst=0 rg={rg} hz={hz} cycles=200 "
                    f"expected=200 slips={3 if missed else 0} late_starts=0 latency_p99={70 * CYCLES_PER_US} "
                    f"latency_max={80 * CYCLES_PER_US} jitter_p99=12 jitter_max=24 exec_max=200 "
                    f"load_runs=20 load_dropped={shed}")
        return lines + ["KIT BREAK axis=slice rg=rg1kHz level=1500 unit=us",
                        "KIT BREAK axis=slice rg=rg100Hz level=none unit=us",
                        "KIT SCHED name=load critical=no anticipated=12000 deferrals=40 expedited=3 late=2",
                        "KIT SCHED name=rg1kHz critical=yes anticipated=900 deferrals=0 expedited=0 late=0",
                        "KIT SCHED name=guard guard=120 guard_max=1200"]

    data = results()
    text = console_log("baremetal_budgeted") + "\n" + "\n".join(budgeted_lines())
    data.variants["baremetal_budgeted"] = metrics.results(
        [metrics.VariantData("baremetal_budgeted", Footprint(96400, 30100, 262144, 65536), console.parse(text))]
    ).variants["baremetal_budgeted"]
    found = analysis.sweeps(data)
    assert found["baremetal_budgeted"].shed("slice", "rg1kHz") == 12
    assert found["baremetal_budgeted"].shed("slice", "rg1kHz", below=1500) == 4
    assert analysis.policy_pairs(data.names()) == [("baremetal", "baremetal_budgeted")]
    lines = analysis.sweep_guidance(data, found).lines
    assert ("baremetal_budgeted against baremetal, slice load, rg1kHz: "
            "baremetal_budgeted holds it up to 1500 µs where baremetal breaks at 1000 µs; "
            "to do so it shed 4 load messages (its queue overflowed while it deferred them); a slice of 1000 µs "
            "or more fits no tick: a cooperative policy can only postpone it, and baremetal_budgeted misses "
            "deadlines from 1500 µs.") in lines
    findings = analysis.findings(data).lines
    assert any(line.startswith("baremetal_budgeted uses") for line in findings)
    assert any("rtos" in line and "baremetal_budgeted" in line and line.startswith("rg1kHz:") for line in findings)
    writer.write(data, tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert "baremetal_budgeted load dropped" in markdown
    assert "| baremetal_budgeted | load | no | 12,000 | 40 | 3 | 2 |" in markdown


def test_a_sweep_record_cut_short_is_left_out_and_said():
    """An interrupt's console line (the UART driver's overrun message) can
    land inside a SWEEP line; the rest of the sweep still reads."""
    data = results()
    cut = console.parse_line("KIT SWEEP axis=slice point=9 level=2500 unit=us burst=0 rg=rg1kHz hz=1000 cycles=200 "
                             "expected=200 slips=0 late_starts=0 latency_p99=720 latency_max=900 jitter_pUART buffer "
                             "overrun")
    assert cut is not None
    data.variants["rtos"].records.append({"kind": cut.kind, **cut.fields})
    parsed = sweep.of_records(data.variants["rtos"].records)
    assert parsed is not None and parsed.max_load("slice") == 2000
    assert parsed.inconsistencies() == ["1 SWEEP record(s) cut short, left out"]


def test_a_host_timed_axis_breaks_past_a_share_a_deterministic_one_at_any_miss():
    """Under icount a load axis is exact: one slip breaks it. A serial axis
    is host-timed: a few slips or lost commands in some plays come and go
    from run to run, so it breaks past sweep.HOST_TIMED_SHARE."""
    def point(unit: str, slips: int, expected: int = 1000) -> sweep.Point:
        return sweep.Point("a", 1, unit, 0, "rg1kHz", 1000, slips, 0, 1, 1, 1, expected=expected)

    assert point("us", 1).breaks
    assert not point("cmd/s", 4).breaks and point("cmd/s", 11).breaks
    assert point("%", 1, expected=10).breaks  # a slow group: one miss is 10 % of its cycles
    plays = {("uplink", 200): [{"lost": lost, "offered": 240} for lost in (0, 2, 3)],
             ("uplink", 300): [{"lost": lost, "offered": 360} for lost in (9, 16, 12)]}
    assert link_report.delivery_breaking_point(plays, "uplink") == 300


def _names(tmp_path: Path, commands: dict[str, int]) -> Dictionary:
    path = tmp_path / "TopologyDictionary.json"
    path.write_text(json.dumps({"commands": [{"name": name, "opcode": opcode} for name, opcode in commands.items()]}))
    return Dictionary.read(path)


@pytest.mark.parametrize("health, events", [("Kit.health", "Kit.events"),  # the reference
                                            ("CdhCore.health", "CdhCore.events")])  # F´'s CdhCore subtopology
def test_health_stops_pinging_the_event_service_with_its_own_command(tmp_path: Path, health: str,
                                                                     events: str) -> None:
    """HLTH_PING_ENABLE's arguments as F´ serializes them: the entry's name
    (a U16 length, then its bytes), then Fw.Enabled as a U8, for the event
    service's entry by F´'s name and by the reference's probe; nothing
    where the build has no health."""
    names = _names(tmp_path, {f"{health}.HLTH_PING_ENABLE": 0x2901, f"{events}.SET_ID_FILTER": 0x2A01})
    entry = events.replace(".", "_").encode()
    sent = services.ping_enable(names, enabled=False)
    assert sent == (client.frame(client.command(0x2901, len(entry).to_bytes(2, "big") + entry + b"\x00"))
                    + client.frame(client.command(0x2901, (len(entry) + 4).to_bytes(2, "big") + entry + b"Ping\x00")))
    assert services.ping_enable(names, enabled=True) != sent
    assert services.ping_enable(_names(tmp_path, {f"{events}.SET_ID_FILTER": 1}), enabled=False) == b""


def test_the_sweep_table_says_how_the_scenario_shaped_its_axis():
    """A load paced for a slow group (tests/team/Thermal's 50 Hz slice) says so in its table's title."""
    lines = sweep_lines("baremetal", None) + ["KIT AXIS name=slice period_us=20000 step_us=2000 top_us=40000 "
                                              "burst=0 every=4"]
    records = [console.parse_line(line) for line in lines]
    found = sweep.of_records([{"kind": r.kind, **r.fields} for r in records if r is not None])
    assert found is not None
    assert found.shape_text("slice") == ("the load's port called each 20,000 µs, its work on one call in 4; "
                                         "levels 0–40,000 µs in steps of 2,000 µs")
    assert found.shape_text("burst") == ""
    from kittools.report import tables
    assert tables.sweep_table({"baremetal": found}, 12e6, "slice").title.startswith(
        "Load sweep, axis 'slice' (the load's port called each 20,000 µs")


def test_the_tasks_table_knows_any_deployments_rate_groups_by_their_records():
    """tests/team/Thermal's rg50Hz has the passive form the reference's rg1kHz has."""
    data = results()
    for variant in data.variants.values():
        for record in variant.records:
            if record.get("name") == "rg1kHz":
                record["name"] = "rg50Hz"
    rows = {row[0]: row[1:] for row in analysis.tasks_table(data).rows}
    assert rows["rg50Hz"][-1] == analysis.RATE_GROUP_REASON


def test_the_conditions_say_how_fine_the_timing_histograms_are():
    data = results()
    assert not any("Timing histograms" in line for line in conditions.conditions_text(data).lines)
    data.conditions["timing_buckets"] = "4"  # CONFIG_KIT_TIMING_SUB_BITS=2 (qemu_cortex_m3)
    assert ("Timing histograms: 4 buckets per power of two, so a percentile is within 25 % above its true value; "
            "min and max are exact.") in conditions.conditions_text(data).lines
