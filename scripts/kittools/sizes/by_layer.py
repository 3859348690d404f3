# SPDX-License-Identifier: Apache-2.0
"""ROM and RAM by module, from Zephyr's attribution of every symbol to its
source path (size_report, from DWARF; run by kittools.sizes.size_report); the kit
sorts those paths into the layers a baremetal-vs-RTOS decision is about.
Symbols without a source path (linker-made tables, vtables, static
constructors) are placed by their C++ namespace where it tells, otherwise
counted as "unattributed".
"""

from __future__ import annotations

import concurrent.futures
import hashlib
import json
import subprocess
import sys
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from kittools.build.folder import BuildFolder
from kittools.link.dictionary import Dictionary
from kittools.sizes import instances, size_report
from kittools.workspace import KitError, environment

FRAMEWORK = "F´ framework"
SERVICES = "F´ services"
HEALTH_VERSION = "F´ health and version (CdhCore's)"
FILE_HANDLING = "F´ FileHandling (parameter database, file downlink and uplink, RAM file system)"
SEQUENCER = "F´ command sequencer"
GROUND_LINK = "F´ ground link (ComFprime chain, UART driver)"
OS_LAYER = "OS layer (fprime-baremetal / fprime-zephyr / kit)"
INSTRUMENTS = "kit instruments (timing, probes, load, faults, record)"
KIT = "kit deployment and components"
ZEPHYR = "Zephyr kernel, arch, drivers"
LIBC = "libc (picolibc, libgcc)"
LIBSTDCXX = "libstdc++"
UNATTRIBUTED = "unattributed"
#: What no symbol covers (size_report's "(hidden)"): mostly read-only data
#: without a symbol, the string literals (F´'s event formats, names), then
#: unwinding tables and alignment
NO_SYMBOL = "no symbol (string literals, unwinding tables, alignment)"
#: The kit's FPP module: its instruments, its ground link, and the reference deployment
KIT_MODULE = "Kit"
#: The layers, F´'s subtopologies among them (CdhCore's health and version,
#: FileHandling, the sequencer, the ComFprime chain) and the kit's
#: instruments apart from the deployment they measure
CATEGORIES = (FRAMEWORK, SERVICES, HEALTH_VERSION, FILE_HANDLING, SEQUENCER, GROUND_LINK, OS_LAYER, INSTRUMENTS, KIT,
              ZEPHYR, LIBC, LIBSTDCXX, NO_SYMBOL, UNATTRIBUTED)

# The components of the ground link (app/Subtopologies/GroundLink/GroundLink.fpp): F´'s ComFprime
# chain and fprime-zephyr's UART driver, by folder and by class name
_LINK_COMPONENTS = ("ComQueue", "FprimeFramer", "FprimeDeframer", "FrameAccumulator", "FprimeRouter", "ComStub",
                    "BufferManager", "ZephyrUartDriver", "FprimeFrameDetector")

# F´'s other subtopologies in the deployment (app/Top/services/), and the
# kit's instruments: their components
_HEALTH_VERSION_COMPONENTS = ("Health", "Version")
_FILE_HANDLING_COMPONENTS = ("PrmDb", "FileDownlink", "FileUplink")
_SEQUENCER_COMPONENTS = ("CmdSequencer",)
_INSTRUMENT_COMPONENTS = ("Timing", "PingProbe", "LinkHealth", "Load", "Faults", "Uplink", "Downlink")
# The kit's own forms of F´'s services: its telemetry store (app/Top/telemetry/)
_KIT_SERVICE_COMPONENTS = ("TlmTable",)

# F´ classes by mangled name (length-prefixed: 6Health is not 10LinkHealth)
_SVC_CLASS_LAYERS = (
    (_LINK_COMPONENTS, GROUND_LINK),
    (_HEALTH_VERSION_COMPONENTS, HEALTH_VERSION),
    (_FILE_HANDLING_COMPONENTS, FILE_HANDLING),
    (_SEQUENCER_COMPONENTS, SEQUENCER),
)
# The namespaces of F´'s and fprime-zephyr's components
_FPRIME_NAMESPACES = ("Svc", "Drv", "Zephyr")
# F´'s subtopologies whose every instance is one layer, whatever its type
# (a data product's buffer manager is not the link's)
_SUBTOPOLOGY_LAYERS = {"ComFprime": GROUND_LINK, "ComCcsds": GROUND_LINK, "FileHandling": FILE_HANDLING,
                       "DataProducts": SERVICES}


