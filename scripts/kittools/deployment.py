# SPDX-License-Identifier: Apache-2.0
"""The F´ deployment a command builds and measures: the reference one (app/)
or a team's, named by --deployment (docs/your-deployment.md). The seam's
rules are app/deployment.cmake's, which every build applies; a command
asks it before it starts, so a folder that is not a deployment gets one
clear error before any build."""

from __future__ import annotations

import contextlib
import re
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from kittools.workspace import KIT_ROOT, KitError, check_board

#: The kit's reference deployment
REFERENCE = KIT_ROOT / "app"
#: The seam's rules (app/deployment.cmake), in CMake's script mode
SEAM_RULES = KIT_ROOT / "app" / "deployment.cmake"
#: A line of CMake's error that only says where in the rules it came from
_CMAKE_LOCATION = re.compile(r"\.cmake:\d+ \(")
#: The CMake cache entry that names a build's deployment (app/kit.cmake)
CACHE_ENTRY = "KIT_DEPLOYMENT_DIR"
#: ... and the one that names the F´ project it is named from
LOCATION_ENTRY = "KIT_DEPLOYMENT_LOCATION"
#: The seam's rules print that project
_LOCATION_LINE = re.compile(rf"^-- {LOCATION_ENTRY}=(.+)$", re.MULTILINE)


@dataclass(frozen=True)
class Deployment:
    """A deployment folder, checked against the seam."""

    path: Path
    #: The F´ project it is named from (app/deployment.cmake): the kit's
    #: repository, or a team's own project
    location: Path = KIT_ROOT

    @property
    def is_reference(self) -> bool:
        return self.path == REFERENCE

    @property
    def name(self) -> str:
        """Its folder, relative to the kit ("app" for the reference), or in
        its own F´ project ("<project>/MyDeployment")."""
        return label(self.path, self.location)

    def cmake_args(self) -> list[str]:
        """What a build of it adds to CMake's command line: nothing for the
        reference, so that its builds stay those of every other command."""
        return [] if self.is_reference else [f"-D{CACHE_ENTRY}={self.path}"]

    def output_suffix(self) -> str:
        """What sets its build folders apart from the reference's: "" or
        "-<folder name>"."""
        return "" if self.is_reference else f"-{self.path.name}"


def label(path: Path, location: Path | None = None) -> str:
    """A deployment folder as the report names it: relative to the kit, or,
    outside it, from its F´ project's folder ("team/Thermal"), so that a
    report names a team's deployment alike wherever its clone is."""
    resolved = path.resolve()
    with contextlib.suppress(ValueError):
        return str(resolved.relative_to(KIT_ROOT))
    if location is not None:
        with contextlib.suppress(ValueError):
            return str(Path(location.name) / resolved.relative_to(location.resolve()))
    return str(path)


def resolve(folder: str | Path | None, boards: Sequence[str] = ()) -> Deployment:
    """The deployment in `folder` (None: the reference), checked against the
    seam's rules, with its table for each of `boards` (board targets);
    KitError with the one thing it lacks otherwise."""
    path = REFERENCE if folder is None else Path(folder).expanduser().resolve()
    command = ["cmake", f"-DKIT_ROOT={KIT_ROOT}", f"-D{CACHE_ENTRY}={path}"]
    if boards:
        command.append(f"-DKIT_BOARDS={';'.join(check_board(board) for board in boards)}")
    result = subprocess.run([*command, "-P", str(SEAM_RULES)], capture_output=True, text=True)
    if result.returncode != 0:
        message = " ".join(line.strip() for line in result.stderr.splitlines()
                           if line.strip() and not line.startswith(("CMake Error", "Call Stack"))
                           and not _CMAKE_LOCATION.search(line))
        raise KitError(" ".join(message.split())
                       or f"the deployment folder {path} failed the seam's check ({SEAM_RULES})")
    found = _LOCATION_LINE.search(result.stdout)
    return Deployment(path, Path(found.group(1).strip()) if found else KIT_ROOT)
