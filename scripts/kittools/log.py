# SPDX-License-Identifier: Apache-2.0
"""The kit's progress lines: one logger, one format. Every line reads
`[kit] <message>` on stdout, as CI logs always have; `kit test`'s two lanes
say things at once, and a handler writes each line in one write."""

from __future__ import annotations

import logging
import sys

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
