# SPDX-License-Identifier: Apache-2.0
"""`kit new-deployment DIR`: the edits of a template deployment's own files
(what is tied to a host becomes the kit's tick, link and time; its topology
gets the kit's instruments and ground link) and the seam's files
(kittools.deployments.seam). Every edit is a fixpoint, and a seam file that
exists is kept, so a second run changes nothing."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

from kittools.deployments import cpp, fpp, seam, template
from kittools.deployments.members import kit_members, uplink_group
from kittools.deployments.template import RATE_GROUP_TYPES, Deployment

#: The host's timer, whose CycleOut the kit's tick replaces
HOST_TIMERS = ("Svc.LinuxTimer",)
#: The host's link drivers, which the kit's ground link (its UART) replaces
HOST_DRIVERS = ("Drv.TcpClient", "Drv.TcpServer", "Drv.LinuxUartDriver")
#: F´'s comm subtopologies, which the kit's ground link replaces (F´ framing,
#: what kit gds, the fuzzers and the integration suite speak)
COMM = re.compile(r"^Com(Ccsds|Fprime)\.")

#: Their ports that carry the deployment's traffic, and the ground link's port that takes each over
COMM_PORTS = {
    "comQueue.bufferQueueIn": "Kit.comQueue.bufferQueueIn[0]",
    "comQueue.bufferReturnOut": "Kit.comQueue.bufferReturnOut[0]",
    "fprimeRouter.commandOut": "Kit.linkHealth.commandOut",
    "fprimeRouter.cmdResponseIn": "Kit.linkHealth.commandStatusIn",
    "fprimeRouter.fileOut": "Kit.router.fileOut",
    "fprimeRouter.fileBufferReturnIn": "Kit.router.fileBufferReturnIn",
    "comQueue.run": "Kit.comQueue.run",
}
DROP = ""


@dataclass
class Record:
    """What a run did: each change and what is left to the team."""

    changes: list[str] = field(default_factory=list)
    todo: list[str] = field(default_factory=list)
    kept: list[str] = field(default_factory=list)


def _host(deployment: Deployment, types: tuple[str, ...]) -> list[fpp.Instance]:
    return [instance for instance in deployment.own if instance.type in types]


def map_endpoint(endpoint: str, removed: dict[str, str]) -> str:
    """Where a connection's end goes once the host's instances and F´'s comm
    subtopology are gone: the kit's port, the same, or DROP."""
    instance = fpp.endpoint_instance(endpoint)
    port = fpp.endpoint_port(endpoint)
    if instance in removed:
        return removed[instance] if port.endswith(".CycleOut") and removed[instance] else DROP
    if COMM.match(endpoint):
        local = port.split(".", 1)[1]
        if local == "comQueue.comPacketQueueIn":
            index = fpp.endpoint_index(endpoint) or ""
            return "Kit.downlink.comIn[1]" if "TELEMETRY" in index or index == "1" else "Kit.downlink.comIn[0]"
        return COMM_PORTS.get(local, DROP)
    return endpoint


