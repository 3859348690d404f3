# SPDX-License-Identifier: Apache-2.0
"""Every symbol of an image with its source file, ROM and RAM: Zephyr's own
attribution, without Zephyr's tree.

Zephyr's `size_report` (deps/zephyr/scripts/footprint) maps each ELF symbol
to its source file from DWARF, then builds a path tree for display. That
tree costs half its run: each of a few thousand symbols searches the whole
tree for its parent (anytree's findall_by_attr), about 20 s of one core per
build, 12 builds per `kit test`. The kit reads only the tree's leaves
(kittools.sizes.by_layer, kittools.sizes.symbols), so this runs size_report's own
functions for the attribution, unchanged (the pinned Zephyr's), and writes
the leaves under the same top-level groups, identifiers and sizes:
`<kind>-symbols.json` in the build folder, a tree one level deep.

Run as a program (`python -m kittools.sizes.size_report ELF BUILD_DIR`) so that
two builds' reports take two cores.
"""

from __future__ import annotations

import argparse
import importlib.machinery
import importlib.util
import json
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

from kittools.build.folder import BuildFolder
from kittools.sizes import definitions, memory
from kittools.workspace import DEPS, KIT_ROOT

KINDS = ("rom", "ram")
#: How the reports are made (now: a symbol's source from its definition first,
#: kittools.sizes.definitions, then the DWARF's; RAM only in SRAM): a report
#: of an older way is made again
FORMAT = 6
#: size_report's group of what no symbol covers
HIDDEN = "(hidden)"
SIZE_REPORT = DEPS / "zephyr" / "scripts" / "footprint" / "size_report"


def output(build_dir: Path, kind: str) -> Path:
    return build_dir / f"{kind}-symbols.json"


def _zephyr_size_report() -> ModuleType:
    """Zephyr's size_report script, loaded as a module (it has no .py)."""
    loader = importlib.machinery.SourceFileLoader("zephyr_size_report", str(SIZE_REPORT))
    spec = importlib.util.spec_from_loader(loader.name, loader)
    assert spec is not None
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def _groups(build_dir: Path) -> list[tuple[str, Path]]:
    """size_report's top-level groups, in its order of precedence
    (generate_any_tree): a path under several goes to the first."""
    return [("ZEPHYR_BASE", DEPS / "zephyr"), ("OUTPUT_DIR", build_dir), ("WORKSPACE", KIT_ROOT)]


def _place(path: Path, groups: list[tuple[str, Path]]) -> tuple[str, str]:
    """(group, identifier) of one symbol's path, as size_report names them."""
    if not path.is_absolute():
        return "(no paths)", str(path)
    for name, base in groups:
        if base in path.parents:
            return name, str(path.relative_to(base))
    return "/", str(path)


def leaves(zr: ModuleType, elf: Any, dwarf: Any, ranges: dict[str, Any], kind: str,
           build_dir: Path, sources: dict[str, str]) -> dict[str, Any]:
    """One kind's report: size_report's attribution (main(), up to its tree),
    its leaves grouped as in its tree, and "(hidden)": what no symbol covers.
    A symbol's source is the one `sources` gives it (its definition:
    kittools.sizes.definitions) where it gives one, else the DWARF's."""
    symbol_dict = zr.get_symbols(elf, ranges)[kind]
    processed = {"mapped_symbols": set(), "mapped_addr": set(), "unmapped_symbols": set(symbol_dict.keys())}
    zr.do_simple_name_matching(dwarf, symbol_dict, processed)
    zr.mark_address_aliases(symbol_dict, processed)
    zr.do_address_range_matching(dwarf, symbol_dict, processed)
    zr.mark_address_aliases(symbol_dict, processed)
    zr.set_root_path_for_unmapped_symbols(symbol_dict, ranges[kind], processed)
    groups = _groups(build_dir.resolve())
    children: dict[str, list[dict[str, Any]]] = {name: [] for name in ("(no paths)", *(g for g, _ in groups), "/")}
    for name, entries in symbol_dict.items():
        for entry in entries:
            size = zr.get_symbol_size(entry["symbol"])
            for file in entry["mapped_files"]:
                # The definitions (the objects', the early debug units') name a
                # source better than the DWARF's address ranges, which put
                # libgcc's helpers at flash's start in whatever unit has a
                # range there (a discarded function's: fprime-baremetal's
                # Directory.cpp on mps2/an385 rtos); a function LTO inlined
                # into another counts as the host only where the DWARF has no path
                file = definitions.defined_in(name, sources, inlined=not Path(file).is_absolute()) or file
                group, identifier = _place(Path(file, name), groups)
                children[group].append({"name": name, "identifier": identifier, "size": size})
    total = int(ranges[f"{kind}_total_size"])
    tops: list[dict[str, Any]] = [{"name": group, "size": sum(leaf["size"] for leaf in found), "children": found}
                                  for group, found in children.items() if found]
    tops.append({"name": HIDDEN, "identifier": HIDDEN, "size": total - sum(t["size"] for t in tops)})
    return {"symbols": {"name": "Root", "identifier": "root", "size": total, "children": tops}, "total_size": total}


def _in_sram(ranges: dict[str, Any], sram: memory.Region, elf: Any) -> dict[str, Any]:
    """size_report's ranges with RAM limited to the sections in SRAM.
    size_report counts every writable section as RAM too (its .data,
    copied there at boot), but LTO leaves the baremetal models' rodata
    writable in flash (flags WA): their RAM report counted 22.7 KB of
    rodata on qemu_cortex_m3 and summed to 87.8 KB on a 64 KiB part."""
    ram = [bound for bound in ranges["ram"] if sram.holds(bound["start"])]
    left_out = sum(elf.get_section_by_name(bound["name"])["sh_size"] for bound in ranges["ram"] if bound not in ram)
    return {**ranges, "ram": ram, "ram_total_size": ranges["ram_total_size"] - left_out}


def make(elf_path: Path, build_dir: Path) -> None:
    """<kind>-symbols.json of every kind, in the build folder."""
    zr = _zephyr_size_report()
    # size_report's functions read its command line's settings
    settings = argparse.Namespace(kernel=str(elf_path), zephyrbase=str(DEPS / "zephyr"), output=str(build_dir),
                                  workspace=str(KIT_ROOT), depth=99, quiet=True, verbose=False, json=None,
                                  target="all")
    vars(zr)["args"] = settings  # size_report's functions read its command line's settings from there
    with elf_path.open("rb") as stream:
        elf = zr.ELFFile(stream)
        zr.set_global_machine_arch(elf.get_machine_arch())
        ranges = zr.get_section_ranges(elf)
        folder = BuildFolder(build_dir)
        if folder.config.is_file():  # the board's SRAM is in it (Zephyr's attribution alone where it is gone)
            ranges = _in_sram(ranges, memory.sram(folder), elf)
        dwarf = elf.get_dwarf_info()
        # The objects' globals first; the early debug information's C statics beside them
        sources = definitions.early_debug_sources(dwarf) | definitions.defining_sources(build_dir)
        for kind in KINDS:
            output(build_dir, kind).write_text(json.dumps(leaves(zr, elf, dwarf, ranges, kind, build_dir, sources)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: python -m kittools.sizes.size_report ELF BUILD_DIR")
    make(Path(sys.argv[1]), Path(sys.argv[2]))
