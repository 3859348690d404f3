# SPDX-License-Identifier: Apache-2.0
"""The seam's files `kit new-deployment` writes into a deployment folder
(docs/your-deployment.md gives what each one is for), from the model
kittools.deployments.template reads. A file that exists is the team's and is
never written again."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from kittools.deployments import fpp
from kittools.deployments.template import Deployment

#: The kit's stack for each task, until the deployment's runs measure its
#: own (rtos: each thread's stack at its size, rtos/ThreadStacks.cpp); the
#: template's 64 KiB are a host's
KIT_STACK = 2048
#: The kit's own tasks' entries (app/Subtopologies/: the load, the downlink's
#: queue), as tests/team/Thermal has them
KIT_QUEUES = {"load": "10", "comQueue": "12"}
#: The event service's queue (F´'s CdhCore: 10): it takes health's pings,
#: and F´ asserts when one finds it full. fprime-util's template, adapted,
#: peaked at 11 under the kit's load sweep in rtos on mps2/an385 (depth 32,
#: KIT QUEUE name=events high_water=11); at F´'s 10 the sweep's first
#: point asserted (EventManager's pingIn)
EVENTS_QUEUE = 16
#: A rate group's queue: one pending cycle, a second is a slip (the kit
#: counts it: the run's KIT QUEUE high_water)
RATE_GROUP_QUEUE = 2
#: F´ priorities on the kit's scale (rtos/Os/PriorityMap.hpp: 0..14, the
#: tick at 12): the fastest group above the tick, the other groups below
#: it, then the dispatcher, the deployment's other tasks, the downlink
#: above the services that feed it, and the background load last
FASTEST_PRIORITY = 13
OTHER_TASKS_PRIORITY = 7
KIT_PRIORITIES = {"comQueue": 5, "telemetry": 4, "event": 3, "load": 1}
#: First shares of F´'s fixed tables; the build checks them against the
#: dictionary and names both counts when one is short (`kit sizing` gives
#: the dictionary's)
FIRST_COMMANDS = 128
#: The main thread's stack, a first size (the kit's boards' largest default is 3200)
MAIN_STACK = 8192
#: The kit's C heap without its optional services (app/Kconfig's COMMON_LIBC_MALLOC_ARENA_SIZE)
KIT_HEAP = 10816
#: F´'s heap per task beyond that: its queue and its share of F´'s
#: allocations. fprime-util's template, adapted, took 34,245 B of F´'s
#: allocations for its 16 tasks in rtos on mps2/an385 (KIT HEAP
#: fprime_peak): about 2,140 B each, and this leaves room for the heap's
#: chunk headers; the run says when it is short (KIT HEAP failures=)
HEAP_PER_TASK = 3072
FIRST_CHANNELS = 128


@dataclass
class Plan:
    """What the seam needs, computed once from the deployment."""

    deployment: Deployment
    #: active instances other than the rate groups: (qualified name, C++ name, stack C++ expression)
    tasks: list[tuple[str, str, str]] = field(default_factory=list)
    queues: dict[str, str] = field(default_factory=dict)  #: own active instance -> its queue depth expression
    members: dict[str, list[str]] = field(default_factory=dict)  #: rate group -> members, as rewritten
    file_uplink: bool = False
    sequencers: dict[str, str] = field(default_factory=dict)  #: C++ name -> buffer bytes expression
    #: F´'s dispatcher's run port where no rate group drives it: it writes
    #: the dispatcher's telemetry (CommandErrors, CommandsDispatched) only
    #: there, and fprime-util's template leaves it out (F´'s Ref has it)
    dispatcher_run: str | None = None
    overrides: dict[str, str] = field(default_factory=dict)  #: config file name -> its text

    @property
    def rate_group_names(self) -> list[str]:
        return [group.name for group in self.deployment.rate_groups]

    def priority(self, group: int) -> int:
        return FASTEST_PRIORITY if group == 0 else FASTEST_PRIORITY - 1 - group

    def task_name(self, qualified: str) -> str:
        """A task's name in the run's record: its instance's name, as the kit
        names its services' (events, tlmSend, cmdDisp), unless two share it."""
        short = qualified.rsplit(".", 1)[-1]
        clashes = [name for name, _, _ in self.tasks if name.rsplit(".", 1)[-1] == short]
        return short if len(clashes) == 1 and short not in self.rate_group_names else qualified

    @property
    def dispatcher_priority(self) -> int:
        return FASTEST_PRIORITY - 1 - len(self.deployment.rate_groups)


