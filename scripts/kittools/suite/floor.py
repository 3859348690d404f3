# SPDX-License-Identifier: Apache-2.0
"""The kernel floor under the deployment's latencies (tests/floor).

tests/floor measures, on each board, how long Zephyr alone takes from the
tick's stamp to the code that would dispatch the 1 kHz group, for each path
shape an execution model uses: `wfi` (a thread-less main loop waking from
WFI), `sem` (a thread woken by a semaphore) and `msgq` (that thread handing
the tick through a k_msgq to a less urgent one). Its builds print one
`KIT FLOOR path=… p50=… p99=… max=… cycles_hz=…` line per path into
twister's handler.log. A model's rate-group latency over its path's floor is
the share F´ and the model add (kittools.metrics's floor metrics).

Beside it, Zephyr's own tests/benchmarks/latency_measure (built by
tests/floor/latency_measure under the same board conditions) gives Zephyr's
figures for the threaded paths: they join the threaded models' records.
"""

from __future__ import annotations

import re
from pathlib import Path

from kittools import console
from kittools.build.folder import BuildFolder

#: Twister configurations of tests/floor start with this
PREFIX = "floor."
#: Where the floor's twister scenarios are (their names start with PREFIX)
SCENARIO_FILES = "tests/floor/*/testcase.yaml"
#: The path shape of a model's dispatch, by how its record says it runs its
#: tasks (TASK `context`): cooperative slices of a thread-less loop woken from
#: WFI, or threads, the tick thread handing the tick to a rate-group thread
PATH_OF_CONTEXT = {"slice": "wfi", "thread": "msgq"}
#: The twister configuration of Zephyr's latency_measure, and its figures:
#: "<metric> - <description>: <cycles> cycles , <ns> ns"
LATENCY_MEASURE = "floor.latency_measure"
_ZEPHYR_FIGURE = re.compile(r"^\s*(?P<metric>[\w.]+)\s+-\s+(?P<description>.*?)\s*:\s*(?P<cycles>\d+) cycles\s*,"
                            r"\s*(?P<ns>\d+) ns")
_ZEPHYR_PASSED = "PROJECT EXECUTION SUCCESSFUL"


def records(builds: list[Path]) -> dict[str, console.Record]:
    """Path -> its FLOOR record, from the consoles of the floor's builds (a
    build whose run ended without PASS gives none: the report then shows no
    floor rather than a wrong one)."""
    found: dict[str, console.Record] = {}
    for build in builds:
        log = BuildFolder(build).console_log
        if not log.is_file():
            continue
        run = console.Run([r for r in map(console.parse_line, log.read_text(errors="replace").splitlines())
                           if r is not None])
        if not any(r.fields.get("result") == "PASS" for r in run.of_kind("END")):
            continue
        for record in run.of_kind("FLOOR"):
            found[record.fields["path"]] = record
    return found


def path_of(run: console.Run) -> str | None:
    """The floor path of the model that made `run`, from its TASK records."""
    contexts = {r.fields.get("context") for r in run.of_kind("TASK")}
    return PATH_OF_CONTEXT.get(contexts.pop() or "") if len(contexts) == 1 else None


def zephyr_records(builds: list[Path]) -> list[console.Record]:
    """Zephyr's latency_measure figures (ZEPHYR records: metric, description,
    cycles, ns) from its build's console, if it ran to the end."""
    for build in builds:
        log = BuildFolder(build).console_log
        if build.name != LATENCY_MEASURE or not log.is_file():
            continue
        text = log.read_text(errors="replace")
        if _ZEPHYR_PASSED not in text:
            return []
        return [console.Record("ZEPHYR", match.groupdict())
                for match in map(_ZEPHYR_FIGURE.match, text.splitlines()) if match]
    return []


def scenarios(root: Path) -> list[str]:
    """The floor's twister scenarios, as its testcase files name them."""
    import yaml

    return sorted(name for path in root.glob(SCENARIO_FILES)
                  for name in (yaml.safe_load(path.read_text()).get("tests") or {}) if name.startswith(PREFIX))
