# SPDX-License-Identifier: Apache-2.0
"""`kit test` as a plan: named steps in two lanes, run at once. The QEMU
lane holds twister and what reads its builds; the host lane what needs no
board (host and tooling tests, the porting check, CI's device path), which
runs beside twister (whose start and last runs leave a core idle). Steps
that must wait for the host lane (the ground link's checks, whose time-outs
are the host's) wait on `host_done`."""

from __future__ import annotations

import concurrent.futures
import threading
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field

from kittools.log import failures_kept, say
from kittools.suite.counts import Tally
from kittools.workspace import one_at_a_time

#: The failure lines the closing summary repeats, and how much of each
FAILURES_SHOWN = 20
FAILURE_LINE_MAX = 400


@dataclass
class Step:
    name: str
    run: Callable[[], Tally]
    #: Started, not waited for: the lane goes on with its next steps and
    #: joins this one at its end
    beside: bool = False


@dataclass
class Plan:
    qemu: list[Step] = field(default_factory=list)
    host: list[Step] = field(default_factory=list)
    #: Set once the host lane has ended
    host_done: threading.Event = field(default_factory=threading.Event)

    def add_qemu(self, name: str, run: Callable[[], Tally], beside: bool = False) -> None:
        self.qemu.append(Step(name, run, beside))

    def add_host(self, name: str, run: Callable[[], Tally]) -> None:
        self.host.append(Step(name, run))

    def run(self) -> int:
        """Both lanes at once, the closing count, the exit status; before
        the count, every failure line said on the way (FAILURES_SHOWN of
        them at most), so that a log's tail names what failed."""
        started = time.monotonic()
        with failures_kept() as failures, one_at_a_time("test"), \
                concurrent.futures.ThreadPoolExecutor(max_workers=1) as beside:
            host = beside.submit(run_steps, self.host)
            host.add_done_callback(lambda _: self.host_done.set())
            total = run_steps(self.qemu)
            total.add(host.result())
        say(f"all steps: {time.monotonic() - started:.0f} s")
        if failures:
            shown = f", the first {FAILURES_SHOWN}" if len(failures) > FAILURES_SHOWN else ""
            say(f"what failed ({len(failures)} line(s) said above{shown}):")
            for line in failures[:FAILURES_SHOWN]:
                say(f"  {line.strip().splitlines()[0][:FAILURE_LINE_MAX]}")  # its first line: the check's
        print(f"total: {total.passed} passed, {total.failed} failed")
        return 0 if total.failed == 0 and total.passed > 0 else 1


def run_steps(steps: list[Step]) -> Tally:
    """Run steps in order, a line as each starts and ends; their added count.
    A step `beside` the next ones starts in a thread of its own when its
    turn comes, and is joined at the end."""
    total = Tally()
    with concurrent.futures.ThreadPoolExecutor() as besides:
        started_beside = []
        for step in steps:
            if step.beside:
                started_beside.append(besides.submit(run_step, step))
            else:
                total.add(run_step(step))
        for future in started_beside:
            total.add(future.result())
    return total


def run_step(step: Step) -> Tally:
    say(f"{step.name} ...{' (beside the next steps)' if step.beside else ''}")
    started = time.monotonic()
    try:
        tally = step.run()
    except Exception:  # noqa: BLE001 - any error a step raises is its failure, not the run's end
        # Counted as one failure, its traceback said: every run ends with
        # its count (a CI run once ended in a traceback halfway through)
        say(f"{step.name}: FAIL, it raised:\n{traceback.format_exc()}")
        tally = Tally(failed=1)
    say(f"{step.name}: {tally.passed} passed, {tally.failed} failed ({time.monotonic() - started:.0f} s)")
    return tally


def settle(future: concurrent.futures.Future[None], job: Callable[[], None]) -> None:
    """Run a job in this thread and settle its future with its outcome."""
    try:
        job()
    except BaseException as error:  # handed to whoever waits on the future
        future.set_exception(error)
    else:
        future.set_result(None)
