# SPDX-License-Identifier: Apache-2.0
"""Builds that do not fit their board: for each build twister could not
link because a memory region overflowed, one line with the numbers (the
region, the bytes over, the board's size and what the build needs),
instead of a build failure to look up in its log. Any deployment, any
board: the numbers are the linker's and the build's Kconfig."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from kittools.build.folder import BuildFolder

#: GNU ld's message for a memory region the sections outgrew
_OVERFLOW = re.compile(r"region `(?P<region>\w+)' overflowed by (?P<over>\d+) bytes")
#: The Kconfig size (KiB) of the regions Zephyr's Cortex-M linker script names
_REGION_SIZE = {"RAM": "CONFIG_SRAM_SIZE", "FLASH": "CONFIG_FLASH_SIZE"}
#: Twister's statuses of a configuration that did not pass
_NOT_PASSED = ("error", "failed")


@dataclass(frozen=True)
class Overflow:
    platform: str
    build: str  # the twister scenario (kit.rtos)
    region: str  # the linker's name (RAM, FLASH)
    over: int  # bytes beyond the region
    size: int | None  # the region's bytes on the board, where the build's Kconfig says

    def text(self) -> str:
        needs = (f": the board has {self.size:,} B, the build needs {self.size + self.over:,} B"
                 if self.size is not None else "")
        return (f"{self.platform} {self.build} does not fit: its {self.region} overflowed by {self.over:,} B{needs} "
                "(where it goes: kit sizing and kit footprint of a build that links)")


def overflows(twister_out: Path) -> list[Overflow]:
    """Every configuration of twister's last run in `twister_out` that
    failed on a region overflow, once per region."""
    report = twister_out / "twister.json"
    if not report.is_file():
        return []
    found = []
    for suite in json.loads(report.read_text()).get("testsuites", []):
        if suite.get("status") not in _NOT_PASSED:
            continue
        platform, name = str(suite.get("platform", "")), str(suite.get("name", "")).rsplit("/", 1)[-1]
        for build in BuildFolder.configured_under(twister_out / platform.replace("/", "_")):
            if build.path.name != name or not build.build_log.is_file():
                continue
            config = build.kconfig(missing_ok=True)
            log = build.build_log.read_text(errors="replace")
            regions = {m["region"]: int(m["over"]) for m in _OVERFLOW.finditer(log)}
            for region, over in regions.items():
                kib = config.get(_REGION_SIZE.get(region, ""), "")
                found.append(Overflow(platform, name, region, over, int(kib) * 1024 if kib.isdigit() else None))
    return found
