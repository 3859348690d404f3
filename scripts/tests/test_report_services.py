# SPDX-License-Identifier: Apache-2.0
"""The report's F´ services per model: what a board's profile leaves out of
a model, and why, in the run's numbers."""

from __future__ import annotations

from kittools import model
from kittools.build.conditions import SERVICES
from kittools.report import tables
from kittools.report.document import Table, Text
from kittools.sizes import by_layer

ALL = {key: True for key, _ in SERVICES}


def _variant(ram: int, services: dict[str, bool], file_ram: int, sequencer_ram: int) -> model.Variant:
    return model.Variant(passed=True, metrics={}, build={"services": services},
                         footprint={"rom": 200000, "ram": ram, "rom_size": 262144, "ram_size": 65536},
                         modules={"ram": {by_layer.FILE_HANDLING: file_ram, by_layer.SEQUENCER: sequencer_ram}})


def _results(rtos_services: dict[str, bool]) -> model.Results:
    return model.Results({"board": "qemu_cortex_m3/ti_lm3s6965"}, {
        "baremetal": _variant(59272, ALL, 5200, 1400),
        "rtos": _variant(63784, rtos_services, 1500, 0)})


def test_a_left_out_service_is_named_with_the_numbers():
    rtos = {**ALL, "CONFIG_KIT_SERVICE_FILES": False, "CONFIG_KIT_SERVICE_FILE_UPLINK": False,
            "CONFIG_KIT_SERVICE_SEQUENCER": False}
    table, why = tables.services_sections(_results(rtos))
    assert isinstance(table, Table) and isinstance(why, Text)
    assert ["file downlink (FileHandling)", "yes", "left out"] in table.rows
    assert ["parameter database (FileHandling)", "yes", "yes"] in table.rows
    [line] = why.lines
    assert line.startswith("rtos leaves out the file downlink (FileHandling), file uplink (FileHandling), command "
                           "sequencer: its static RAM is 63,784 B of 65,536 (1,752 B free).")
    assert f"In baremetal, which carries them, their layers take this much more RAM ({by_layer.FILE_HANDLING} " \
           f"3,700 B; {by_layer.SEQUENCER} 1,400 B)" in line


def test_every_service_carried_needs_no_why():
    assert [type(s) for s in tables.services_sections(_results(ALL))] == [Table]


def test_results_from_before_the_record_have_no_services_table():
    data = _results(ALL)
    data.variants["rtos"].build = {}
    assert tables.services_sections(data) == []
