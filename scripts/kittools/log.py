# SPDX-License-Identifier: Apache-2.0
"""The kit's progress lines: one logger, one format. Every line reads
`[kit] <message>` on stdout, as CI logs always have; `kit test`'s two lanes
say things at once, and a handler writes each line in one write."""

from __future__ import annotations

import logging
import re
import sys
from collections.abc import Iterator
from contextlib import contextmanager

LOG = logging.getLogger("kittools")


class _Stdout(logging.StreamHandler):
    """The stdout of the moment, not the one at import: pytest's capture and
    a caller's redirection swap sys.stdout after the kit is imported."""

    def emit(self, record: logging.LogRecord) -> None:
        self.stream = sys.stdout
        super().emit(record)


if not LOG.handlers:
    _handler = _Stdout()
    _handler.setFormatter(logging.Formatter("[kit] %(message)s"))
    LOG.addHandler(_handler)
    LOG.setLevel(logging.INFO)
    LOG.propagate = False


def say(message: str) -> None:
    """A progress line."""
    LOG.info(message)


class _Failures(logging.Handler):
    """Keeps the progress lines that report a failure: a check's "FAIL", a
    count with failures in it."""

    MARK = re.compile(r"\bFAIL\b|\b[1-9][0-9]* failed\b")

    def __init__(self) -> None:
        super().__init__()
        self.lines: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        message = record.getMessage()
        if self.MARK.search(message):
            self.lines.append(message)


@contextmanager
def failures_kept() -> Iterator[list[str]]:
    """The failure lines said while the block runs (a long run's tail can
    then say what failed, where CI shows only its last lines)."""
    handler = _Failures()
    LOG.addHandler(handler)
    try:
        yield handler.lines
    finally:
        LOG.removeHandler(handler)
