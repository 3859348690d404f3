# SPDX-License-Identifier: Apache-2.0
"""`kit new-board`: bring the kit to a new board.

Checks that the pinned Zephyr knows the board (a twister platform file names
it), that it is an ARM board, and that its flash and RAM hold the deployment
as measured on a ported board; then copies the reference board's folder with
a TODO header in each file and adds the board to the twister files'
platform lists: a QEMU board to the suites that run, a real board to the
boards built and not run (tests/boards) alone (suite_files). A real board
(no emulator) gets its vendor HAL (its file in the folder, west.yml's
allow-list), a kit.conf without icount, and a link UART: one its devicetree
enables besides the console, else one its SoC has, enabled on pins the HAL's
pinctrl file names (spare_uart). docs/porting.md is the checklist that follows.

By concern: zephyr (the board as the pinned Zephyr knows it, its HAL),
devicetree (its devicetree: memory sizes, UARTs, a spare UART's pins),
memory (whether it holds the deployment), suites (the twister files' and
west.yml's lists), scaffold (new_board: the folder and its TODO headers).
"""

from __future__ import annotations

from kittools.boards.devicetree import SpareUart, link_uarts, spare_uart
from kittools.boards.memory import check_fit, smallest_models
from kittools.boards.scaffold import REFERENCE_BOARD, TODOS, new_board, with_todo
from kittools.boards.suites import (
    BUILD_ONLY_SUITE,
    add_to_scenario_lists,
    add_to_twister_lists,
    allow_module,
    exclude_from_scenarios,
    suite_files,
    twister_files,
)
from kittools.boards.zephyr import HalModule, ZephyrBoard, check_arch, find_board, hal_module

__all__ = [
    "BUILD_ONLY_SUITE",
    "REFERENCE_BOARD",
    "TODOS",
    "HalModule",
    "SpareUart",
    "ZephyrBoard",
    "add_to_scenario_lists",
    "exclude_from_scenarios",
    "add_to_twister_lists",
    "allow_module",
    "check_arch",
    "check_fit",
    "find_board",
    "hal_module",
    "link_uarts",
    "new_board",
    "smallest_models",
    "spare_uart",
    "suite_files",
    "twister_files",
    "with_todo",
]
