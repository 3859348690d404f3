# SPDX-License-Identifier: Apache-2.0
"""The report's "what fits where": every build against every board's memory."""

from __future__ import annotations

from kittools import model
from kittools.report import tables


def _board(board: str, rom_size: int, ram_size: int, builds: dict[str, tuple[int, int]]) -> model.Results:
    return model.Results({"board": board}, {
        name: model.Variant(passed=True, metrics={model.ROM: rom, model.RAM: ram},
                            footprint={"rom": rom, "ram": ram, "rom_size": rom_size, "ram_size": ram_size})
        for name, (rom, ram) in builds.items()})


def test_a_build_is_its_own_where_built_and_the_smallest_measured_elsewhere():
    reference = _board("qemu_cortex_m3", 262_144, 65_536, {"baremetal_passive": (110_415, 45_392),
                                                           "rtos": (157_048, 64_140),
                                                           "small.baremetal_passive": (106_000, 41_000)})
    small = _board("qemu_cortex_m3_small", 131_072, 36_864, {"small.baremetal_passive": (105_711, 36_092)})
    table = tables.fits_table([reference, small])
    assert table is not None and table.columns == ["build", "qemu_cortex_m3", "qemu_cortex_m3_small"]
    rows = {row[0]: row[1:] for row in table.rows}
    assert rows["rtos, kit profile"] == ["built: ROM 157,048 of 262,144, RAM 64,140 of 65,536",
                                         "does not fit: ROM 25,976 B short, RAM 27,276 B short"]
    assert rows["baremetal_passive, kit profile"][1] == "does not fit: RAM 8,528 B short"
    # where both built it, each its own; the smallest of them is the estimate elsewhere
    assert rows["baremetal_passive, fprime-small"] == [
        "built: ROM 106,000 of 262,144, RAM 41,000 of 65,536", "built: ROM 105,711 of 131,072, RAM 36,092 of 36,864"]


def test_one_board_has_no_table():
    assert tables.fits_table([_board("qemu_cortex_m3", 262_144, 65_536, {"rtos": (1, 1)})]) is None
