# SPDX-License-Identifier: Apache-2.0
"""ROM and RAM by module, from Zephyr's `rom_report` / `ram_report` trees.

Zephyr attributes every symbol to its source path (from DWARF); the kit
sorts those paths into the layers a baremetal-vs-RTOS decision is about.
Symbols without a source path (linker-made tables, vtables, static
constructors) are placed by their C++ namespace where it tells, otherwise
counted as "unattributed".
"""

from __future__ import annotations

import json
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from .workspace import KIT_ROOT, KitError, environment

CATEGORIES = (
    "F´ framework",
    "F´ services",
    "OS layer (fprime-baremetal / fprime-zephyr / kit)",
    "kit deployment and components",
    "Zephyr kernel, arch, drivers",
    "libc (picolibc, libgcc)",
    "libstdc++",
    "unattributed",
)

_BY_PATH = (
    # (substring of the source path, category); first match wins
    ("/deps/fprime-baremetal/", 2),
    ("/deps/fprime-zephyr/", 2),
    ("/rtos/", 2),
    ("/baremetal/", 2),
    ("/F-Prime/Svc/", 1),
    ("/deps/fprime/Svc/", 1),
    ("/deps/fprime/Drv/", 1),
    ("/F-Prime/", 0),
    ("/deps/fprime/", 0),
    ("/app/", 3),
    ("/deps/zephyr/", 4),
    ("/zephyr/", 4),
    ("libstdc++", 6),
    ("libsupc++", 6),
    ("/libgcc/", 5),
    ("/build/gcc-", 6),  # the toolchain's own build of its C++ runtime
    ("newlib", 5),
    ("picolibc", 5),
    ("/libc/", 5),
)

_BY_SYMBOL = (
    ("_ZN3Kit", 3), ("_ZTVN3Kit", 3), ("_ZN3Svc", 1), ("_ZTVN3Svc", 1), ("_ZN2Fw", 0), ("_ZTVN2Fw", 0),
    ("_ZN2Os9Baremetal", 2), ("_ZN2Os6Zephyr", 2), ("_ZN2Os", 0), ("_ZTVN2Os", 0), ("_ZNSt", 6), ("_ZSt", 6),
    ("__cxa", 6), ("__gnu_cxx", 6),
)


# Leaf identifiers are relative to the report's top-level groups
_GROUP_PREFIX = {"ZEPHYR_BASE": "/deps/zephyr/", "OUTPUT_DIR": "/OUTPUT_DIR/", "WORKSPACE": "/"}


def classify(identifier: str, group: str = "") -> str:
    """Category of one leaf of a rom/ram report (its 'identifier', within
    the top-level group named `group`)."""
    path = _GROUP_PREFIX.get(group, "") + identifier.replace("\\", "/")
    for needle, index in _BY_PATH:
        if needle in path:
            return CATEGORIES[index]
    symbol = path.rsplit("/", 1)[-1].removeprefix("_GLOBAL__sub_I_")
    for prefix, index in _BY_SYMBOL:
        if symbol.startswith(prefix):
            return CATEGORIES[index]
    return CATEGORIES[-1]


def _leaves(node: dict) -> Iterator[dict]:
    children = node.get("children")
    if not children:
        yield node
        return
    for child in children:
        yield from _leaves(child)


def breakdown(report: dict) -> dict[str, int]:
    """Bytes per category; sums to the report's total_size."""
    sizes = {name: 0 for name in CATEGORIES}
    for group in report["symbols"].get("children", []):
        for leaf in _leaves(group):
            sizes[classify(str(leaf.get("identifier", "")), str(group.get("name", "")))] += int(leaf.get("size", 0))
    return sizes


def report(build_dir: Path, kind: str) -> dict:
    """Zephyr's rom or ram report of a build, generated if missing or stale."""
    if kind not in ("rom", "ram"):
        raise ValueError(kind)
    path = build_dir / f"{kind}.json"
    elf = build_dir / "zephyr" / "zephyr.elf"
    if not elf.is_file():
        raise KitError(f"{elf} is missing: build first")
    if not path.is_file() or path.stat().st_mtime < elf.stat().st_mtime:
        result = subprocess.run(["west", "build", "-d", str(build_dir), "-t", f"{kind}_report"], cwd=KIT_ROOT,
                                env=environment(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if result.returncode != 0 or not path.is_file():
            raise KitError(f"west build -t {kind}_report failed for {build_dir}: {result.stderr[-2000:]}")
    loaded: dict[str, Any] = json.loads(path.read_text())
    return loaded
