# SPDX-License-Identifier: Apache-2.0
"""The integration suite's copy of the kit's test pattern (Load::Pattern,
app/Components/Load/Load.hpp) against xorshift32 (Marsaglia's 13, 17, 5)
worked from its definition: seed 1 gives 270369 (0x42021), 67634689
(0x4080601), 2647435461, whose low bytes the firmware writes. The firmware's side is held to the same
values by Load's host test."""

import importlib.util
from pathlib import Path
from types import ModuleType

SUITE = Path(__file__).resolve().parents[2] / "tests" / "integration" / "test_ground.py"


def _suite() -> ModuleType:
    spec = importlib.util.spec_from_file_location("kit_ground_suite", SUITE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_pattern_is_xorshift32s_low_bytes() -> None:
    assert _suite().pattern(1, 3) == bytes([270369 & 0xFF, 67634689 & 0xFF, 2647435461 & 0xFF])


def test_pattern_has_no_short_period() -> None:
    data = _suite().pattern(0x4B495431, 4096)
    assert all(data[:256] != data[shift:shift + 256] for shift in range(1, 2048))
