# SPDX-License-Identifier: Apache-2.0
"""The conditions of a build, read from the build itself: toolchain, the
Kconfig values and F´ settings a result depends on."""

from __future__ import annotations

import subprocess
from pathlib import Path

from kittools.build.folder import BuildFolder
from kittools.deployment import CACHE_ENTRY, LOCATION_ENTRY, label

# Kconfig values that change what the kit measures
KCONFIG = (
    "CONFIG_BOARD", "CONFIG_KIT_TICK_HZ", "CONFIG_KIT_RUN_TICKS", "CONFIG_SYS_CLOCK_TICKS_PER_SEC",
    "CONFIG_SYS_CLOCK_HW_CYCLES_PER_SEC", "CONFIG_QEMU_ICOUNT", "CONFIG_QEMU_ICOUNT_SHIFT", "CONFIG_MULTITHREADING",
    "CONFIG_NUM_PREEMPT_PRIORITIES", "CONFIG_MAIN_THREAD_PRIORITY", "CONFIG_MAIN_STACK_SIZE",
    "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE",
    "CONFIG_PICOLIBC", "CONFIG_SIZE_OPTIMIZATIONS", "CONFIG_SPEED_OPTIMIZATIONS", "CONFIG_LTO", "CONFIG_COMPILER_OPT",
)

#: F´'s optional services (app/Kconfig), each with what the report calls
#: it: a board's profile leaves out, per model, what its RAM cannot hold
SERVICES = (
    ("CONFIG_KIT_SERVICE_CDH", "health and version (CdhCore)"),
    ("CONFIG_KIT_SERVICE_PARAMS", "parameter database (FileHandling)"),
    ("CONFIG_KIT_SERVICE_FILES", "file downlink (FileHandling)"),
    ("CONFIG_KIT_SERVICE_FILE_UPLINK", "file uplink (FileHandling)"),
    ("CONFIG_KIT_SERVICE_SEQUENCER", "command sequencer"),
)


def kconfig(folder: BuildFolder) -> dict[str, str]:
    """The Kconfig values of KCONFIG a build has (FileNotFoundError without a .config)."""
    return {key: value for key, value in folder.kconfig().items() if key in KCONFIG}


def toolchain(folder: BuildFolder) -> str:
    """The first line of the build's C++ compiler's --version, or "unknown"."""
    compiler = folder.cache_value("CMAKE_CXX_COMPILER") if folder.configured() else None
    if not compiler:
        return "unknown"
    result = subprocess.run([compiler.strip(), "--version"], capture_output=True, text=True)
    return result.stdout.splitlines()[0] if result.returncode == 0 and result.stdout else "unknown"


def deployment(folder: BuildFolder) -> str:
    """The F´ deployment the build measures (its folder, relative to the
    kit: "app" for the reference one), or "unknown"."""
    path = folder.cache_value(CACHE_ENTRY) if folder.configured() else None
    location = folder.cache_value(LOCATION_ENTRY) if path else None
    return label(Path(path), Path(location) if location else None) if path else "unknown"


def services(folder: BuildFolder) -> dict[str, bool]:
    """Which of F´'s optional services (SERVICES) the build carries."""
    config = folder.kconfig(missing_ok=True)
    return {key: config.get(key) == "y" for key, _ in SERVICES}


def read(build_dir: Path) -> dict[str, object]:
    folder = BuildFolder(build_dir)
    return {"toolchain": toolchain(folder), "deployment": deployment(folder), "kconfig": kconfig(folder),
            "services": services(folder), "fprime": folder.fprime_settings()}