def _qualify(expression: str, namespace: str) -> str:
    """A constant of the deployment's module, named from module Kit."""
    if re.fullmatch(r"[A-Za-z_][\w.]*", expression) and not expression.startswith(("Kit.", namespace + ".")):
        return f"{namespace}.{expression}"
    return expression


def plan(deployment: Deployment) -> Plan:
    result = Plan(deployment)
    dispatcher = deployment.patterns.get("command", "cmdDisp")
    found = deployment.instance(dispatcher)
    topology = deployment.folder / "Top" / "topology.fpp"
    if found is not None and found.type == "Svc.CommandDispatcher" and topology.is_file() and not re.search(
            r"->\s*" + re.escape(dispatcher) + r"\.run\b", topology.read_text()):
        result.dispatcher_run = f"{dispatcher}.run"
    rate_groups = set(result.rate_group_names)
    for instance in deployment.own:
        if instance.active and instance.name not in rate_groups:
            result.tasks.append((instance.qualified, deployment.cpp(instance.qualified), f"Stacks::{instance.name}"))
            queue = instance.queue or "10"
            result.queues[instance.name] = "10" if queue.startswith("Kit.") else _qualify(queue, deployment.namespace)
        if instance.type == "Svc.CmdSequencer":
            result.sequencers[deployment.cpp(instance.qualified)] = "5 * 1024"
    for instances in deployment.subtopologies.values():
        for instance in instances:
            if instance.active:
                stack = (instance.stack or str(KIT_STACK)).replace(".", "::")
                result.tasks.append((instance.qualified, deployment.cpp(instance.qualified), stack))
    return result


# ----------------------------------------------------------------------
# The files
# ----------------------------------------------------------------------

def config_overrides(result: Plan, fprime_subtopologies: Path) -> dict[str, str]:
    """F´'s subtopology configurations with the kit's stacks and priorities
    (their queue depths and other values are F´'s): files of the same name in
    the deployment's config/ replace F´'s (register_fprime_config's
    CONFIGURATION_OVERRIDES)."""
    deployment = result.deployment
    files: dict[str, str] = {}
    roles = {instance: role for role, instance in deployment.patterns.items()}
    for name in deployment.subtopologies:
        for path in sorted((fprime_subtopologies / name).glob(f"{name}Config/*.fpp")):
            text = path.read_text()
            if re.search(r":\s*Svc\.FatalHandler\b", text):
                # F´'s fatal handler on this platform raises a host signal;
                # the kit's reports the halt and stops the run
                files[path.name] = (f"# F´'s {path.name} (Svc/Subtopologies/{name}) with the kit's fatal handler:\n"
                                    "# F´'s raises a host signal; the kit's reports the FATAL event and stops\n"
                                    "# the run. Written by kit new-deployment; yours to change.\n"
                                    + re.sub(r"(:\s*)Svc\.FatalHandler\b", r"\1Kit.FatalHandler", text))
                continue
            stacks = fpp.constants(text, "StackSizes")
            priorities = fpp.constants(text, "Priorities")
            if not stacks and not priorities:
                continue
            new_priorities = {}
            for instance in priorities:
                role = roles.get(f"{name}.{instance}")
                if role == "command":
                    new_priorities[instance] = str(result.dispatcher_priority)
                elif role in KIT_PRIORITIES:
                    new_priorities[instance] = str(KIT_PRIORITIES[role])
                else:
                    new_priorities[instance] = str(OTHER_TASKS_PRIORITY)
            queues = {instance: str(EVENTS_QUEUE) for instance, depth in fpp.constants(text, "QueueSizes").items()
                      if roles.get(f"{name}.{instance}") == "event" and depth.isdigit() and int(depth) < EVENTS_QUEUE}
            text = fpp.set_constants(text, "QueueSizes", queues)
            text = fpp.set_constants(text, "StackSizes", {instance: str(KIT_STACK) for instance in stacks})
            text = fpp.set_constants(text, "Priorities", new_priorities)
            events = (f"# The event service's queue holds {EVENTS_QUEUE}: health's pings must find room.\n"
                      if queues else "")
            header = (f"# F´'s {path.name} (Svc/Subtopologies/{name}) with the kit's stacks and priorities: a\n"
                      f"# {KIT_STACK} B stack each, and F´ priorities on the kit's scale\n"
                      f"{events}# (docs/your-deployment.md). Written by kit new-deployment; yours to change.\n")
            files[path.name] = header + text
    return files


