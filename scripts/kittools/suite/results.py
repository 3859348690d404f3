# SPDX-License-Identifier: Apache-2.0
"""A run's results file: load and check it, or build it from a twister run.

The schema is documented in docs/results.md; `compare.results(...).to_json()` writes it.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from kittools import console, metrics, model
from kittools.build import conditions
from kittools.build.folder import BuildFolder
from kittools.link import serial_points
from kittools.sizes import by_layer, sizing, symbols
from kittools.sizes.memory import Footprint, measure
from kittools.suite import floor
from kittools.workspace import KitError

REQUIRED_METRICS = (model.ROM, model.RAM)
#: Schemas this kit reads: the current one, and 1 (upgraded on load: metric keys were labels)
READABLE_SCHEMAS = (1, model.SCHEMA_VERSION)


def load(path: Path) -> model.Results:
    """The results in `path`; KitError naming what is wrong if it is not a results file."""
    if not path.is_file():
        raise KitError(f"results file {path} does not exist (kit compare writes build/compare/comparison.json)")
    try:
        data = json.loads(path.read_text())
    except json.JSONDecodeError as error:
        raise KitError(f"results file {path} is not valid JSON: {error}") from error
    return parse(data, str(path))


def parse(data: Any, path: str = "results") -> model.Results:
    """Results from a results file's JSON; KitError naming what is wrong."""
    if not isinstance(data, dict):
        raise KitError(f"results file {path}: expected a JSON object, found {type(data).__name__}")
    if data.get("schema_version") not in READABLE_SCHEMAS:
        raise KitError(f"results file {path}: schema_version {data.get('schema_version')!r}, "
                       f"this kit reads {' and '.join(map(str, READABLE_SCHEMAS))} (docs/results.md)")
    variants = data.get("variants")
    if not isinstance(variants, dict) or not variants:
        raise KitError(f"results file {path}: no 'variants'")
    for name, variant in variants.items():
        if not isinstance(variant, dict):
            raise KitError(f"results file {path}: variant '{name}' is not an object")
        if not isinstance(variant.get("metrics"), dict):
            raise KitError(f"results file {path}: variant '{name}' has no 'metrics'")
        if not isinstance(variant.get("records", []), list):
            raise KitError(f"results file {path}: variant '{name}': 'records' is not a list")
    if not isinstance(data.get("conditions"), dict):
        raise KitError(f"results file {path}: no 'conditions'")
    try:
        if data["schema_version"] == 1:
            data = model.upgrade_v1(data)
        results = model.Results.from_json(data)
    except (ValueError, TypeError, AttributeError) as error:
        raise KitError(f"results file {path}: {error}") from error
    for name, variant in results.variants.items():
        for metric in REQUIRED_METRICS:
            if variant.metric(metric) is None:
                raise KitError(f"results file {path}: variant '{name}' lacks the metric '{metric.key}' "
                               f"({metric.label})")
    return results


def twister_build(twister_out: Path, platform: str, scenario: str) -> Path:
    """The build folder twister made for a scenario on a platform."""
    platform_dir = twister_out / platform.replace("/", "_")
    builds = BuildFolder.built_under(platform_dir, scenario)
    if len(builds) != 1:
        raise KitError(f"expected one twister build of {scenario} on {platform}, found {len(builds)}")
    return builds[0].path


#: Where the suite's pytest harness keeps each scenario's console, per build
#: (tests/deployment/pytest/test_scenarios.py): <build>/kit-runs/<scenario>.log
RUNS_DIR = "kit-runs"


#: Records of the scenario's choice at boot (app/scenarios/Scenarios.cpp)
BOOT_KINDS = ("SELECT", "SCENARIO")


def run_log(build: Path, scenario: str) -> Path:
    return build / RUNS_DIR / f"{scenario}.log"


def played(build: Path, scenario: str) -> console.Run | None:
    """The records of a scenario the suite played on a build, or None when it
    did not play it (a `kit compare` run plays two)."""
    log = run_log(build, scenario)
    if not log.is_file():
        return None
    text = log.read_text(errors="replace")
    # The SELECT lines are the prompt's, before the run: not the run's records
    return console.Run([r for r in (console.parse_line(line) for line in text.splitlines())
                        if r is not None and r.kind not in BOOT_KINDS])


# Kinds of record the load scenario adds to a variant's results (the sweep)
SWEEP_KINDS = ("SWEEP", "BREAK", "AXIS")