def instance_layer(namespace: str, component: str) -> str:
    """The layer of an instance (its object: its component's static RAM) in
    the namespace `namespace`, of the component type `component`
    (kittools.sizes.instances)."""
    if namespace in _SUBTOPOLOGY_LAYERS:
        return _SUBTOPOLOGY_LAYERS[namespace]
    owner, _, name = component.rpartition("::")
    if owner == KIT_MODULE and name in _INSTRUMENT_COMPONENTS:
        return INSTRUMENTS
    if owner == KIT_MODULE and name in _KIT_SERVICE_COMPONENTS:
        return SERVICES
    if owner in _FPRIME_NAMESPACES:
        return next((layer for names, layer in _SVC_CLASS_LAYERS if name in names), SERVICES)
    return KIT


@dataclass(frozen=True)
class Deployment:
    """What a build's deployment says of its symbols: its own C++
    namespaces beyond the kit's, and each instance's layer by its mangled
    name (deployment_of)."""
    namespaces: tuple[str, ...] = ()
    instances: Mapping[str, str] = field(default_factory=dict)

    @classmethod
    def of(cls, namespaces: tuple[str, ...], declared: Mapping[str, tuple[str, str]]) -> Deployment:
        """From its namespaces and its instances as the topology declares
        them (kittools.sizes.instances: mangled name -> namespace, type)."""
        return cls(namespaces, {symbol: instance_layer(namespace, component)
                                for symbol, (namespace, component) in declared.items()})


#: A build whose deployment says nothing more (no dictionary, no topology headers)
NO_DEPLOYMENT = Deployment()


_BY_PATH = (
    # (substring of the source path, category); first match wins
    *((f"/Svc/{name}/", GROUND_LINK) for name in _LINK_COMPONENTS),
    ("/Drv/ZephyrUartDriver/", GROUND_LINK),
    *((f"/Svc/{name}/", HEALTH_VERSION) for name in _HEALTH_VERSION_COMPONENTS),
    *((f"/Svc/{name}/", FILE_HANDLING) for name in _FILE_HANDLING_COMPONENTS),
    *((f"/Svc/{name}/", SEQUENCER) for name in _SEQUENCER_COMPONENTS),
    # fprime-baremetal's MicroFs, F´'s file system in every model, and the
    # kit's mount of it
    ("/Os/Baremetal/MicroFs/", FILE_HANDLING),
    *((f"/Os/Baremetal/{name}.", FILE_HANDLING) for name in ("File", "FileSystem", "Directory", "DefaultFile",
                                                             "error")),
    ("/app/src/RamFs.", FILE_HANDLING),
    # The kit's ground link subtopology's setup (its instances are the chain's)
    ("/app/Subtopologies/GroundLink/", GROUND_LINK),
    *((f"/app/Components/{name}/", INSTRUMENTS) for name in _INSTRUMENT_COMPONENTS),
    *((f"/app/Components/{name}/", SERVICES) for name in _KIT_SERVICE_COMPONENTS),
    ("/app/src/", INSTRUMENTS),
    ("/app/scenarios/", INSTRUMENTS),
    # fprime-baremetal's services (its passive dispatcher, its linear
    # telemetry channel), built or generated, are F´ services; the rest of
    # it is the OS layer
    ("/fprime-baremetal/Svc/", SERVICES),
    ("/deps/fprime-baremetal/", OS_LAYER),
    ("/deps/fprime-zephyr/", OS_LAYER),
    ("/rtos/", OS_LAYER),
    ("/baremetal/", OS_LAYER),
    ("/F-Prime/Svc/", SERVICES),
    ("/deps/fprime/Svc/", SERVICES),
    ("/deps/fprime/Drv/", SERVICES),
    ("/F-Prime/", FRAMEWORK),
    ("/deps/fprime/", FRAMEWORK),
    ("/app/", KIT),
    ("/deps/zephyr/", ZEPHYR),
    ("/zephyr/", ZEPHYR),
    ("libstdc++", LIBSTDCXX),
    ("libsupc++", LIBSTDCXX),
    ("/libgcc/", LIBC),
    ("/build/gcc-", LIBSTDCXX),  # the toolchain's own build of its C++ runtime
    ("newlib", LIBC),
    ("picolibc", LIBC),
    ("/libc/", LIBC),
)

