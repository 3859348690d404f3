# SPDX-License-Identifier: Apache-2.0
"""F´'s first check of a platform: a NO_OP from the ground, and its events."""


def test_noop_completes(fprime_test_api):
    fprime_test_api.send_and_assert_command("Kit.cmdDisp.CMD_NO_OP", max_delay=5.0)
    fprime_test_api.assert_event("Kit.cmdDisp.NoOpReceived", timeout=5.0)
