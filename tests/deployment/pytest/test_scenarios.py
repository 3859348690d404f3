# SPDX-License-Identifier: Apache-2.0
"""Every scenario of the suite, played on one build per execution model and
board (twister's pytest harness, tests/deployment/testcase.yaml).

Each test boots the build under QEMU (the `dut` fixture: a fresh boot per
test), sends the scenario's name on the console (the firmware asks at boot:
CONFIG_KIT_SCENARIO_AT_BOOT, app/scenarios/Scenarios.cpp) and reads the
console until the run's end line or its fatal report. The lines must match
the scenario's expectations below, in order. Every console line is kept in
<build>/kit-runs/<scenario>.log: `scripts/kit` reads its results from there.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest
import yaml
from twister_harness import DeviceAdapter
from twister_harness.exceptions import TwisterHarnessTimeoutException

# A line that ends a run: the end line, the kit's halt line, or the halt
# marker every fatal path prints last (app/src/Fatal.cpp)
END = re.compile(r"^KIT (END|HALT) |PROJECT EXECUTION FAILED")
SELECT = re.compile(r"^KIT SELECT scenarios=")
RUNS = "kit-runs"

# Seconds of host time a scenario may take; the soak, this much more per
# virtual minute (CONFIG_KIT_SOAK_CHECKPOINTS of CONFIG_KIT_SOAK_CHECKPOINT_SECONDS). A baremetal model never idles,
# so icount skips no time and every virtual second is emulated whole: on
# 2026-12-05 qemu_cortex_m3 baremetal_passive's two-minute soak took 288 s
# beside one other QEMU, and ran past 420 s with a second build and the
# porting step's compiles beside it (both soaks, and the time-out, in
# `kit test --update-baseline` of e5e0d0f): host time, not the firmware's
DEFAULT_TIMEOUT_S = 180.0
SOAK_TIMEOUT_PER_MINUTE_S = 300.0

# The comparison run. In order: the banner (variant, board, 1 kHz tick,
# the board's icount shift: 0 on a real board), every rate group ran exactly the cycles its divider gives (the
# firmware prints both, the regex requires them equal) with zero slips
# (baremetal's 1 kHz group: the firmware fails the run on a slip where the
# board expects the model to hold it, CONFIG_KIT_DEADLINES_EXPECTED;
# mps2/an385 measures that it cannot, and the budget gate holds it to its
# baseline), nothing was allocated after init, the uplinked NO_OP completed
# OK and its event reached the downlink, the 1 kHz group's queue held at most
# the one pending cycle, or two where it slipped (its QUEUE line: the sizing
# advice reads every queue's high-water mark from these), health's pings
# all answered with no warning where the build has health, the downlink's
# and the event service's queues dropped nothing, the 1 kHz group's
# dispatch stage by stage (DispatchStages.hpp), and the verdict.
def _nominal(variant: str, fast_slips: str, passive: bool = False) -> list[str]:
    # Passive rate groups have no queue: their path is the tick taken, then
    # the first member (one mark, two stages)
    marks, last_stage = ("1", "taken_to_member") if passive else ("5", "received_to_member")
    stages = (rf"KIT STAGES rg=FASTEST complete=[1-9][0-9]* incomplete={'0' if fast_slips == '0' else '[0-9]+'} "
              rf"marks={marks} mark_cycles=[1-9][0-9]*$")
    return [
        rf"KIT BANNER variant={variant} board=\S+ .* tick_hz=1000 .* icount_shift={ICOUNT_SHIFT} ",
        # the RAM file system, where the build has one: a fresh boot formats it
        RAM_FILE_SYSTEM_COLD,
        rf"KIT RG name=FASTEST hz=[1-9][0-9]* cycles=([1-9][0-9]*) expected=\1 slips={fast_slips} ",
        # every slower group: its own check (slower_groups_held), for any
        # number of them
        SLOWER_GROUP_HELD,
        # every cycle of the 1 kHz group broken into stages (none missing a
        # mark where none slipped), the probe's cost measured
        stages,
        rf"KIT STAGE rg=FASTEST name={last_stage} cycles_min=[1-9]",
        r"KIT HEAP fprime_peak=[1-9][0-9]* .* after_init=0 failures=0 ",
        r"KIT CMD frame=0 opcode=0x[0-9a-f]+ noop=yes response=OK",
        r"KIT DOWNLINK .* malformed=0 noop_events=1 uncounted=0",
        # F´'s health and version services, where the board's profile has
        # them (CONFIG_KIT_SERVICE_CDH): every ping entry answered (the
        # firmware fails the run on one never answered), no warning at
        # rest, the versions reported once
        HEALTH_AT_REST,
        *([] if passive else [r"KIT QUEUE name=FASTEST depth=2 slot_bytes=[1-9][0-9]* high_water=[12] dropped=0$"]),
        # the downlink and the event service lost nothing to a full queue
        EVENTS_KEPT,
        r"KIT QUEUE name=comQueue depth=[1-9][0-9]* slot_bytes=[1-9][0-9]* high_water=[0-9]+ dropped=0$",
    ]


# A slower rate group ran exactly its cycles, without a slip
SLOWER_GROUP_HELD = r"KIT RG name=(?!FASTEST )\S+ hz=[1-9][0-9]* cycles=([1-9][0-9]*) expected=\1 slips=0 "

# Stands for the deployment's fastest rate group, the first the firmware
# reports (its RATE_GROUPS, fastest first: app/src/Deployment.hpp)
FASTEST = "FASTEST"
FIRST_GROUP = re.compile(r"^KIT (?:RG name=|SWEEP .* rg=)(\S+)")


def fastest_group(lines: list[str]) -> str:
    """The deployment's fastest rate group, as the run names it."""
    for line in lines:
        found = FIRST_GROUP.search(line)
        if found:
            return found.group(1)
    return FASTEST  # no group reported: every expectation naming it fails