_BY_SYMBOL = (
    ("_ZN2Os9Baremetal7MicroFs", FILE_HANDLING), ("_ZZN2Os9Baremetal7MicroFs", FILE_HANDLING),
    # A function's own statics (_ZZ: the function's name, then the static's)
    ("_ZZN2Os9Baremetal", OS_LAYER), ("_ZZN2Os6Zephyr", OS_LAYER), ("_ZZN2Os", FRAMEWORK), ("_ZZN2Fw", FRAMEWORK),
    ("_ZZN3Svc", SERVICES), ("_ZZN3Kit", KIT),
    # LTO merges every object's static constructor (_GLOBAL__sub_I_<file>)
    # into one, _sub_I_65535_0: the instances' constructors, the deployment's
    ("_sub_I_", KIT),
    # The C library's heap arena (Zephyr's lib/libc/common), a file's static
    ("malloc_arena", ZEPHYR),
    # libgcc's soft-float and long-division helpers: the toolchain's
    # libgcc carries no DWARF, so no build names their source
    ("__aeabi_", LIBC), ("__float", LIBC), ("__fix", LIBC), ("__trunc", LIBC), ("__extend", LIBC),
    ("_ZN3Kit", KIT), ("_ZTVN3Kit", KIT), ("_ZN3Svc", SERVICES), ("_ZTVN3Svc", SERVICES), ("_ZN2Fw", FRAMEWORK),
    ("_ZTVN2Fw", FRAMEWORK), ("_ZN2Os9Baremetal", OS_LAYER), ("_ZN2Os6Zephyr", OS_LAYER), ("_ZN2Os", FRAMEWORK),
    ("_ZTVN2Os", FRAMEWORK), ("_ZNSt", LIBSTDCXX), ("_ZSt", LIBSTDCXX), ("__cxa", LIBSTDCXX), ("__gnu_cxx", LIBSTDCXX),
)


#: The niceness of size reports made beside other work (`reports(background=True)`)
BACKGROUND_NICENESS = 19


def reports(builds: list[Path], jobs: int = 2, background: bool = False) -> list[tuple[dict, dict]]:
    """(rom, ram) reports of several builds (`report`), `jobs` builds at a
    time; `background`: at the lowest CPU priority, so that they take only
    the CPU time the work beside them leaves (the ground link's checks,
    whose time-outs are the host's)."""
    niceness = BACKGROUND_NICENESS if background else 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(lambda build: (report(build, "rom", niceness), report(build, "ram", niceness)), builds))