def adapt_topology(text: str, deployment: Deployment, plan: seam.Plan, removed: dict[str, str],
                   record: Record) -> str:
    lines = text.splitlines()
    groups = [group.name for group in deployment.rate_groups]
    dispatcher = deployment.patterns.get("command", "cmdDisp")
    out: list[str] = []
    members: dict[str, list[tuple[str, str]]] = {name: [] for name in groups}
    # First pass: the deployment's own members of each group, in index order
    for line in lines:
        connection = fpp.CONNECTION.match(line)
        if not connection or fpp.endpoint_port(connection.group("source")) not in {
                f"{name}.RateGroupMemberOut" for name in groups}:
            continue
        group = fpp.endpoint_instance(connection.group("source"))
        target = map_endpoint(connection.group("target"), removed)
        if target == DROP or target.startswith("Kit."):
            continue
        index = fpp.endpoint_index(connection.group("source")) or "0"
        members[group].append((index, target + (f"  {connection.group('comment')}" if connection.group("comment")
                                                  else "")))
    for name in groups:
        members[name].sort(key=lambda member: int(member[0]) if member[0].isdigit() else 0)
        plan.members[name] = [target for _, target in members[name]]
    # The kit's scripted uplink goes after the topology's pattern specifiers
    # (the dispatcher is the command pattern's)
    patterns = [number for number, line in enumerate(lines)
                if re.match(r"^\s*(command|event|telemetry|health|param|time)\s+connections\s+instance\b", line)]
    last_pattern = patterns[-1] if "command" in deployment.patterns and patterns else -1
    if last_pattern < 0 and "Kit.uplink.cmdOut" not in text:
        record.todo.append("Top/topology.fpp names no command dispatcher (`command connections instance`): connect "
                           "Kit.uplink.cmdOut and cmdResponseIn to its seqCmdBuff and seqCmdStatus")
    for number, line in enumerate(lines):
        imported = re.match(r"^(\s*)import\s+([\w.]+)", line)
        if imported and COMM.match(imported.group(2) + "."):
            out.append(f"{imported.group(1)}# The kit's ground link (F´ framing, on the board's link UART) in place "
                       f"of {imported.group(2)} (kit new-deployment)")
            out.append(f"{imported.group(1)}import Kit.GroundLink")
            if "import Kit.Instruments" not in text:
                out.append(f"{imported.group(1)}# The kit's instruments: tick, timing probe, load, faults, scripted "
                           "uplink")
                out.append(f"{imported.group(1)}import Kit.Instruments")
            record.changes.append(f"Top/topology.fpp: {imported.group(2)} -> Kit.GroundLink (F´ framing, the board's "
                                  "link UART), with Kit.Instruments")
            continue
        if re.match(r"^\s*text\s+event\s+connections\s+instance\b", line):
            # Text events on the console would interleave with the run's record
            # the kit parses (F´'s console logger writes no line ends)
            record.changes.append("Top/topology.fpp: no text event connections (F´'s console text would "
                                  "interleave with the kit's record of the run; events reach the ground)")
            continue
        listed = re.match(r"^\s*instance\s+(\$?\w+)\s*$", line)
        if listed and listed.group(1) in removed:
            continue
        connection = fpp.CONNECTION.match(line)
        if connection:
            source, target = connection.group("source"), connection.group("target")
            if fpp.endpoint_port(source) in {f"{name}.RateGroupMemberOut" for name in groups}:
                continue
            new_source, new_target = map_endpoint(source, removed), map_endpoint(target, removed)
            if DROP in (new_source, new_target):
                record.changes.append(f"Top/topology.fpp: dropped `{source} -> {target}` (the kit's ground link "
                                      "has its own)")
                continue
            if (new_source, new_target) != (source, target):
                record.changes.append(f"Top/topology.fpp: `{source} -> {target}` is now `{new_source} -> "
                                      f"{new_target}`")
            comment = f"  {connection.group('comment')}" if connection.group("comment") else ""
            out.append(f"{connection.group('indent')}{new_source} -> {new_target}{comment}")
            driven = fpp.endpoint_instance(new_target)
            if fpp.endpoint_port(new_target).endswith(".CycleIn") and driven in groups:
                before, after = kit_members(plan, groups.index(driven))
                indent = connection.group("indent")
                own = [target for _, target in members[driven]]
                for port, member in enumerate(before + own + after):
                    out.append(f"{indent}{driven}.RateGroupMemberOut[{port}] -> {member}")
            continue
        out.append(line)
        if number == last_pattern and "Kit.uplink.cmdOut" not in text:
            indent = re.match(r"^(\s*)", line).group(1)  # type: ignore[union-attr]
            out.extend([
                "",
                f"{indent}# The kit's scripted uplink: a scenario's commands (kit new-deployment)",
                f"{indent}connections KitUplink {{",
                f"{indent}  Kit.uplink.cmdOut -> {dispatcher}.seqCmdBuff",
                f"{indent}  {dispatcher}.seqCmdStatus -> Kit.uplink.cmdResponseIn",
                f"{indent}}}",
            ])
            record.changes.append("Top/topology.fpp: connections KitUplink (the kit's scripted uplink to "
                                  f"{dispatcher})")
    if "Kit.timing.cycleStart" not in text:
        record.changes.append("Top/topology.fpp: the kit's tick drives the rate group driver; each rate group "
                              "starts and ends with the kit's timing probe, and takes the kit's members (load, "
                              "faults, the link's polls)")
    if "import Kit.GroundLink" not in "\n".join(out):
        record.todo.append("Top/topology.fpp imports no comm subtopology: add `import Kit.GroundLink` and wire "
                           "its events and telemetry to Kit.downlink.comIn[0] and [1]")
    return "\n".join(out) + ("\n" if text.endswith("\n") else "")


