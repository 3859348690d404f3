# SPDX-License-Identifier: Apache-2.0
"""kit test's lanes: steps in order, a step beside the next ones."""

from __future__ import annotations

import threading

from kittools.suite import plan
from kittools.suite.counts import Tally


def test_a_step_beside_the_next_ones_runs_while_they_run_and_is_counted_at_the_end():
    order: list[str] = []
    next_step_ran = threading.Event()

    def beside() -> Tally:
        order.append("beside started")
        # Only ends once the step after it has run: a lane that waited for it
        # would never get there
        assert next_step_ran.wait(timeout=10)
        order.append("beside ended")
        return Tally(2, 1)

    def before() -> Tally:
        order.append("before")
        return Tally(1, 0)

    def after() -> Tally:
        order.append("after")
        next_step_ran.set()
        return Tally(1, 0)

    steps = [plan.Step("before", before), plan.Step("beside", beside, beside=True), plan.Step("after", after)]
    total = plan.run_steps(steps)
    assert (total.passed, total.failed) == (4, 1)
    assert order[0] == "before" and order.index("beside started") < order.index("beside ended")
    assert order.index("after") < order.index("beside ended")


def test_steps_not_beside_run_one_after_another_in_order():
    order: list[str] = []
    steps = [plan.Step(name, lambda name=name: (order.append(name), Tally(1, 0))[1]) for name in "abc"]
    assert plan.run_steps(steps).passed == 3 and order == ["a", "b", "c"]


def test_the_closing_lines_repeat_what_failed_on_the_way(monkeypatch, capsys):
    """CI shows a long run's last lines: they name the failed checks, said
    in any step of either lane, before the count."""
    import contextlib

    from kittools.log import say

    monkeypatch.setattr(plan, "one_at_a_time", lambda name: contextlib.nullcontext())

    def failing() -> Tally:
        say("  board_model: fuzzing (seed 1): 2 invalid frames: FAIL: LinkHealth.Oversized: 1, expected 2")
        say("  board_model: flood: PASS")
        return Tally(1, 1)

    steps = plan.Plan()
    steps.add_qemu("ground link", failing)
    steps.add_host("tooling tests", lambda: Tally(3, 0))
    assert steps.run() == 1
    out = capsys.readouterr().out.splitlines()
    summary = out[out.index("[kit] what failed (2 line(s) said above):"):]
    assert summary == ["[kit] what failed (2 line(s) said above):",
                       "[kit]   board_model: fuzzing (seed 1): 2 invalid frames: FAIL: LinkHealth.Oversized: 1, "
                       "expected 2",
                       "[kit]   ground link: 1 passed, 1 failed (0 s)",
                       "total: 4 passed, 1 failed"]


def test_a_run_that_failed_nothing_says_no_failures(monkeypatch, capsys):
    import contextlib

    monkeypatch.setattr(plan, "one_at_a_time", lambda name: contextlib.nullcontext())
    steps = plan.Plan()
    steps.add_qemu("twister", lambda: Tally(5, 0))
    assert steps.run() == 0
    assert "what failed" not in capsys.readouterr().out


def test_a_step_that_raises_is_one_failure_and_the_lane_goes_on():
    def broken() -> Tally:
        raise ValueError("Unknown type name: FwEventIdType")

    steps = [plan.Step("broken", broken), plan.Step("after", lambda: Tally(3, 0))]
    total = plan.run_steps(steps)
    assert (total.passed, total.failed) == (3, 1)