def _make_reports(build_dir: Path, elf: Path, niceness: int = 0) -> None:
    """<kind>-symbols.json in the build folder: Zephyr's size_report
    attribution without its display tree (kittools.sizes.size_report), in a
    process of its own so that two builds take two cores. PYTHONHASHSEED=0:
    the tool gives a symbol that shares its address with another one name or
    the other by the order of a Python set, so that two runs on one image
    moved a few bytes between layers. `niceness`: run it under nice(1)."""
    command = [sys.executable, "-m", "kittools.sizes.size_report", str(elf), str(build_dir)]
    if niceness:
        command = ["nice", "-n", str(niceness), *command]
    result = subprocess.run(command, cwd=build_dir, env={**environment(), "PYTHONHASHSEED": "0"},
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    missing = [kind for kind in size_report.KINDS if not size_report.output(build_dir, kind).is_file()]
    if result.returncode != 0 or missing:
        raise KitError(f"the size report failed for {build_dir} ({' '.join(command)}): {result.stderr[-2000:]}")


# Leaf identifiers are relative to the report's top-level groups
_GROUP_PREFIX = {"ZEPHYR_BASE": "/deps/zephyr/", "OUTPUT_DIR": "/OUTPUT_DIR/", "WORKSPACE": "/"}


def deployment_of(build_dir: Path) -> Deployment:
    """A build's deployment: its own FPP modules (tests/team/Thermal's
    Thermal) from its dictionary, none where it has no dictionary; its
    instances from its topology's headers."""
    try:
        namespaces = tuple(sorted(Dictionary.read(BuildFolder(build_dir).dictionary()).modules - {KIT_MODULE}))
    except KitError:
        namespaces = ()
    return Deployment.of(namespaces, instances.of_build(build_dir))


def classify(identifier: str, group: str = "", deployment: Deployment = NO_DEPLOYMENT) -> str:
    """Category of one leaf of a rom/ram report (its 'identifier', within
    the top-level group named `group`): an instance of the `deployment`
    (deployment_of) by its component type, a symbol of one of its
    namespaces is the deployment's, as the reference's (namespace Kit) is."""
    if group == size_report.HIDDEN:
        return NO_SYMBOL
    path = _GROUP_PREFIX.get(group, "") + identifier.replace("\\", "/")
    symbol = path.rsplit("/", 1)[-1].removeprefix("_GLOBAL__sub_I_")
    # An instance belongs to its subtopology, wherever the topology's code defines it
    if symbol in deployment.instances:
        return deployment.instances[symbol]
    for needle, category in _BY_PATH:
        if needle in path:
            return category
    # Mangled C++ names spell each class name out (e.g. _ZTVN3Svc8ComQueueE)
    if symbol.startswith(("_ZN3Svc", "_ZTVN3Svc", "_ZN6Zephyr", "_ZTVN6Zephyr")):
        for names, category in _SVC_CLASS_LAYERS:
            if any(f"{len(name)}{name}" in symbol for name in names):
                return category
    if any(symbol.startswith((f"_ZN{len(ns)}{ns}", f"_ZTVN{len(ns)}{ns}")) for ns in deployment.namespaces):
        return KIT
    for prefix, category in _BY_SYMBOL:
        if symbol.startswith(prefix):
            return category
    return UNATTRIBUTED


def _leaves(node: dict) -> Iterator[dict]:
    children = node.get("children")
    if not children:
        yield node
        return
    for child in children:
        yield from _leaves(child)


def breakdown(report: dict, deployment: Deployment = NO_DEPLOYMENT) -> dict[str, int]:
    """Bytes per category; sums to the report's total_size. `deployment`:
    the build's (deployment_of)."""
    sizes = {name: 0 for name in CATEGORIES}
    for group in report["symbols"].get("children", []):
        for leaf in _leaves(group):
            category = classify(str(leaf.get("identifier", "")), str(group.get("name", "")), deployment)
            sizes[category] += int(leaf.get("size", 0))
    return sizes


def report(build_dir: Path, kind: str, niceness: int = 0) -> dict:
    """A build's rom or ram report (every symbol, its source path, its
    bytes: kittools.sizes.size_report), made if missing or made from another
    image. "Another image" is decided by content: a configure relinks
    (Zephyr rewrites its linker snippets every time) into the same bytes,
    and the reports take about 20 s of one core (DWARF)."""
    if kind not in ("rom", "ram"):
        raise ValueError(kind)
    path = size_report.output(build_dir, kind)
    made_from = build_dir / "size-reports.elf-sha256"
    elf = BuildFolder(build_dir).built_elf()
    # A report made the same way from the same image: the way's version beside the image's digest
    image = f"{hashlib.sha256(elf.read_bytes()).hexdigest()} {size_report.FORMAT}"
    if not path.is_file() or not made_from.is_file() or made_from.read_text().strip() != image:
        _make_reports(build_dir, elf, niceness)
        made_from.write_text(image + "\n")
    loaded: dict[str, Any] = json.loads(path.read_text())
    return loaded
