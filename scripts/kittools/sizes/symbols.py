# SPDX-License-Identifier: Apache-2.0
"""Symbol-level size diffs between two builds, as Linux's bloat-o-meter
prints them: symbols added, removed, grown and shrunk, with totals.

The symbols come from Zephyr's `rom_report` / `ram_report` trees (the same
leaves kittools.sizes.by_layer sorts into layers), so a diff's totals agree with the
report's ROM and RAM by module. A baseline keeps only the symbols of at least
SYMBOL_FLOOR bytes and one total per layer for the smaller ones: the gate can
then say which large symbols grew and in which layer the small ones did,
without the baseline carrying every name of every build.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from kittools.sizes import by_layer

KINDS = ("rom", "ram")
#: Symbols smaller than this are kept in a baseline as one total per layer
SYMBOL_FLOOR = 128
_SMALL = "(symbols under {floor} B: {layer})"
# A constructor's or destructor's variants (complete C1/D1, base C2/D2) are
# often one body with two names, and the report names it by either, build
# to build: one key for both, so an alias swap is not a change
_STRUCTOR = re.compile(r"(?<=[A-Za-z_])([CD])[12](?=E)")


def _name(identifier: str) -> str:
    name = identifier.rsplit("/", 1)[-1]
    return _STRUCTOR.sub(r"\g<1>2", name) if name.startswith("_Z") else name


@dataclass(frozen=True)
class Leaf:
    """One symbol of a rom/ram report: its key, bytes and layer."""

    key: str
    size: int
    layer: str


def _leaves(node: dict, group: str) -> Iterator[tuple[str, str, int]]:
    children = node.get("children")
    if not children:
        yield str(node.get("identifier", "")), group, int(node.get("size", 0))
        return
    for child in children:
        yield from _leaves(child, group)


def leaves(report: dict, deployment: by_layer.Deployment = by_layer.NO_DEPLOYMENT) -> list[Leaf]:
    """Every symbol of a Zephyr rom/ram report, in its layer (`deployment`:
    the build's, by_layer.deployment_of). The key is the symbol's name; a
    name defined in several files (static functions, `CSWTCH.n`) gets its
    file after an `@` so that each stays one row."""
    raw = [(identifier, group, size) for top in report["symbols"].get("children", [])
           for identifier, group, size in _leaves(top, str(top.get("name", "")))]
    names = [_name(identifier) for identifier, _, _ in raw]
    seen: dict[str, int] = {}
    for name in names:
        seen[name] = seen.get(name, 0) + 1
    found = []
    for (identifier, group, size), name in zip(raw, names, strict=True):
        if size <= 0:
            continue
        where = identifier.rsplit("/", 1)[0] if "/" in identifier else ""
        key = name if seen[name] == 1 else f"{name}@{where.rsplit('/', 1)[-1] or group}"
        found.append(Leaf(key, size, by_layer.classify(identifier, group, deployment)))
    return found


def table(found: Iterable[Leaf], floor: int = 0) -> dict[str, int]:
    """Symbol key -> bytes; with a floor, the smaller symbols summed per layer."""
    sizes: dict[str, int] = {}
    for leaf in found:
        key = leaf.key if leaf.size >= floor else _SMALL.format(floor=floor, layer=leaf.layer)
        sizes[key] = sizes.get(key, 0) + leaf.size
    return sizes


def of_build(build_dir: Path, floor: int = 0) -> dict[str, dict[str, int]]:
    """A build's symbol tables, rom and ram."""
    deployment = by_layer.deployment_of(build_dir)
    return {kind: table(leaves(by_layer.report(build_dir, kind), deployment), floor) for kind in KINDS}


@dataclass(frozen=True)
class Delta:
    key: str
    before: int
    now: int

    @property
    def delta(self) -> int:
        return self.now - self.before


@dataclass
class SizeDiff:
    """What changed between two symbol tables of one kind (rom or ram)."""

    kind: str
    added: list[Delta] = field(default_factory=list)
    removed: list[Delta] = field(default_factory=list)
    grown: list[Delta] = field(default_factory=list)
    shrunk: list[Delta] = field(default_factory=list)
    before_total: int = 0
    now_total: int = 0

    @property
    def up(self) -> int:
        return sum(d.delta for d in self.added + self.grown)

    @property
    def down(self) -> int:
        return sum(d.delta for d in self.removed + self.shrunk)

    @property
    def changed(self) -> bool:
        return bool(self.added or self.removed or self.grown or self.shrunk)

    def rows(self) -> list[Delta]:
        """Every change, largest first (by absolute bytes)."""
        return sorted(self.added + self.removed + self.grown + self.shrunk, key=lambda d: (-abs(d.delta), d.key))

    def summary(self) -> str:
        """bloat-o-meter's header line."""
        return (f"{self.kind.upper()}: add/remove: {len(self.added)}/{len(self.removed)} "
                f"grow/shrink: {len(self.grown)}/{len(self.shrunk)} up/down: {self.up}/{self.down} "
                f"({self.now_total - self.before_total:+d}); total {self.before_total} -> {self.now_total}")


def diff(before: Mapping[str, int], now: Mapping[str, int], kind: str) -> SizeDiff:
    result = SizeDiff(kind, before_total=sum(before.values()), now_total=sum(now.values()))
    for key in sorted(set(before) | set(now)):
        old, new = before.get(key), now.get(key)
        if old is None:
            result.added.append(Delta(key, 0, int(new or 0)))
        elif new is None:
            result.removed.append(Delta(key, old, 0))
        elif new > old:
            result.grown.append(Delta(key, old, new))
        elif new < old:
            result.shrunk.append(Delta(key, old, new))
    return result


def demangle(names: Iterable[str]) -> dict[str, str]:
    """Readable names for mangled C++ symbols (the toolchain's c++filt, or the
    host's); unchanged where neither is installed."""
    keys = list(dict.fromkeys(names))
    tool = shutil.which("arm-none-eabi-c++filt") or shutil.which("c++filt")
    if not tool or not keys:
        return {k: k for k in keys}
    bare = [k.split("@", 1)[0] for k in keys]
    result = subprocess.run([tool], input="\n".join(bare) + "\n", capture_output=True, text=True, check=False)
    lines = result.stdout.splitlines()
    if result.returncode != 0 or len(lines) != len(keys):
        return {k: k for k in keys}
    return {k: line + (f" @{k.split('@', 1)[1]}" if "@" in k else "") for k, line in zip(keys, lines, strict=True)}


def render(result: SizeDiff, limit: int | None = None) -> list[str]:
    """bloat-o-meter's text: the header, then one row per changed symbol
    (largest first, at most `limit`)."""
    rows = result.rows()
    shown = rows if limit is None else rows[:limit]
    names = demangle(d.key for d in shown)
    lines = [result.summary()]
    if shown:
        lines.append(f"{'function/object':<60} {'old':>7} {'new':>7} {'delta':>7}")
    for d in shown:
        lines.append(f"{names[d.key][:60]:<60} {d.before:>7} {d.now:>7} {d.delta:>+7}")
    if len(rows) > len(shown):
        lines.append(f"... and {len(rows) - len(shown)} more")
    return lines
