# SPDX-License-Identifier: Apache-2.0
"""`kit new-board`: bring the kit to a new board.

Checks that the pinned Zephyr knows the board (a twister platform file names
it), that it is an ARM board, and that its flash and RAM hold the deployment
as measured on a ported board; then copies the reference board's folder with
a TODO header in each file and adds the board to the twister files'
platform lists: a QEMU board to the suites that run, a real board to the
boards built and not run (tests/boards) alone (suite_files). A real board
(no emulator) gets its vendor HAL (its file in the folder, west.yml's
allow-list), a kit.conf without icount, and a link UART: one its devicetree
enables besides the console, else one its SoC has, enabled on pins the HAL's
pinctrl file names (spare_uart). docs/porting.md is the checklist that follows.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from kittools import model, workspace
from kittools.suite import results
from kittools.workspace import VARIANTS, KitError, board_dir_name, board_folder, ported_boards

REFERENCE_BOARD = "qemu_cortex_m3"
# The kit's toolchains (Debian's arm-none-eabi GCC, the Zephyr SDK's ARM one)
# build nothing else, and every measurement so far is a Cortex-M's
SUPPORTED_ARCH = "arm"
# Twister files whose platform lists name the kit's boards, relative to the kit
# The suite's, the kernel floor's (tests/floor/<app>/) and the samples'
TWISTER_GLOBS = ("tests/*/testcase.yaml", "tests/*/*/testcase.yaml", "app/sample.yaml")
TWISTER_LIST_KEYS = ("platform_allow", "integration_platforms")

# What the porter must check in each file of the new folder (docs/porting.md)
TODOS: dict[str, tuple[str, ...]] = {
    "kit.conf": (
        "QEMU icount: set CONFIG_QEMU_ICOUNT_SHIFT so that 10^9 / 2^shift instructions",
        "per second models the real part's speed, and say why here (docs/porting.md, step 4).",
        "Console: the run's record goes to the zephyr,console UART; the banner must appear at boot.",
        "Tick: the system timer must do 1 kHz; check the banner's cycles_hz (the cycle counter's rate).",
    ),
    "Kconfig.defconfig": (
        "Re-measure the stacks on this board from the 'KIT STACK' lines of a run of every",
        "scenario, with headroom: MAIN_STACK_SIZE per model, DYNAMIC_THREAD_STACK_SIZE (rtos).",
        "Stack protection (rtos): HW_STACK_PROTECTION where the part has an MPU, else STACK_SENTINEL.",
    ),
    "Tables.fpp": (
        "Priorities and stacks are the reference board's: re-measure the stacks from the",
        "'KIT STACK' lines of this board's runs and check the priorities (docs/porting.md,",
        "steps 6-7). Every stack must be <= DYNAMIC_THREAD_STACK_SIZE (Kconfig.defconfig; the build checks).",
    ),
    "app.overlay": (
        "Devicetree copied from the reference board: choose the ground link's UART (kit,link-uart:",
        "not the console; under QEMU the machine's second serial port) and check the console UART",
        "(zephyr,console) and the timers against this board's devicetree (docs/porting.md, step 3).",
    ),
}
DEFAULT_TODO = ("Copied from the reference board: check this file for the new board (docs/porting.md).",)
# A real board's (docs/porting.md, "A real board"): no icount, its own UARTs and timer
REAL_TODOS: dict[str, tuple[str, ...]] = {
    "kit.conf": (
        "Console: the run's record goes to the zephyr,console UART (often the debugger's virtual COM port).",
        "Tick and timestamps: 1 kHz system timer; check cycles_hz in the banner on the board.",
        "Zephyr symbols only here; a kit symbol belongs in Kconfig.defconfig.",
    ),
    "app.overlay": (
        "Written for this board by the scaffold: check the ground link's UART (kit,link-uart: not the",
        "console; enabled, with its pins) against the board's schematic, and say how to wire it.",
    ),
}
REAL_KIT_CONF = """# SPDX-License-Identifier: Apache-2.0
# {identifier}: a real board, built by the kit for every execution model and
# not run (tests/boards/testcase.yaml). No QEMU icount: the cycle counter is
# the part's own timer, and times vary from run to run as hardware does.
"""
REAL_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link: F´'s comm stack talks to the ground over this UART
 * (app/Top/KitTopology.cpp), one the board's devicetree enables that is not
 * its console (the run's record). Wire a 3.3 V USB-serial adapter to its pins.
 */
/ {{
	chosen {{
		kit,link-uart = &{uart};
	}};
}};
"""
# A UART of the SoC the board leaves disabled, enabled here on pins of the
# HAL's pinctrl file: the form the boards' own devicetrees use for theirs
SPARE_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link: F´'s comm stack talks to the ground over this UART
 * (app/Top/KitTopology.cpp). The board enables no UART besides its console
 * (the run's record), so the scaffold enabled {uart}, disabled in the SoC's
 * devicetree, on pins the HAL's {pinctrl} names:
 * TX {tx_pin}, RX {rx_pin}. Wire a 3.3 V USB-serial adapter: its RX to {tx_pin},
 * its TX to {rx_pin}, and ground. None of these pins is used by the board's
 * own devicetree; check the board's schematic (solder bridges, the connector).
 */
/ {{
	chosen {{
		kit,link-uart = &{uart};
	}};
}};

&{uart} {{
	pinctrl-0 = <&{tx} &{rx}>;
	pinctrl-names = "default";
	current-speed = <115200>;
	status = "okay";
}};
"""
# No UART found for the link: no kit,link-uart, so the build stops at the
# kit's own #error (app/Top/KitTopology.cpp) rather than in devicetree
NO_LINK_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link needs a UART besides the console, and the scaffold
 * found none it could enable: {reason}.
 * Choose one here (chosen {{ kit,link-uart = &usartN; }}) and enable it with
 * its pins (pinctrl-0, pinctrl-names, current-speed, status = "okay");
 * until then the build stops and says so (app/Top/KitTopology.cpp).
 */
"""
HAL_FILE = """# The Zephyr modules this board needs beyond CMSIS (app/board.cmake refuses
# a workspace without them): the module's name in Zephyr's manifest, and its
# folder in the kit's workspace. west.yml allow-lists each.
{name} {path}
"""
TODO_MARK = "TODO(port):"


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


#: Real boards: built for every model, not run (no emulator)
BUILD_ONLY_SUITE = "tests/boards/testcase.yaml"
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


def board_dts(platform_file: Path) -> Path | None:
    """The board's .dts: the platform file's stem, else the folder's .dts
    whose stem starts the platform file's (a board with several platform
    files: nucleo_f030r8_1.yaml is nucleo_f030r8.dts's)."""
    dts = platform_file.with_suffix(".dts")
    if dts.is_file():
        return dts
    prefixes = [p for p in platform_file.parent.glob("*.dts") if platform_file.stem.startswith(p.stem)]
    return max(prefixes, key=lambda p: len(p.stem), default=None)


def _dts_texts(platform_file: Path) -> list[str]:
    """The board's .dts (board_dts), then every .dtsi it
    includes, directly or not, that sits in the same folder. The SoC's .dtsi
    files live elsewhere and are left out: a size defined only there is
    reported as unknown rather than guessed."""
    dts = board_dts(platform_file)
    if dts is None:
        return []
    texts, queue, seen = [], [dts], {dts}
    while queue:
        text = queue.pop(0).read_text(errors="replace")
        texts.append(text)
        for include in re.findall(r'#include\s+["<]([^">]+\.dtsi)[">]', text):
            path = platform_file.parent / include
            if path.is_file() and path not in seen:
                seen.add(path)
                queue.append(path)
    return texts


def _braced(text: str, open_at: int) -> str:
    """The text between the brace at `open_at` and its matching close."""
    depth = 0
    for index in range(open_at, len(text)):
        depth += {"{": 1, "}": -1}.get(text[index], 0)
        if depth == 0:
            return text[open_at + 1:index]
    return text[open_at + 1:]


def _own_properties(body: str) -> str:
    """A node's body without its child nodes (a flash node's partitions have
    regs of their own)."""
    while True:
        stripped = re.sub(r"\{[^{}]*\}", "", body)
        if stripped == body:
            return body
        body = stripped


def _cell(token: str) -> int | None:
    """One devicetree cell: a number, or Zephyr's DT_SIZE_K / DT_SIZE_M."""
    scaled = re.fullmatch(r"DT_SIZE_([KM])\s*\(\s*(\w+)\s*\)", token.strip())
    try:
        if scaled:
            return int(scaled.group(2), 0) * (1024 if scaled.group(1) == "K" else 1024 * 1024)
        return int(token.strip().strip("()"), 0)
    except ValueError:
        return None  # another macro or an expression: left to the build to tell


def _reg_size(body: str) -> int | None:
    """The size of `reg = <ADDR SIZE>` (one or two cells each)."""
    reg = re.search(r"\breg\s*=\s*<([^>]*)>", _own_properties(body))
    if reg is None:
        return None
    cells = [_cell(c) for c in re.findall(r"DT_SIZE_[KM]\s*\([^)]*\)|\S+", reg.group(1))]
    if len(cells) == 2:
        return cells[1]
    if len(cells) == 4 and cells[2] is not None and cells[3] is not None:
        return (cells[2] << 32) | cells[3]
    return None


def dts_size_kib(platform_file: Path, chosen: str) -> int | None:
    """Size in KiB of the node the board's devicetree chooses as `chosen`
    (zephyr,sram or zephyr,flash); None when the board's own files do not say."""
    texts = _dts_texts(platform_file)
    label = next((m.group(1) for t in texts for m in re.finditer(rf"{re.escape(chosen)}\s*=\s*&(\w+)\s*;", t)), None)
    if label is None:
        return None
    # A board's `&label { reg = ...; };` overrides the node's own definition
    patterns = (rf"&{label}\s*\{{", rf"(?<![\w&]){label}\s*:\s*[\w,.@+-]+\s*\{{")
    for pattern in patterns:
        for text in texts:
            for match in re.finditer(pattern, text):
                size = _reg_size(_braced(text, match.end() - 1))
                if size is not None:
                    return size // 1024
    return None


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


def link_uarts(platform_file: Path) -> list[str]:
    """The UARTs the board's own devicetree enables, the console's left out:
    the labels a real board's ground link can take (usart6, uart1)."""
    texts = _dts_texts(platform_file)
    console = next((m.group(1) for t in texts for m in [re.search(r"zephyr,console\s*=\s*&(\w+)", t)] if m), None)
    found: list[str] = []
    for text in texts:
        for match in re.finditer(r"^&((?:lp)?u(?:s)?art\d+)\s*\{", text, re.MULTILINE):
            body = _own_properties(_braced(text, match.end() - 1))
            if re.search(r'status\s*=\s*"okay"', body) and match.group(1) != console and match.group(1) not in found:
                found.append(match.group(1))
    return found


@dataclass(frozen=True)
class SpareUart:
    """A UART of the board's SoC that its devicetree leaves disabled, with
    TX and RX pins the HAL's pinctrl file names and the board does not use."""

    label: str  #: e.g. usart1
    tx: str  #: pinctrl label, e.g. usart1_tx_pa9
    rx: str  #: e.g. usart1_rx_pa10
    pinctrl: str  #: the pinctrl file as the board includes it, e.g. st/l1/stm32l152retx-pinctrl.dtsi

    def pin(self, label: str) -> str:
        """A pinctrl label's pin as a datasheet writes it: PA9."""
        return label.rsplit("_", 1)[-1].upper()


def dts_include_dirs(board: ZephyrBoard, zephyr: Path, hal_folder: Path | None = None) -> list[Path]:
    """Where `#include <...>` of a board's devicetree resolves, as Zephyr's
    build searches: the board's folder, Zephyr's dts/<arch>, dts/common,
    dts, and the HAL module's dts (an STM32's pinctrl files live there)."""
    dirs = [board.platform_file.parent, zephyr / "dts" / board.arch, zephyr / "dts" / "common", zephyr / "dts"]
    return dirs + ([hal_folder / "dts"] if hal_folder is not None else [])


def dts_tree(platform_file: Path, include_dirs: list[Path]) -> tuple[list[tuple[Path, str]], list[str]]:
    """The board's .dts and every devicetree file it includes, directly or
    not, wherever it sits (the SoC's .dtsi, the HAL's pinctrl file); and the
    includes not found (a HAL not fetched yet). Headers (.h) are left out."""
    dts = board_dts(platform_file)
    if dts is None:
        return [], []
    found: list[tuple[Path, str]] = []
    missing: list[str] = []
    queue, seen = [dts], {dts}
    while queue:
        path = queue.pop(0)
        text = path.read_text(errors="replace")
        found.append((path, text))
        for quote, include in re.findall(r'#include\s+(["<])([^">]+\.dtsi?)[">]', text):
            # A quoted include is looked for beside its file first, as cpp does
            dirs = ([path.parent] if quote == '"' else []) + include_dirs
            target = next((d / include for d in dirs if (d / include).is_file()), None)
            if target is None:
                missing.append(include)
            elif target not in seen:
                seen.add(target)
                queue.append(target)
    return found, missing


_PIN = re.compile(r"_(p[a-z]\d+)$")


def _pins_in_use(texts: list[str]) -> set[str]:
    """The pins a board's own devicetree gives to something (pinctrl-N of
    its nodes, *-gpios of its LEDs and buttons), as 'pa9'; a connector's
    gpio-map (every header pin) is not a use."""
    used: set[str] = set()
    for text in texts:
        for cells in re.findall(r"\bpinctrl-\d+\s*=\s*<([^;]*)>", text):
            used.update(m.group(1) for ref in re.findall(r"&(\w+)", cells) for m in [_PIN.search(ref)] if m)
        for cells in re.findall(r"(?<![\w-])(?:[\w-]+-)?gpios\s*=\s*<([^;]*)>", text):
            used.update(f"p{port}{pin}" for port, pin in re.findall(r"&gpio([a-z])\s+(\d+)", cells))
    return used


def _uart_order(label: str) -> tuple[bool, int, str]:
    """usart1 before usart3 before uart4; an LPUART last (a low-power
    peripheral, slower clocked on many parts)."""
    number = re.search(r"(\d+)$", label)
    return label.startswith("lp"), int(number.group(1)) if number else 0, label


def spare_uart(board: ZephyrBoard, zephyr: Path, hal_folder: Path | None) -> tuple[SpareUart | None, str]:
    """For a board whose devicetree enables no UART besides its console: a
    UART of its SoC (defined in the SoC's devicetree, disabled, not the
    console) with a TX and an RX pin the HAL's pinctrl file for its part
    names and the board's own devicetree does not use. Returns it, or None
    and why none was found (for the porter's TODO)."""
    files, missing = dts_tree(board.platform_file, dts_include_dirs(board, zephyr, hal_folder))
    if not files:
        return None, f"no devicetree of the board found beside {board.platform_file.name}"
    board_texts = [t for p, t in files if p.parent == board.platform_file.parent]
    console = next((m.group(1) for t in board_texts for m in [re.search(r"zephyr,console\s*=\s*&(\w+)", t)] if m),
                   None)
    status: dict[str, str] = {}
    for _, text in files:
        for match in re.finditer(r"(?<![\w&])(\w+)\s*:\s*(?:serial|uart)@[0-9a-fA-F]+\s*\{", text):
            body = _own_properties(_braced(text, match.end() - 1))
            if re.search(r"compatible\s*=[^;]*u(?:s)?art", body):  # any of its compatibles: st,stm32-uart
                found = re.search(r'status\s*=\s*"(\w+)"', body)
                status[match.group(1)] = found.group(1) if found else "okay"
    # What overrides a node's status: the SoC's files first, the board's last, as they are included
    for _, text in sorted(files, key=lambda f: f[0].parent == board.platform_file.parent):
        for match in re.finditer(r"^\s*&(\w+)\s*\{", text, re.MULTILINE):
            found = re.search(r'status\s*=\s*"(\w+)"', _own_properties(_braced(text, match.end() - 1)))
            if match.group(1) in status and found:
                status[match.group(1)] = found.group(1)
    candidates = sorted((label for label, state in status.items() if state == "disabled" and label != console),
                        key=_uart_order)
    if not candidates:
        return None, f"the SoC's devicetree defines no disabled UART besides the console ({console or 'none'})"
    pinctrl = [(path, text) for path, text in files if path.name.endswith("-pinctrl.dtsi")]
    if not pinctrl:
        absent = [name for name in missing if name.endswith("-pinctrl.dtsi")]
        if absent:
            return None, (f"the board's devicetree includes {absent[0]}, not found: fetch the board's HAL "
                          "(scripts/setup.sh), then scaffold again with --force")
        return None, f"no pinctrl file in the board's devicetree names pins for {', '.join(candidates)}"
    used = _pins_in_use(board_texts)
    path, text = pinctrl[0]
    labels = list(dict.fromkeys(re.findall(r"(?<![\w&])(\w+_(?:tx|rx)_(?:\w+_)?p[a-z]\d+)\s*:", text)))
    shown = next((str(path.relative_to(d)) for d in dts_include_dirs(board, zephyr, hal_folder)
                  if path.is_relative_to(d)), path.name)
    for uart in candidates:
        free = {end: [label for label in labels if label.startswith(f"{uart}_{end}_")
                      and label.rsplit("_", 1)[-1] not in used]
                for end in ("tx", "rx")}
        if free["tx"] and free["rx"]:
            return SpareUart(uart, free["tx"][0], free["rx"][0], shown), ""
    return None, (f"{shown} names no TX and RX pins free on this board for {', '.join(candidates)} "
                  f"(in use: {', '.join(sorted(used)) or 'none'})")


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


def allow_module(west_yml: str, module: str) -> str:
    """west.yml with `module` in the zephyr import's name-allowlist (once),
    its comments and layout kept."""
    # The list's items: the lines at the first item's indentation
    match = re.search(r"^[ \t]*name-allowlist:[ \t]*\r?\n"
                      r"(?P<items>(?P<item_indent>[ \t]+)-[^\n]*\n(?:(?P=item_indent)-[^\n]*\n)*)",
                      west_yml, re.MULTILINE)
    if match is None:
        raise KitError("west.yml has no name-allowlist under the zephyr project: add the module by hand")
    items = match.group("items")
    if module in [_item_name(re.sub(r"^\s*-", "", line)) for line in items.splitlines()]:
        return west_yml
    return west_yml[:match.end("items")] + f"{match.group('item_indent')}- {module}\n" + west_yml[match.end("items"):]


def check_arch(board: ZephyrBoard) -> None:
    if board.arch != SUPPORTED_ARCH:
        raise KitError(f"{board.identifier} is a '{board.arch}' board ({board.platform_file.name}); the kit is ARM "
                       "only: its toolchains are Debian's arm-none-eabi GCC and the Zephyr SDK's ARM one, and its "
                       "OS layers and measurements are Cortex-M's.")


# What to shrink when a resource is short, from docs/porting.md, "Memory budget"
_LEVERS = {
    "flash": "F´'s configuration (app/config/) and the components built in",
    "RAM": "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE (app/prj.conf), the queue depths (app/Top/instances.fpp), "
           "the stack table (Tables.fpp), F´'s configuration (app/config/)",
}


def smallest_models(measured: model.Results) -> dict[str, str]:
    """Per resource ("flash", "RAM"), the variant of a results file that
    needs the least of it: the model a small board can still take."""
    if not measured.variants:
        raise KitError("the reference's results have no variant to measure the deployment from")
    need = {"flash": model.ROM, "RAM": model.RAM}
    return {what: min(measured.variants, key=lambda v: (measured.variants[v].metrics[metric], v))
            for what, metric in need.items()}


def check_fit(board: ZephyrBoard, baseline: Path, shown_as: str | None = None) -> list[str]:
    """The deployment's measured need (a ported board's results file)
    against the board's memory, from the smallest model (per resource, the
    variant that needs the least): KitError if even it does not fit, named.
    Returns a headroom line per variant, and for a larger model the board
    cannot hold, a line saying so (its build in kit test fails until the
    deployment shrinks)."""
    shown_as = shown_as or str(baseline)
    if board.ram_kib is None or board.flash_kib is None:
        raise KitError(f"the memory of {board.identifier} is unknown (no ram/flash in {board.platform_file.name}, "
                       "no size of its zephyr,sram / zephyr,flash nodes in the board's own devicetree), so the fit "
                       f"cannot be checked. Find out: build once (west build -b {board.identifier} -T app/kit.rtos) "
                       "and read the linker's 'Memory region' lines, or the board's documentation.")
    measured = results.load(baseline)
    # Every model, or the smallest might be one of those measured only
    for variant in VARIANTS:
        if variant not in measured.variants:
            raise KitError(f"{shown_as} has no {variant} variant to measure the deployment from")
    have = {"flash": board.flash_kib * 1024, "RAM": board.ram_kib * 1024}
    need = {variant: {"flash": found.metrics[model.ROM], "RAM": found.metrics[model.RAM]}
            for variant, found in measured.variants.items()}
    smallest = smallest_models(measured)
    short = [f"{what}: the smallest model, {smallest[what]}, needs {need[smallest[what]][what] / 1024:.1f} KiB, "
             f"the board has {have[what] / 1024:.0f} KiB" for what in ("flash", "RAM")
             if need[smallest[what]][what] > have[what]]
    if short:
        levers = "; ".join(f"{what}: {_LEVERS[what]}" for what in ("flash", "RAM")
                           if need[smallest[what]][what] > have[what])
        raise KitError(f"{board.identifier} cannot hold the deployment as measured in {shown_as}: "
                       + "; ".join(short) + ". Shrink the deployment first (docs/porting.md, 'Memory budget'): "
                       + levers + ".")
    lines: list[str] = []
    for variant in sorted(need, key=lambda v: (need[v]["flash"], v)):
        spare = {what: have[what] - need[variant][what] for what in ("flash", "RAM")}
        mark = " (the smallest)" if variant in smallest.values() else ""
        lines.append(f"{variant}{mark}: " + ", ".join(
            f"{what} {need[variant][what] / 1024:.1f} of {have[what] / 1024:.0f} KiB "
            f"({spare[what] / 1024:.1f} KiB spare)" for what in ("flash", "RAM")))
        over = [f"{-spare[what] / 1024:.1f} KiB of {what}" for what in ("flash", "RAM") if spare[what] < 0]
        if over:
            lines.append(f"{variant} does not fit: {' and '.join(over)} short; its build fails until the "
                         "deployment shrinks (docs/porting.md, 'Memory budget')")
    return lines


def _without_todo(name: str, text: str) -> str:
    """The text without a TODO header of an earlier scaffold (scaffolding from
    a port whose TODOs are still open must not stack two headers)."""
    if name.endswith(".overlay"):
        match = re.match(rf"/\*\n(?: \* {re.escape(TODO_MARK)}.*\n)+ \*/\n", text)
        return text[match.end():] if match else text
    lines = text.splitlines(keepends=True)
    kept = 0
    while kept < len(lines) and lines[kept].startswith(f"# {TODO_MARK}"):
        kept += 1
    return "".join(lines[kept:])


def with_todo(name: str, text: str, reference: str, identifier: str,
              todos: dict[str, tuple[str, ...]] | None = None) -> str:
    """A copied file with its TODO header, in the file's comment syntax."""
    todo = (f"copied from boards/{reference}/ for {identifier}: check what follows, then delete this header.",
            *(todos or TODOS).get(name, TODOS.get(name, DEFAULT_TODO)))
    body = _without_todo(name, text)
    if name.endswith(".overlay"):
        return "/*\n" + "".join(f" * {TODO_MARK} {line}\n" for line in todo) + " */\n" + body
    return "".join(f"# {TODO_MARK} {line}\n" for line in todo) + body


def _item_name(item: str) -> str:
    """A list item as a name: no comment, no quotes."""
    return item.split(" #", 1)[0].strip().strip("'\"")


def _add_inline(rest: str, identifier: str) -> str:
    """A list written on the key's line: `[a, b]` or twister's `a b`; the
    spacing around it and its comment stay as they were."""
    value, hash_sign, comment = rest.partition(" #")
    lead, core, trail = re.fullmatch(r"(\s*)(.*?)(\s*)", value).groups()  # type: ignore[union-attr]
    if core.startswith("["):
        if not core.endswith("]"):
            return rest  # a flow list over several lines: left alone rather than mangled
        inner = core[1:-1].rstrip()
        if identifier in [_item_name(n) for n in inner.split(",")]:
            return rest
        core = f"[{inner}{', ' if inner.strip() else ''}{identifier}]"
    elif identifier in [_item_name(n) for n in core.split()]:
        return rest
    else:
        core = f"{core} {identifier}"
    return f"{lead}{core}{trail}{hash_sign}{comment}"


def add_to_twister_lists(text: str, identifier: str) -> str:
    """`identifier` added once to every platform_allow / integration_platforms
    list of a twister file, editing the text so its comments and layout stay:
    a `- identifier` line after the list's last item, at its indentation."""
    key = re.compile(rf"^(?P<indent>[ \t]*)(?:{'|'.join(TWISTER_LIST_KEYS)}):(?P<rest>.*?)(?P<eol>\r?\n?)$")
    lines = text.splitlines(keepends=True)
    out: list[str] = []
    index = 0
    while index < len(lines):
        match = key.match(lines[index])
        index += 1
        if match is None:
            out.append(lines[index - 1])
            continue
        rest = match.group("rest")
        if rest.split(" #", 1)[0].strip():
            out.append(lines[index - 1][:match.start("rest")] + _add_inline(rest, identifier) + match.group("eol"))
            continue
        out.append(lines[index - 1])
        # The block list: its items, and the comments and blank lines between them
        item_indent: str | None = None
        block: list[str] = []
        last_item = -1
        while index < len(lines):
            line = lines[index]
            item = re.match(r"^([ \t]*)-(?:[ \t]+(.*))?$", line.rstrip("\r\n"))
            if item and len(item.group(1)) >= len(match.group("indent")) and item_indent in (None, item.group(1)):
                item_indent = item.group(1)
                last_item = len(block)
            elif line.strip() and not line.lstrip().startswith("#"):
                break
            block.append(line)
            index += 1
        names = [_item_name(re.sub(r"^\s*-", "", line)) for line in block
                 if re.match(r"^\s*-", line) and not line.lstrip().startswith("#")]
        if last_item >= 0 and identifier not in names:
            ending = "\r\n" if block[last_item].endswith("\r\n") else "\n"
            if not block[last_item].endswith("\n"):
                block[last_item] += ending  # the list ended the file
            block.insert(last_item + 1, f"{item_indent}- {identifier}{ending}")
        out.extend(block)
    return "".join(out)


def twister_files(root: Path) -> list[Path]:
    """The twister files whose platform lists name the kit's boards."""
    return [path for pattern in TWISTER_GLOBS for path in sorted(root.glob(pattern)) if path.is_file()]


def _check_target_folder(folder: Path, identifier: str, boards: Path, force: bool) -> None:
    """Refuse to overwrite a port (or shadow one that covers the board) unless forced."""
    existing = board_folder(identifier, boards)
    if existing is None or force:
        return
    if existing == folder:
        raise KitError(f"boards/{folder.name} exists already: {identifier} is ported. Use --force to write its "
                       "files again from the reference (its other files are kept).")
    raise KitError(f"boards/{existing.name} already covers {identifier} (a folder named after the board covers all "
                   f"its qualifiers). Use --force to give {identifier} a folder of its own, boards/{folder.name}.")


def _reference_folder(reference: str, folder: Path, boards: Path) -> Path:
    reference_dir = board_folder(reference, boards)
    if reference_dir is None:
        raise KitError(f"reference board '{reference}' has no kit port. Ported boards: "
                       f"{', '.join(ported_boards(boards))}.")
    if reference_dir == folder:
        raise KitError(f"boards/{folder.name} is the reference itself: pick another with --from.")
    return reference_dir


def _copy_folder(reference_dir: Path, folder: Path, identifier: str, root: Path, say: Callable[[str], None],
                 todos: dict[str, tuple[str, ...]] | None = None) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    copied = set()
    for source in sorted(p for p in reference_dir.iterdir() if p.is_file()):
        (folder / source.name).write_text(with_todo(source.name, source.read_text(), reference_dir.name, identifier,
                                                    todos))
        copied.add(source.name)
        say(f"created: {(folder / source.name).relative_to(root)} (from {reference_dir.name}, TODO header)")
    for other in sorted(p.name for p in folder.iterdir() if p.name not in copied):
        say(f"kept: {(folder / other).relative_to(root)} (not in the reference)")


def suite_files(root: Path, emulated: bool) -> list[Path]:
    """The twister files a new board joins: the one rule for both kinds. A
    QEMU board joins every suite that runs (the deployment's, the kernel
    floor's, the samples'); a real board only the boards built and not run
    (BUILD_ONLY_SUITE), which is how `kit compare` and `kit test` tell it is
    one (cli.is_real_board): a QEMU board listed there would be refused."""
    build_only = root / BUILD_ONLY_SUITE
    if not emulated:
        return [build_only]
    return [path for path in twister_files(root) if path != build_only]


def _join_suite(root: Path, board: ZephyrBoard, say: Callable[[str], None]) -> None:
    identifier = board.identifier
    for path in suite_files(root, board.emulated):
        if not path.is_file():
            raise KitError(f"{path.relative_to(root)} is missing: a real board joins its platform list")
        before = path.read_text()
        after = add_to_twister_lists(before, identifier)
        name = path.relative_to(root)
        if after != before:
            path.write_text(after)
            say(f"twister: added {identifier} to the platform lists of {name}")
        else:
            say(f"twister: {name} unchanged (its lists name {identifier} already, or it has none)")


def new_board(target: str, reference: str = REFERENCE_BOARD, force: bool = False,
              say: Callable[[str], None] = print, root: Path | None = None, zephyr: Path | None = None) -> Path:
    """Check the board, scaffold boards/<dir>/ from the reference's folder and
    add the board to the twister files; returns the new folder."""
    root = workspace.KIT_ROOT if root is None else root
    zephyr = workspace.DEPS / "zephyr" if zephyr is None else zephyr
    board = find_board(target, zephyr)
    check_arch(board)
    boards = root / "boards"
    folder = boards / board_dir_name(board.identifier)
    _check_target_folder(folder, board.identifier, boards, force)
    reference_dir = _reference_folder(reference, folder, boards)
    baseline = root / "tests" / "baselines" / f"{reference_dir.name}.json"
    shown_as = str(baseline.relative_to(root))
    say(f"{board.identifier}: known to {zephyr_version(zephyr)} ({board.platform_file.name}), arch arm")
    for line in check_fit(board, baseline, shown_as):
        say(f"memory: {line}")
    smallest = smallest_models(results.load(baseline))
    named = " and ".join(dict.fromkeys(smallest.values()))
    say(f"memory: an estimate from {reference_dir.name}'s build ({shown_as}), the board checked against its "
        f"smallest model, {named}; ROM can differ a few % on another board, so the real check is this port's "
        "own run")
    _copy_folder(reference_dir, folder, board.identifier, root, say, None if board.emulated else REAL_TODOS)
    if board.emulated:
        _join_suite(root, board, say)
        say("next: resolve the TODO(port) headers in "
            f"boards/{folder.name}/, then follow the checklist in docs/porting.md:")
        say(f"  scripts/kit compare --board {board.identifier}")
        say(f"  scripts/kit test --board {board.identifier} --update-baseline   (review and commit the baseline)")
        return folder
    say(f"{board.identifier} is a real board (no emulator in {board.platform_file.name}): built for every model, "
        "not run")
    (folder / "kit.conf").write_text(with_todo("kit.conf", REAL_KIT_CONF.format(identifier=board.identifier),
                                               reference_dir.name, board.identifier, REAL_TODOS))
    say(f"created: {(folder / 'kit.conf').relative_to(root)} (a real board's: no QEMU icount)")
    hal, hals = hal_module(board, zephyr)
    fetch = ""
    if hal is None:
        say(f"hal: no hal_<family> or hal_<vendor> module for its SoC in {zephyr_version(zephyr)}'s manifest; "
            "CMSIS alone may do. If the build stops in devicetree (an include not found), add its module to "
            f"west.yml's name-allowlist and to boards/{folder.name}/hal, from: {', '.join(hals)}")
    else:
        (folder / "hal").write_text(HAL_FILE.format(name=hal.name, path=hal.path))
        say(f"created: {(folder / 'hal').relative_to(root)} ({hal.name} {hal.path})")
        west_yml = root / "west.yml"
        before = west_yml.read_text()
        after = allow_module(before, hal.name)
        if after != before:
            west_yml.write_text(after)
            fetch = "  scripts/setup.sh   (fetches it)"
        say(f"west.yml: {hal.name} {'allow-listed' if fetch else 'was allow-listed'} "
            f"({zephyr_version(zephyr)} pins {hal.revision[:12]})")
    overlay = folder / "app.overlay"
    uarts = link_uarts(board.platform_file)
    todo = ""
    if uarts:
        overlay.write_text(with_todo("app.overlay", REAL_OVERLAY.format(uart=uarts[0]), reference_dir.name,
                                     board.identifier, REAL_TODOS))
        say(f"created: {overlay.relative_to(root)} (ground link on {uarts[0]}, the first UART "
            f"the board enables besides its console; the others: {', '.join(uarts[1:]) or 'none'})")
    else:
        # The board enables its console alone: the reference's overlay would
        # name a UART this devicetree lacks (a devicetree error), so one of
        # the SoC's is enabled on the HAL's pins, or the porter is told
        spare, reason = spare_uart(board, zephyr, root / hal.path if hal is not None else None)
        if spare is not None:
            overlay.write_text(with_todo("app.overlay", SPARE_OVERLAY.format(
                uart=spare.label, tx=spare.tx, rx=spare.rx, tx_pin=spare.pin(spare.tx), rx_pin=spare.pin(spare.rx),
                pinctrl=spare.pinctrl), reference_dir.name, board.identifier, REAL_TODOS))
            say(f"created: {overlay.relative_to(root)} (the board enables no UART besides its console: ground "
                f"link on {spare.label}, enabled there on TX {spare.pin(spare.tx)} and RX {spare.pin(spare.rx)}, "
                f"pins from {spare.pinctrl}; wire a 3.3 V USB-serial adapter to them)")
        else:
            overlay.write_text(with_todo("app.overlay", NO_LINK_OVERLAY.format(reason=reason), reference_dir.name,
                                         board.identifier, REAL_TODOS))
            todo = (f"{TODO_MARK} no UART for the ground link: {reason}. Choose one in "
                    f"boards/{folder.name}/app.overlay (kit,link-uart, with its pins); until then the build stops "
                    "and says so")
            say(f"created: {overlay.relative_to(root)} (no ground link chosen)")
            say(todo)
    _join_suite(root, board, say)
    say("next: resolve the TODO(port) headers in "
        f"boards/{folder.name}/ (docs/porting.md, 'A real board'), then:")
    if fetch:
        say(fetch)
    if todo:
        say(f"  {todo}")
    say(f"  scripts/kit test --board {board.identifier}   (builds every model; nothing runs)")
    return folder