def config_cmake(result: Plan, counts: dict[str, int]) -> str:
    overrides = "".join(f'        "${{CMAKE_CURRENT_LIST_DIR}}/{name}"\n' for name in sorted(result.overrides))
    lines = [
        "# The deployment's F´ configuration: the kit's (app/config/), with this",
        "# deployment's port counts, and F´'s subtopology configurations with the",
        "# kit's stacks and priorities (files of the same name replace F´'s).",
        "# Written by kit new-deployment (docs/your-deployment.md).",
    ]
    lines += [f"set({name} {value})" for name, value in counts.items()]
    lines.append('include("${KIT_ROOT}/app/config/CMakeLists.txt")')
    text = "\n".join(lines) + "\n"
    if overrides:
        text += (f"register_fprime_config(\n    {result.deployment.namespace}_SubtopologyConfig\n"
                 f"    CONFIGURATION_OVERRIDES\n{overrides}    INTERFACE\n)\n")
    return text


def components_cmake(deployment: Deployment) -> str:
    """The deployment's own components: the folders its CMakeLists.txt adds
    (other than Top/), from here."""
    lines = ["# The deployment's own components (written by kit new-deployment from the",
             "# folders its CMakeLists.txt adds; add a new component here and there)."]
    deployment_cmake = deployment.folder / "CMakeLists.txt"
    if deployment_cmake.is_file():
        for match in re.finditer(r'^\s*add_fprime_subdirectory\(\s*"\$\{CMAKE_CURRENT_LIST_DIR\}/([^"]+)"\s*\)',
                                 deployment_cmake.read_text(), flags=re.MULTILINE):
            folder = match.group(1).strip("/")
            if folder not in ("Top", "config", "Components"):
                lines.append(f'add_fprime_subdirectory("${{CMAKE_CURRENT_LIST_DIR}}/../{folder}/")')
    return "\n".join(lines) + "\n"


def rate_group_files(result: Plan) -> dict[str, str]:
    deployment = result.deployment
    header = ("# The rate groups as F´'s {what} (written by kit new-deployment from\n"
              "# Top/instances.fpp); the other form is beside it, and the execution model\n"
              "# chooses (CONFIG_KIT_RATE_GROUPS_PASSIVE: baremetal_passive).\n")
    active = [header.format(what="ActiveRateGroup, a task each"), f"module {deployment.namespace} {{", ""]
    passive = [header.format(what="PassiveRateGroup, called in the tick"), f"module {deployment.namespace} {{", ""]
    for group in deployment.rate_groups:
        instance = deployment.instance(group.name)
        base = instance.base if instance else "0"
        active += [f"  instance {group.name}: Svc.ActiveRateGroup base id {base} \\",
                   f"    queue size Kit.Queues.{group.name} \\",
                   f"    stack size Kit.Stacks.{group.name} \\",
                   f"    priority Kit.Priorities.{group.name}", ""]
        passive += [f"  instance {group.name}: Svc.PassiveRateGroup base id {base}", ""]
    cmake = ("# The rate groups in the form the execution model chose\n"
             "# (CONFIG_KIT_RATE_GROUPS_PASSIVE). INTERFACE: generated with the topology.\n"
             "# Written by kit new-deployment.\n"
             "if(CONFIG_KIT_RATE_GROUPS_PASSIVE)\n    set(KIT_RATE_GROUP_FORM PassiveRateGroups)\nelse()\n"
             "    set(KIT_RATE_GROUP_FORM ActiveRateGroups)\nendif()\n"
             'register_fprime_module(\n  EXCLUDE_FROM_ALL\n  AUTOCODER_INPUTS\n'
             '    "${CMAKE_CURRENT_LIST_DIR}/${KIT_RATE_GROUP_FORM}.fpp"\n  INTERFACE\n)\n')
    return {"rategroups/ActiveRateGroups.fpp": "\n".join(active) + "}\n",
            "rategroups/PassiveRateGroups.fpp": "\n".join(passive) + "}\n",
            "rategroups/CMakeLists.txt": cmake}


