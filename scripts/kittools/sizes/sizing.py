# SPDX-License-Identifier: Apache-2.0
"""Sizing advice for a build, as fprime-baremetal's `baremetal-size` gives it
for native and Arduino builds, but from this build's own dictionary, debug
information and run: each fixed table's current size (the length of its
array as compiled), the size the deployment needs, and the bytes the
difference is worth.

A table smaller than what the deployment needs is a latent fault, not a
saving: F´'s command dispatcher asserts when a command registers past its
table, TlmChan when a channel is first written past its buckets (it never
frees one). `check` fails on those.
"""

from __future__ import annotations

import json
import re
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from kittools.build.folder import BuildFolder
from kittools.sizes import ports
from kittools.sizes.debuginfo import DebugInfo
from kittools.workspace import KitError


@dataclass(frozen=True)
class Advice:
    table: str  # what the table is
    setting: str  # where its size is set
    current: int
    needed: int
    unit_bytes: int  # bytes one entry takes, all copies of the table together
    basis: str  # where `needed` comes from
    must_fit: bool = True  # False: `needed` is a measurement or a rule of thumb, not a hard limit

    @property
    def spare_bytes(self) -> int:
        """Bytes the entries beyond what is needed take (negative: too small)."""
        return (self.current - self.needed) * self.unit_bytes

    @property
    def verdict(self) -> str:
        if self.current < self.needed:
            return "TOO SMALL" if self.must_fit else "below the measure"
        return "exact" if self.current == self.needed else "spare"

    def to_json(self) -> dict[str, Any]:
        return {**asdict(self), "spare_bytes": self.spare_bytes, "verdict": self.verdict}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Advice:
        return cls(str(data["table"]), str(data["setting"]), int(data["current"]), int(data["needed"]),
                   int(data["unit_bytes"]), str(data["basis"]), bool(data.get("must_fit", True)))


def too_small(advice: list[Advice]) -> list[str]:
    """Tables smaller than the deployment needs: latent asserts, not savings."""
    return [f"{a.table}: {a.current} < {a.needed} needed ({a.basis}); raise {a.setting}"
            for a in advice if a.must_fit and a.current < a.needed]


@dataclass(frozen=True)
class Sizing:
    advice: list[Advice]
    ports: ports.PortCost

    def to_json(self) -> dict[str, Any]:
        return {"tables": [a.to_json() for a in self.advice], "ports": self.ports.to_json()}


class _Types:
    """Serialized sizes of the dictionary's types, as F´ serializes them:
    integers and floats by width, bool one byte, enums by their
    representation, arrays and structs by their members, strings as a
    length (FwSizeStoreType) and at most their declared size, and at most
    `string_cap` where F´ truncates them (an event's string arguments to
    FW_LOG_STRING_MAX_SIZE, a command's to FW_CMD_STRING_MAX_SIZE, a
    channel's to FW_TLM_STRING_MAX_SIZE: the generated code's FW_MIN)."""

    def __init__(self, dictionary: dict[str, Any], string_cap: int | None = None) -> None:
        self.defined = {t["qualifiedName"]: t for t in dictionary.get("typeDefinitions", [])}
        self.string_cap = string_cap

    def size(self, kind: dict[str, Any], depth: int = 0) -> int:
        if depth > 16:
            raise KitError(f"dictionary type nests too deep: {kind}")
        match kind.get("kind"):
            case "integer" | "float":
                return int(kind["size"]) // 8
            case "bool":
                return 1
            case "string":
                declared = int(kind["size"])
                kept = declared if self.string_cap is None else min(declared, self.string_cap)
                return self.named("FwSizeStoreType") + kept
            case "qualifiedIdentifier":
                return self.defined_size(self.defined[kind["name"]], depth + 1)
        raise KitError(f"dictionary type of unknown kind: {kind}")

    def defined_size(self, definition: dict[str, Any], depth: int) -> int:
        match definition["kind"]:
            case "alias":
                return self.size(definition["underlyingType"], depth + 1)
            case "enum":
                return self.size(definition["representationType"], depth + 1)
            case "array":
                return int(definition["size"]) * self.size(definition["elementType"], depth + 1)
            case "struct":
                return sum(self.size(m["type"], depth + 1) * int(m.get("size", 1))
                           for m in definition["members"].values())
        raise KitError(f"dictionary type definition of unknown kind: {definition.get('qualifiedName')}")

    def named(self, name: str) -> int:
        return self.defined_size(self.defined[name], 0)


