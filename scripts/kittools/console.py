# SPDX-License-Identifier: Apache-2.0
"""Parse the firmware's console record.

Every result line the deployment prints has the form
``KIT <KIND> key=value key=value ...`` (see app/src/Report.cpp); this module
turns a console log into typed records. Values stay strings unless asked for.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

_LINE = re.compile(r"^KIT (?P<kind>[A-Z]+)(?: (?P<fields>.*))?$")
_FIELD = re.compile(r"(\w+)=(\S+)")


class ConsoleError(ValueError):
    """The console log lacks what a complete run prints."""


@dataclass(frozen=True)
class Record:
    kind: str
    fields: dict[str, str]

    def int(self, key: str) -> int:
        try:
            return int(self.fields[key], 0)
        except KeyError as exc:
            raise ConsoleError(f"KIT {self.kind} line has no '{key}' field") from exc
        except ValueError as exc:
            raise ConsoleError(f"KIT {self.kind} field {key}={self.fields[key]!r} is not a number") from exc


@dataclass
class Run:
    """One run of one variant, as its console tells it."""

    records: list[Record] = field(default_factory=list)

    def of_kind(self, kind: str) -> list[Record]:
        return [r for r in self.records if r.kind == kind]

    def one(self, kind: str) -> Record:
        found = self.of_kind(kind)
        if len(found) != 1:
            raise ConsoleError(f"expected one KIT {kind} line, found {len(found)}")
        return found[0]

    @property
    def variant(self) -> str:
        return self.one("BANNER").fields["variant"]

    @property
    def passed(self) -> bool:
        return self.one("END").fields.get("result") == "PASS"


def parse_line(line: str) -> Record | None:
    """The record on this console line, or None for any other output."""
    match = _LINE.match(line.strip())
    if match is None:
        return None
    return Record(match["kind"], dict(_FIELD.findall(match["fields"] or "")))


def parse(text: str) -> Run:
    """All records of a console log; raises ConsoleError if the run is incomplete."""
    run = Run([r for r in (parse_line(line) for line in text.splitlines()) if r is not None])
    for kind in ("BANNER", "END"):
        if not run.of_kind(kind):
            raise ConsoleError(f"no KIT {kind} line: the run did not {'start' if kind == 'BANNER' else 'finish'}")
    return run
