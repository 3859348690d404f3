# SPDX-License-Identifier: Apache-2.0
"""The conditions of a build, read from the build itself: toolchain, the
Kconfig values and F´ settings a result depends on."""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

# Kconfig values that change what the kit measures
KCONFIG = (
    "CONFIG_BOARD", "CONFIG_KIT_TICK_HZ", "CONFIG_KIT_RUN_TICKS", "CONFIG_SYS_CLOCK_TICKS_PER_SEC",
    "CONFIG_SYS_CLOCK_HW_CYCLES_PER_SEC", "CONFIG_QEMU_ICOUNT", "CONFIG_QEMU_ICOUNT_SHIFT", "CONFIG_MULTITHREADING",
    "CONFIG_NUM_PREEMPT_PRIORITIES", "CONFIG_MAIN_THREAD_PRIORITY", "CONFIG_MAIN_STACK_SIZE",
    "CONFIG_DYNAMIC_THREAD_POOL_SIZE", "CONFIG_DYNAMIC_THREAD_STACK_SIZE", "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE",
    "CONFIG_PICOLIBC", "CONFIG_SIZE_OPTIMIZATIONS",
)
# F´ settings passed as compile definitions (app/kit.cmake)
_FW_DEFINE = re.compile(r"-D(FW_[A-Z_]+)=(\S+)")
# F´ constants from the kit's configuration (app/config)
FPP_CONSTANTS = ("FW_COM_BUFFER_MAX_SIZE", "FW_LOG_STRING_MAX_SIZE", "FW_TLM_BUFFER_MAX_SIZE",
                 "FW_FIXED_LENGTH_STRING_SIZE", "FW_ASSERT_COUNT_MAX")


def kconfig(build_dir: Path) -> dict[str, str]:
    values: dict[str, str] = {}
    config = build_dir / "zephyr" / ".config"
    for line in config.read_text().splitlines():
        if "=" in line and not line.startswith("#"):
            key, value = line.split("=", 1)
            if key in KCONFIG:
                values[key] = value.strip('"')
    return values


def fprime_settings(build_dir: Path) -> dict[str, str]:
    settings: dict[str, str] = {}
    commands = build_dir / "compile_commands.json"
    if commands.is_file():
        for entry in json.loads(commands.read_text()):
            found = dict(_FW_DEFINE.findall(entry.get("command", "")))
            if found:
                settings.update(found)
                break
    for header in build_dir.glob("F-Prime/default/config/FppConstantsAc.hpp"):
        text = header.read_text()
        for name in FPP_CONSTANTS:
            match = re.search(rf"\b{name}\s*=\s*(\d+)", text)
            if match:
                settings[name] = match.group(1)
    return settings


def toolchain(build_dir: Path) -> str:
    cache = build_dir / "CMakeCache.txt"
    match = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.+)$", cache.read_text(), re.MULTILINE) if cache.is_file() else None
    if match is None:
        return "unknown"
    result = subprocess.run([match.group(1).strip(), "--version"], capture_output=True, text=True)
    return result.stdout.splitlines()[0] if result.returncode == 0 and result.stdout else "unknown"


def read(build_dir: Path) -> dict[str, object]:
    return {"toolchain": toolchain(build_dir), "kconfig": kconfig(build_dir), "fprime": fprime_settings(build_dir)}