def largest_packet(dictionary: dict[str, Any], config: dict[str, str] | None = None) -> tuple[int, str]:
    """The largest command, event or telemetry packet the dictionary allows
    (F´'s packet layouts: a descriptor, the id, the time tag where there is
    one, the arguments or value) and which one it is: the least
    FW_COM_BUFFER_MAX_SIZE that holds every packet of this deployment. With
    the build's `config`, string arguments count as F´ truncates them."""
    def cap(symbol: str) -> int | None:
        value = (config or {}).get(symbol)
        return int(value) if value else None

    types = _Types(dictionary)
    commands = _Types(dictionary, cap("CONFIG_FPRIME_CMD_STRING_MAX_SIZE"))
    events = _Types(dictionary, cap("CONFIG_FPRIME_LOG_STRING_MAX_SIZE"))
    channels = _Types(dictionary, cap("CONFIG_FPRIME_TLM_STRING_MAX_SIZE"))
    descriptor = types.named("FwPacketDescriptorType")
    time_tag = types.named("FwTimeBaseStoreType") + types.named("FwTimeContextStoreType") + 4 + 4  # s, us: U32
    candidates = [(descriptor + types.named("FwOpcodeType") + sum(commands.size(p["type"]) for p in c["formalParams"]),
                   f"command {c['name']}") for c in dictionary.get("commands", [])]
    candidates += [(descriptor + types.named("FwEventIdType") + time_tag
                    + sum(events.size(p["type"]) for p in e["formalParams"]), f"event {e['name']}")
                   for e in dictionary.get("events", [])]
    candidates += [(descriptor + types.named("FwChanIdType") + time_tag + channels.size(c["type"]),
                    f"channel {c['name']}") for c in dictionary.get("telemetryChannels", [])]
    return max(candidates) if candidates else (0, "nothing")


#: Svc.Version's channels: ten custom versions, set only through its
#: setVersion port, and a library slot for each of up to ten F´ libraries
_VERSION_SLOT = re.compile(r"\.(CustomVersion|LibraryVersion)(\d\d)$")
_LIBRARY_COUNT = re.compile(r"LIBRARY_VERSIONS_COUNT\s*=\s*(\d+)")


def silent_version_channels(channels: list[dict[str, Any]], libraries: int) -> int:
    """Svc.Version's channels no path of the build writes, which TlmChan's
    buckets need not hold (app/config/TlmChanImplCfg.hpp.in): every custom
    version (the kit leaves setVersion unconnected) and the library slots
    past the build's `libraries`. Svc.Version's instances are the ones with
    a FrameworkVersion channel; another component's channel of such a name
    is not one of them."""
    versions = {c["name"].rpartition(".")[0] for c in channels if c["name"].endswith(".FrameworkVersion")}
    silent = 0
    for channel in channels:
        slot = _VERSION_SLOT.search(channel["name"])
        if (slot and channel["name"].rpartition(".")[0] in versions
                and (slot.group(1) == "CustomVersion" or int(slot.group(2)) > libraries)):
            silent += 1
    return silent


def version_libraries(build_dir: Path) -> int:
    """The F´ libraries whose versions the build's Svc.Version writes, from
    F´'s generated versions/version.cpp (10, every slot, when there is none)."""
    generated = build_dir / "versions" / "version.cpp"
    found = _LIBRARY_COUNT.search(generated.read_text()) if generated.is_file() else None
    return int(found.group(1)) if found else 10


