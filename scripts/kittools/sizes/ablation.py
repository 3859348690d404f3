# SPDX-License-Identifier: Apache-2.0
"""What each F´ knob costs: `kit footprint`.

For one board and variant (app/variants.yaml), build the deployment with a footprint profile
(modules/fprime/snippets), then once per knob with only that knob moved to
another profile's value (or, for the assert level, to each other level), and
record ROM, static RAM and their change per layer against the profile's own
build; each build then plays the nominal run under QEMU. A build that fails,
or whose nominal run does not pass, is a row of the table like the others:
what a knob costs includes what it breaks.

The knobs are the F´ switches of modules/fprime/Kconfig in which the two
profiles differ, so the list follows the Kconfig and the profiles, not a
list here; the services' other forms the variant's model has
(SERVICE_KNOBS), but for those its build has already (a policy may select
one); and the whole-build compiler and linker options (COMPILER_KNOBS),
each moved off the kit's choice, with what it does to rg1kHz's dispatch
latency beside ROM and RAM.
"""

from __future__ import annotations

import json
import re
import subprocess
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

from kittools import console, variants
from kittools.build import runner
from kittools.build.folder import FPRIME_SWITCH, BuildFolder
from kittools.deployment import Deployment
from kittools.report import render
from kittools.report.document import CAVEAT, Section, Table, Text
from kittools.sizes import by_layer
from kittools.sizes.memory import measure
from kittools.workspace import KIT_ROOT, KitError, board_dir_name, environment

SNIPPETS = KIT_ROOT / "modules" / "fprime" / "snippets"
#: The assert level is a choice: each alternative is a knob of its own
ASSERT_LEVELS = ("CONFIG_FPRIME_ASSERT_NONE", "CONFIG_FPRIME_ASSERT_FILE_ID", "CONFIG_FPRIME_ASSERT_FILE_NAME",
                 "CONFIG_FPRIME_ASSERT_RELATIVE_PATH")


def profiles() -> list[str]:
    """The footprint profiles: the snippets of modules/fprime."""
    return sorted(p.parent.name for p in SNIPPETS.glob("*/snippet.yml"))


def check_profile(name: str) -> str:
    if name not in profiles():
        raise KitError(f"unknown profile '{name}'; the profiles are: {', '.join(profiles())} "
                       f"(modules/fprime/snippets)")
    return name


@dataclass(frozen=True)
class Knob:
    """One build of the ablation: its name and the settings it adds to the profile."""

    name: str
    settings: tuple[str, ...] = ()  # CONFIG_X=value
    models: tuple[str, ...] = ()  # the execution models it applies to, whatever the policy (empty: all)
    #: bytes its build takes from the C heap beyond the profile's: its arena
    #: grows by them from the profile build's (a board sizes that arena to
    #: what its runs use, boards/qemu_cortex_m3/Kconfig.defconfig)
    heap_bytes: int = 0


#: Knobs that are not F´ switches: a service's other form, where a model has it
SERVICE_KNOBS = (
    # fprime-baremetal builds TlmLinearChan for its own model only; its table
    # comes out of the C heap: an entry per channel, about the 76 B of a
    # TlmChan bucket (whose two tables it replaces), for up to 100 channels
    # (the reference's baremetal build on qemu_cortex_m3 has 71). A deployment with
    # more says so in its row (KIT ARENA exhausted request=)
    Knob("telemetry store: TlmChan -> TlmLinearChan", ("CONFIG_KIT_TELEMETRY_LINEAR=y",), ("baremetal",),
         heap_bytes=8192),
    # fprime-baremetal's dispatcher: no task, stack or queue; its tables
    # from F´'s allocator (baremetal_passive's policy selects it already)
    Knob("command dispatcher: CommandDispatcher -> PassiveCmdDispatcher",
         ("CONFIG_KIT_CMD_DISPATCHER_PASSIVE=y",), ("baremetal",)),
)