def top_cmake(deployment: Deployment, defs: str) -> str:
    return (f"# The {deployment.name} deployment's topology, as the kit builds it: its rate\n"
            "# groups in the model's form (rategroups/), its instances and topology, and\n"
            "# its priority, stack and queue table for the board (kit_deployment_tables:\n"
            "# Top/Tables.fpp, or Top/boards/<board>/Tables.fpp). Written by kit\n"
            "# new-deployment; the kit's main and KitTopology.cpp replace the host's\n"
            f"# Main.cpp and {deployment.name}Topology.cpp.\n"
            'add_fprime_subdirectory("${CMAKE_CURRENT_LIST_DIR}/rategroups")\n'
            'kit_deployment_tables(KIT_TABLES "${KIT_DEPLOYMENT_DIR}" "${KIT_BOARD}")\n\n'
            "register_fprime_module(\n  AUTOCODER_INPUTS\n"
            '    "${CMAKE_CURRENT_LIST_DIR}/instances.fpp"\n'
            '    "${CMAKE_CURRENT_LIST_DIR}/topology.fpp"\n'
            '    "${KIT_TABLES}"\n  SOURCES\n'
            '    "${CMAKE_CURRENT_LIST_DIR}/KitTopology.cpp"\n  HEADERS\n'
            '    "${CMAKE_CURRENT_LIST_DIR}/KitTopology.hpp"\n'
            f'    "${{CMAKE_CURRENT_LIST_DIR}}/{defs}"\n'
            '    "${CMAKE_CURRENT_LIST_DIR}/ActiveStacks.hpp"\n  DEPENDS\n    Fw_Logger\n)\n')


def _role_reference(result: Plan, role: str, module: str) -> str | None:
    """The table entry of the instance a pattern names, where an F´
    subtopology's configuration holds it (`CdhCoreConfig.Priorities.cmdDisp`)."""
    qualified = result.deployment.patterns.get(role)
    instance = result.deployment.instance(qualified) if qualified else None
    if qualified is None or instance is None or instance.module == result.deployment.namespace \
            or "." not in qualified:
        return None
    value = {"Priorities": instance.priority, "Stacks": instance.stack, "Queues": instance.queue}[module]
    return value


def tables(result: Plan) -> str:
    deployment = result.deployment
    priorities: list[tuple[str, str]] = []
    stacks: list[tuple[str, str]] = []
    queues: list[tuple[str, str]] = []
    for index, group in enumerate(deployment.rate_groups):
        priorities.append((group.name, str(result.priority(index))))
        stacks.append((group.name, str(KIT_STACK)))
        queues.append((group.name, str(RATE_GROUP_QUEUE)))
    for name, depth in result.queues.items():
        priorities.append((name, str(OTHER_TASKS_PRIORITY)))
        stacks.append((name, str(KIT_STACK)))
        queues.append((name, depth))
    for kit_name, role in (("cmdDisp", "command"), ("events", "event"), ("tlmSend", "telemetry")):
        if any(name == kit_name for name, _ in priorities):
            continue
        priority = _role_reference(result, role, "Priorities")
        if priority is None:
            priority = str(result.dispatcher_priority if role == "command" else KIT_PRIORITIES[role])
        priorities.append((kit_name, priority))
    priorities += [("comQueue", str(KIT_PRIORITIES["comQueue"])), ("load", str(KIT_PRIORITIES["load"]))]
    stacks += [("comQueue", str(KIT_STACK)), ("load", str(KIT_STACK))]
    queues += list(KIT_QUEUES.items())

    def module(name: str, why: str, entries: list[tuple[str, str]]) -> str:
        body = "\n".join(f"    constant {entry} = {value}" for entry, value in entries)
        return f"  @ {why}\n  module {name} {{\n{body}\n  }}\n"

    return (f"# The {deployment.name} deployment's priority, stack and queue table for the\n"
            "# kit's boards, in module Kit because the kit's instances (load, comQueue)\n"
            "# take their entries from it; each model's build-time checks hold it to its\n"
            "# rules (<model>/ModelChecks.cpp). Written by kit new-deployment; yours to\n"
            "# change, or to override per board in Top/boards/<board>/Tables.fpp.\n"
            "module Kit {\n\n"
            + module("Priorities", "F´'s convention, a higher number more urgent, on the kit's scale (rtos: the "
                                   "tick is 12; only the fastest group is above it)", priorities)
            + "\n"
            + module("Stacks", f"Thread stacks (rtos; baremetal runs every task on the main stack): one "
                               f"{KIT_STACK} B each until the runs' KIT STACK lines measure them", stacks)
            + "\n"
            + module("Queues", "Queue depths: a rate group's holds one pending cycle (a second is a slip the "
                               "run counts), the template's for its other tasks, the kit's for its own", queues)
            + "\n}\n")


#: F´'s components that read and write files: a deployment with any of
#: them gets the kit's RAM file system (without it F´'s file calls fail)
FILE_USERS = ("Svc.FileUplink", "Svc.FileDownlink", "Svc.FileManager", "Svc.PrmDb", "Svc.CmdSequencer",
              "Svc.FpySequencer")


