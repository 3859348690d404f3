# SPDX-License-Identifier: Apache-2.0
"""C++ style check: the kit's own C++ against F´'s clang-format style.

The style is the kit's `.clang-format` (F´'s, verbatim); the formatter is the
clang-format pinned in the kit's venv (the PyPI wheel, the same pin as F´'s
requirements.txt), since another clang-format version formats differently.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from kittools.log import LOG
from kittools.workspace import KIT_ROOT, KitError

if TYPE_CHECKING:
    from kittools.suite.counts import Tally

# The pinned formatter; the same as clang-format==... in scripts/requirements.txt.
CLANG_FORMAT_VERSION = "20.1.8"

# The kit's own C++, relative to the kit's root: the one list of what is checked.
SOURCE_GLOBS: tuple[str, ...] = (
    "app/**/*.cpp",
    "app/**/*.hpp",
    "baremetal/**/*.cpp",
    "baremetal/**/*.hpp",
    "rtos/**/*.cpp",
    "rtos/**/*.hpp",
    "tests/host/**/*.cpp",
    "tests/host/**/*.hpp",
)

# Never checked: build folders (F´ and twister write generated C++ there),
# hidden folders, and FPP's generated files (*Ac.cpp, *Ac.hpp).
_EXCLUDED_DIR_PREFIXES = ("build", "twister-out", ".")
_GENERATED_SUFFIXES = ("Ac.cpp", "Ac.hpp")

# What clang-format --dry-run --Werror says about an unformatted file.
_VIOLATION = "-Wclang-format-violations"


def source_files(root: Path) -> list[Path]:
    """The kit's C++ files under root that the style applies to, sorted."""
    found: set[Path] = set()
    for pattern in SOURCE_GLOBS:
        for path in root.glob(pattern):
            parts = path.relative_to(root).parts
            if any(part.startswith(_EXCLUDED_DIR_PREFIXES) for part in parts[:-1]):
                continue
            if path.name.endswith(_GENERATED_SUFFIXES) or not path.is_file():
                continue
            found.add(path)
    return sorted(found)


def find_clang_format() -> Path:
    """The pinned clang-format: the venv's (next to this Python), else PATH's."""
    name = "clang-format.exe" if os.name == "nt" else "clang-format"
    beside = Path(sys.executable).parent / name
    found = beside if beside.is_file() else None
    if found is None:
        on_path = shutil.which("clang-format")
        found = Path(on_path) if on_path else None
    if found is None:
        raise KitError(f"clang-format not found (next to {sys.executable} or on PATH); install the pinned one "
                       f"into the kit's venv: pip install clang-format=={CLANG_FORMAT_VERSION}")
    try:
        version = subprocess.run([str(found), "--version"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        raise KitError(f"{found} does not run: {error}") from error
    if f"version {CLANG_FORMAT_VERSION}" not in version:
        raise KitError(f"{found} is {version.strip() or 'of an unknown version'}, not the pinned "
                       f"{CLANG_FORMAT_VERSION} (another version formats differently); install it into the "
                       f"kit's venv: pip install clang-format=={CLANG_FORMAT_VERSION}")
    return found


def clang_format_check(root: Path) -> list[Path]:
    """The kit's C++ files under root that are not formatted in root's .clang-format style.

    Runs the pinned clang-format in check mode (--dry-run --Werror, nothing is
    rewritten) on every file of source_files(root). Raises KitError if the
    formatter is missing or of another version, root has no .clang-format, or
    clang-format fails for another reason than formatting (a bad style key).
    """
    root = Path(root)
    style = root / ".clang-format"
    if not style.is_file():
        raise KitError(f"no .clang-format at {root}: the style the kit's C++ is checked against")
    binary = find_clang_format()
    unclean: list[Path] = []
    for path in source_files(root):
        done = subprocess.run([str(binary), f"--style=file:{style}", "--dry-run", "--Werror", str(path)],
                              check=False, capture_output=True, text=True)
        if done.returncode == 0:
            continue
        if _VIOLATION not in done.stderr:
            raise KitError(f"clang-format failed on {path} (exit {done.returncode}): {done.stderr.strip()}")
        unclean.append(path)
    return unclean


def run_style_check(root: Path = KIT_ROOT) -> Tally:
    """The style check as one test of `kit test`: passed if every file is clean;
    else failed, with each unformatted file and the command that fixes it."""
    # The suite's count; imported here, as the suite needs nothing of this module
    from kittools.suite.counts import Tally

    unclean = clang_format_check(root)
    for path in unclean:
        LOG.error(f"  not in F´ style: {path.relative_to(root)} "
                  f"(fix: clang-format -i {path.relative_to(root)})")
    return Tally(failed=1) if unclean else Tally(passed=1)