#: Whole-build compiler and linker options, each moved off the kit's choice
#: (baremetal/Kconfig.model: link-time optimization, -fconserve-stack; Zephyr's default -Os)
COMPILER_KNOBS = (
    Knob("link-time optimization: on -> off", ("CONFIG_LTO=n", "CONFIG_ISR_TABLES_LOCAL_DECLARATION=n")),
    # the model without it (rtos/Kconfig.model): what it would give
    Knob("link-time optimization: off -> on", ("CONFIG_LTO=y", "CONFIG_ISR_TABLES_LOCAL_DECLARATION=y",
                                               'CONFIG_COMPILER_OPT="-fconserve-stack"')),
    # what keeps LTO's inlining from deepening the stacks (app/prj.conf)
    Knob("-fconserve-stack: on -> off", ('CONFIG_COMPILER_OPT=""',)),
    Knob("optimization: -Os -> -O2", ("CONFIG_SPEED_OPTIMIZATIONS=y",)),
    Knob("optimization: -Os -> -Og", ("CONFIG_DEBUG_OPTIMIZATIONS=y",)),
)
#: Each row reports the dispatch latency of the deployment's fastest rate
#: group (the first to feel a slower path; the highest `hz` of its RG records)
LATENCY_RG = "the fastest rate group"


@dataclass
class Row:
    knob: str
    settings: list[str]
    built: bool
    passed: bool | None = None  # the nominal run; None: not run (the build failed)
    rom: int | None = None
    ram: int | None = None
    rom_layers: dict[str, int] = field(default_factory=dict)
    ram_layers: dict[str, int] = field(default_factory=dict)
    note: str = ""
    seconds: float = 0.0
    latency: dict[str, int] = field(default_factory=dict)  # LATENCY_RG's p50 and max, cycles


def knobs(base: dict[str, str], other: dict[str, str], model: str, built: dict[str, str] | None = None) -> list[Knob]:
    """One knob per F´ switch in which two profiles' builds differ (moved to
    the other's value), one per other assert level, and the execution
    model's service knobs but those the profile's build (its whole .config,
    `built`) has already."""
    found = [Knob("profile")]
    current_assert = next((k for k in ASSERT_LEVELS if base.get(k) == "y"), None)
    for level in ASSERT_LEVELS:
        if level != current_assert:
            found.append(Knob(f"asserts: {level.removeprefix('CONFIG_FPRIME_ASSERT_').lower()}", (f"{level}=y",)))
    for key in sorted(set(base) | set(other)):
        if key in ASSERT_LEVELS or key == "CONFIG_FPRIME":
            continue
        before, after = base.get(key, "n"), other.get(key, "n")
        if before != after:
            name = key.removeprefix(FPRIME_SWITCH).lower()
            found.append(Knob(f"{name}: {before} -> {after}", (f"{key}={after}",)))
    def has(knob: Knob) -> bool:
        # an unset bool reads as n; a string's quotes are not part of its value
        return built is not None and all(built.get(k, "n") == v.strip('"')
                                         for k, v in (s.split("=", 1) for s in knob.settings))

    services = [with_heap(k, built) for k in SERVICE_KNOBS if (not k.models or model in k.models) and not has(k)]
    return found + services + [k for k in COMPILER_KNOBS if not has(k)]


ARENA = "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE"


def with_heap(knob: Knob, built: dict[str, str] | None) -> Knob:
    """The knob with its arena: the profile build's grown by what the knob
    takes from the heap (none given, or no build: as it is)."""
    if not knob.heap_bytes or built is None or ARENA not in built:
        return knob
    return replace(knob, settings=(*knob.settings, f"{ARENA}={int(built[ARENA]) + knob.heap_bytes}"))


_OVERFLOW = re.compile(r"region `(?P<region>\w+)' overflowed by (?P<bytes>\d+) bytes")
_ERROR = re.compile(r"error: (?P<message>.+)$", re.MULTILINE)