def slower_groups_held(lines: list[str], fastest: str) -> list[str]:
    """The RG lines of the slower groups that missed a cycle or slipped."""
    held = re.compile(SLOWER_GROUP_HELD.replace(FASTEST, re.escape(fastest)))
    return [line for line in lines if line.startswith("KIT RG name=")
            and not line.startswith(f"KIT RG name={fastest} ") and not held.search(line)]


# bulk_bytes: the file downlink's file, 0 where the build has none
RAM_FILE_SYSTEM_COLD = (r"KIT RAMFS mount=(absent|formatted files=[1-9][0-9]* file_bytes=[1-9][0-9]* "
                        r"bulk_bytes=[0-9]+ bytes=[1-9][0-9]*)$")

HEALTH_AT_REST = (r"KIT HEALTH services=(absent|present entries=[1-9][0-9]* warnings=0 fatals=0)$")


# Stands for the build's icount shift (CONFIG_QEMU_ICOUNT_SHIFT; a real
# board, run through twister's device testing, has none and prints 0)
ICOUNT_SHIFT = "ICOUNT_SHIFT"


# The event service's queue lost nothing: EventManager drops an event its
# queue cannot take, and an operator never sees it
EVENTS_KEPT = r"KIT QUEUE name=events depth=[1-9][0-9]* slot_bytes=[1-9][0-9]* high_water=[0-9]+ dropped=0$"


# Faults the system must survive: each malformed command answered with its
# error, the injected overrun detected as a slip of the 1 kHz group only (and
# as its event), the overflowed load queue's drops counted and reported (the
# load's, not an event: every one reached the event service), every cycle
# still completed, a later NO_OP still OK.
FAULTS = [
    r"KIT RG name=FASTEST hz=[1-9][0-9]* cycles=([1-9][0-9]*) expected=\1 slips=[1-9]",
    r"KIT CMD frame=0 .* response=INVALID_OPCODE expected=INVALID_OPCODE",
    r"KIT CMD frame=1 .* response=FORMAT_ERROR expected=FORMAT_ERROR",
    r"KIT CMD frame=2 .* response=FORMAT_ERROR expected=FORMAT_ERROR",
    r"KIT CMD frame=3 .* response=VALIDATION_ERROR expected=VALIDATION_ERROR",
    r"KIT CMD frame=4 .* response=VALIDATION_ERROR expected=VALIDATION_ERROR",
    r"KIT CMD frame=9 .* noop=yes response=OK",
    r"KIT FAULTS invalid_opcode_events=[1-9][0-9]* malformed_events=[2-9][0-9]* opcode_error_events=[2-9][0-9]* "
    r"slips=[1-9][0-9]* slip_events=[1-9][0-9]* other_slips=0 load_dropped=[1-9][0-9]* drop_events=[1-9][0-9]* "
    r"cycles_complete=yes",
    EVENTS_KEPT,
    r"KIT END variant=\w+ result=PASS",
]

