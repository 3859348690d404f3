# SPDX-License-Identifier: Apache-2.0
"""The stacks a build's integration suite ends with: the STACK lines after
the last segment's SWEEP lines, once the burst is over."""

from __future__ import annotations

from kittools.suite import stack_marks


class FakeStation:
    """A console that prints one more batch of lines at each read."""

    def __init__(self, batches: list[list[str]]) -> None:
        self.batches = batches
        self.printed: list[str] = []

    def lines(self, read_s: float = 0.0) -> list[str]:
        if read_s > 0 and self.batches:
            self.printed += self.batches.pop(0)
        return list(self.printed)


BOOT = ["KIT BANNER variant=rtos", "KIT STACK name=main size=1408 used=900"]
SWEEP = ["KIT SWEEP axis=uplink point=0 rg=rg1kHz"]
STACKS = ["KIT STACK name=prmDb size=2048 used=1100", "KIT STACK name=main size=1408 used=1116"]


def test_the_stacks_after_the_last_sweep_once_they_stop_coming():
    station = FakeStation([BOOT, SWEEP + STACKS[:1], STACKS[1:], [], []])
    assert stack_marks.stacks_after_the_suite(station) == STACKS


def test_no_sweep_no_stacks(monkeypatch):
    monkeypatch.setattr(stack_marks, "STACKS_WAIT_S", 0.05)
    station = FakeStation([BOOT])
    assert stack_marks.stacks_after_the_suite(station) == []


def test_the_summary_names_each_thread_used_of_size():
    assert stack_marks.stack_summary(STACKS) == "prmDb 1100/2048, main 1116/1408"
