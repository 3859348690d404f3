"""`kit new-board`: bring the kit to a new board. Checks that the pinned
Zephyr knows the board, that it is an ARM board, and that its memory holds
the deployment as measured on a ported board; then copies the reference
board's folder with TODOs and adds the board to the twister files."""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import yaml

from . import results
from .workspace import DEPS, KIT_ROOT, VARIANTS, KitError, board_dir_name, board_folder

REFERENCE_BOARD = "qemu_cortex_m3"
# Twister files whose platform lists name the kit's boards
TWISTER_FILES = ("tests/deployment/testcase.yaml", "app/sample.yaml")

# What the porter must check in each file of the new folder (docs/porting.md)
TODOS = {
    "kit.conf": ["QEMU icount: set CONFIG_QEMU_ICOUNT_SHIFT so 10^9 / 2^shift instructions per second models",
                 "the real part's speed, and say why here. Check the console UART and that the system timer",
                 "does 1 kHz (the banner's cycles_hz is the cycle counter's rate)."],
    "baremetal.conf": ["Re-measure: run the suite on this board and size CONFIG_MAIN_STACK_SIZE from the",
                       "'KIT STACK name=main' lines of every scenario, with headroom."],
    "rtos.conf": ["Re-measure the stacks from the 'KIT STACK' lines of every scenario. Stack protection:",
                  "CONFIG_HW_STACK_PROTECTION=y where the part has an MPU, else CONFIG_STACK_SENTINEL=y."],
    "Tables.fpp": ["Priorities and stacks copied from the reference board: check them against this",
                   "board's runs; every stack must be <= CONFIG_DYNAMIC_THREAD_STACK_SIZE (rtos.conf)."],
    "app.overlay": ["Devicetree for this board: check the console UART and timers."],
}


@dataclass(frozen=True)
class ZephyrBoard:
    identifier: str  #: twister's platform name, e.g. mps2/an385
    platform_file: Path
    arch: str
    ram_kib: int | None
    flash_kib: int | None


def zephyr_version(zephyr: Path) -> str:
    version = zephyr / "VERSION"
    if not version.is_file():
        return "the pinned Zephyr"
    fields = dict(re.findall(r"^(\w+)\s*=\s*(\S*)", version.read_text(), re.MULTILINE))
    return "Zephyr {}.{}.{}".format(fields.get("VERSION_MAJOR", "?"), fields.get("VERSION_MINOR", "?"),
                                    fields.get("PATCHLEVEL", "?"))


def _platforms(zephyr: Path) -> dict[str, Path]:
    """Twister platform identifier -> its platform file, for every board."""
    found: dict[str, Path] = {}
    for path in sorted((zephyr / "boards").glob("**/*.yaml")):
        try:
            data = yaml.safe_load(path.read_text())
        except yaml.YAMLError:
            continue
        if isinstance(data, dict) and isinstance(data.get("identifier"), str):
            found[data["identifier"]] = path
    return found


def _dts_size_kib(platform_file: Path, chosen: str) -> int | None:
    """Size of the node the board's devicetree chooses as `chosen` (zephyr,sram
    or zephyr,flash), from its .dts and the .dtsi files beside it."""
    texts = []
    dts = platform_file.with_suffix(".dts")
    if dts.is_file():
        texts.append(dts.read_text())
        for include in re.findall(r'#include\s+"([^"]+\.dtsi)"', texts[0]):
            if (platform_file.parent / include).is_file():
                texts.append((platform_file.parent / include).read_text())
    text = "\n".join(texts)
    label = re.search(rf"{re.escape(chosen)}\s*=\s*&(\w+)\s*;", text)
    if label is None:
        return None
    node = re.search(rf"\b{label.group(1)}\s*:[^{{]*\{{[^}}]*?reg\s*=\s*<\s*(\S+)\s+(\S+)\s*>", text, re.DOTALL)
    if node is None:
        return None
    try:
        return int(node.group(2), 0) // 1024
    except ValueError:
        return None  # a macro or an expression: left to the build to tell


def find_board(target: str, zephyr: Path = DEPS / "zephyr") -> ZephyrBoard:
    """The board as the pinned Zephyr knows it; KitError naming close matches otherwise."""
    platforms = _platforms(zephyr)
    identifier = target if target in platforms else None
    if identifier is None:
        by_name = [i for i in platforms if i.split("/", 1)[0] == target]
        identifier = by_name[0] if len(by_name) == 1 else None
    if identifier is None:
        close = difflib.get_close_matches(target, list(platforms), n=5)
        hint = f" Close matches: {', '.join(close)}." if close else ""
        raise KitError(f"{zephyr_version(zephyr)} has no board '{target}'.{hint} "
                       "`west boards` lists them (the kit pins Zephyr in west.yml).")
    path = platforms[identifier]
    data: dict[str, Any] = yaml.safe_load(path.read_text())
    ram = data.get("ram") if isinstance(data.get("ram"), int) else _dts_size_kib(path, "zephyr,sram")
    flash = data.get("flash") if isinstance(data.get("flash"), int) else _dts_size_kib(path, "zephyr,flash")
    return ZephyrBoard(identifier, path, str(data.get("arch", "?")), ram, flash)