# CONFIG_KIT_SOAK_CHECKPOINTS checkpoints of virtual time: no slip (the
# firmware's verdict where the board expects the model to hold its
# deadlines), every NO_OP answered, nothing allocated after init, stack
# high-water marks flat after the first checkpoint, no health warning in
# any, every ping entry answered over the soak. LAST stands for the build's
# last checkpoint, LENGTH for its checkpoints' seconds.
def _soak(variant: str, slips: str) -> list[str]:
    return [
        rf"KIT SOAK checkpoint=1 seconds=LENGTH slips={slips} cycles_complete=yes .* health_warnings=0 noop=OK",
        rf"KIT SOAK checkpoint=LAST seconds=LENGTH slips={slips} cycles_complete=yes .* stack_flat=yes .* heap_after_init=0 "
        r"health_warnings=0 noop=OK",
        HEALTH_AT_REST,
        rf"KIT END variant={variant} result=PASS",
    ]


# Fatal faults: the run must end in the fatal report, at once (the kit's
# halt line, not a time-out)
def _stack_overflow(context: str, first: str) -> list[str]:
    return [first, rf"KIT HALT reason=stack_overflow code=2 context={context} expected=yes"]


# Stands for the rtos thread the dispatcher runs on: its own, or the shared
# thread where the build's band of levels holds its level (see
# dispatcher_thread())
DISPATCHER_THREAD = "DISPATCHER_THREAD"
BAREMETAL_STACK_FAULT = r"KIT FATAL stack=main guard_word=[0-9]+ address=0x[0-9a-f]+: stack overflow"
# Stands for what F´ prints for the injected assert (Fw/Types/Assert.cpp) at
# the build's assert level (modules/fprime/Kconfig): see assert_report()
ASSERT_REPORT = "ASSERT_REPORT"
ASSERT = [
    ASSERT_REPORT,
    r"KIT FATAL event=0x[0-9a-f]+",
    r"KIT HALT reason=kernel_panic code=4 context=\w+ expected=yes",
]
# rtos reports an assert on a thread of its own (rtos/AssertReport.cpp): the
# halt is that thread's, with its stack's line (the report's depth)
RTOS_ASSERT = [
    ASSERT_REPORT,
    r"KIT FATAL event=0x[0-9a-f]+",
    r"KIT STACK name=assert size=[0-9]+ used=[0-9]+",
    r"KIT HALT reason=kernel_panic code=4 context=assert expected=yes",
]

# Health's side of the sweep, where the build has health: the longest a ping
# waited for its answer on each axis, and the first level where that reached
# health's warning deadline (or none)
HEALTH_ON_THE_LOAD_AXES = (r"KIT HEALTHBREAK axis=slice (services=absent|level=([0-9]+|none) ping_max=[0-9]+ "
                           r"warn=[1-9][0-9]*)$")

