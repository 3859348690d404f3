# SPDX-License-Identifier: Apache-2.0
from kittools import console, metrics, model
from kittools.sizes.memory import Footprint

from sample_console import console_log


def _data(variant: str, rom: int, ram: int, **kwargs) -> metrics.VariantData:
    return metrics.VariantData(variant, Footprint(rom, ram, 262144, 65536),
                               console.parse(console_log(variant, **kwargs)))


def test_metrics_convert_cycles_to_microseconds():
    values = metrics.metrics(_data("baremetal", 1000, 500))
    assert values[model.rg_metric("rg1kHz", "latency", "max")] == 100.0  # 1200 cycles at 12 MHz
    assert values[model.rg_metric("rg1kHz", "latency", "p99")] == 1100 / 12
    assert values[model.rg_metric("rg1kHz", "exec", "max")] == 200.0
    assert values[model.rg_metric("rg1kHz", "jitter", "p50")] == 1.0
    assert values[model.cpu_share("rg1kHz")] == 7.5
    assert values[model.STACKS_RESERVED] == 2048
    assert values[model.ROM] == 1000


def test_json_carries_records_and_footprints():
    data = metrics.results([_data("baremetal", 1, 2), _data("rtos", 3, 4, slips=2)]).to_json()
    assert data["schema_version"] == metrics.SCHEMA_VERSION
    assert data["variants"]["rtos"]["footprint"]["ram"] == 4
    assert data["variants"]["rtos"]["metrics"]["rg.rg1kHz.slips.count"] == 2
    assert data["conditions"]["icount_shift"] == "4"


def test_the_ground_links_share_of_the_heap_is_a_metric_of_its_own():
    heap = ("KIT HEAP fprime_peak=9000 fprime_allocations=40 bytes=11000 allocations=50 frees=0 after_init=0 "
            "failures=0 arena=13312 arena_left=1200 link_buffers=2100")
    text = console_log("rtos").replace("KIT END", heap + "\nKIT END", 1)
    values = metrics.metrics(metrics.VariantData("rtos", Footprint(1, 2, 262144, 65536), console.parse(text)))
    assert values[model.HEAP_LINK] == 2100
    assert values[model.HEAP_ARENA_LEFT] == 1200
    assert values[model.HEAP_FPRIME_PEAK] == 9000


def test_the_link_queues_overflows_are_a_metric():
    line = "KIT DOWNLINK events=24 telemetry=81 malformed=0 noop_events=1 uncounted=0 queue_overflows=2"
    text = console_log("baremetal").replace("KIT END", line + "\nKIT END", 1)
    values = metrics.metrics(metrics.VariantData("baremetal", Footprint(1, 2, 262144, 65536), console.parse(text)))
    assert values[model.LINK_QUEUE_OVERFLOWS] == 2
