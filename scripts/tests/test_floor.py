# SPDX-License-Identifier: Apache-2.0
"""The kernel floor (tests/floor) in the results: read from twister's
consoles, matched to each model's dispatch path, and held by the budget."""

import copy

from kittools import console, metrics, model
from kittools.build.folder import BuildFolder
from kittools.sizes.memory import Footprint
from kittools.suite import budget, floor

from sample_console import console_log

FLOOR_CONSOLE = """*** Booting Zephyr OS build 0d6f47a50097 ***
KIT FLOOR path=sem samples=1000 missed=0 p50=80 p99=83 max=90 cycles_hz=12000000
KIT FLOOR path=msgq samples=1000 missed=0 p50=160 p99=164 max=170 cycles_hz=12000000
KIT END app=floor result={result}
"""


def _floor_build(tmp_path, name, text):
    build = tmp_path / name
    build.mkdir()
    BuildFolder(build).console_log.write_text(text)
    return build


def test_floor_records_come_from_passed_floor_runs_only(tmp_path):
    passed = _floor_build(tmp_path, "threads", FLOOR_CONSOLE.format(result="PASS"))
    wfi = _floor_build(tmp_path, "nothreads", "KIT FLOOR path=wfi samples=1000 missed=3 p50=40 p99=42 max=50 "
                                              "cycles_hz=12000000\nKIT END app=floor result=FAIL\n")
    never_ran = tmp_path / "never"
    never_ran.mkdir()
    found = floor.records([passed, wfi, never_ran])
    assert sorted(found) == ["msgq", "sem"]
    assert found["msgq"].int("p50") == 160


def test_a_models_floor_path_follows_its_task_context():
    assert floor.path_of(console.parse(console_log("rtos"))) == "msgq"
    assert floor.path_of(console.parse(console_log("baremetal"))) == "wfi"
    assert floor.path_of(console.Run([])) is None


def _with_floor(p50: int) -> metrics.VariantData:
    run = console.parse(console_log("rtos"))
    run.records.append(console.Record("FLOOR", {"path": "msgq", "samples": "1000", "missed": "0", "p50": str(p50),
                                                "p99": str(p50 + 4), "max": str(p50 + 10),
                                                "cycles_hz": "12000000"}))
    return metrics.VariantData("rtos", Footprint(100000, 40000, 262144, 65536), run)


def test_the_floor_and_the_latency_over_it_are_metrics():
    values = metrics.metrics(_with_floor(160))
    assert values[model.floor_latency("p50")] == 160 * 1e6 / 12000000
    assert values[model.FLOOR_RATIO] == 3.75  # rg1kHz latency p50 600 cycles over 160
    assert model.FLOOR_RATIO not in metrics.metrics(metrics.VariantData(
        "rtos", Footprint(1, 1, 2, 2), console.parse(console_log("rtos"))))


def test_a_dispatch_path_slower_against_its_floor_fails_the_budget():
    baseline = metrics.results([_with_floor(160)])
    slower = copy.deepcopy(baseline)
    slower.variants["rtos"].metrics[model.FLOOR_RATIO] *= 1.2
    verdict = budget.check(slower, baseline)
    assert [v for v in verdict.violations if "kernel floor" in v and "dispatch slowed" in v]
    within = copy.deepcopy(baseline)
    within.variants["rtos"].metrics[model.FLOOR_RATIO] *= 1.05
    assert budget.check(within, baseline).passed


def test_zephyr_latency_measure_figures_are_read_when_it_finished(tmp_path):
    text = ("*** Booting Zephyr OS build 0d6f47a50097 ***\n"
            "  isr.resume.different.thread.kernel  - Return from ISR to another thread         :   "
            "   412 cycles ,     34333 ns :\n"
            "  sem.give.immediate.kernel           - Give a semaphore (no waiters)              :   "
            "    95 cycles ,      7916 ns :\n"
            "PROJECT EXECUTION SUCCESSFUL\n")
    build = _floor_build(tmp_path, floor.LATENCY_MEASURE, text)
    found = floor.zephyr_records([build])
    assert [(r.fields["metric"], r.int("cycles")) for r in found] == [
        ("isr.resume.different.thread.kernel", 412), ("sem.give.immediate.kernel", 95)]
    assert found[0].fields["description"] == "Return from ISR to another thread"
    BuildFolder(build).console_log.write_text(text.replace("PROJECT EXECUTION SUCCESSFUL\n", ""))
    assert floor.zephyr_records([build]) == []