def _same_board(platform: str, board: str) -> bool:
    """Twister names the platform with its qualifiers (qemu_cortex_m3/ti_lm3s6965)."""
    return platform == board or platform.startswith(board + "/")


def suite_builds(twister_out: Path, board: str | None = None, prefix: str = "kit.") -> list[tuple[str, Path]]:
    """(platform, build folder) of every configuration twister built whose
    name starts with `prefix`, on `board` or on all: by default the suite's
    (tests/deployment: one per execution model and board); "floor." for the
    kernel floor's (tests/floor)."""
    report = twister_out / "twister.json"
    if not report.is_file():
        raise KitError(f"no twister report at {report}")
    found = []
    for suite in json.loads(report.read_text()).get("testsuites", []):
        platform, name = suite.get("platform", ""), suite.get("name", "").rsplit("/", 1)[-1]
        if (board is None or _same_board(platform, board)) and name.startswith(prefix) \
                and suite.get("status") not in ("filtered", "skipped"):
            if suite.get("status") == "error" and not BuildFolder.built_under(
                    twister_out / platform.replace("/", "_"), name):
                continue  # it never linked: twister counted it, and kittools.suite.fit says why when it did not fit
            found.append((platform, twister_build(twister_out, platform, name)))
    return sorted(found, key=lambda pair: (pair[0], pair[1].name))


#: The real boards' builds (tests/boards: built, not run)
BUILD_ONLY_PREFIX = "board."
#: The suite played again with a footprint profile (profile.<profile>.<model>,
#: modules/fprime/snippets/fprime-<profile>): not the comparison's builds
PROFILE_PREFIX = "profile."
#: The conditions of a board only built: what a reader must know before any figure
NOT_RUN = "built only: not run on hardware (no emulator); ROM and RAM are the build's, there is no timing"


#: The conditions of a small part: its builds are played, and judged by twister and the ground link
SMALL_PART_RUN = ("a small part: the builds that fit it (the fprime-small profile) played every scenario and the "
                  "ground link, judged there; ROM and RAM are the builds'")


def built_only(twister_out: Path, board: str, prefix: str = BUILD_ONLY_PREFIX) -> model.Results:
    """Results of a real board's builds (tests/boards, one per execution
    model), or with `prefix` PROFILE_PREFIX a small part's (tests/deployment's
    profile builds, the ones that fit it, played): footprint and ROM/RAM by
    layer, no records."""
    run = NOT_RUN if prefix == BUILD_ONLY_PREFIX else SMALL_PART_RUN
    builds = suite_builds(twister_out, board, prefix)
    if not builds:
        raise KitError(f"twister built nothing named {prefix}* on {board} in {twister_out}")
    reports = by_layer.reports([build for _, build in builds])
    variants: dict[str, model.Variant] = {}
    for (_, build), (rom, ram) in zip(builds, reports, strict=True):
        size, own = measure(build), by_layer.deployment_of(build)
        variants[build.name.removeprefix(prefix)] = model.Variant(
            passed=False, metrics={model.ROM: size.rom, model.RAM: size.ram}, build=conditions.read(build),
            modules={"rom": by_layer.breakdown(rom, own), "ram": by_layer.breakdown(ram, own)},
            footprint={"rom": size.rom, "ram": size.ram, "rom_size": size.rom_size, "ram_size": size.ram_size})
    return model.Results({"board": builds[0][0], "run": run}, variants)


def integration_logs(log_dir: Path, platform: str, build_name: str) -> Path:
    """Where `kit test` keeps what it ran on a twister build of the ground
    scenario (integration suite, fuzzing, serial-load sweep)."""
    return log_dir / f"integration.{platform.replace('/', '_')}_{build_name}"


SERIAL_SWEEP_FILE = "serial.json"
#: The flood's records (kittools.link.flood), beside the sweep's
FLOOD_FILE = "flood.json"
#: The ground link's record files whose "lines" go into a variant's records
LINK_RECORD_FILES = (SERIAL_SWEEP_FILE, FLOOD_FILE)


@dataclass
class Played:
    """One build's part of a board's results, before the kernel floor is
    attached: what `from_twister` reads of the build (its runs, sizes,
    layers, configuration) and of the ground link's checks on it. A shard of
    the suite (kit test --subset) keeps these, and the floor's records, apart
    (kittools.suite.shards): the build and the floor's builds may be in different
    shards, and `assemble` joins them as a single run would."""

    platform: str
    variant: str
    footprint: Footprint
    records: list[console.Record]  #: the nominal run's, then the load sweep's
    link_records: list[console.Record]  #: the ground link's (serial sweep, flood)
    rom_modules: dict[str, int]
    ram_modules: dict[str, int]
    build: dict[str, Any]
    symbols: dict[str, dict[str, int]]
    sizing: dict[str, Any]


