# SPDX-License-Identifier: Apache-2.0
"""The ground link proves its uplink before the first test.

fprime-gds's test client publishes commands on a ZeroMQ PUB socket it has
just connected, and ZeroMQ drops what a PUB sends before that connection
completes (its "slow joiner"). A fresh-clone run lost the first test's NO_OP
that way: sent 7 ms after the client connected, its frame never reached the
deployment (LinkHealth.FramesDetected stayed 0 until the next command). So a
NO_OP is sent until one is answered, at most UPLINK_TRIES times, and the
tests run on a link known to carry commands; a link that never answers
fails every test with one message."""

from typing import Any

import pytest

UPLINK_TRIES = 5
# Far above a NO_OP's round trip (well under a second on either board), so
# that a late answer to one try cannot land in the first test's history
ANSWER_S = 5


@pytest.fixture(scope="session", autouse=True)
def uplink_proven(fprime_test_api_session: Any) -> None:
    api = fprime_test_api_session
    for _ in range(UPLINK_TRIES):
        if api.send_and_await_event("Kit.cmdDisp.CMD_NO_OP", events="Kit.cmdDisp.NoOpReceived",
                                    timeout=ANSWER_S) is not None:
            return
    pytest.fail(f"the ground link answered none of {UPLINK_TRIES} NO_OPs ({ANSWER_S} s each)")
