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
