# SPDX-License-Identifier: Apache-2.0
"""`kit new-board`'s scaffold: boards/<dir>/ copied from the reference
board's folder with a TODO header in each file, and for a real board its
kit.conf, its HAL file and its ground link's overlay."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

from kittools import log, workspace
from kittools.boards.devicetree import link_uarts, spare_uart
from kittools.boards.memory import DoesNotFit, SmallFit, check_fit, fit_small_part, smallest_models
from kittools.boards.suites import allow_module, join_small_suite, join_suite
from kittools.boards.zephyr import ZephyrBoard, check_arch, find_board, hal_module, zephyr_version
from kittools.suite import platforms, results
from kittools.workspace import KitError, board_dir_name, board_folder, ported_boards

REFERENCE_BOARD = "qemu_cortex_m3"
#: The suite whose small parts (boards only its fprime-small scenarios allow) measured what a small board holds
SMALL_PART_SUITE = Path("tests") / "deployment" / "testcase.yaml"

# What the porter must check in each file of the new folder (docs/porting.md)
TODOS: dict[str, tuple[str, ...]] = {
    "kit.conf": (
        "QEMU icount: set CONFIG_QEMU_ICOUNT_SHIFT so that 10^9 / 2^shift instructions",
        "per second models the real part's speed, and say why here (docs/porting.md, step 4).",
        "Console: the run's record goes to the zephyr,console UART; the banner must appear at boot.",
        "Tick: the system timer must do 1 kHz; check the banner's cycles_hz (the cycle counter's rate).",
    ),
    "Kconfig.defconfig": (
        "Re-measure the stacks on this board from the 'KIT STACK' lines of a run of every",
        "scenario, with headroom: MAIN_STACK_SIZE per model (the rtos threads' own are in Tables.fpp).",
        "Stack protection (rtos): HW_STACK_PROTECTION where the part has an MPU, else STACK_SENTINEL.",
        "The C heap's arena per model (COMMON_LIBC_MALLOC_ARENA_SIZE) is what the reference board's runs used:",
        "the same code uses the same heap; re-measure from 'KIT HEAP arena_left' if this board's build differs.",
        "F´ services a model leaves out (KIT_SERVICE_CDH, KIT_SERVICE_PARAMS, KIT_SERVICE_FILES,",
        "KIT_SERVICE_FILE_UPLINK, KIT_SERVICE_SEQUENCER) are the reference board's RAM decisions, with its",
        "numbers: turn on what this board holds, and say why for what stays off.",
    ),
    # A board's Tables.fpp is an optional override of the deployment's table
    # (app/Top/Tables.fpp): this header only for a copied folder that has one
    # (the reference board's has none)
    "Tables.fpp": (
        "Priorities and stacks are the reference board's: re-measure the stacks from the",
        "'KIT STACK' lines of this board's runs and check the priorities (docs/porting.md,",
        "steps 6-7). Each rtos thread gets its stack at this size (rtos/ThreadStacks.cpp).",
    ),
    "app.overlay": (
        "Devicetree copied from the reference board: choose the ground link's UART (kit,link-uart:",
        "not the console; under QEMU the machine's second serial port) and check the console UART",
        "(zephyr,console) and the timers against this board's devicetree (docs/porting.md, step 3).",
    ),
}
DEFAULT_TODO = ("Copied from the reference board: check this file for the new board (docs/porting.md).",)
# A real board's (docs/porting.md, "A real board"): no icount, its own UARTs and timer
REAL_TODOS: dict[str, tuple[str, ...]] = {
    "kit.conf": (
        "Console: the run's record goes to the zephyr,console UART (often the debugger's virtual COM port).",
        "Tick and timestamps: 1 kHz system timer; check cycles_hz in the banner on the board.",
        "Zephyr symbols only here; a kit symbol belongs in Kconfig.defconfig.",
    ),
    "app.overlay": (
        "Written for this board by the scaffold: check the ground link's UART (kit,link-uart: not the",
        "console; enabled, with its pins) against the board's schematic, and say how to wire it.",
    ),
}
REAL_KIT_CONF = """# SPDX-License-Identifier: Apache-2.0
# {identifier}: a real board, built by the kit for every execution model and
# not run (tests/boards/testcase.yaml). No QEMU icount: the cycle counter is
# the part's own timer, and times vary from run to run as hardware does.
"""
REAL_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link: F´'s comm stack talks to the ground over this UART
 * (app/Top/KitTopology.cpp), one the board's devicetree enables that is not
 * its console (the run's record). Wire a 3.3 V USB-serial adapter to its pins.
 */
/ {{
	chosen {{
		kit,link-uart = &{uart};
	}};
}};
"""
# A UART of the SoC the board leaves disabled, enabled here on pins of the
# HAL's pinctrl file: the form the boards' own devicetrees use for theirs
SPARE_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link: F´'s comm stack talks to the ground over this UART
 * (app/Top/KitTopology.cpp). The board enables no UART besides its console
 * (the run's record), so the scaffold enabled {uart}, disabled in the SoC's
 * devicetree, on pins the HAL's {pinctrl} names:
 * TX {tx_pin}, RX {rx_pin}. Wire a 3.3 V USB-serial adapter: its RX to {tx_pin},
 * its TX to {rx_pin}, and ground. None of these pins is used by the board's
 * own devicetree; check the board's schematic (solder bridges, the connector).
 */
/ {{
	chosen {{
		kit,link-uart = &{uart};
	}};
}};

&{uart} {{
	pinctrl-0 = <&{tx} &{rx}>;
	pinctrl-names = "default";
	current-speed = <115200>;
	status = "okay";
}};
"""
# No UART found for the link: no kit,link-uart, so the build stops at the
# kit's own #error (app/Top/KitTopology.cpp) rather than in devicetree
NO_LINK_OVERLAY = """/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The kit's ground link needs a UART besides the console, and the scaffold
 * found none it could enable: {reason}.
 * Choose one here (chosen {{ kit,link-uart = &usartN; }}) and enable it with
 * its pins (pinctrl-0, pinctrl-names, current-speed, status = "okay");
 * until then the build stops and says so (app/Top/KitTopology.cpp).
 */
"""
HAL_FILE = """# The Zephyr modules this board needs beyond CMSIS (app/board.cmake refuses
# a workspace without them): the module's name in Zephyr's manifest, and its
# folder in the kit's workspace. west.yml allow-lists each.
{name} {path}
"""
TODO_MARK = "TODO(port):"


def _without_todo(name: str, text: str) -> str:
    """The text without a TODO header of an earlier scaffold (scaffolding from
    a port whose TODOs are still open must not stack two headers)."""
    if name.endswith(".overlay"):
        match = re.match(rf"/\*\n(?: \* {re.escape(TODO_MARK)}.*\n)+ \*/\n", text)
        return text[match.end():] if match else text
    lines = text.splitlines(keepends=True)
    kept = 0
    while kept < len(lines) and lines[kept].startswith(f"# {TODO_MARK}"):
        kept += 1
    return "".join(lines[kept:])


def with_todo(name: str, text: str, reference: str, identifier: str,
              todos: dict[str, tuple[str, ...]] | None = None) -> str:
    """A copied file with its TODO header, in the file's comment syntax."""
    todo = (f"copied from boards/{reference}/ for {identifier}: check what follows, then delete this header.",
            *(todos or TODOS).get(name, TODOS.get(name, DEFAULT_TODO)))
    body = _without_todo(name, text)
    if name.endswith(".overlay"):
        return "/*\n" + "".join(f" * {TODO_MARK} {line}\n" for line in todo) + " */\n" + body
    return "".join(f"# {TODO_MARK} {line}\n" for line in todo) + body



def _check_target_folder(folder: Path, identifier: str, boards: Path, force: bool) -> None:
    """Refuse to overwrite a port (or shadow one that covers the board) unless forced."""
    existing = board_folder(identifier, boards)
    if existing is None or force:
        return
    if existing == folder:
        raise KitError(f"boards/{folder.name} exists already: {identifier} is ported. Use --force to write its "
                       "files again from the reference (its other files are kept).")
    raise KitError(f"boards/{existing.name} already covers {identifier} (a folder named after the board covers all "
                   f"its qualifiers). Use --force to give {identifier} a folder of its own, boards/{folder.name}.")


def _reference_folder(reference: str, folder: Path, boards: Path) -> Path:
    reference_dir = board_folder(reference, boards)
    if reference_dir is None:
        raise KitError(f"reference board '{reference}' has no kit port. Ported boards: "
                       f"{', '.join(ported_boards(boards))}.")
    if reference_dir == folder:
        raise KitError(f"boards/{folder.name} is the reference itself: pick another with --from.")
    return reference_dir


def _copy_folder(reference_dir: Path, folder: Path, identifier: str, root: Path, say: Callable[[str], None],
                 todos: dict[str, tuple[str, ...]] | None = None) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    copied = set()
    for source in sorted(p for p in reference_dir.iterdir() if p.is_file()):
        (folder / source.name).write_text(with_todo(source.name, source.read_text(), reference_dir.name, identifier,
                                                    todos))
        copied.add(source.name)
        say(f"created: {(folder / source.name).relative_to(root)} (from {reference_dir.name}, TODO header)")
    for other in sorted(p.name for p in folder.iterdir() if p.name not in copied):
        say(f"kept: {(folder / other).relative_to(root)} (not in the reference)")



def _fit(board: ZephyrBoard, baseline: Path, shown_as: str, reference: str, root: Path,
         say: Callable[[str], None]) -> SmallFit | None:
    """The board's memory against the deployment's measured need: the kit
    profile's smallest model (the reference's baseline), else the smallest
    build a small part plays that the board holds (None: the kit profile
    fits); KitError when neither does."""
    try:
        lines = check_fit(board, baseline, shown_as)
    except DoesNotFit as refused:
        small = fit_small_part(board, root, platforms.small_parts(root / SMALL_PART_SUITE))
        if small is None:
            raise KitError(f"{refused} Nor does the smallest build of a small part (tests/baselines of "
                           "the suite's small parts; docs/porting.md, 'A small part').") from refused
        say(f"memory: the kit profile does not fit: {str(refused).split('. Shrink')[0]}")
        for line in small.lines:
            say(f"memory: {line}")
        say(f"memory: the smallest build that passes the suite and fits: {small.described}, as measured on "
            f"{small.part}, whose stacks and heap this port starts from (boards/{small.part}/Kconfig.defconfig); "
            "the board joins the suite's fprime-small builds only")
        return small
    for line in lines:
        say(f"memory: {line}")
    named = " and ".join(dict.fromkeys(smallest_models(results.load(baseline)).values()))
    say(f"memory: an estimate from {reference}'s build ({shown_as}), the board checked against its smallest "
        f"model, {named} (kit profile); ROM can differ a few % on another board, so the real check is this "
        "port's own run")
    return None


def new_board(target: str, reference: str = REFERENCE_BOARD, force: bool = False,
              say: Callable[[str], None] = log.say, root: Path | None = None, zephyr: Path | None = None) -> Path:
    """Check the board, scaffold boards/<dir>/ from the reference's folder and
    add the board to the twister files; returns the new folder."""
    root = workspace.KIT_ROOT if root is None else root
    zephyr = workspace.DEPS / "zephyr" if zephyr is None else zephyr
    board = find_board(target, zephyr)
    check_arch(board)
    boards = root / "boards"
    folder = boards / board_dir_name(board.identifier)
    _check_target_folder(folder, board.identifier, boards, force)
    reference_dir = _reference_folder(reference, folder, boards)
    baseline = root / "tests" / "baselines" / f"{reference_dir.name}.json"
    shown_as = str(baseline.relative_to(root))
    say(f"{board.identifier}: known to {zephyr_version(zephyr)} ({board.platform_file.name}), arch arm")
    small = _fit(board, baseline, shown_as, reference_dir.name, root, say)
    if small is not None:  # the port starts from the small part's folder (its stacks and heap)
        reference_dir = _reference_folder(small.part, folder, boards)
    _copy_folder(reference_dir, folder, board.identifier, root, say, None if board.emulated else REAL_TODOS)
    join = join_suite if small is None else join_small_suite
    if board.emulated:
        join(root, board, say)
        say("next: resolve the TODO(port) headers in "
            f"boards/{folder.name}/, then follow the checklist in docs/porting.md:")
        if small is None:  # a small part has no comparison: the fprime-small build's scenarios and link
            say(f"  scripts/kit compare --board {board.identifier}")
        say(f"  scripts/kit test --board {board.identifier} --update-baseline   (review and commit the baseline)")
        return folder
    builds = "every model" if small is None else small.described
    say(f"{board.identifier} is a real board (no emulator in {board.platform_file.name}): built ({builds}), not run")
    (folder / "kit.conf").write_text(with_todo("kit.conf", REAL_KIT_CONF.format(identifier=board.identifier),
                                               reference_dir.name, board.identifier, REAL_TODOS))
    say(f"created: {(folder / 'kit.conf').relative_to(root)} (a real board's: no QEMU icount)")
    hal, hals = hal_module(board, zephyr)
    fetch = ""
    if hal is None:
        say(f"hal: no hal_<family> or hal_<vendor> module for its SoC in {zephyr_version(zephyr)}'s manifest; "
            "CMSIS alone may do. If the build stops in devicetree (an include not found), add its module to "
            f"west.yml's name-allowlist and to boards/{folder.name}/hal, from: {', '.join(hals)}")
    else:
        (folder / "hal").write_text(HAL_FILE.format(name=hal.name, path=hal.path))
        say(f"created: {(folder / 'hal').relative_to(root)} ({hal.name} {hal.path})")
        west_yml = root / "west.yml"
        before = west_yml.read_text()
        after = allow_module(before, hal.name)
        if after != before:
            west_yml.write_text(after)
            fetch = "  scripts/setup.sh   (fetches it)"
        say(f"west.yml: {hal.name} {'allow-listed' if fetch else 'was allow-listed'} "
            f"({zephyr_version(zephyr)} pins {hal.revision[:12]})")
    overlay = folder / "app.overlay"
    uarts = link_uarts(board.platform_file)
    todo = ""
    if uarts:
        overlay.write_text(with_todo("app.overlay", REAL_OVERLAY.format(uart=uarts[0]), reference_dir.name,
                                     board.identifier, REAL_TODOS))
        say(f"created: {overlay.relative_to(root)} (ground link on {uarts[0]}, the first UART "
            f"the board enables besides its console; the others: {', '.join(uarts[1:]) or 'none'})")
    else:
        # The board enables its console alone: the reference's overlay would
        # name a UART this devicetree lacks (a devicetree error), so one of
        # the SoC's is enabled on the HAL's pins, or the porter is told
        spare, reason = spare_uart(board, zephyr, root / hal.path if hal is not None else None)
        if spare is not None:
            overlay.write_text(with_todo("app.overlay", SPARE_OVERLAY.format(
                uart=spare.label, tx=spare.tx, rx=spare.rx, tx_pin=spare.pin(spare.tx), rx_pin=spare.pin(spare.rx),
                pinctrl=spare.pinctrl), reference_dir.name, board.identifier, REAL_TODOS))
            say(f"created: {overlay.relative_to(root)} (the board enables no UART besides its console: ground "
                f"link on {spare.label}, enabled there on TX {spare.pin(spare.tx)} and RX {spare.pin(spare.rx)}, "
                f"pins from {spare.pinctrl}; wire a 3.3 V USB-serial adapter to them)")
        else:
            overlay.write_text(with_todo("app.overlay", NO_LINK_OVERLAY.format(reason=reason), reference_dir.name,
                                         board.identifier, REAL_TODOS))
            todo = (f"{TODO_MARK} no UART for the ground link: {reason}. Choose one in "
                    f"boards/{folder.name}/app.overlay (kit,link-uart, with its pins); until then the build stops "
                    "and says so")
            say(f"created: {overlay.relative_to(root)} (no ground link chosen)")
            say(todo)
    join(root, board, say)
    say("next: resolve the TODO(port) headers in "
        f"boards/{folder.name}/ (docs/porting.md, 'A real board'), then:")
    if fetch:
        say(fetch)
    if todo:
        say(f"  {todo}")
    say(f"  scripts/kit test --board {board.identifier}   (builds {builds}; nothing runs)")
    return folder
