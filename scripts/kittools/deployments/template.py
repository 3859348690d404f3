# SPDX-License-Identifier: Apache-2.0
"""What a deployment folder is, read from its files: its F´ project, its
module, its instances and those of the F´ subtopologies it imports, its
rate groups and their rates, and the instances its topology's patterns name
(dispatcher, events, telemetry, time)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

from kittools import workspace
from kittools.deployments import fpp
from kittools.workspace import KitError

#: Rate group types: F´'s active form, and the passive one the kit adds for baremetal_passive
RATE_GROUP_TYPES = ("Svc.ActiveRateGroup", "Svc.PassiveRateGroup")
#: The docs page that gives the seam
SEAM_DOC = "docs/your-deployment.md"


@dataclass(frozen=True)
class RateGroup:
    """A rate group, in the order of the rate group driver's outputs."""

    name: str
    period: Fraction  #: seconds


@dataclass
class Deployment:
    folder: Path
    project: Path  #: the F´ project it is named from (its settings.ini)
    namespace: str  #: the module of its own instances and its topology
    topology: str  #: its topology's name
    own: list[fpp.Instance]  #: the instances its Top/ declares
    subtopologies: dict[str, list[fpp.Instance]]  #: F´ subtopology imported -> its instances
    rate_groups: list[RateGroup]
    patterns: dict[str, str]  #: "command", "event", "telemetry", "time", ... -> the instance named

    @property
    def name(self) -> str:
        return self.folder.name

    @property
    def include_root(self) -> str:
        """Its path from its project's root, as its includes start ("MyDeployment")."""
        return self.folder.relative_to(self.project).as_posix()

    def instance(self, qualified: str) -> fpp.Instance | None:
        for candidate in self.all_instances():
            if candidate.qualified == qualified or (candidate.module == self.namespace
                                                    and candidate.name == qualified):
                return candidate
        return None

    def all_instances(self) -> list[fpp.Instance]:
        found = list(self.own)
        for instances in self.subtopologies.values():
            found.extend(instances)
        return found

    def cpp(self, qualified: str) -> str:
        """The C++ name of an instance: `CdhCore.cmdDisp` -> `CdhCore::cmdDisp`."""
        instance = self.instance(qualified)
        if instance is None:
            raise KitError(f"'{qualified}' is not an instance of '{self.folder}' or of the F´ subtopologies it imports")
        return f"{instance.module.replace('.', '::')}::{instance.name.lstrip('$')}"


def project_of(folder: Path) -> Path:
    """The F´ project a deployment folder is in: the nearest folder above it
    with F´'s settings.ini (app/deployment.cmake names it the same way)."""
    for above in folder.parents:
        if (above / "settings.ini").is_file():
            return above
    raise KitError(f"'{folder}' is in no F´ project: no settings.ini above it. Make the deployment with "
                   f"`fprime-util new --deployment` inside an F´ project ({SEAM_DOC}).")


def fprime_subtopologies() -> Path:
    return workspace.DEPS / "fprime" / "Svc" / "Subtopologies"


def subtopology_instances(name: str) -> list[fpp.Instance]:
    """The instances of one of F´'s subtopologies (its config's included:
    CdhCore's telemetry and fatal handler are declared there)."""
    folder = fprime_subtopologies() / name
    if not folder.is_dir():
        raise KitError(f"the topology imports {name}.Subtopology, which is not one of F´'s subtopologies "
                       f"({fprime_subtopologies()}): kit new-deployment adapts those only")
    return fpp.instances_in(folder)


def _topology_name(text: str) -> str | None:
    match = re.search(r"^\s*topology\s+(\w+)\s*\{", text, flags=re.MULTILINE)
    return match.group(1) if match else None


def _patterns(text: str) -> dict[str, str]:
    return {match.group(1).replace(" ", ""): match.group(2)
            for match in re.finditer(r"^\s*(command|event|telemetry|text event|health|param|time)\s+connections\s+"
                                     r"instance\s+([\w.$]+)", text, flags=re.MULTILINE)}


def driver_order(text: str) -> list[str]:
    """The rate groups in the order the topology connects them to the rate
    group driver's outputs."""
    order: list[str] = []
    for line in text.splitlines():
        connection = fpp.CONNECTION.match(line.split("#", 1)[0])
        if connection and fpp.endpoint_port(connection.group("target")).endswith(".CycleIn") \
                and ".CycleOut" in connection.group("source") and "rateGroupDriver" in connection.group("source"):
            order.append(fpp.endpoint_instance(connection.group("target")))
    return order


def _rates(folder: Path, groups: list[str]) -> list[Fraction] | None:
    """The periods the template gives its rate groups: the host timer's
    interval (Main.cpp's startRateGroups) times each group's divisor
    (<Name>Topology.cpp's DividerSet). None when they are not there."""
    main = folder / "Main.cpp"
    interval = Fraction(1)
    if main.is_file():
        found = re.search(r"startRateGroups\s*\(\s*Fw::TimeInterval\s*\(\s*(\d+)\s*,\s*(\d+)\s*\)", main.read_text())
        if found:
            interval = Fraction(int(found.group(1))) + Fraction(int(found.group(2)), 1_000_000)
    for source in sorted((folder / "Top").glob("*.cpp")):
        text = source.read_text()
        found = re.search(r"DividerSet\s+\w+\s*\{\s*\{(?P<body>.*?)\}\s*\}\s*;", text, flags=re.DOTALL)
        if found:
            divisors = [int(pair.group(1)) for pair in re.finditer(r"\{\s*(\d+)\s*,\s*\d+\s*\}", found.group("body"))]
            if len(divisors) >= len(groups):
                return [interval * divisor for divisor in divisors[:len(groups)]]
    return None


