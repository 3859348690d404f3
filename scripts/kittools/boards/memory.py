# SPDX-License-Identifier: Apache-2.0
"""Whether a board holds the deployment: its memory against the footprint
measured on a ported board (that board's results file)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from kittools import model
from kittools.boards.zephyr import ZephyrBoard
from kittools.suite import results
from kittools.workspace import VARIANTS, KitError, board_dir_name

# What to shrink when a resource is short, from docs/porting.md, "Memory budget"
_LEVERS = {
    "flash": "F´'s configuration (app/config/) and the components built in",
    "RAM": "the telemetry store (the board's Kconfig.defconfig: CONFIG_KIT_TELEMETRY_TABLE=y, the kit's "
           "TlmTable, one table in its object, in any model; or CONFIG_KIT_TELEMETRY_LINEAR=y in the baremetal "
           "model, fprime-baremetal's TlmLinearChan, one table from the heap's arena: 4.9 KiB "
           "less on the reference's baremetal_passive, its larger arena included), "
           "in the rtos model one thread for the services and the dispatcher (CONFIG_KIT_RTOS_SHARED_LEVEL_HIGH=6, "
           "rtos/Os/SharedThread.cpp: their stacks become the largest of theirs, about 10.5 KiB less on "
           "qemu_cortex_m3), the timing histograms' resolution (CONFIG_KIT_TIMING_SUB_BITS=2, every model: 3.6 KiB, "
           "percentiles within 25 %), "
           "F´'s health and version services (CONFIG_KIT_SERVICE_CDH=n in the board's Kconfig.defconfig, about 8 KiB), "
           "its parameter database (CONFIG_KIT_SERVICE_PARAMS=n, 4 to 6 KiB with its thread), "
           "its file downlink (CONFIG_KIT_SERVICE_FILES=n, 5.6 KiB with a 2 KiB file), "
           "its file uplink (CONFIG_KIT_SERVICE_FILE_UPLINK=n, about 2 KiB), "
           "its command sequencer (CONFIG_KIT_SERVICE_SEQUENCER=n, about 4 KiB with its heap), "
           "CONFIG_COMMON_LIBC_MALLOC_ARENA_SIZE (app/Kconfig), the queue depths "
           "(app/Top/instances.fpp), the stack table (Tables.fpp), F´'s configuration (app/config/)",
}


def smallest_models(measured: model.Results) -> dict[str, str]:
    """Per resource ("flash", "RAM"), the variant of a results file that
    needs the least of it: the model a small board can still take."""
    if not measured.variants:
        raise KitError("the reference's results have no variant to measure the deployment from")
    need = {"flash": model.ROM, "RAM": model.RAM}
    return {what: min(measured.variants, key=lambda v: (measured.variants[v].metrics[metric], v))
            for what, metric in need.items()}


class DoesNotFit(KitError):
    """The board is too small for the deployment as measured (not: the
    measurement or the board's memory is missing, which stay KitErrors)."""


def check_fit(board: ZephyrBoard, baseline: Path, shown_as: str | None = None) -> list[str]:
    """The deployment's measured need (a ported board's results file)
    against the board's memory, from the smallest model (per resource, the
    variant that needs the least): DoesNotFit if even it does not fit, named;
    KitError when the board's memory or a model's measurement is missing.
    Returns a headroom line per variant, and for a larger model the board
    cannot hold, a line saying so (its build in kit test fails until the
    deployment shrinks)."""
    shown_as = shown_as or str(baseline)
    if board.ram_kib is None or board.flash_kib is None:
        raise KitError(f"the memory of {board.identifier} is unknown (no ram/flash in {board.platform_file.name}, "
                       "no size of its zephyr,sram / zephyr,flash nodes in the board's own devicetree), so the fit "
                       f"cannot be checked. Find out: build once (west build -b {board.identifier} -T app/kit.rtos) "
                       "and read the linker's 'Memory region' lines, or the board's documentation.")
    measured = results.load(baseline)
    # Every model, or the smallest might be one of those measured only
    for variant in VARIANTS:
        if variant not in measured.variants:
            raise KitError(f"{shown_as} has no {variant} variant to measure the deployment from")
    have = {"flash": board.flash_kib * 1024, "RAM": board.ram_kib * 1024}
    need = {variant: {"flash": found.metrics[model.ROM], "RAM": found.metrics[model.RAM]}
            for variant, found in measured.variants.items()}
    smallest = smallest_models(measured)
    short = [f"{what}: the smallest model, {smallest[what]}, needs {need[smallest[what]][what] / 1024:.1f} KiB, "
             f"the board has {have[what] / 1024:.0f} KiB" for what in ("flash", "RAM")
             if need[smallest[what]][what] > have[what]]
    if short:
        levers = "; ".join(f"{what}: {_LEVERS[what]}" for what in ("flash", "RAM")
                           if need[smallest[what]][what] > have[what])
        raise DoesNotFit(f"{board.identifier} cannot hold the deployment as measured in {shown_as}: "
                       + "; ".join(short) + ". Shrink the deployment first (docs/porting.md, 'Memory budget'): "
                       + levers + ".")
    lines: list[str] = []
    for variant in sorted(need, key=lambda v: (need[v]["flash"], v)):
        spare = {what: have[what] - need[variant][what] for what in ("flash", "RAM")}
        mark = " (the smallest)" if variant in smallest.values() else ""
        lines.append(f"{variant}{mark}: " + ", ".join(
            f"{what} {need[variant][what] / 1024:.1f} of {have[what] / 1024:.0f} KiB "
            f"({spare[what] / 1024:.1f} KiB spare)" for what in ("flash", "RAM")))
        over = [f"{-spare[what] / 1024:.1f} KiB of {what}" for what in ("flash", "RAM") if spare[what] < 0]
        if over:
            lines.append(f"{variant} does not fit: {' and '.join(over)} short; its build fails until the "
                         "deployment shrinks (docs/porting.md, 'Memory budget')")
    return lines


@dataclass(frozen=True)
class SmallFit:
    """The smallest build of a small part (its baseline: the fprime-small
    builds the suite plays there) that a board can hold."""
    part: str  # the small part's board folder, which a small board's port starts from
    variant: str  # as its baseline names it: <profile>.<variant> (small.baremetal_passive)
    lines: list[str]

    @property
    def described(self) -> str:
        return _described(self.variant)


def _described(variant: str) -> str:
    """A small part's build as its baseline names it (small.baremetal_passive), in words."""
    profile, _, model_name = variant.partition(".")
    return f"{model_name} with fprime-{profile}"


def fit_small_part(board: ZephyrBoard, root: Path, parts: list[str]) -> SmallFit | None:
    """Where the kit profile does not fit `board`: the smallest build among
    the small parts' baselines (tests/baselines/<part>.json) that it holds,
    with a headroom line per build measured there; None when none fits (or
    no small part has a baseline yet)."""
    have = {"flash": (board.flash_kib or 0) * 1024, "RAM": (board.ram_kib or 0) * 1024}
    candidates: list[tuple[int, int, str, str]] = []
    for part in parts:
        path = root / "tests" / "baselines" / f"{board_dir_name(part)}.json"
        if path.is_file():
            for variant, found in results.load(path).variants.items():
                candidates.append((int(found.metrics[model.RAM]), int(found.metrics[model.ROM]), board_dir_name(part),
                                   variant))
    fitting = [c for c in sorted(candidates) if c[1] <= have["flash"] and c[0] <= have["RAM"]]
    if not fitting:
        return None
    ram, rom, part, variant = fitting[0]
    lines = [f"{_described(v)} (measured on {p}{', the smallest that fits' if (p, v) == (part, variant) else ''}): "
             f"flash {r_o / 1024:.1f} of {have['flash'] / 1024:.0f} KiB, RAM {r_a / 1024:.1f} of "
             f"{have['RAM'] / 1024:.0f} KiB" for r_a, r_o, p, v in sorted(candidates)]
    return SmallFit(part, variant, lines)
