# SPDX-License-Identifier: Apache-2.0
"""Where things are, and the checks every command makes before it starts."""

from __future__ import annotations

import contextlib
import fcntl
import os
import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path

KIT_ROOT = Path(__file__).resolve().parents[2]
DEPS = KIT_ROOT / "deps"
BOARDS = KIT_ROOT / "boards"
# The execution models: every folder with a Kconfig.model (app/Kconfig
# sources each one as an entry of its KIT_MODEL choice). The variants the
# commands take (a model, or a model under a policy) are kittools.variants'.
VARIANTS = tuple(sorted(path.parent.name for path in KIT_ROOT.glob("*/Kconfig.model")))
UPSTREAMS = ("zephyr", "fprime", "fprime-baremetal", "fprime-zephyr")


class KitError(RuntimeError):
    """A problem the user can fix; the message says how."""


def ported_boards(boards: Path | None = None) -> list[str]:
    boards = BOARDS if boards is None else boards
    return sorted(p.name for p in boards.iterdir() if p.is_dir()) if boards.is_dir() else []


def board_dir_name(target: str) -> str:
    """A board target as its kit folder is named: '/' becomes '_' (mps2/an385: mps2_an385)."""
    return target.replace("/", "_")


def board_folder(target: str, boards: Path | None = None) -> Path | None:
    """The kit folder of a board target: the target with '/' as '_', else a
    folder named after the board alone (it covers all its qualifiers). The
    full name wins, so one qualifier can have a port of its own."""
    boards = BOARDS if boards is None else boards  # looked up at call time: tests point it elsewhere
    for name in (board_dir_name(target), target.split("/", 1)[0]):
        if (boards / name).is_dir():
            return boards / name
    return None


def check_board(board: str, boards: Path | None = None) -> str:
    """The board's kit folder name; KitError if the kit has no port for it
    (app/kit.cmake applies the same rule)."""
    folder = board_folder(board, boards)
    if folder is None:
        raise KitError(
            f"board '{board}' has no kit port. Ported boards: {', '.join(ported_boards(boards))}. "
            "To bring the kit to a new board, see docs/porting.md (kit new-board scaffolds one)."
        )
    return folder.name


def west_topdir(root: Path | None = None) -> Path | None:
    """The west workspace the kit is in: the clone itself (scripts/setup.sh
    makes its .west/), or the workspace of a manifest that imports the kit;
    None outside any."""
    root = KIT_ROOT if root is None else root
    return next((folder for folder in (root, *root.parents) if (folder / ".west" / "config").is_file()), None)


def check_provisioned() -> None:
    missing = [name for name in UPSTREAMS if not (DEPS / name).is_dir()]
    if missing or west_topdir() is None:
        what = ", ".join(missing) if missing else ".west/config"
        raise KitError(f"the workspace is not provisioned (missing: {what}). Run scripts/setup.sh first.")


GDS_MISSING = "fprime-gds is not installed: run scripts/setup.sh (it installs the pinned fprime-gds)"


def check_gds_patched() -> None:
    """KitError unless the installed fprime-gds carries every patch the kit
    keeps for it (modules/fprime-gds/patches, applied by scripts/setup.sh):
    a ground station on an unfixed fprime-gds would stall file uplinks."""
    import importlib.metadata

    try:
        installed = Path(str(importlib.metadata.distribution("fprime-gds").locate_file("")))
    except importlib.metadata.PackageNotFoundError as error:
        raise KitError(GDS_MISSING) from error
    for patch in sorted((KIT_ROOT / "modules" / "fprime-gds" / "patches").glob("*.patch")):
        check = subprocess.run(["git", "-C", str(installed), "apply", "--reverse", "--check", str(patch)],
                               capture_output=True, check=False)
        if check.returncode != 0:
            raise KitError(f"fprime-gds in {installed} lacks the kit's patch {patch.name}: run scripts/setup.sh "
                           "(it applies the patches after installing fprime-gds)")


def uncommitted_changes(root: Path | None = None) -> list[str]:
    """The kit's tracked files with uncommitted changes (git status), empty
    for a committed tree or where git cannot tell."""
    root = KIT_ROOT if root is None else root
    done = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--untracked-files=no"],
                          capture_output=True, text=True, check=False)
    return [line[3:] for line in done.stdout.splitlines()] if done.returncode == 0 else []


def commit_label(root: Path | None = None) -> str:
    """The kit's commit as its image carries it (app/provenance.cmake): the
    short hash, with -dirty for uncommitted changes; "unknown" without git."""
    root = KIT_ROOT if root is None else root
    done = subprocess.run(["git", "-C", str(root), "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True,
                          check=False)
    label = done.stdout.strip() if done.returncode == 0 else "unknown"
    return f"{label}-dirty" if uncommitted_changes(root) else label


def check_committed(why: str, root: Path | None = None) -> None:
    """KitError if the kit's tree has uncommitted changes, saying `why` that matters."""
    changed = uncommitted_changes(root)
    if changed:
        shown = ", ".join(changed[:5]) + (f" and {len(changed) - 5} more" if len(changed) > 5 else "")
        raise KitError(f"uncommitted changes ({shown}): {why}. Commit them first.")


def environment() -> dict[str, str]:
    """Environment for west, twister and CMake: the kit's venv first, and
    Debian's arm-none-eabi GCC through Zephyr's gnuarmemb variant unless a
    toolchain (for example a Zephyr SDK) is already selected."""
    env = dict(os.environ)
    venv_bin = KIT_ROOT / ".venv" / "bin"
    env["PATH"] = f"{venv_bin}{os.pathsep}{env.get('PATH', '')}"
    env["VIRTUAL_ENV"] = str(KIT_ROOT / ".venv")
    env["ZEPHYR_BASE"] = str(DEPS / "zephyr")
    # ccache hits across build folders (every twister scenario has its own)
    # only when paths under the clone are hashed relative to it
    env.setdefault("CCACHE_BASEDIR", str(KIT_ROOT))
    env.setdefault("CCACHE_NOHASHDIR", "1")
    if "ZEPHYR_TOOLCHAIN_VARIANT" not in env and "ZEPHYR_SDK_INSTALL_DIR" not in env:
        gcc = shutil.which("arm-none-eabi-gcc", path=env["PATH"])
        if gcc is None:
            raise KitError(
                "no ARM toolchain: install Debian's gcc-arm-none-eabi (scripts/setup.sh does) "
                "or set ZEPHYR_SDK_INSTALL_DIR to use a Zephyr SDK"
            )
        env["ZEPHYR_TOOLCHAIN_VARIANT"] = "gnuarmemb"
        env["GNUARMEMB_TOOLCHAIN_PATH"] = str(Path(gcc).resolve().parent.parent)
    return env


@contextlib.contextmanager
def one_at_a_time(command: str) -> Iterator[None]:
    """Hold this tree's lock for `kit <command>` while it runs: two of them
    would share its build folders, the builds' QEMU consoles (FIFOs) and
    link sockets, and each would fail in the other's way. The lock is the
    kernel's (flock): it goes with the process, however it ends."""
    path = KIT_ROOT / "build" / f".kit-{command}.lock"
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("a+") as lock:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            lock.seek(0)
            holder = lock.read().strip() or "a process"
            raise KitError(f"another `kit {command}` is running in this tree ({holder}); the two would share its "
                           "build folders, QEMU consoles and link sockets: wait for it, or stop it") from None
        lock.seek(0)
        lock.truncate()
        lock.write(f"pid {os.getpid()}\n")
        lock.flush()
        yield