def build_failure(log: Path) -> str:
    """Why a build failed, in a line: the memory regions that overflowed, or
    the first distinct compiler errors (F´'s static asserts tie knobs together)."""
    text = log.read_text(errors="replace") if log.is_file() else ""
    found = [f"{m['region']} overflowed by {int(m['bytes']):,} B" for m in _OVERFLOW.finditer(text)]
    if not found:
        found = [m["message"].strip() for m in _ERROR.finditer(text)
                 if not m["message"].startswith(("ld returned", "command exited"))]
    return f"{'; '.join(list(dict.fromkeys(found))[:2]) or 'no reason found'} ({log.name})"


def _build(board: str, variant: str, profile: str, settings: tuple[str, ...], build_dir: Path, log: Path,
           cmake_only: bool = False, chosen_deployment: Deployment | None = None) -> bool:
    command = ["west", "build", "-p", "always", "-b", board, "-d", str(build_dir), "-S", profile,
               *(["--cmake-only"] if cmake_only else []), str(KIT_ROOT / "app"), "--",
               *variants.get(variant).cmake_args(), *(f"-D{s}" for s in settings),
               *(chosen_deployment.cmake_args() if chosen_deployment else [])]
    log.parent.mkdir(parents=True, exist_ok=True)
    with log.open("w") as output:
        output.write(" ".join(command) + "\n")
        output.flush()
        return subprocess.run(command, cwd=KIT_ROOT, env=environment(), stdout=output,
                              stderr=subprocess.STDOUT).returncode == 0


def _slug(knob: str) -> str:
    """A knob's build folder and log names."""
    return re.sub(r"-+", "-", "".join(c if c.isalnum() else "-" for c in knob)).strip("-")


def nominal_outcome(text: str) -> tuple[bool, str, dict[str, int]]:
    """A nominal run's console: whether it passed, why not (a halted run has
    no END line: its ARENA, HALT, FATAL or HEAP line says why), and LATENCY_RG's
    dispatch latency (p50, max)."""
    records = [r for r in map(console.parse_line, text.splitlines()) if r is not None]
    passed = any(r.kind == "END" and r.fields.get("result") == "PASS" for r in records)
    groups = [r for r in records if r.kind == "RG" and r.fields.get("hz", "").isdigit()]
    fastest = max(groups, key=lambda r: int(r.fields["hz"]), default=None)
    latency = {key: int(fastest.fields[f"latency_{key}"]) for key in ("p50", "max")
               if fastest is not None and f"latency_{key}" in fastest.fields}
    why = ("ARENA", "HALT", "FATAL", "HEAP")
    note = "" if passed else "; ".join(f"{r.kind} {' '.join(f'{k}={v}' for k, v in r.fields.items())}"
                                       for r in records if r.kind in why)[:300] or "no END PASS"
    return passed, note, latency


def _measure(knob: Knob, board: str, variant: str, profile: str, out_dir: Path,
             chosen_deployment: Deployment | None = None) -> Row:
    started = time.monotonic()
    slug = _slug(knob.name)
    build_dir = out_dir / slug
    row = Row(knob.name, list(knob.settings), built=_build(board, variant, profile, knob.settings, build_dir,
                                                            out_dir / f"{slug}.build.log",
                                                            chosen_deployment=chosen_deployment))
    refused = not_taken(knob.settings, BuildFolder(build_dir).kconfig(missing_ok=True)) if row.built else []
    if refused:
        # Measured, it would be the profile again under the knob's name
        row.built = False
        row.note = f"Kconfig did not take {'; '.join(refused)}"
    elif row.built:
        footprint = measure(build_dir)
        row.rom, row.ram = footprint.rom, footprint.ram
        own = by_layer.deployment_of(build_dir)
        row.rom_layers = by_layer.breakdown(by_layer.report(build_dir, "rom"), own)
        row.ram_layers = by_layer.breakdown(by_layer.report(build_dir, "ram"), own)
        try:
            text = runner.run(build_dir, out_dir / f"{slug}.run.log")
        except KitError as error:  # no end line in time
            row.passed = False
            row.note = str(error).splitlines()[0][:300]
        else:
            row.passed, row.note, row.latency = nominal_outcome(text)
    else:
        row.note = build_failure(out_dir / f"{slug}.build.log")
    row.seconds = time.monotonic() - started
    return row