def _tables(info: DebugInfo, dictionary: dict[str, Any], config: dict[str, str], active: int,
            libraries: int) -> list[Advice]:
    commands = len({c["name"] for c in dictionary.get("commands", [])})
    channels = dictionary.get("telemetryChannels", [])
    written = len(channels) - silent_version_channels(channels, libraries)
    with_channels = len({c["name"].split(".")[-2] for c in channels})
    found: list[Advice] = []
    packet, largest = largest_packet(dictionary, config)
    if config.get("CONFIG_FPRIME_COM_BUFFER_MAX_SIZE"):
        # Every queued command, event and packet carries a buffer of this
        # size, in many copies: what a byte of it costs is measured, not
        # counted (kit footprint's com_buffer_max_size knob), so no bytes here
        found.append(Advice("packet buffer (bytes)", "CONFIG_FPRIME_COM_BUFFER_MAX_SIZE (modules/fprime/Kconfig)",
                            int(config["CONFIG_FPRIME_COM_BUFFER_MAX_SIZE"]), packet, 0,
                            f"the largest packet, {largest}; a byte's cost: kit footprint"))
    # F´'s dispatcher holds its table; fprime-baremetal's passive one takes it from F´'s allocator
    dispatch = (info.member("Svc::CommandDispatcherImpl", "m_entryTable")
                or info.member("Baremetal::PassiveCmdDispatcher::CmdTables", "m_entryTable"))
    if dispatch is not None:
        found.append(Advice("command dispatch table", "CONFIG_KIT_DEPLOYMENT_COMMANDS (app/Kconfig; the services' "
                            "in app/config/CommandDispatcherImplCfg.hpp)", dispatch.count, commands,
                            dispatch.element_bytes, f"{commands} commands in the dictionary"))
    sets = info.member("Svc::TlmChan", "m_tlmEntries")
    buckets = info.member("Svc::TlmChan::TlmSet", "buckets")
    slots = info.member("Svc::TlmChan::TlmSet", "slots")
    if sets is not None and buckets is not None and slots is not None:
        found.append(Advice("telemetry buckets (TlmChan)", "CONFIG_KIT_DEPLOYMENT_CHANNELS (app/Kconfig; "
                            "the services' in app/config/TlmChanImplCfg.hpp.in)",
                            buckets.count, written, buckets.element_bytes * sets.count,
                            f"{written} channels the build can write of the dictionary's {len(channels)}; "
                            "a bucket is never freed"))
        found.append(Advice("telemetry hash slots (TlmChan)", "TLMCHAN_NUM_TLM_HASH_SLOTS "
                            "(app/config/TlmChanImplCfg.hpp.in)", slots.count, with_channels,
                            slots.element_bytes * sets.count,
                            f"baremetal-size's rule: one per component with channels ({with_channels}); fewer "
                            "only lengthens the search", must_fit=False))
    linear = info.cls("Baremetal::TlmLinearChan::tlmEntry")
    linear_entries = info.enumerator("TlmLinearChan.cpp", "TLMCHAN_HASH_BUCKETS") if linear is not None else None
    if linear is not None and linear_entries is not None:
        found.append(Advice("telemetry table (TlmLinearChan, heap)", "CONFIG_KIT_DEPLOYMENT_CHANNELS "
                            "(app/Kconfig)", linear_entries, written, info.size(linear),
                            f"{written} channels the build can write of the dictionary's {len(channels)}; "
                            "an entry is never freed"))
    table = info.member("Kit::TlmTable", "m_entries")
    if table is not None:
        found.append(Advice("telemetry table (TlmTable)", "CONFIG_KIT_DEPLOYMENT_CHANNELS (app/Kconfig; "
                            "the services' in app/config/TlmChanImplCfg.hpp.in)", table.count, written,
                            table.element_bytes,
                            f"{written} channels the build can write of the dictionary's {len(channels)}; "
                            "an entry is never freed"))
    runner = info.member("Os::Baremetal::TaskRunner", "m_task_table")
    if runner is not None:
        found.append(Advice("TaskRunner task table", "TASK_CAPACITY (fprime-baremetal "
                            "Os/TaskRunner/TaskRunner.hpp, an upstream constant)", runner.count, active,
                            runner.element_bytes, f"{active} active instances"))
    prm_db = info.member("Svc::PrmDbImpl", "m_dbStore1")
    if prm_db is not None:
        parameters = len(dictionary.get("parameters", []))
        found.append(Advice("parameter database (PrmDb, two tables)", "CONFIG_KIT_DEPLOYMENT_PARAMETERS "
                            "(app/Kconfig)", prm_db.count, parameters, 2 * prm_db.element_bytes,
                            f"{parameters} parameters in the dictionary"))
    # The kit's rtos model sizes each stack from its table (rtos/ThreadStacks.cpp);
    # a build on Zephyr's thread pool gives each thread one slot
    if int(config.get("CONFIG_DYNAMIC_THREAD_POOL_SIZE", "0")) > 0:
        thread = info.cls("k_thread")
        slot = int(config.get("CONFIG_DYNAMIC_THREAD_STACK_SIZE", "0")) + info.size(thread)
        found.append(Advice("thread pool", "CONFIG_DYNAMIC_THREAD_POOL_SIZE (rtos/Kconfig.model)",
                            int(config["CONFIG_DYNAMIC_THREAD_POOL_SIZE"]), active, slot,
                            f"{active} active instances; a slot is its stack and its struct k_thread"))
    return found


