# SPDX-License-Identifier: Apache-2.0
"""The ground link proves its uplink before the first test.

fprime-gds's test client publishes commands on a ZeroMQ PUB socket it has
just connected, and ZeroMQ drops what a PUB sends before that connection
completes (its "slow joiner"). A fresh-clone run lost the first test's NO_OP
that way: sent 7 ms after the client connected, its frame never reached the
deployment (LinkHealth.FramesDetected stayed 0 until the next command). So a
NO_OP is sent until one is answered, at most UPLINK_TRIES times, and the
tests run on a link known to carry commands; a link that never answers
fails every test with one message.

After the last test the deployment measures one segment (Timing's
MEASURE_SEGMENT, where the station asks for it with --kit-stacks-ticks),
at whose end it prints every stack's high-water mark: the suite's paths
(parameter files, file transfers, sequences, warm restarts) reach no other
scenario's, and the station keeps these marks (kittools.suite.ground_checks)."""

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fprime_gds.common.history.test import TestHistory

from kittools.link.dictionary import Dictionary

UPLINK_TRIES = 5
STACKS_OPTION = "--kit-stacks-ticks"
# Far above a NO_OP's round trip (well under a second on either board), so
# that a late answer to one try cannot land in the first test's history
ANSWER_S = 5


def keep_receive_order(api: Any) -> None:
    """The test API's histories in the order the ground received them.
    fprime-gds keeps them in flight-software time order (fsw_order), but the
    deployment's time starts at zero at every boot, a warm restart's too: a
    command sent after a restart, its answer stamped 0.2 s, was sorted in
    before the last boot's answers (11.8 s), and the API's search from
    "now" found an answer of the last boot instead of its own (CI: the
    parameter tests after a warm restart). One boot at a time, receive
    order is time order."""
    coders = api.pipeline.coders
    for kind, register, remove in (
            ("command_history", coders.register_command_consumer, coders.remove_command_consumer),
            ("event_history", coders.register_event_consumer, coders.remove_event_consumer),
            ("telemetry_history", coders.register_channel_consumer, coders.remove_channel_consumer)):
        remove(getattr(api, kind))
        history = TestHistory()
        register(history)
        setattr(api, kind, history)
    api.fsw_ordered = False


@pytest.fixture(scope="session", autouse=True)
def uplink_proven(fprime_test_api_session: Any) -> None:
    api = fprime_test_api_session
    keep_receive_order(api)
    names = Dictionary.read(Path(api.dictionaries.dictionary_path))
    for _ in range(UPLINK_TRIES):
        if api.send_and_await_event(names.noop_command, events=names.noop_event,
                                    timeout=ANSWER_S) is not None:
            return
    pytest.fail(f"the ground link answered none of {UPLINK_TRIES} NO_OPs ({ANSWER_S} s each)")


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(STACKS_OPTION, type=int, default=0,
                     help="after the last test, ask the deployment for a segment of this many ticks (whole "
                          "hyperperiods), at whose end it prints its stacks' high-water marks; 0: do not")


@pytest.fixture(scope="session", autouse=True)
def stacks_after_the_suite(request: pytest.FixtureRequest, fprime_test_api_session: Any) -> Iterator[None]:
    yield
    ticks = request.config.getoption(STACKS_OPTION)
    api = fprime_test_api_session
    owner = Dictionary.read(Path(api.dictionaries.dictionary_path)).owner_of("MEASURE_SEGMENT")
    if ticks and owner is not None:
        # The uplink axis at level 0: no load of the sweep's, one segment
        api.send_and_assert_event(f"{owner}.MEASURE_SEGMENT", ["UPLINK", 0, 0, ticks],
                                  events=[f"{owner}.SegmentRequested"], timeout=ANSWER_S)