#: The bulk file a deployment with F´'s file downlink gets (the kit's
#: default on a small board: app/Kconfig)
BULK_FILE_BYTES = 2048


def file_users(deployment: Deployment) -> list[fpp.Instance]:
    """The deployment's instances that use files (FILE_USERS)."""
    instances = [*deployment.own, *(i for group in deployment.subtopologies.values() for i in group)]
    return [instance for instance in instances if instance.type in FILE_USERS]


def deployment_conf(result: Plan, tasks: int, heap: int, text_loggers: bool, fixed_dispatcher: bool) -> str:
    lines = [
        f"# The {result.deployment.name} deployment's Kconfig for the kit (app/Kconfig).",
        "# Written by kit new-deployment; yours to change.",
        "# None of the kit's own F´ services: the deployment carries F´'s",
        "CONFIG_KIT_SERVICE_CDH=n",
        "CONFIG_KIT_SERVICE_PARAMS=n",
        "CONFIG_KIT_SERVICE_FILES=n",
        "CONFIG_KIT_SERVICE_FILE_UPLINK=n",
        "CONFIG_KIT_SERVICE_SEQUENCER=n",
        "# Its tasks with its rate groups active: the models' task tables and the",
        "# reports' execution contexts hold this many",
        "CONFIG_KIT_DEPLOYMENT_OWN_TASKS=y",
        f"CONFIG_KIT_DEPLOYMENT_TASKS={tasks}",
        "# First shares of F´'s fixed tables: the build fails naming both counts",
        "# when its dictionary outgrows one, and `kit sizing` gives the dictionary's",
        f"CONFIG_KIT_DEPLOYMENT_COMMANDS={FIRST_COMMANDS}",
        f"CONFIG_KIT_DEPLOYMENT_CHANNELS={FIRST_CHANNELS}",
    ]
    lines += [
        "# The C heap: the kit's, with F´'s buffers this deployment takes from it",
        f"CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE={heap}",
        "# The main thread's stack: the setup of F´'s subtopologies (and in baremetal",
        "# every task) runs on it; the run's KIT STACK lines give its high-water mark",
        f"CONFIG_MAIN_STACK_SIZE={MAIN_STACK}",
    ]
    users = file_users(result.deployment)
    if users:
        lines += [f"# Its file services ({', '.join(i.qualified for i in users)}) on the kit's RAM",
                  "# file system: fprime-baremetal's MicroFs, files named /bin<b>/file<n> (app/Kconfig)",
                  "CONFIG_KIT_RAMFS=y"]
    if any(instance.type == "Svc.FileDownlink" for instance in users):
        lines += ["# and the bulk file (Kit.RamFs.bulkFile) its file downlink sends in the",
                  "# serial-load sweep's file axis",
                  f"CONFIG_KIT_RAMFS_BULK_FILE_SIZE={BULK_FILE_BYTES}"]
    if text_loggers:
        lines += ["# F´'s CdhCore subtopology is built only with F´'s text loggers",
                  "CONFIG_KIT_FPRIME_TEXT_LOGGERS=y"]
    if fixed_dispatcher:
        lines += ["# Its dispatcher is an F´ subtopology's, active in every model (baremetal_passive",
                  "# keeps its rate groups passive)",
                  "CONFIG_KIT_DEPLOYMENT_ACTIVE_DISPATCHER=y"]
    return "\n".join(lines) + "\n"


def heap_bytes(result: Plan, fprime_subtopologies: Path) -> int:
    """The C heap the deployment needs: the kit's, F´'s DataProducts
    buffers (its BuffMgr store), the sequencers' buffers."""
    total = KIT_HEAP
    for name in result.deployment.subtopologies:
        for path in sorted((fprime_subtopologies / name).glob(f"{name}Config/*.fpp")):
            store = fpp.constants(path.read_text(), "BuffMgr")
            if "dpBufferStoreSize" in store and "dpBufferStoreCount" in store:
                total += _evaluate(store["dpBufferStoreSize"]) * _evaluate(store["dpBufferStoreCount"])
    total += sum(_evaluate(size) for size in result.sequencers.values())
    return total + HEAP_PER_TASK * (len(result.tasks) + len(result.deployment.rate_groups))


def _evaluate(expression: str) -> int:
    """A constant expression of integers, * and + (FPP's and C++'s sizes)."""
    if not re.fullmatch(r"[\d\s*+()]+", expression):
        raise ValueError(f"not a size: {expression}")
    return int(eval(expression, {"__builtins__": {}}))  # noqa: S307 - digits and operators only
