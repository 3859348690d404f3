# SPDX-License-Identifier: Apache-2.0
"""The deployment from the ground: F´'s integration-test API through
fprime-gds, against a build of the ground scenario (kit test boots each one,
with fprime-gds on its link: kittools/link/ground.py).

QEMU counts instructions (icount); the station runs it in real time (idle
time in host time: GroundStation says why), but host and deployment clocks
still drift, so rates are checked on the F´ time tags the deployment puts
on its telemetry, never on the host's clock.
"""

from __future__ import annotations

import time
from typing import Any

import pytest

TIMEOUT_S = 10  # whole seconds: the API arms signal.alarm with it
# Controller::SETPOINT_LIMIT (app/Components/Controller/Controller.hpp)
SETPOINT_LIMIT = 20000
# Health's 10 Hz cycles a check watches: a ping unanswered for 3 of them is
# health's warning (PING_WARN_CYCLES, app/Top/KitTopologyDefs.hpp)
HEALTH_WATCH_S = 2.0


def _services(api: Any, command: str) -> None:
    """Skips a test of F´'s health and version services on a build whose
    board profile leaves them out (CONFIG_KIT_SERVICE_CDH: its dictionary
    has neither; the firmware's record says KIT HEALTH services=absent)."""
    if command not in api.dictionaries.command_name:
        pytest.skip("this board's profile leaves F´'s health and version services out for this model")


def test_noop_completes_with_its_events(fprime_test_api: Any) -> None:
    fprime_test_api.send_and_assert_command("Kit.cmdDisp.CMD_NO_OP", max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.cmdDisp.NoOpReceived", timeout=TIMEOUT_S)


@pytest.mark.parametrize("setpoint", [0, 1500, -SETPOINT_LIMIT, SETPOINT_LIMIT])
def test_setpoint_accepted_and_reported(fprime_test_api: Any, setpoint: int) -> None:
    # The handler's event may precede the dispatcher's: checked on its own
    fprime_test_api.send_and_assert_command("Kit.controller.SET_SETPOINT", [setpoint], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.controller.SetpointChanged", [setpoint], timeout=TIMEOUT_S)
    fprime_test_api.assert_telemetry("Kit.controller.Setpoint", setpoint, timeout=TIMEOUT_S)


@pytest.mark.parametrize("setpoint", [SETPOINT_LIMIT + 1, -SETPOINT_LIMIT - 1, 2**31 - 1])
def test_setpoint_out_of_range_rejected(fprime_test_api: Any, setpoint: int) -> None:
    fprime_test_api.send_command("Kit.controller.SET_SETPOINT", [setpoint])
    fprime_test_api.assert_event("Kit.controller.SetpointRejected", [setpoint, SETPOINT_LIMIT], timeout=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.cmdDisp.OpCodeError", timeout=TIMEOUT_S)


def test_load_commands_complete(fprime_test_api: Any) -> None:
    fprime_test_api.send_and_assert_command("Kit.load.SET_SLICE", [0], max_delay=TIMEOUT_S)
    fprime_test_api.send_and_assert_command("Kit.load.SET_BURST", [0, 0], max_delay=TIMEOUT_S)


def test_telemetry_every_tenth_of_a_second(fprime_test_api: Any) -> None:
    """The 1 kHz group's cycle count changes every tick; the telemetry
    service (10 Hz group) sends it once per run: consecutive samples are
    100 ms apart in the deployment's time, and 100 cycles apart."""
    samples = fprime_test_api.await_telemetry_count(6, "Kit.timing.FastCycles", timeout=TIMEOUT_S)
    times = [sample.get_time().get_float() for sample in samples]
    values = [sample.get_val() for sample in samples]
    gaps = [later - earlier for earlier, later in zip(times, times[1:], strict=False)]
    steps = [later - earlier for earlier, later in zip(values, values[1:], strict=False)]
    assert all(abs(gap - 0.1) < 0.002 for gap in gaps), gaps
    assert all(step == 100 for step in steps), steps


def test_version_reported_on_command(fprime_test_api: Any) -> None:
    _services(fprime_test_api, "Kit.version.VERSION")
    fprime_test_api.send_and_assert_command("Kit.version.VERSION", ["FRAMEWORK"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.version.FrameworkVersion", timeout=TIMEOUT_S)
    fprime_test_api.send_and_assert_command("Kit.version.VERSION", ["PROJECT"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.version.ProjectVersion", timeout=TIMEOUT_S)


def test_health_checks_without_warning_at_rest(fprime_test_api: Any) -> None:
    """Health's checking, turned on again from the ground, pings every entry
    each 10 Hz cycle; at rest no entry is late (HLTH_PING_WARN) over 20
    cycles, with the link busy with this test's commands and telemetry."""
    _services(fprime_test_api, "Kit.health.HLTH_ENABLE")
    fprime_test_api.send_and_assert_command("Kit.health.HLTH_ENABLE", ["ENABLED"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.health.HLTH_CHECK_ENABLE", ["ENABLED"], timeout=TIMEOUT_S)
    time.sleep(HEALTH_WATCH_S)
    fprime_test_api.assert_event_count(0, "Kit.health.HLTH_PING_WARN")