def not_taken(settings: tuple[str, ...], config: dict[str, str]) -> list[str]:
    """The settings a build's .config does not hold as given (Kconfig
    overrides an assignment a symbol's dependencies or another default
    forbid, and only warns), each with the value it got."""
    refused = []
    for setting in settings:
        key, _, given = setting.partition("=")
        wanted = given.strip('"')  # as .config's reading gives a string
        got = config.get(key, "n")  # .config leaves out a symbol that is n
        if got != wanted:
            refused.append(f"{setting} (got {got})")
    return refused


def chosen(plan: list[Knob], only: list[str]) -> list[Knob]:
    """The profile's own build and the knobs whose name contains one of
    `only` (all of them when it is empty); a filter that keeps no knob is an
    error that lists them."""
    if not only:
        return plan
    kept = [k for k in plan[1:] if any(text.lower() in k.name.lower() for text in only)]
    if not kept:
        raise KitError(f"no knob matches {', '.join(repr(o) for o in only)}; the knobs are: "
                       f"{'; '.join(k.name for k in plan[1:])}")
    return [plan[0], *kept]


def run(board: str, variant: str, profile: str, toward: str, out_dir: Path,
        say: Callable[[str], None], only: list[str] | None = None,
        chosen_deployment: Deployment | None = None) -> list[Row]:
    """The ablation of one board and variant from `profile`, each knob moved
    toward `toward` (only those `only` names, when given: then the other
    profile's whole build is left out too), of the reference deployment or
    `chosen_deployment`."""
    out_dir.mkdir(parents=True, exist_ok=True)
    say(f"footprint: {board} {variant}: building the profiles {profile} and {toward}")
    base = _measure(Knob("profile"), board, variant, profile, out_dir, chosen_deployment)
    if not base.built:
        raise KitError(f"the profile {profile} does not build for {board} {variant}: {base.note}")
    # The other profile's values: its configuration is enough (it need not fit)
    other_dir = out_dir / "toward"
    if not _build(board, variant, toward, (), other_dir, out_dir / "toward.configure.log", cmake_only=True,
                  chosen_deployment=chosen_deployment):
        raise KitError(f"the profile {toward} does not configure for {board} {variant}: "
                       f"{out_dir / 'toward.configure.log'}")
    profile_build = BuildFolder(out_dir / "profile")
    plan = knobs(profile_build.fprime_switches(), BuildFolder(other_dir).fprime_switches(),
                 variants.get(variant).model, profile_build.kconfig())
    plan = chosen(plan, only or [])
    rows = [base]
    for index, knob in enumerate(plan[1:], start=1):
        row = _measure(knob, board, variant, profile, out_dir, chosen_deployment)
        rows.append(row)
        verdict = "build FAILED" if not row.built else ("nominal PASS" if row.passed else "nominal FAIL")
        say(f"footprint: {index}/{len(plan)} {knob.name}: {verdict}, ROM {row.rom} RAM {row.ram} "
            f"({row.seconds:.0f} s)")
    if not only:  # last, the other profile whole: every knob moved at once
        rows.append(_measure(Knob(f"profile {toward}"), board, variant, toward, out_dir, chosen_deployment))
        say(f"footprint: profile {toward}: {'built' if rows[-1].built else 'build FAILED'} {rows[-1].note}")
    # "model": the variant, as `kit footprint --model` names it
    (out_dir / "footprint.json").write_text(json.dumps(
        {"board": board, "model": variant, "profile": profile, "toward": toward,
         "rows": [asdict(r) for r in rows]}, indent=2) + "\n")
    return rows