@dataclass
class Floors:
    """The kernel floor's records of a board's floor builds: FLOOR per path,
    Zephyr's own figures for the threaded paths."""

    paths: dict[str, console.Record] = field(default_factory=dict)
    zephyr: list[console.Record] = field(default_factory=list)

    def add(self, other: Floors) -> None:
        self.paths.update(other.paths)
        self.zephyr = self.zephyr or other.zephyr


def collect(twister_out: Path, board: str, log_dir: Path | None = None) -> tuple[list[Played], Floors]:
    """What a twister run of tests/deployment made on one board: per build
    that played the nominal scenario, its Played (with the load scenario's
    sweep records when it played, and those of the serial-load sweep and the
    flood `kit test` ran on it under `log_dir`); and the floor builds'
    records (kittools.suite.floor)."""
    builds = [(platform, build, run) for platform, build in suite_builds(twister_out, board)
              if (run := played(build, "nominal")) is not None and run.of_kind("BANNER")]
    reports = by_layer.reports([build for _, build, _ in builds])
    floors = floors_of(twister_out, board)
    found = []
    for (platform, build, run), (rom, ram) in zip(builds, reports, strict=True):
        own = by_layer.deployment_of(build)
        sweep = played(build, "load")
        if sweep is not None:
            run.records += [r for r in sweep.records if r.kind in SWEEP_KINDS]
        link_records: list[console.Record] = []
        if log_dir is not None:
            for file_name in LINK_RECORD_FILES:
                records_file = integration_logs(log_dir, platform, build.name) / file_name
                if records_file.is_file():
                    link_records += serial_points.records_of(records_file)
        found.append(Played(
            platform, run.variant, measure(build), run.records, link_records,
            by_layer.breakdown(rom, own), by_layer.breakdown(ram, own), conditions.read(build),
            {kind: symbols.table(symbols.leaves(report, own), symbols.SYMBOL_FLOOR)
             for kind, report in (("rom", rom), ("ram", ram))},
            sizing.measure(build, [r.fields for r in run.of_kind("QUEUE")]).to_json()))
    return found, floors


def floors_of(twister_out: Path, board: str) -> Floors:
    """The kernel floor's records of a twister run's floor builds on a board
    (none where it made none, or there is no run: a deployment's run takes
    the suite's)."""
    if not (twister_out / "twister.json").is_file():
        return Floors()
    floor_builds = [build for _, build in suite_builds(twister_out, board, floor.PREFIX)]
    return Floors(floor.records(floor_builds), floor.zephyr_records(floor_builds))


def assemble(found: list[Played], floors: Floors, board: str) -> model.Results:
    """A board's results from its builds' parts and its floor: each
    variant's records are its runs', then the kernel floor of its dispatch
    path on this board (and Zephyr's own figures for the threaded paths),
    then the ground link's."""
    if not found:
        raise KitError(f"no nominal scenario played on {board} (no {RUNS_DIR}/nominal.log in its builds)")
    variants = []
    for part in sorted(found, key=lambda p: p.variant):
        run = console.Run(list(part.records))
        path = floor.path_of(run)
        if path in floors.paths:
            run.records.append(floors.paths[path])
        if path == floor.PATH_OF_CONTEXT["thread"]:
            run.records += floors.zephyr
        run.records += part.link_records
        variants.append(metrics.VariantData(part.variant, part.footprint, run, part.rom_modules,
                                            part.ram_modules, part.build, part.symbols, part.sizing))
    return metrics.results(variants)


def from_twister(twister_out: Path, board: str, log_dir: Path | None = None) -> model.Results:
    """Results of a twister run of tests/deployment on one board, in the
    results-file schema (collect, then assemble): per build (one per
    variant), the nominal scenario's records, footprint and modules, plus
    the sweep records of the load scenario when it played, those of the
    serial-load sweep and the flood `kit test` ran on the build (under
    `log_dir`), and the kernel floor of the model's dispatch path from the
    run's tests/floor builds (kittools.suite.floor)."""
    found, floors = collect(twister_out, board, log_dir)
    if not found:
        raise KitError(f"twister run in {twister_out} played no nominal scenario on {board} "
                       f"(no {RUNS_DIR}/nominal.log in its builds; a build that failed is named above)")
    return assemble(found, floors, board)