def adapt_instances(text: str, deployment: Deployment, plan: seam.Plan, record: Record, path: str) -> str:
    lines = text.splitlines()
    groups = {group.name for group in deployment.rate_groups}
    replace: dict[int, tuple[int, list[str]]] = {}
    for instance in fpp.instances(text):
        indent = re.match(r"^(\s*)", lines[instance.first]).group(1)  # type: ignore[union-attr]
        if instance.type in HOST_TIMERS:
            replace[instance.first] = (instance.last, [
                f"{indent}# {instance.name} ({instance.type}): the kit's tick, Kit.timing, drives the rate groups"])
            record.changes.append(f"{path}: {instance.name} ({instance.type}) removed: the kit's tick drives the "
                                  "rate group driver")
        elif instance.type in HOST_DRIVERS:
            replace[instance.first] = (instance.last, [
                f"{indent}# {instance.name} ({instance.type}): the kit's ground link, Kit.linkUart, on the "
                "board's link UART"])
            record.changes.append(f"{path}: {instance.name} ({instance.type}) removed: the kit's ground link "
                                  "(Kit.linkUart, the board's link UART) carries the link")
        elif instance.type in template.HOST_CLOCKS:
            block = "\n".join(lines[instance.first:instance.last + 1]).replace(instance.type, "Svc.OsTime", 1)
            replace[instance.first] = (instance.last, block.splitlines())
            record.changes.append(f"{path}: {instance.name} is Svc.OsTime (the board's clock through Os::RawTime), "
                                  f"not {instance.type}")
        elif instance.type in RATE_GROUP_TYPES and instance.name in groups:
            replace[instance.first] = (instance.last, [
                f"{indent}# {instance.name}: in rategroups/, in the form the execution model chooses"])
            record.changes.append(f"{path}: {instance.name} moved to Top/rategroups/ (active, or passive in "
                                  "baremetal_passive), its stack, priority and queue in Top/Tables.fpp")
        elif instance.active and not (instance.stack or "").startswith("Kit."):
            block = "\n".join(lines[instance.first:instance.last + 1])
            block = re.sub(r"(queue\s+size\s+)[^\\\n]+?(\s*(\\|$))", rf"\g<1>Kit.Queues.{instance.name}\g<2>",
                           block, count=1, flags=re.MULTILINE)
            block = re.sub(r"(stack\s+size\s+)[^\\\n]+?(\s*(\\|$))", rf"\g<1>Kit.Stacks.{instance.name}\g<2>",
                           block, count=1, flags=re.MULTILINE)
            block = re.sub(r"(priority\s+)[^\\\n{]+?(\s*(\\|\{|$))", rf"\g<1>Kit.Priorities.{instance.name}\g<2>",
                           block, count=1, flags=re.MULTILINE)
            replace[instance.first] = (instance.last, block.splitlines())
            record.changes.append(f"{path}: {instance.name} takes its stack, priority and queue from Top/Tables.fpp")
    out: list[str] = []
    index = 0
    while index < len(lines):
        if index in replace:
            last, new = replace[index]
            out.extend(new)
            index = last + 1
            continue
        out.append(lines[index])
        index += 1
    return "\n".join(out) + ("\n" if text.endswith("\n") else "")


def adapt_defs(text: str, record: Record, path: str) -> str:
    """The template's TopologyDefs.hpp: the kit's TopologyState, and no
    comm subtopology's headers."""
    new = re.sub(r"^\s*//\s*Com(Ccsds|Fprime) Enum Includes\s*\n", "", text, flags=re.MULTILINE)
    new = re.sub(r'^#include\s+"Svc/Subtopologies/Com(Ccsds|Fprime)/[^"]*"\s*\n', "", new, flags=re.MULTILINE)
    new = re.sub(r"struct\s+TopologyState\s*\{.*?\n\};", "//! The kit's: its main hands the setup the kit's counting "
                 "allocator (kit new-deployment)\nusing Kit::TopologyState;", new, count=1, flags=re.DOTALL)
    if '#include "app/src/TopologyState.hpp"' not in new:
        new = re.sub(r"^(#define\s+\w+\s*\n)", r'\1\n#include "app/src/TopologyState.hpp"\n', new, count=1,
                     flags=re.MULTILINE)
    if new != text:
        record.changes.append(f"{path}: TopologyState is the kit's (its counting allocator); the comm "
                              "subtopology's headers are gone")
    return new