def check_fit(board: ZephyrBoard, baseline: Path) -> list[str]:
    """Per variant, the deployment's measured need against the board's memory;
    KitError if a variant does not fit. Returns the headroom lines."""
    if board.ram_kib is None or board.flash_kib is None:
        raise KitError(f"cannot tell the memory of {board.identifier} (no ram/flash in {board.platform_file.name}, "
                       "no zephyr,sram/zephyr,flash size in its devicetree): the fit cannot be checked. Build once "
                       "(west build -b <board> -T app/kit.rtos) and read the linker's 'Memory region' lines.")
    measured = results.load(baseline)
    lines, misfits = [], []
    for variant in VARIANTS:
        metrics = measured["variants"].get(variant, {}).get("metrics", {})
        need_rom, need_ram = metrics.get("ROM (bytes)"), metrics.get("RAM, static (bytes)")
        if not isinstance(need_rom, (int, float)) or not isinstance(need_ram, (int, float)):
            raise KitError(f"{baseline} has no ROM/RAM for the {variant} variant")
        have_rom, have_ram = board.flash_kib * 1024, board.ram_kib * 1024
        for what, need, have in (("flash", need_rom, have_rom), ("RAM", need_ram, have_ram)):
            text = f"{variant}: {what} needs {need / 1024:.1f} KiB, the board has {have / 1024:.0f} KiB"
            if need > have:
                misfits.append(text)
            else:
                lines.append(f"{text} ({(have - need) / 1024:.1f} KiB spare)")
    if misfits:
        raise KitError(f"{board.identifier} cannot hold the deployment, as measured on the reference board "
                       f"({baseline.name}): " + "; ".join(misfits) + ". Shrink it first: docs/porting.md, "
                       "'Memory budget'.")
    return lines


def _with_todo(name: str, text: str) -> str:
    todo = TODOS.get(name, ["Check this file for the new board (docs/porting.md)."])
    if name.endswith(".overlay"):
        return "/*\n" + "".join(f" * TODO(port): {line}\n" for line in todo) + " */\n" + text
    return "".join(f"# TODO(port): {line}\n" for line in todo) + text


def add_to_twister_lists(text: str, identifier: str) -> str:
    """`identifier` appended to every platform_allow / integration_platforms
    list of a twister file, as text (comments and layout kept), once."""
    lines = text.splitlines(keepends=True)
    out: list[str] = []
    index = 0
    while index < len(lines):
        line = lines[index]
        out.append(line)
        index += 1
        if re.match(r"^\s*(platform_allow|integration_platforms):\s*$", line):
            items: list[str] = []
            while index < len(lines) and re.match(r"^\s*-\s", lines[index]):
                items.append(lines[index])
                index += 1
            out += items
            names = [item.split("-", 1)[1].strip() for item in items]
            if items and identifier not in names:
                indent = items[-1][: len(items[-1]) - len(items[-1].lstrip())]
                out.append(f"{indent}- {identifier}\n")
    return "".join(out)


def new_board(target: str, reference: str = REFERENCE_BOARD, force: bool = False,
              say: Callable[[str], None] = print, root: Path = KIT_ROOT, zephyr: Path = DEPS / "zephyr") -> Path:
    """Scaffold boards/<target>/ and add it to the twister files; returns the folder."""
    board = find_board(target, zephyr)
    if board.arch != "arm":
        raise KitError(f"{board.identifier} is a '{board.arch}' board: the kit's toolchains (Debian's "
                       "arm-none-eabi GCC, the Zephyr SDK's ARM one) and its Cortex-M measurements are ARM only.")
    boards = root / "boards"
    reference_dir = board_folder(reference, boards)
    if reference_dir is None:
        raise KitError(f"reference board '{reference}' has no folder in {boards}")
    baseline = root / "tests" / "baselines" / f"{reference_dir.name}.json"
    for line in check_fit(board, baseline):
        say(f"memory: {line}")
    say(f"memory: estimated from {reference_dir.name}'s build; the port's own run is the real check")
    folder = boards / board_dir_name(board.identifier)
    if folder.exists() and not force:
        raise KitError(f"{folder} exists already: it is a port. Use --force to write it again from {reference}.")
    folder.mkdir(parents=True, exist_ok=True)
    for source in sorted(reference_dir.iterdir()):
        if source.is_file():
            (folder / source.name).write_text(_with_todo(source.name, source.read_text()))
            say(f"created: {folder.relative_to(root) / source.name}")
    for name in TWISTER_FILES:
        path = root / name
        if path.is_file():
            before = path.read_text()
            after = add_to_twister_lists(before, board.identifier)
            if after != before:
                path.write_text(after)
                say(f"twister: {board.identifier} added to {name}")
    say("next: resolve the TODO(port) lines, then")
    say(f"  scripts/kit compare --board {board.identifier}")
    say(f"  scripts/kit test --board {board.identifier} --update-baseline   (review and commit the baseline)")
    say("  and the checklist in docs/porting.md")
    return folder