def queue_advice(records: list[dict[str, str]]) -> list[Advice]:
    """Queue depths against the run's high-water marks (QUEUE records): a
    measure of that run, not a bound; the depth must cover the worst case.
    A queue that dropped messages (dropped=, F´'s count for its `drop`
    ports) was full: it needed at least one slot more."""
    advice = []
    for r in records:
        depth, high_water, dropped = int(r["depth"]), int(r["high_water"]), int(r.get("dropped", 0))
        needed, basis = high_water, "this run's high-water mark"
        if dropped:
            needed, basis = max(high_water, depth + 1), f"this run dropped {dropped} messages to a full queue"
        advice.append(Advice(f"queue of {r['name']}", f"queue size of {r['name']} (app/Top/instances.fpp)",
                             depth, needed, int(r["slot_bytes"]), basis, must_fit=False))
    return advice


def measure(build_dir: Path, queue_records: list[dict[str, str]] | None = None) -> Sizing:
    """The sizing of a build; with the QUEUE records of its run, its queues too."""
    folder = BuildFolder(build_dir)
    dictionary = json.loads(folder.dictionary().read_text())
    config = folder.kconfig()
    with DebugInfo(build_dir) as info:
        cost = ports.measure(info)
        active = sum(1 for i in info.instances() if info.derives_from(i.cls, "ActiveComponentBase"))
        advice = _tables(info, dictionary, config, active, version_libraries(build_dir))
    return Sizing(advice + queue_advice(queue_records or []), cost)


def render(sizing: Sizing) -> list[str]:
    lines = [f"{'table':<34} {'current':>7} {'needed':>7} {'B/entry':>7} {'spare B':>8}  verdict / basis / set in"]
    for a in sizing.advice:
        lines.append(f"{a.table:<34} {a.current:>7} {a.needed:>7} {a.unit_bytes:>7} {a.spare_bytes:>8}  "
                     f"{a.verdict}; {a.basis}; {a.setting}")
    cost = sizing.ports
    lines += ["", f"ports of {len(cost.instances)} instances: {cost.total('inputs')} input "
                  f"({cost.total('input_bytes')} B), {cost.total('outputs')} output ({cost.total('output_bytes')} B) "
                  f"of {cost.total('object_bytes')} B of instance objects",
              f"{'instance':<18} {'component':<32} {'object B':>8} {'in':>4} {'in B':>6} {'out':>4} {'out B':>6}"]
    for i in cost.instances:
        lines.append(f"{i.name:<18} {i.component[:32]:<32} {i.object_bytes:>8} {i.inputs:>4} {i.input_bytes:>6} "
                     f"{i.outputs:>4} {i.output_bytes:>6}")
    return lines