def _sequencer_sizes(deployment: Deployment, plan: seam.Plan) -> None:
    """The template's sequencer buffer sizes (`cmdSeq.allocateBuffer(0,
    mallocator, 5 * 1024)`), for the kit's setup."""
    for source in sorted((deployment.folder / "Top").glob("*.cpp")):
        calls = re.finditer(r"(\w+)\.allocateBuffer\(\s*\d+\s*,\s*\w+\s*,\s*([^;]+?)\s*\)\s*;", source.read_text())
        for match in calls:
            cpp = f"{deployment.namespace}::{match.group(1)}"
            if cpp in plan.sequencers:
                plan.sequencers[cpp] = match.group(2)


def counts(deployment: Deployment, plan: seam.Plan) -> dict[str, int]:
    """The port counts of F´'s configuration this topology needs
    (app/config/AcConstants.fpp.in): every queued or active instance may be
    pinged, every instance may own commands."""
    everything = deployment.all_instances()
    text = (deployment.folder / "Top" / "topology.fpp").read_text()
    dispatcher = deployment.patterns.get("command", "cmdDisp")
    sources = len(re.findall(r"->\s*" + re.escape(dispatcher) + r"\.seqCmdBuff", text))
    members = max(len(kit_members(plan, index)[0]) + len(plan.members.get(group.name, []))
                  + len(kit_members(plan, index)[1]) for index, group in enumerate(deployment.rate_groups))
    return {
        "KIT_HEALTH_PING_PORTS": sum(1 for instance in everything if instance.queued) + 2,
        "KIT_COMMAND_SOURCES": max(sources, 2),
        "KIT_COMMAND_COMPONENTS": len(everything) + 8,
        "KIT_RATE_GROUP_DRIVER_PORTS": len(deployment.rate_groups),
        "KIT_RATE_GROUP_MEMBERS": max(members, 13),
    }


def _write(folder: Path, relative: str, text: str, record: Record, why: str) -> None:
    path = folder / relative
    if path.exists():
        record.kept.append(relative)
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    record.changes.append(f"{relative}: written ({why})")


def _edit(folder: Path, relative: str, edit: Callable[[str], str]) -> None:
    path = folder / relative
    text = path.read_text()
    new = edit(text)
    if new != text:
        path.write_text(new)


