# SPDX-License-Identifier: Apache-2.0
import copy
import json

import pytest

from kittools import console, metrics, model
from kittools.report import analysis, writer
from kittools.sizes.memory import Footprint
from kittools.suite import budget, results
from kittools.workspace import KitError

from sample_console import console_log


def _results(**rtos_kwargs) -> model.Results:
    def data(variant, rom, ram, **kwargs):
        return metrics.VariantData(variant, Footprint(rom, ram, 262144, 65536),
                                   console.parse(console_log(variant, **kwargs)),
                                   {"F´ framework": 20000, "libc (picolibc, libgcc)": 9000},
                                   {"F´ framework": 70, "libc (picolibc, libgcc)": 200})
    return metrics.results([data("baremetal", 96000, 30000), data("rtos", 102000, 42000, **rtos_kwargs)])


def _write(tmp_path, name, data) -> object:
    path = tmp_path / name
    path.write_text(json.dumps(data))
    return path


def test_missing_results_file_is_explained(tmp_path):
    with pytest.raises(KitError, match="does not exist"):
        results.load(tmp_path / "nope.json")


def test_malformed_results_are_explained(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    with pytest.raises(KitError, match="not valid JSON"):
        results.load(bad)
    broken = _results().to_json()
    del broken["variants"]["rtos"]["metrics"]["footprint.rom.bytes"]
    with pytest.raises(KitError, match="lacks the metric 'footprint.rom.bytes' \\(ROM \\(bytes\\)\\)"):
        results.load(_write(tmp_path, "broken.json", broken))
    unknown = _results().to_json()
    unknown["variants"]["rtos"]["metrics"]["ROM, total"] = 1
    with pytest.raises(KitError, match="not a metric key: 'ROM, total'"):
        results.load(_write(tmp_path, "unknown.json", unknown))
    old = _results().to_json()
    old["schema_version"] = 0
    with pytest.raises(KitError, match="schema_version"):
        results.load(_write(tmp_path, "old.json", old))


def test_findings_are_generated_from_the_numbers():
    text = analysis.findings(_results())
    assert "rtos uses 5.9 KiB (6.2%) more ROM than baremetal (99.6 KiB vs 93.8 KiB)." in text.lines
    assert any(line.startswith("rg1kHz: p99 dispatch latency") for line in text.lines)
    assert text.lines[-1] == "Run verdicts: baremetal PASS, rtos PASS."


def test_outputs_are_written_and_the_html_is_self_contained(tmp_path):
    outcome = writer.write(_results(), tmp_path)
    names = {p.name for p in outcome.files}
    assert {"report.md", "report.html", "report.json", "report.csv"} <= names
    html = (tmp_path / "report.html").read_text()
    assert "data:image/png;base64," in html and "http://" not in html and "https://" not in html
    assert "not hardware latencies" in (tmp_path / "report.md").read_text()
    assert "baremetal,ROM (bytes),96000" in (tmp_path / "report.csv").read_text()


def test_budget_passes_on_the_baseline_itself(tmp_path):
    data = _results()
    outcome = writer.write(data, tmp_path, baseline=copy.deepcopy(data))
    assert budget.check(data, copy.deepcopy(data)).passed
    assert outcome.violations == []
    assert "Budget check: PASS" in (tmp_path / "report.md").read_text()


def test_budget_fails_on_a_worsened_run(tmp_path):
    baseline = _results()
    worse = copy.deepcopy(baseline)
    worse.variants["rtos"].metrics[model.ROM] *= 1.05                              # +5% ROM
    worse.variants["rtos"].metrics[model.rg_metric("rg1kHz", "latency", "p99")] += 20  # p99 regression
    worse.variants["baremetal"].metrics[model.slips("rg1kHz")] = 3
    outcome = writer.write(worse, tmp_path, baseline=baseline)
    assert outcome.violations == budget.check(worse, baseline).violations
    assert len(outcome.violations) == 3
    assert any("ROM (bytes)" in v and "over budget" in v for v in outcome.violations)
    assert any("latency p99" in v and "regressed" in v for v in outcome.violations)
    assert any("slips" in v for v in outcome.violations)


def _counting_checks(monkeypatch) -> list[int]:
    """budget.check, counting its calls."""
    calls: list[int] = []
    check = budget.check

    def counted(*args, **kwargs):
        calls.append(1)
        return check(*args, **kwargs)

    monkeypatch.setattr(budget, "check", counted)
    return calls


def test_kit_test_computes_the_budget_verdict_once(tmp_path, monkeypatch):
    from kittools.suite import verdict

    baseline = _results()
    worse = copy.deepcopy(baseline)
    worse.variants["rtos"].metrics[model.ROM] *= 1.05
    monkeypatch.setattr(verdict, "BASELINES", tmp_path / "baselines")
    verdict.write_baseline(baseline, tmp_path / "baselines" / "qemu_cortex_m3.json")
    calls = _counting_checks(monkeypatch)
    tally = verdict.judge(worse, "qemu_cortex_m3", tmp_path / "logs", budget.Budget())
    assert len(calls) == 1  # the gate's verdict is the report's
    assert (tally.passed, tally.failed) == (1, 1)  # the budget fails, the tables fit
    report = (tmp_path / "logs" / "qemu_cortex_m3" / "report" / "report.md").read_text()
    assert "Budget check: FAIL" in report and "over budget" in report


def test_kit_report_on_its_own_computes_the_verdict(tmp_path, monkeypatch):
    baseline = _results()
    calls = _counting_checks(monkeypatch)
    outcome = writer.write(copy.deepcopy(baseline), tmp_path, baseline=baseline)
    assert len(calls) == 1 and outcome.violations == []
    assert "Budget check: PASS" in (tmp_path / "report.md").read_text()


def test_small_p99_changes_are_not_regressions(tmp_path):
    baseline = _results()
    noisy = copy.deepcopy(baseline)
    noisy.variants["rtos"].metrics[model.rg_metric("rg1kHz", "jitter", "p99")] += 1.5  # +150% but under 2 us
    assert writer.write(noisy, tmp_path, baseline=baseline).violations == []


def test_a_board_only_built_is_reported_without_runs_verdicts_or_times(tmp_path):
    def built(rom: int, ram: int) -> model.Variant:
        return model.Variant(passed=False, metrics={model.ROM: rom, model.RAM: ram},
                             modules={"rom": {"F´ framework": rom - 9000, "libc (picolibc, libgcc)": 9000},
                                      "ram": {"F´ framework": ram - 200, "libc (picolibc, libgcc)": 200}},
                             footprint={"rom": rom, "ram": ram, "rom_size": 524288, "ram_size": 98304})
    data = model.Results({"board": "nucleo_f401re/stm32f401xe", "run": results.NOT_RUN},
                         {"baremetal": built(157054, 46428), "rtos": built(162204, 64092)})
    writer.write(data, tmp_path)
    markdown = (tmp_path / "report.md").read_text()
    assert f"Board nucleo_f401re/stm32f401xe: {results.NOT_RUN}." in markdown
    assert "Run verdicts" not in markdown and "virtual time" not in markdown
    assert "| F´ framework | 148,054 | 153,204 | 46,228 | 63,892 |" in markdown
    # Beside the emulated boards: its ROM and RAM, no timing
    writer.write_boards([_results(), data], tmp_path / "boards")
    assert "nucleo_f401re/stm32f401xe rtos" in (tmp_path / "boards" / "report.md").read_text()


def _serial(axis: str, level: int, lost: int, latency_max: int, slips: int = 0) -> list[dict[str, str]]:
    lines = [f"KIT SWEEP axis={axis} point=0 level={level} unit=% burst=0 rg=rg1kHz hz=1000 cycles=1000 "
             f"expected=1000 slips={slips} late_starts=0 latency_p99=700 latency_max={latency_max} jitter_p99=1 "
             "jitter_max=2",
             f"KIT SERIAL axis={axis} point=0 level={level} repeat=0 offered=48 delivered={48 - lost} lost={lost} "
             "bytes_sent=1 uart_received=1 ring_drops=0 uart_errors=0"]
    return [{"kind": r.kind, **r.fields} for line in lines if (r := console.parse_line(line)) is not None]


def test_the_budget_holds_breaking_points_not_serial_latencies():
    """A serial level's latencies are host-timed and not held; where a group
    or the link's delivery breaks is, and breaking earlier fails."""
    baseline = _results()
    baseline.variants["rtos"].records += _serial("noise", 50, 0, 900) + _serial("noise", 75, 2, 900)
    slower = copy.deepcopy(baseline)
    slower.variants["rtos"].records = [r for r in slower.variants["rtos"].records if r.get("axis") != "noise"]
    slower.variants["rtos"].records += _serial("noise", 50, 0, 5000) + _serial("noise", 75, 2, 5000)
    assert budget.check(slower, baseline).passed
    earlier = copy.deepcopy(baseline)
    earlier.variants["rtos"].records = [r for r in earlier.variants["rtos"].records if r.get("axis") != "noise"]
    earlier.variants["rtos"].records += _serial("noise", 50, 1, 900, slips=20) + _serial("noise", 75, 2, 900)
    violations = budget.check(earlier, baseline).violations
    assert any("noise delivery: 50, earlier than the baseline (broke at 75)" in v for v in violations)
    assert any("noise load, rg1kHz: 50, earlier than the baseline (held through the sweep to 75)" in v
               for v in violations)
    # A level the baseline never swept is not earlier
    further = copy.deepcopy(baseline)
    further.variants["rtos"].records += _serial("noise", 100, 5, 900, slips=4)
    assert budget.check(further, baseline).passed


def test_the_fastest_period_is_the_deployments_own_fastest_group():
    """A deployment whose fastest group is slower than the tick (tests/team/Thermal:
    50 Hz on a 1 kHz tick) has its sweep's breaking points set against 20,000 µs,
    not the tick's 1,000 µs."""
    data = _results()
    assert analysis.fastest_period_us(data) == 1000.0  # the reference: its 1 kHz group
    for variant in data.variants.values():
        for record in variant.of_kind("RG"):
            record["hz"] = str(int(record["hz"]) // 20)
    assert analysis.fastest_period_us(data) == 20000.0
