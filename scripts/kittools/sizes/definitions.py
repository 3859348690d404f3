# SPDX-License-Identifier: Apache-2.0
"""Which source file defines each global symbol of a build, read from the
build's own objects.

Zephyr's size_report finds a symbol's source in the image's DWARF. An LTO
build (the baremetal models: CONFIG_LTO) compiles its code again at link
time, and the image's DWARF then names no source for most symbols: on
mps2/an385 baremetal 151 KB of 181 KB of ROM had no path, so a layer such as
the command sequencer read 0 B where the build has one. The objects the
build compiled still say who defines what: the compiler's nm (`gcc-nm`,
which reads LTO objects through the compiler's plugin) lists each object's
global symbols, and the build's compile commands name each object's source.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path
from typing import Any

from kittools.build.folder import BuildFolder
from kittools.sizes import instances

# nm's types of a definition that is not weak (T text, D data, B bss, R
# read-only, C common); a weak one (W, V) yields to a strong one
_STRONG = frozenset("TDBRC")
_WEAK = frozenset("WV")
# LTO and GCC's clones name a copy of `name` `name.<pass>.<n>` (lto_priv,
# constprop, part, isra, cold): the copy is defined where `name` is
_CLONE_SEPARATOR = "."
# How many objects one nm command line reads
_BATCH = 200


def _objects(folder: BuildFolder) -> dict[Path, str]:
    """Each compiled object of the build that exists, with its source file."""
    if not folder.compile_commands.is_file():
        return {}
    found = {}
    for entry in json.loads(folder.compile_commands.read_text()):
        output = entry.get("output")
        if not output:
            continue
        obj = Path(entry["directory"], output)
        if obj.is_file():
            found[obj] = str(Path(entry["directory"], entry["file"]))
    return found


def _nm(folder: BuildFolder) -> str | None:
    """The toolchain's nm that reads its LTO objects: `<compiler>-nm` beside
    the build's C compiler (gcc-nm for gcc, as Debian's toolchain and the
    Zephyr SDK have it), else the build's own nm, else none."""
    compiler = folder.cache_value("CMAKE_C_COMPILER")
    if compiler and Path(f"{compiler}-nm").is_file():
        return f"{compiler}-nm"
    nm = folder.cache_value("CMAKE_NM")
    return nm if nm and shutil.which(nm) else None


def defining_sources(build_dir: Path) -> dict[str, str]:
    """Each global symbol the build's objects define, with the source file of
    the object that defines it (a strong definition wins over a weak one, a
    weak one several sources make is left out); empty where the build kept
    no compile commands or has no nm."""
    folder = BuildFolder(build_dir)
    if not folder.configured():
        return {}
    objects = _objects(folder)
    nm = _nm(folder)
    if not objects or nm is None:
        return {}
    strong: dict[str, str] = {}
    weak: dict[str, set[str]] = {}
    paths = list(objects)
    for start in range(0, len(paths), _BATCH):
        batch = paths[start:start + _BATCH]
        # An object with no symbols makes nm complain and go on: its status says nothing here
        listing = subprocess.run([nm, "--defined-only", "-A", *map(str, batch)], capture_output=True, text=True,
                                 check=False).stdout
        for line in listing.splitlines():
            where, _, rest = line.rpartition(":")
            fields = rest.split()
            if len(fields) != 3 or not where:
                continue
            _, kind, name = fields
            source = objects.get(Path(where))
            if source is None:
                continue
            if kind in _STRONG:
                strong.setdefault(name, source)
            elif kind in _WEAK:
                weak.setdefault(name, set()).add(source)
    # A weak definition several sources make (an inline function of a
    # header, a vtable) names none of them: the symbol's name places it
    only_weak = {name: next(iter(sources)) for name, sources in weak.items() if len(sources) == 1}
    return only_weak | strong


# Zephyr's main thread's entry (kernel/init.c, a static nm does not list)
# holds the deployment's main() inlined under LTO: most of its bytes are
# main's, so it goes where main is defined
_HOLDS_INLINED = {"bg_thread_main": "main"}


def defined_in(name: str, sources: dict[str, str], inlined: bool = True) -> str | None:
    """The source defining the symbol `name`, or the one defining the
    function it is a clone of (`name` up to its first '.'); with `inlined`,
    a function that holds another one inlined under LTO (_HOLDS_INLINED)
    is that one's."""
    base = name.split(_CLONE_SEPARATOR, 1)[0]
    host = _HOLDS_INLINED.get(base) if inlined else None
    if host is not None and host in sources:
        return sources[host]
    return sources.get(name) or sources.get(base)


# The DWARF entries of what a C file defines at its top level
_DEFINITIONS = ("DW_TAG_subprogram", "DW_TAG_variable")
# The unit LTO's link-time compilation makes, which names no source
_LTO_UNIT = b"<artificial>"


def early_debug_sources(dwarf: Any) -> dict[str, str]:
    """What the globals nm does not list leave in an LTO image's DWARF: the
    compiler's early debug information keeps one unit per source, with the
    C functions and variables it defines at its top level, file statics
    among them (Zephyr's heap arena, F´'s CRC table). A name defined in one
    source only, with that source's path (its unit's name against its
    build folder); a name several sources define is left out."""
    found: dict[str, set[str]] = {}
    for unit in dwarf.iter_CUs():
        top = unit.get_top_DIE()
        name = top.attributes.get("DW_AT_name")
        if name is None or name.value == _LTO_UNIT:
            continue
        folder = top.attributes.get("DW_AT_comp_dir")
        source = str(Path(folder.value.decode() if folder else "", name.value.decode()).resolve())
        for entry in top.iter_children():
            if entry.tag not in _DEFINITIONS or "DW_AT_declaration" in entry.attributes:
                continue
            symbol = _defined_name(entry)
            if symbol is not None:
                found.setdefault(symbol, set()).add(source)
    return {symbol: next(iter(files)) for symbol, files in found.items() if len(files) == 1}


# GCC's name of an anonymous namespace in a mangled name
_ANONYMOUS_NAMESPACE = "_GLOBAL__N_1"


def _defined_name(entry: Any) -> str | None:
    """The symbol a top-level definition defines: a C name as it is; a C++
    variable's definition points at its declaration in its namespaces
    (DW_AT_specification), whose names mangle into the symbol (Kit::RamFs's
    anonymous s_region: the RAM file system's 17 KB); None for a C++
    function, whose mangled name needs its parameters (nm lists those that
    are global, the rest keep their name's layer)."""
    name = entry.attributes.get("DW_AT_name")
    if name is not None:
        return str(name.value.decode(errors="replace"))
    if entry.tag != "DW_TAG_variable" or "DW_AT_specification" not in entry.attributes:
        return None
    declaration = entry.get_DIE_from_attribute("DW_AT_specification")
    declared = declaration.attributes.get("DW_AT_name")
    if declared is None:
        return None
    scope: list[str] = []
    parent = declaration.get_parent()
    while parent is not None and parent.tag == "DW_TAG_namespace":
        named = parent.attributes.get("DW_AT_name")
        scope.insert(0, named.value.decode(errors="replace") if named is not None else _ANONYMOUS_NAMESPACE)
        parent = parent.get_parent()
    text = declared.value.decode(errors="replace")
    return instances.mangled(scope, text) if scope else str(text)
