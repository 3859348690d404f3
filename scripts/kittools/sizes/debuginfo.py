# SPDX-License-Identifier: Apache-2.0
"""A build's debug information (DWARF), as the kit asks it: the topology's
component instances, class sizes and the lengths of array members. The
answers are this build's layout, so they move with the switches that change
it (object names, port serialization, table sizes).

GCC describes a class with a vtable only where its key function is and
declares it everywhere else, so declared classes are resolved to their
definitions across every compilation unit.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from elftools.elf.elffile import ELFFile

from kittools.build.folder import BuildFolder
from kittools.workspace import KitError

#: How the compilation unit that defines every instance of the topology ends
#: (F´'s autocoder: <Topology>TopologyAc.cpp, KitTopologyAc.cpp in the
#: reference deployment, ThermalTopologyAc.cpp in tests/team/Thermal). Its
#: instances are in their modules' namespaces: the deployment's, and Kit
#: for the kit's subtopologies'
TOPOLOGY_UNIT = "TopologyAc.cpp"
_QUALIFIERS = ("DW_TAG_typedef", "DW_TAG_const_type", "DW_TAG_volatile_type")
_CLASSES = ("DW_TAG_class_type", "DW_TAG_structure_type")
_DEPTH = 16  # bound on typedef chains, base-class chains and scopes


def name(die: Any) -> str:
    attribute = die.attributes.get("DW_AT_name")
    return attribute.value.decode(errors="replace") if attribute is not None else ""


def _qualified(die: Any) -> str:
    parts = [name(die)]
    parent = die.get_parent()
    for _ in range(_DEPTH):
        if parent is None or parent.tag == "DW_TAG_compile_unit":
            break
        parts.append(name(parent))
        parent = parent.get_parent()
    return "::".join(reversed(parts))


@dataclass(frozen=True)
class Instance:
    """A component instance of the topology and its (complete) class."""

    name: str
    cls: Any


@dataclass(frozen=True)
class ArrayMember:
    count: int
    element: Any  # the element's type, or None for a scalar type without a DIE
    element_bytes: int

    @property
    def bytes(self) -> int:
        return self.count * self.element_bytes


class DebugInfo:
    def __init__(self, build_dir: Path) -> None:
        elf_path = BuildFolder(build_dir).built_elf()
        self._stream = elf_path.open("rb")
        elf = ELFFile(self._stream)
        if not elf.has_dwarf_info():
            raise KitError(f"{elf_path} has no debug information")
        self.path = elf_path
        self._units = list(elf.get_dwarf_info().iter_CUs())
        self._classes: dict[str, Any] = {}
        for unit in self._units:
            self._scan(unit.get_top_DIE(), "")

    def close(self) -> None:
        self._stream.close()

    def __enter__(self) -> DebugInfo:
        return self

    def __exit__(self, *_exc: object) -> None:
        self.close()

    def _scan(self, scope: Any, prefix: str) -> None:
        for die in scope.iter_children():
            if die.tag == "DW_TAG_namespace":
                self._scan(die, f"{prefix}{name(die)}::")
            elif die.tag in _CLASSES and "DW_AT_declaration" not in die.attributes \
                    and "DW_AT_byte_size" in die.attributes and name(die):
                self._classes.setdefault(prefix + name(die), die)
                self._scan(die, f"{prefix}{name(die)}::")  # nested classes (TlmChan::TlmSet)

    def cls(self, qualified: str) -> Any | None:
        """The definition of a class by its qualified name (Svc::TlmChan)."""
        return self._classes.get(qualified)

    def type_of(self, die: Any) -> Any | None:
        """The DIE's type: typedefs and qualifiers stripped, a declared class
        replaced by its definition."""
        if "DW_AT_type" not in die.attributes:
            return None
        found = die.get_DIE_from_attribute("DW_AT_type")
        for _ in range(_DEPTH):
            if found.tag not in _QUALIFIERS or "DW_AT_type" not in found.attributes:
                break
            found = found.get_DIE_from_attribute("DW_AT_type")
        if found.tag in _CLASSES and "DW_AT_declaration" in found.attributes:
            return self._classes.get(_qualified(found), found)
        return found

    @staticmethod
    def size(die: Any) -> int:
        attribute = die.attributes.get("DW_AT_byte_size") if die is not None else None
        return int(attribute.value) if attribute is not None else 0

    def derives_from(self, cls: Any, base: str, depth: int = 0) -> bool:
        """Whether the class is, or derives from, a class named `base` (unqualified)."""
        if name(cls) == base:
            return True
        if depth >= _DEPTH:
            return False
        return any(self.derives_from(parent, base, depth + 1) for parent in self.bases(cls))

    def bases(self, cls: Any) -> Iterator[Any]:
        for child in cls.iter_children():
            if child.tag == "DW_TAG_inheritance":
                parent = self.type_of(child)
                if parent is not None:
                    yield parent

    def members(self, cls: Any, depth: int = 0) -> Iterator[tuple[str, ArrayMember]]:
        """Every data member of a class and its bases, as (name, array of
        count elements); a member that is not an array counts as one."""
        if depth >= _DEPTH:
            return
        for parent in self.bases(cls):
            yield from self.members(parent, depth + 1)
        for child in cls.iter_children():
            if child.tag != "DW_TAG_member" or "DW_AT_data_member_location" not in child.attributes:
                continue
            member = self.type_of(child)
            if member is None:
                continue
            count = 1
            if member.tag == "DW_TAG_array_type":
                count = _count(member)
                member = self.type_of(member)
            yield name(child), ArrayMember(count, member, self.size(member))

    def member(self, qualified_class: str, member_name: str) -> ArrayMember | None:
        """A class's array member by name (m_entryTable of Svc::CommandDispatcherImpl)."""
        cls = self.cls(qualified_class)
        if cls is None:
            return None
        return next((m for n, m in self.members(cls) if n == member_name), None)

    def enumerator(self, unit_suffix: str, enumerator_name: str) -> int | None:
        """The value of an enumerator as a compilation unit saw it (a
        configuration constant such as TLMCHAN_HASH_BUCKETS)."""
        for unit in self._units:
            top = unit.get_top_DIE()
            if not name(top).endswith(unit_suffix):
                continue
            for die in unit.iter_DIEs():
                if die.tag == "DW_TAG_enumerator" and name(die) == enumerator_name:
                    return int(die.attributes["DW_AT_const_value"].value)
        return None

    def instances(self) -> list[Instance]:
        """Every component instance of the topology (classes derived from F´'s
        ObjBase, defined in a namespace of the topology's unit)."""
        units = [unit.get_top_DIE() for unit in self._units if name(unit.get_top_DIE()).endswith(TOPOLOGY_UNIT)]
        if len(units) != 1:
            raise KitError(f"{self.path}: {len(units)} compilation units named *{TOPOLOGY_UNIT}, expected the one "
                           "of the deployment's topology (is this a kit build?)")
        found: list[Instance] = []
        scopes = [scope for scope in units[0].iter_children() if scope.tag == "DW_TAG_namespace"]
        for _ in range(_DEPTH):  # nested modules are nested namespaces
            if not scopes:
                break
            found += [Instance(name(v), cls) for scope in scopes for v in scope.iter_children()
                      if v.tag == "DW_TAG_variable" for cls in [self.type_of(v)]
                      if cls is not None and cls.tag in _CLASSES and self.derives_from(cls, "ObjBase")]
            scopes = [inner for scope in scopes for inner in scope.iter_children() if inner.tag == "DW_TAG_namespace"]
        return found


def _count(array: Any) -> int:
    count = 1
    for sub in array.iter_children():
        if sub.tag != "DW_TAG_subrange_type":
            continue
        if "DW_AT_count" in sub.attributes:
            count *= int(sub.attributes["DW_AT_count"].value)
        elif "DW_AT_upper_bound" in sub.attributes:
            count *= int(sub.attributes["DW_AT_upper_bound"].value) + 1
        else:
            return 0
    return count
