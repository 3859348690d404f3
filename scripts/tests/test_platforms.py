# SPDX-License-Identifier: Apache-2.0
"""The suite's boards: compared, small parts, built only."""

from __future__ import annotations

import pytest

from kittools.suite import platforms
from kittools.workspace import KitError

SUITE = """\
common:
  platform_allow: [qemu_cortex_m3, mps2/an385]
tests:
  kit.rtos: {extra_args: [CONFIG_KIT_MODEL_RTOS=y]}
  profile.small.baremetal_passive:
    platform_allow: [qemu_cortex_m3, mps2/an385, qemu_cortex_m3_small]
  profile.small.rtos:
    platform_allow: [qemu_cortex_m3_small]
"""


def test_a_small_part_is_a_board_a_scenario_allows_beyond_the_common_list(tmp_path):
    suite = tmp_path / "testcase.yaml"
    suite.write_text(SUITE)
    assert platforms.small_parts(suite) == ["qemu_cortex_m3_small"]  # once, though two scenarios name it
    assert platforms.suite_boards(suite) == ["qemu_cortex_m3", "mps2/an385"]


def test_the_suites_small_part_is_the_emulated_one_and_is_not_compared():
    assert platforms.small_parts() == ["qemu_cortex_m3_small"]
    assert platforms.is_small_part("qemu_cortex_m3_small/ti_lm3s6965")  # as twister names it
    assert not platforms.is_small_part("qemu_cortex_m3")
    with pytest.raises(KitError, match="small part.*fprime-small"):
        platforms.check_runs_here("qemu_cortex_m3_small")
    platforms.check_runs_here("qemu_cortex_m3")