def new_deployment(folder: Path, fastest_hz: Fraction | None = None) -> Record:
    """Adapt the deployment in `folder` to the kit; what it did, and what is
    left to the team."""
    deployment = template.read(folder, fastest_hz)
    record = Record()
    plan = seam.plan(deployment)
    _sequencer_sizes(deployment, plan)
    removed = {instance.name: "Kit.timing.CycleOut" for instance in _host(deployment, HOST_TIMERS)}
    removed.update({instance.name: DROP for instance in _host(deployment, HOST_DRIVERS)})
    folder = deployment.folder
    top = folder / "Top"
    # The topology first: it gives each rate group's members to the rest
    _edit(folder, "Top/topology.fpp", lambda text: adapt_topology(text, deployment, plan, removed, record))
    plan.file_uplink = "Kit.router.fileOut" in (top / "topology.fpp").read_text()
    # Rate group files are written before their instances leave instances.fpp
    for relative, text in seam.rate_group_files(plan).items():
        _write(folder, f"Top/{relative}", text, record, "the rate groups in both forms")
    for path in sorted(top.glob("*.fpp")):
        if path.name in ("topology.fpp",):
            continue
        name = f"Top/{path.name}"

        def edit(text: str, name: str = name) -> str:
            return adapt_instances(text, deployment, plan, record, name)

        _edit(folder, name, edit)
    defs = f"{deployment.topology}TopologyDefs.hpp"
    if (top / defs).is_file():
        _edit(folder, f"Top/{defs}", lambda text: adapt_defs(text, record, f"Top/{defs}"))
    else:
        record.todo.append(f"Top/{defs} is missing: F´'s generated code includes it for TopologyState")
    top_cmake = top / "CMakeLists.txt"
    if "kit_deployment_tables" not in (top_cmake.read_text() if top_cmake.is_file() else ""):
        top_cmake.write_text(seam.top_cmake(deployment, defs))
        record.changes.append("Top/CMakeLists.txt: the kit's (rate groups in the model's form, the board's table, "
                              f"KitTopology.cpp in place of {deployment.topology}Topology.cpp)")
    plan.overrides = seam.config_overrides(plan, template.fprime_subtopologies())
    tasks = len(plan.tasks) + 2 + len(deployment.rate_groups)
    _write(folder, "config/CMakeLists.txt", seam.config_cmake(plan, counts(deployment, plan)), record,
           "the kit's F´ configuration, with this topology's port counts")
    for name, text in plan.overrides.items():
        _write(folder, f"config/{name}", text, record, "F´'s, with the kit's stacks and priorities")
    _write(folder, "Components/CMakeLists.txt", seam.components_cmake(deployment), record,
           "the deployment's own components")
    _write(folder, "Top/Tables.fpp", seam.tables(plan), record, "priorities, stacks and queues for the kit's boards")
    _write(folder, "Top/KitTopology.hpp", cpp.kit_topology_hpp(plan), record, "the seam's counts")
    _write(folder, "Top/KitTopology.cpp", cpp.kit_topology_cpp(plan), record,
           "the rates, the active instances and the setup")
    _write(folder, "Top/ActiveStacks.hpp", cpp.active_stacks_hpp(plan), record, "the stacks, for the models' checks")
    fixed_dispatcher = "." in deployment.patterns.get("command", "")
    text_loggers = "CdhCore" in deployment.subtopologies
    heap = seam.heap_bytes(plan, template.fprime_subtopologies())
    _write(folder, "deployment.conf", seam.deployment_conf(plan, tasks, heap, text_loggers, fixed_dispatcher), record,
           "its Kconfig: services, task count, table shares")
    if not record.kept:
        for stale in ("Main.cpp", f"Top/{deployment.topology}Topology.cpp", f"Top/{deployment.topology}Topology.hpp",
                      "CMakeLists.txt"):
            if (folder / stale).exists():
                record.todo.append(f"{stale}: the host build's; the kit builds without it (its main, "
                                   "Top/KitTopology.cpp). Keep it for a host build of your own or delete it")
    top_us = 2 * deployment.rate_groups[0].period * 1_000_000
    slice_max = template.load_slice_max_us()
    if top_us > slice_max:
        record.todo.append(f"the load sweep reaches twice the fastest group's period, {float(top_us) / 1000:g} ms, "
                           f"past the load's slice limit ({slice_max / 1000:g} ms, app/Components/Load/Load.hpp): its "
                           "points above it are refused and the sweep fails; a faster fastest group (--fastest-hz "
                           f"{template.sweep_min_hz()} or more) keeps it in range")
    if "DataProducts" in deployment.subtopologies:
        record.todo.append("DataProducts takes its buffers from malloc (DataProductsConfig: 10 x 10,000 B by "
                           "default): the heap of a small board holds less")
    if plan.dispatcher_run:
        record.changes.append(f"Top/topology.fpp: {plan.dispatcher_run} in rate group "
                              f"{deployment.rate_groups[uplink_group(plan)].name}, as F´'s Ref has it: the "
                              "dispatcher writes its telemetry (CommandErrors, CommandsDispatched) only there")
    if "Top/KitTopology.cpp" not in record.kept:  # written this run
        for instance in cpp.fixed_parameter_files(deployment):
            record.changes.append(f"Top/KitTopology.cpp: {instance.qualified} configured again with "
                                  "Kit.RamFs.parameterFile before the parameters load: F´'s FileHandling names its "
                                  "file PrmDb.dat, which the kit's RAM file system (MicroFs: /bin<b>/file<n>) has not")
    return record