# Background-load sweep: at zero load no group misses a deadline; the
# cooperative loop must break its 1 kHz group within the sweep (a slice
# longer than the period cannot be preempted), the preemptive one must not;
# no load message is dropped. The budgeted policy defers what does not fit
# before the next tick and may shed load (counted per point); where it
# breaks is the result, asserted only to be in range.
EXPECTED: dict[str, dict[str, list[str]]] = {
    "baremetal": {
        "nominal": [*_nominal("baremetal", "[0-9]+"), r"KIT END variant=baremetal result=PASS"],
        "load": [
            r"KIT BANNER variant=baremetal ",
            r"KIT SWEEP axis=slice point=0 level=0 unit=us .* rg=FASTEST ",
            r"KIT BREAK axis=slice rg=FASTEST level=[0-9]+ unit=us$",
            HEALTH_ON_THE_LOAD_AXES,
            r"KIT LOAD commands=OK .* dropped=0",
            r"KIT END variant=baremetal result=PASS",
        ],
        "faults": FAULTS,
        "soak": _soak("baremetal", "[0-9]+"),
        "stack_overflow": _stack_overflow("main", BAREMETAL_STACK_FAULT),
        "assert": ASSERT,
    },
    "baremetal_budgeted": {
        "nominal": [
            *_nominal("baremetal_budgeted", "[0-9]+"),
            r"KIT SCHED name=FASTEST critical=yes anticipated=[1-9][0-9]* deferrals=0 ",
            r"KIT SCHED name=guard guard=[1-9][0-9]* guard_max=[1-9][0-9]*",
            r"KIT END variant=baremetal_budgeted result=PASS",
        ],
        "load": [
            r"KIT BANNER variant=baremetal_budgeted ",
            r"KIT SWEEP axis=slice point=0 level=0 unit=us .* rg=FASTEST .* load_dropped=0",
            r"KIT BREAK axis=slice rg=FASTEST level=([0-9]+|none) unit=us$",
            HEALTH_ON_THE_LOAD_AXES,
            r"KIT LOAD commands=OK ",
            r"KIT SCHED name=FASTEST critical=yes ",
            r"KIT END variant=baremetal_budgeted result=PASS",
        ],
        "faults": FAULTS,
        "soak": _soak("baremetal_budgeted", "[0-9]+"),
        "stack_overflow": _stack_overflow("main", BAREMETAL_STACK_FAULT),
        "assert": ASSERT,
    },
    "baremetal_passive": {
        "nominal": [*_nominal("baremetal_passive", "[0-9]+", passive=True),
                    r"KIT END variant=baremetal_passive result=PASS"],
        "load": [
            r"KIT BANNER variant=baremetal_passive ",
            r"KIT SWEEP axis=slice point=0 level=0 unit=us .* rg=FASTEST ",
            r"KIT BREAK axis=slice rg=FASTEST level=([0-9]+|none) unit=us$",
            HEALTH_ON_THE_LOAD_AXES,
            r"KIT LOAD commands=OK .* dropped=0",
            r"KIT END variant=baremetal_passive result=PASS",
        ],
        "faults": FAULTS,
        "soak": _soak("baremetal_passive", "[0-9]+"),
        "stack_overflow": _stack_overflow("main", BAREMETAL_STACK_FAULT),
        "assert": ASSERT,
    },
    "rtos": {
        "nominal": [*_nominal("rtos", "0"), r"KIT END variant=rtos result=PASS"],
        "load": [
            r"KIT BANNER variant=rtos ",
            r"KIT SWEEP axis=slice point=0 level=0 unit=us .* rg=FASTEST .* slips=0 late_starts=0 ",
            r"KIT BREAK axis=slice rg=FASTEST level=none unit=us",
            HEALTH_ON_THE_LOAD_AXES,
            r"KIT LOAD commands=OK .* dropped=0",
            r"KIT END variant=rtos result=PASS",
        ],
        "faults": FAULTS,
        "soak": _soak("rtos", "0"),
        "stack_overflow": _stack_overflow(DISPATCHER_THREAD, r"ZEPHYR FATAL ERROR 2: Stack overflow"),
        "assert": RTOS_ASSERT,
    },
}
SCENARIOS = ("nominal", "load", "faults", "soak", "stack_overflow", "assert")
#: The kit's variants (their one table); each has its expectations above
VARIANTS_FILE = Path(__file__).resolve().parents[3] / "app" / "variants.yaml"


def check_expectations(variant: str) -> None:
    """Fail a run on a variant the table lists and EXPECTED does not, or one
    the table does not list, with what to fix (scripts/tests/test_variants.py
    checks the table against EXPECTED before any build)."""
    table = list(yaml.safe_load(VARIANTS_FILE.read_text())["variants"])
    assert variant in table, f"the build's variant {variant} is not in {VARIANTS_FILE.name}: {table}"
    missing = [name for name in table if name not in EXPECTED]
    assert not missing, f"no expectations for {', '.join(missing)} ({VARIANTS_FILE.name}): add them to EXPECTED"


def config_value(build_dir: Path, name: str, default: str | None = None) -> str:
    """A string or int option of the build's Kconfig (zephyr/.config), or
    `default` where the build does not set it."""
    match = re.search(rf'^{name}="?([^"\n]*)"?$', (build_dir / "zephyr" / ".config").read_text(), re.MULTILINE)
    assert match or default is not None, f"{build_dir} has no {name}"
    return match.group(1) if match else str(default)


def assert_report(build_dir: Path) -> str:
    """The injected assert's line: its file's path (relative, or full with
    FILE_NAME asserts) and line, or with FILE_ID asserts (the fprime-small
    profile) the file's 32-bit id and line; then its argument."""
    if config_value(build_dir, "CONFIG_FPRIME_ASSERT_FILE_ID", default="n") == "y":
        return r"Assert: 0x[0-9a-f]{8}:[0-9]+ 42"
    return r'Assert: ".*app/Components/Faults/Faults.cpp:[0-9]+" 42'


def dispatcher_thread(build_dir: Path) -> str:
    """The rtos thread the dispatcher runs on: "services" where its level
    (the build's priority table, as FPP generated it) is in the band that
    shares one thread (CONFIG_KIT_RTOS_SHARED_LEVEL_LOW/HIGH,
    rtos/Os/SharedThread.hpp), else its own, "cmdDisp"."""
    high = int(config_value(build_dir, "CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH", default="0"))
    if high == 0:
        return "cmdDisp"
    low = int(config_value(build_dir, "CONFIG_KIT_RTOS_SHARED_LEVEL_LOW"))
    constants = (build_dir / "app" / "Top" / "FppConstantsAc.hpp").read_text()
    # The Priorities namespace, to the next one (Stacks)
    priorities = re.search(r"namespace Priorities \{(.*?)(namespace |\Z)", constants, re.DOTALL)
    assert priorities, f"{build_dir}: no Priorities in the topology's FppConstantsAc.hpp"
    level = re.search(r"\bcmdDisp = ([0-9]+)", priorities.group(1))
    assert level, f"{build_dir}: no dispatcher in the priority table"
    return "services" if low <= int(level.group(1)) <= high else "cmdDisp"


