# SPDX-License-Identifier: Apache-2.0
from kittools import compare, console, model
from kittools.footprint import Footprint

from sample_console import console_log


def _data(variant: str, rom: int, ram: int, **kwargs) -> compare.VariantData:
    return compare.VariantData(variant, Footprint(rom, ram, 262144, 65536),
                               console.parse(console_log(variant, **kwargs)))


def test_metrics_convert_cycles_to_microseconds():
    values = compare.metrics(_data("baremetal", 1000, 500))
    assert values[model.rg_metric("rg1kHz", "latency", "max")] == 100.0  # 1200 cycles at 12 MHz
    assert values[model.rg_metric("rg1kHz", "latency", "p99")] == 1100 / 12
    assert values[model.rg_metric("rg1kHz", "exec", "max")] == 200.0
    assert values[model.rg_metric("rg1kHz", "jitter", "p50")] == 1.0
    assert values[model.cpu_share("rg1kHz")] == 7.5
    assert values[model.STACKS_RESERVED] == 2048
    assert values[model.ROM] == 1000


def test_json_carries_records_and_footprints():
    data = compare.results([_data("baremetal", 1, 2), _data("rtos", 3, 4, slips=2)]).to_json()
    assert data["schema_version"] == compare.SCHEMA_VERSION
    assert data["variants"]["rtos"]["footprint"]["ram"] == 4
    assert data["variants"]["rtos"]["metrics"]["rg.rg1kHz.slips.count"] == 2
    assert data["conditions"]["icount_shift"] == "4"