#: The host's clocks, which F´'s OsTime (Os::RawTime on the board) replaces
HOST_CLOCKS = ("Svc.ChronoTime", "Svc.PosixTime")
#: The kit's tick (CONFIG_KIT_TICK_HZ's default, app/Kconfig)
KIT_TICK_HZ = 1000
#: F´'s RateGroupDriver multiplies its divisors into a rollover count of
#: FwSizeType (32 bits in the kit's builds) and asserts past it
ROLLOVER_MAX = 2**32 - 1


def load_slice_max_us() -> int:
    """The kit's load's slice limit, where the component declares it."""
    header = workspace.KIT_ROOT / "app" / "Components" / "Load" / "Load.hpp"
    found = re.search(r"SLICE_MAX_US\s*=\s*(\d+)", header.read_text())
    if not found:
        raise KitError(f"{header} declares no SLICE_MAX_US")
    return int(found.group(1))


def sweep_min_hz() -> int:
    """The slowest fastest group whose load sweep stays within the load's
    slice limit: the sweep reaches twice the fastest group's period."""
    return -(-2_000_000 // load_slice_max_us())


def check_rollover(groups: list[RateGroup], folder: Path) -> None:
    divisors = [int(group.period * KIT_TICK_HZ) for group in groups]
    product = 1
    for divisor in divisors:
        product *= divisor
    if product > ROLLOVER_MAX:
        rates = ", ".join(f"{group.name} {float(1 / group.period):g} Hz" for group in groups)
        raise KitError(f"the rates of '{folder}' ({rates}) at the kit's {KIT_TICK_HZ} Hz tick need divisors "
                       f"{' x '.join(f'{divisor:,}' for divisor in divisors)} = {product:,}, more than F´'s "
                       f"RateGroupDriver counts to ({ROLLOVER_MAX:,}, FwSizeType): give the fastest group's rate "
                       f"with --fastest-hz (the others keep their ratios to it): --fastest-hz {sweep_min_hz()} or "
                       f"more keeps the kit's load sweep within its load's slice limit")


def read(folder: Path, fastest_hz: Fraction | None = None) -> Deployment:
    """The deployment in `folder`, or one error naming what is missing;
    with `fastest_hz`, its rates scaled to give its fastest group that rate."""
    folder = folder.resolve()
    top = folder / "Top"
    topology_file = top / "topology.fpp"
    if not topology_file.is_file():
        raise KitError(f"'{folder}' is not an F´ deployment as fprime-util new --deployment makes one: it has no "
                       f"Top/topology.fpp ({SEAM_DOC})")
    project = project_of(folder)
    if project == folder:
        raise KitError(f"'{folder}' is an F´ project's root; name the deployment folder inside it")
    text = topology_file.read_text()
    topology = _topology_name(text)
    if topology is None:
        raise KitError(f"{topology_file} declares no topology")
    own = fpp.instances_in(top)
    namespaces = {instance.module for instance in own}
    namespace = next(iter(namespaces)) if len(namespaces) == 1 else topology_module(text)
    subtopologies = {name.split(".", 1)[0]: subtopology_instances(name.split(".", 1)[0])
                     for name in fpp.imports(text)
                     if name.endswith(".Subtopology") and not name.startswith("Com")}
    groups = driver_order(text)
    if not groups:
        raise KitError(f"the kit cannot find the rate groups of '{folder}': no rateGroupDriver.CycleOut -> "
                       f"<group>.CycleIn connection in Top/topology.fpp ({SEAM_DOC})")
    # Once adapted, the rates are the deployment's table (Top/KitTopology.cpp)
    periods = None if (top / "KitTopology.cpp").is_file() else _rates(folder, groups)
    if periods is None:
        periods = _kit_rates(top, groups)
    elif fastest_hz is not None:
        scale = 1 / (fastest_hz * min(periods))
        periods = [period * scale for period in periods]
    rate_groups = [RateGroup(name, period) for name, period in zip(groups, periods, strict=True)]
    check_rollover(rate_groups, folder)
    return Deployment(folder=folder, project=project, namespace=namespace, topology=topology, own=own,
                      subtopologies=subtopologies, rate_groups=rate_groups, patterns=_patterns(text))


def topology_module(text: str) -> str:
    match = re.search(r"^\s*module\s+(\w+)\s*\{", text, flags=re.MULTILINE)
    if not match:
        raise KitError("Top/topology.fpp declares its topology in no module")
    return match.group(1)


def _kit_rates(top: Path, groups: list[str]) -> list[Fraction]:
    """The periods of a deployment the kit already measures: its RATE_GROUPS
    table (Top/KitTopology.cpp), `CONFIG_KIT_TICK_HZ * n / d` per group."""
    table = top / "KitTopology.cpp"
    if table.is_file():
        found = re.findall(r"\{\"\w+\",\s*CONFIG_KIT_TICK_HZ\s*\*\s*(\d+)\s*/\s*(\d+)\s*,", table.read_text())
        if len(found) == len(groups):
            return [Fraction(int(numerator), int(denominator)) for numerator, denominator in found]
    raise KitError(f"the kit cannot find the rates of the rate groups of '{top.parent}': neither the host "
                   "timer's interval and divisors (Main.cpp, Top/*Topology.cpp) nor Top/KitTopology.cpp's "
                   f"RATE_GROUPS ({SEAM_DOC})")