def _delta(value: int | None, base: int | None) -> str:
    if value is None or base is None:
        return ""
    return f"{value - base:+,d}"


def table(rows: list[Row], board: str, model: str, profile: str, toward: str) -> Table:
    """The ablation of one model: each knob's ROM and RAM against the
    profile, the layers that moved most, and whether the nominal run passed."""
    base = rows[0]
    body: list[list[Any]] = []
    for row in rows:
        moved = []
        for kind, layers, base_layers in (("ROM", row.rom_layers, base.rom_layers),
                                          ("RAM", row.ram_layers, base.ram_layers)) if row.built else ():
            changes = sorted(((layers.get(k, 0) - base_layers.get(k, 0), k) for k in set(layers) | set(base_layers)),
                             key=lambda c: (-abs(c[0]), c[1]))
            moved += [f"{kind} {k} {d:+,d}" for d, k in changes[:2] if d]
        verdict = f"build failed: {row.note}" if not row.built else ("PASS" if row.passed else f"FAIL: {row.note}")
        deltas = ("", "") if row is base else (_delta(row.rom, base.rom), _delta(row.ram, base.ram))
        latency = row.latency
        body.append([row.knob, row.rom if row.rom is not None else "", deltas[0],
                     row.ram if row.ram is not None else "", deltas[1],
                     latency.get("p50", ""), latency.get("max", ""), "; ".join(moved), verdict])
    return Table(f"Knobs on {board}, {model}: from {profile}, one knob at a time toward {toward} (bytes; "
                 f"{LATENCY_RG}'s dispatch latency in cycles, nominal run)",
                 ["knob", "ROM", "ΔROM", "RAM", "ΔRAM", "fastest group's latency p50", "fastest group's latency max",
                  "layers moved most (ROM / RAM)", "nominal run"], body)


def write_report(tables: list[Table], out_dir: Path) -> list[Path]:
    """The ablation's report: Markdown and self-contained HTML, like the
    design-review report's."""
    intro: Section = Text("What each F´ knob costs", [
        "Each row is one build: the profile's, or the profile with one knob moved; ΔROM and ΔRAM are against the "
        "profile's build, static RAM as the linker places it (a knob that moves memory into the C heap shows the "
        "arena it needs).",
        "Each build then plays the nominal run under QEMU; a row that fails says why (its ARENA, HALT, FATAL or HEAP "
        "line).", CAVEAT])
    sections: list[Section] = [intro, *tables]
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "report.md").write_text(render.to_markdown(sections, {}))
    (out_dir / "report.html").write_text(render.to_html(sections))
    return [out_dir / "report.md", out_dir / "report.html"]


def load(path: Path) -> tuple[dict[str, str], list[Row]]:
    """A footprint.json: its conditions (board, model, profile, toward) and rows."""
    if not path.is_file():
        raise KitError(f"no ablation at {path}: run scripts/kit footprint first")
    data = json.loads(path.read_text())
    rows = [Row(**row) for row in data["rows"]]  # an older file's rows have no latency: left empty
    for row in rows:
        if not row.built:  # the reason, as this version reads it from the build's log
            row.note = build_failure(path.parent / f"{_slug(row.knob)}.build.log")
    return ({k: str(data[k]) for k in ("board", "model", "profile", "toward")}, rows)


def report_dir_of(board: str, profile: str, suffix: str = "") -> Path:
    """Where the report goes; `suffix`: a deployment's (Deployment.output_suffix)."""
    return KIT_ROOT / "build" / "footprint" / f"{board_dir_name(board)}-{profile}{suffix}-report"


def out_dir_of(board: str, model: str, profile: str, suffix: str = "") -> Path:
    """Where a variant's builds go; `suffix`: a deployment's (Deployment.output_suffix)."""
    return KIT_ROOT / "build" / "footprint" / f"{board_dir_name(board)}-{model}-{profile}{suffix}"
