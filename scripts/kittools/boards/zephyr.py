# SPDX-License-Identifier: Apache-2.0
"""What the pinned Zephyr knows of a board: its twister platform file (name,
arch, memory, whether QEMU runs it) and the vendor HAL its SoC needs."""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from kittools import workspace
from kittools.boards.devicetree import dts_size_kib
from kittools.workspace import KitError

# The kit's toolchains (Debian's arm-none-eabi GCC, the Zephyr SDK's ARM one)
# build nothing else, and every measurement so far is a Cortex-M's
SUPPORTED_ARCH = "arm"


@dataclass(frozen=True)
class ZephyrBoard:
    identifier: str  #: twister's platform name, e.g. mps2/an385
    platform_file: Path
    arch: str
    ram_kib: int | None
    flash_kib: int | None
    #: QEMU runs it (its platform file's `simulation`); else a real board, built and not run
    emulated: bool = True


@dataclass(frozen=True)
class HalModule:
    """A vendor HAL a real board's SoC needs: a Zephyr module of the pinned
    Zephyr's manifest, at the revision it pins."""

    name: str  #: e.g. hal_stm32
    path: str  #: its folder in the workspace, e.g. deps/modules/hal/stm32
    revision: str


#: Where west.yml lands Zephyr's modules (its import's path-prefix)
MODULES_PREFIX = "deps"



def zephyr_version(zephyr: Path) -> str:
    """'Zephyr 4.0.0' from its VERSION file, for messages."""
    version = zephyr / "VERSION"
    if not version.is_file():
        return "the pinned Zephyr"
    fields = dict(re.findall(r"^(\w+)\s*=\s*(\S*)", version.read_text(), re.MULTILINE))
    parts = [fields.get(key, "") for key in ("VERSION_MAJOR", "VERSION_MINOR", "PATCHLEVEL")]
    return f"Zephyr {'.'.join(parts)}" if all(parts) else "the pinned Zephyr"


def platforms(zephyr: Path) -> dict[str, Path]:
    """Twister platform identifier -> its platform file, for every board."""
    found: dict[str, Path] = {}
    for path in sorted((zephyr / "boards").glob("**/*.yaml")):
        text = path.read_text(errors="replace")
        if "identifier:" not in text:  # most board yaml are not platform files: skip the parse
            continue
        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError:
            continue
        if isinstance(data, dict) and isinstance(data.get("identifier"), str):
            found[data["identifier"]] = path
    return found


def resolve_identifier(target: str, known: dict[str, Path], zephyr: Path) -> str:
    """The platform identifier a user's target means: itself, or the one
    identifier it is the board name of (mps2 for mps2/an385, and likewise a
    target short of its last qualifiers); KitError with close matches otherwise."""
    if target in known:
        return target
    same_board = sorted(i for i in known if i.startswith(target + "/"))
    if len(same_board) == 1:
        return same_board[0]
    if same_board:
        raise KitError(f"'{target}' is several boards in {zephyr_version(zephyr)}: {', '.join(same_board)}. "
                       "Give the full target.")
    close = difflib.get_close_matches(target, list(known), n=5)
    hint = f" Close matches: {', '.join(close)}." if close else ""
    raise KitError(f"{zephyr_version(zephyr)} has no board '{target}'.{hint} "
                   "Check the name with `west boards` (the kit pins Zephyr in west.yml).")



def _yaml_kib(data: dict[str, Any], key: str) -> int | None:
    value = data.get(key)
    return value if isinstance(value, int) and not isinstance(value, bool) else None


def find_board(target: str, zephyr: Path | None = None) -> ZephyrBoard:
    """The board as the pinned Zephyr knows it, with its memory in KiB: the
    platform file's ram/flash, else its devicetree's chosen sram/flash."""
    zephyr = workspace.DEPS / "zephyr" if zephyr is None else zephyr
    if not (zephyr / "boards").is_dir():
        raise KitError(f"no Zephyr board tree at {zephyr / 'boards'}: run scripts/setup.sh first.")
    known = platforms(zephyr)
    identifier = resolve_identifier(target, known, zephyr)
    path = known[identifier]
    data: dict[str, Any] = yaml.safe_load(path.read_text())
    ram = _yaml_kib(data, "ram")
    flash = _yaml_kib(data, "flash")
    simulation = data.get("simulation")
    names = [s.get("name") if isinstance(s, dict) else s for s in
             (simulation if isinstance(simulation, list) else [simulation])]
    return ZephyrBoard(identifier, path, str(data.get("arch", "?")),
                       ram if ram is not None else dts_size_kib(path, "zephyr,sram"),
                       flash if flash is not None else dts_size_kib(path, "zephyr,flash"),
                       emulated="qemu" in names)



def check_arch(board: ZephyrBoard) -> None:
    if board.arch != SUPPORTED_ARCH:
        raise KitError(f"{board.identifier} is a '{board.arch}' board ({board.platform_file.name}); the kit is ARM "
                       "only: its toolchains are Debian's arm-none-eabi GCC and the Zephyr SDK's ARM one, and its "
                       "OS layers and measurements are Cortex-M's.")



def soc_folder(board: ZephyrBoard, zephyr: Path) -> Path | None:
    """The folder of Zephyr's soc/ tree whose soc.yml lists the board's SoC
    (its board.yml names it): soc/<vendor>/ or soc/<vendor>/<family>/."""
    board_yml = board.platform_file.parent / "board.yml"
    if not board_yml.is_file():
        return None
    socs = (yaml.safe_load(board_yml.read_text()) or {}).get("board", {}).get("socs", [])
    names = {s.get("name") for s in socs if isinstance(s, dict)}
    return next((p.parent for p in sorted((zephyr / "soc").glob("**/soc.yml"))
                 if names & set(re.findall(r"name:\s*(\S+)", p.read_text()))), None)


def hal_module(board: ZephyrBoard, zephyr: Path) -> tuple[HalModule | None, list[str]]:
    """The vendor HAL a board's SoC uses, found the way Zephyr lays itself
    out: the SoC's folder is soc/<vendor>/[<family>/], and its HAL is the
    manifest's hal_<family> (hal_stm32) or else hal_<vendor> (hal_nxp).
    Returns it, or None and the manifest's HAL modules when neither name is
    there (an SoC that needs CMSIS alone, or a HAL named otherwise)."""
    manifest_file = zephyr / "west.yml"
    manifest = yaml.safe_load(manifest_file.read_text())["manifest"]["projects"] if manifest_file.is_file() else []
    projects = {p["name"]: p for p in manifest if isinstance(p, dict) and "name" in p}
    hals = sorted(n for n in projects if n.startswith("hal_"))
    folder = soc_folder(board, zephyr)
    if folder is None:
        return None, hals
    parts = folder.relative_to(zephyr / "soc").parts
    for name in [f"hal_{part}" for part in reversed(parts[:2])]:
        if name in projects:
            project = projects[name]
            return HalModule(name, f"{MODULES_PREFIX}/{project.get('path', name)}", str(project["revision"])), hals
    return None, hals

