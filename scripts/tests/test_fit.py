# SPDX-License-Identifier: Apache-2.0
"""A build that does not fit its board is said once, with the linker's
numbers and the board's size (kittools.suite.fit), for any deployment."""

from __future__ import annotations

import json
from pathlib import Path

from kittools.suite import fit

LINKER = ("/usr/bin/arm-none-eabi-ld: zephyr/zephyr_pre0.elf section `noinit' will not fit in region `RAM'\n"
          "/usr/bin/arm-none-eabi-ld: region `RAM' overflowed by 7984 bytes\n"
          "collect2: error: ld returned 1 exit status\n")


def _twister_out(root: Path, status: str, log: str) -> Path:
    out = root / "twister-out"
    build = out / "qemu_cortex_m3_ti_lm3s6965" / "deployment" / "kit.rtos"
    (build / "zephyr").mkdir(parents=True)
    (build / "CMakeCache.txt").write_text("BOARD:STRING=qemu_cortex_m3\n")
    (build / "zephyr" / ".config").write_text("CONFIG_SRAM_SIZE=64\nCONFIG_FLASH_SIZE=256\n")
    (build / "build.log").write_text(log)
    suites = [{"name": "deployment/kit.rtos", "platform": "qemu_cortex_m3/ti_lm3s6965", "status": status}]
    (out / "twister.json").write_text(json.dumps({"testsuites": suites}))
    return out


def test_a_build_that_overflows_its_ram_is_said_with_the_numbers(tmp_path: Path):
    (overflow,) = fit.overflows(_twister_out(tmp_path, "error", LINKER))
    assert (overflow.region, overflow.over, overflow.size) == ("RAM", 7984, 65536)
    text = overflow.text()
    assert "kit.rtos does not fit: its RAM overflowed by 7,984 B" in text
    assert "the board has 65,536 B, the build needs 73,520 B" in text


def test_a_build_that_passed_or_failed_otherwise_says_nothing(tmp_path: Path):
    assert fit.overflows(_twister_out(tmp_path / "a", "passed", LINKER)) == []
    assert fit.overflows(_twister_out(tmp_path / "b", "error", "error: 'x' was not declared in this scope\n")) == []
    assert fit.overflows(tmp_path / "nothing") == []


def test_a_build_that_never_linked_is_left_out_of_the_suites_builds(tmp_path: Path):
    """The other models' builds are still compared (kit compare, the reports)."""
    from kittools.suite import results

    out = _twister_out(tmp_path, "error", LINKER)
    assert results.suite_builds(out) == []
    elf = out / "qemu_cortex_m3_ti_lm3s6965" / "deployment" / "kit.rtos" / "zephyr" / "zephyr.elf"
    elf.touch()  # it linked, then failed: counted, and listed
    assert [build.name for _, build in results.suite_builds(out)] == ["kit.rtos"]
