# SPDX-License-Identifier: Apache-2.0
"""The boards of the suite: those run under QEMU (tests/deployment) and the
real boards, built and not run (tests/boards)."""

from __future__ import annotations

from pathlib import Path

from kittools.boards.suites import BUILD_ONLY_SUITE as BOARDS_SUITE_FILE
from kittools.workspace import KIT_ROOT, KitError, check_board

SUITE = KIT_ROOT / "tests" / "deployment" / "testcase.yaml"
#: Real boards, built and not run (no emulator): every model's build
BUILD_ONLY_SUITE = KIT_ROOT / BOARDS_SUITE_FILE
TWISTER_OUT = KIT_ROOT / "twister-out"


def suite_boards(suite: Path = SUITE) -> list[str]:
    """The boards the suite runs on: its common platform_allow list (with
    BUILD_ONLY_SUITE, the real boards built and not run)."""
    import yaml  # Zephyr's requirements bring PyYAML into the venv

    try:
        platforms = yaml.safe_load(suite.read_text())["common"]["platform_allow"]
    except (OSError, KeyError, TypeError, yaml.YAMLError) as error:
        raise KitError(f"{suite} names no platforms (common: platform_allow): {error}") from error
    if not platforms:
        raise KitError(f"{suite}: common: platform_allow is empty")
    return [str(p) for p in platforms]


def small_parts(suite: Path = SUITE) -> list[str]:
    """The suite's small parts: boards a scenario of `suite` allows beyond
    its common platform_allow list (the kit's emulated small part,
    qemu_cortex_m3_small), on which only the builds that fit play: the
    fprime-small profile's (tests/deployment's profile.small.* scenarios).
    They have no comparison of the models, so no baseline; twister's tally
    and the ground link judge them."""
    import yaml

    data = yaml.safe_load(suite.read_text())
    common = [str(board) for board in data["common"]["platform_allow"]]
    found: list[str] = []
    for scenario in (data.get("tests") or {}).values():
        for board in (scenario or {}).get("platform_allow") or []:
            if str(board) not in common + found:
                found.append(str(board))
    return found


def is_small_part(board: str) -> bool:
    """A board of small_parts(), as the suite names it or as twister does
    (with its qualifiers: qemu_cortex_m3_small/ti_lm3s6965)."""
    return any(board == small or board.startswith(small + "/") for small in small_parts())


def real_boards() -> list[str]:
    """The boards the kit builds and does not run (tests/boards): every
    model on those of its common list, the fprime-small build on a small one
    (a scenario's list beyond the common one)."""
    return suite_boards(BUILD_ONLY_SUITE) + small_parts(BUILD_ONLY_SUITE)


def is_real_board(board: str) -> bool:
    """A board of real_boards(), however the board target is spelled
    (nucleo_f401re, nucleo_f401re/stm32f401xe)."""
    return check_board(board) in {check_board(real) for real in real_boards()}


def check_runs_here(board: str) -> None:
    """Refuse a real board where the command must run the deployment under
    QEMU: the kit builds it (tests/boards) and runs the suite on it only
    through device testing (kit test --device-testing)."""
    if is_real_board(board):
        raise KitError(f"{board} is a real board: the kit builds it (kit test, tests/boards) but cannot run it "
                       f"here (no emulator; on the board itself: kit test --device-testing --hardware-map FILE). "
                       f"Boards it runs on: {', '.join(suite_boards())}")
    if is_small_part(board):
        raise KitError(f"{board} is a small part: the kit profile's builds of the models do not fit it, so there "
                       f"is nothing to compare; the suite plays the fprime-small profile there (kit test --board "
                       f"{board}). Boards the models are compared on: {', '.join(suite_boards())}")
