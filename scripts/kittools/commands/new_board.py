# SPDX-License-Identifier: Apache-2.0
"""kit new-board: scaffold a new board's folder (kittools.boards)."""

from __future__ import annotations

import argparse

from kittools.boards.scaffold import new_board
from kittools.log import say


def run(args: argparse.Namespace) -> int:
    # Only Zephyr's board tree is needed (new_board says so if it is missing):
    # no F´ checkout, so a port can be scaffolded before the rest is fetched
    new_board(args.board, args.reference, args.force, say)
    return 0
