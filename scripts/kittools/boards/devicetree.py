# SPDX-License-Identifier: Apache-2.0
"""A board's devicetree, read as text: the sizes of its chosen memory nodes,
the UARTs it enables, and for a board that enables its console alone, a
spare UART of its SoC on pins the HAL's pinctrl file names (spare_uart)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .zephyr import ZephyrBoard


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