def for_build(build_dir: Path, expected: list[str]) -> list[str]:
    """A scenario's expectations with the build's own values in place of
    ICOUNT_SHIFT, ASSERT_REPORT and DISPATCHER_THREAD."""
    values = {ICOUNT_SHIFT: config_value(build_dir, "CONFIG_QEMU_ICOUNT_SHIFT", default="0"),
              ASSERT_REPORT: assert_report(build_dir)}
    if DISPATCHER_THREAD in "".join(expected):
        values[DISPATCHER_THREAD] = dispatcher_thread(build_dir)
    for placeholder, value in values.items():
        expected = [pattern.replace(placeholder, value) for pattern in expected]
    if config_value(build_dir, "CONFIG_KIT_DISPATCH_STAGES", default="n") != "y":
        # a build without the stage marks (the fprime-small profile) has no STAGE lines
        expected = [pattern for pattern in expected if not pattern.startswith("KIT STAGE")]
    return expected


def unmatched(lines: list[str], expected: list[str]) -> list[str]:
    """The expectations the lines do not meet, in order (each on a later line
    than the one before it): [] when all are met."""
    position = 0
    for index, pattern in enumerate(expected):
        regex = re.compile(pattern)
        while position < len(lines) and not regex.search(lines[position]):
            position += 1
        if position == len(lines):
            return expected[index:]
        position += 1
    return []


def read_until_end(dut: DeviceAdapter, timeout_s: float) -> tuple[list[str], bool]:
    """Console lines until a run's end (True) or `timeout_s` (False)."""
    lines: list[str] = []
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            line = dut.readline(timeout=min(5.0, max(0.1, deadline - time.monotonic())), print_output=False)
        except TwisterHarnessTimeoutException:
            continue
        lines.append(line.rstrip("\r\n"))
        if END.search(lines[-1]):
            return lines, True
    return lines, False


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_scenario(dut: DeviceAdapter, scenario: str) -> None:
    build = Path(dut.device_config.build_dir)
    variant = config_value(build, "CONFIG_KIT_VARIANT_NAME")
    check_expectations(variant)
    expected = for_build(build, EXPECTED[variant][scenario])
    timeout_s = DEFAULT_TIMEOUT_S
    if scenario == "soak":
        checkpoints = int(config_value(build, "CONFIG_KIT_SOAK_CHECKPOINTS"))
        seconds = int(config_value(build, "CONFIG_KIT_SOAK_CHECKPOINT_SECONDS"))
        expected = [pattern.replace("checkpoint=LAST", f"checkpoint={checkpoints}").replace(
            "seconds=LENGTH", f"seconds={seconds}") for pattern in expected]
        if checkpoints == 1:  # one checkpoint: its line is the first's and the last
            expected = expected[1:]
        timeout_s += SOAK_TIMEOUT_PER_MINUTE_S * checkpoints * seconds / 60
    prompt, asked = [], False
    deadline = time.monotonic() + DEFAULT_TIMEOUT_S
    while not asked and time.monotonic() < deadline:
        try:
            prompt.append(dut.readline(timeout=5.0, print_output=False).rstrip("\r\n"))
        except TwisterHarnessTimeoutException:
            continue
        asked = bool(SELECT.search(prompt[-1]))
    assert asked, f"the firmware never asked for a scenario (CONFIG_KIT_SCENARIO_AT_BOOT): {prompt[-5:]}"
    dut.write(f"{scenario}\n".encode())
    lines, ended = read_until_end(dut, timeout_s)
    runs = build / RUNS
    runs.mkdir(exist_ok=True)
    (runs / f"{scenario}.log").write_text("\n".join(prompt + lines) + "\n")
    fastest = fastest_group(lines)
    missing = unmatched(lines, [pattern.replace(FASTEST, re.escape(fastest)) for pattern in expected])
    missing += [f"a slower group held its cycles: {line}" for line in slower_groups_held(lines, fastest)
                if scenario == "nominal"]
    tail = "\n".join(lines[-15:])
    assert ended, f"{variant} {scenario}: no end line within the time-out; last lines:\n{tail}"
    assert not missing, f"{variant} {scenario}: not found, in order: {missing}; last lines:\n{tail}"
