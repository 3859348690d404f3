# SPDX-License-Identifier: Apache-2.0
"""The results model: metric keys and labels, schema-1 upgrade, the budget
gate's independence from the report, the CPU context kind."""

import json
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from kittools import console, metrics, model
from kittools.report import analysis
from kittools.sizes.memory import Footprint
from kittools.suite import results

from sample_console import console_log

BASELINES = Path(__file__).resolve().parents[2] / "tests" / "baselines"


@pytest.mark.parametrize("metric, key, label", [
    (model.ROM, "footprint.rom.bytes", "ROM (bytes)"),
    (model.RAM, "footprint.ram.bytes", "RAM, static (bytes)"),
    (model.HEAP_FPRIME_PEAK, "heap.fprime_peak.bytes", "heap, F´ allocator peak (bytes)"),
    (model.rg_metric("rg1kHz", "latency", "p99"), "rg.rg1kHz.latency.p99_us", "rg1kHz latency p99 (us)"),
    (model.rg_metric("rg10Hz", "jitter", "max"), "rg.rg10Hz.jitter.max_us", "rg10Hz period error max (us)"),
    (model.slips("rg100Hz"), "rg.rg100Hz.slips.count", "rg100Hz slips"),
    (model.cpu_share("rg1kHz"), "task.rg1kHz.cpu.pct", "rg1kHz CPU share (%)"),
])
def test_metric_keys_and_labels(metric, key, label):
    assert metric.key == key
    assert model.MetricId.parse(key) == metric
    assert metric.label == label
    assert model.metric_of_v1_label(label) == metric


@pytest.mark.parametrize("key", ["ROM (bytes)", "rg.rg1kHz.latency.p98_us", "rg.rg1kHz.latency.p99_ms", "a..b"])
def test_bad_metric_keys_are_refused(key):
    with pytest.raises(ValueError):
        model.MetricId.parse(key)


def _data(variant: str, **kwargs) -> metrics.VariantData:
    return metrics.VariantData(variant, Footprint(1000, 500, 262144, 65536),
                               console.parse(console_log(variant, **kwargs)))


def test_a_results_file_round_trips(tmp_path):
    data = metrics.results([_data("baremetal"), _data("rtos")])
    path = tmp_path / "r.json"
    path.write_text(json.dumps(data.to_json()))
    assert results.load(path) == data


def test_schema_1_files_load_with_the_same_values(tmp_path):
    data = metrics.results([_data("baremetal"), _data("rtos", slips=2)])
    v1 = data.to_json()
    v1["schema_version"] = 1
    for variant in v1["variants"].values():
        variant["metrics"] = {model.MetricId.parse(k).label: v for k, v in variant["metrics"].items()}
    path = tmp_path / "v1.json"
    path.write_text(json.dumps(v1))
    assert results.load(path) == data


@pytest.mark.parametrize("board", ["qemu_cortex_m3", "mps2_an385"])
def test_the_committed_baselines_load(board):
    raw = json.loads((BASELINES / f"{board}.json").read_text())
    loaded = results.load(BASELINES / f"{board}.json")
    # Every variant the suite builds (kit.<variant>; profile.* builds are not the comparison's)
    suite = yaml.safe_load((BASELINES.parent / "deployment" / "testcase.yaml").read_text())["tests"]
    assert set(loaded.variants) == {name.removeprefix("kit.") for name in suite if name.startswith("kit.")}
    for name, variant in loaded.variants.items():
        assert len(variant.metrics) == len(raw["variants"][name]["metrics"])
        assert variant.metric(model.ROM) == raw["variants"][name]["footprint"]["rom"]
        assert variant.rate_groups() == ["rg1kHz", "rg100Hz", "rg10Hz"]


def test_the_budget_gate_imports_no_plotting_or_templating_library():
    code = ("import sys, kittools.suite.budget, kittools.suite.results, kittools.suite.verdict,"
            " kittools.commands.test\n"
            "bad = sorted(m for m in sys.modules if m.split('.')[0] in ('matplotlib', 'jinja2', 'kittools')"
            " and m in ('matplotlib', 'jinja2', 'kittools.report.writer', 'kittools.report.plots',"
            " 'kittools.report.render'))\n"
            "print(','.join(bad))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == ""


def test_the_cpu_context_kind_comes_from_the_task_records():
    data = metrics.results([_data("baremetal"), _data("rtos")])
    assert data.variants["baremetal"].context_kind() == "slice"
    assert data.variants["rtos"].context_kind() == "thread"
    # The record, not the variant's name, decides: threads on a variant named otherwise count switches
    renamed = metrics.results([_data("baremetal", context="thread"), _data("rtos", context="slice")])
    assert analysis.switches_per_second(renamed, "baremetal") == 2001 / 2  # runs over a 2 s run
    assert analysis.switches_per_second(renamed, "rtos") is None
    # Records that do not say: no guess
    old = metrics.results([_data("baremetal"), _data("rtos")])
    for r in old.variants["rtos"].records:
        r.pop("context", None)
    assert old.variants["rtos"].context_kind() is None
    assert analysis.switches_per_second(old, "rtos") is None
