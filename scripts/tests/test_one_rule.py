# SPDX-License-Identifier: Apache-2.0
"""One place per fact: the rules the builds apply in CMake and kittools
applies in Python agree. The CMake side is the rule (app/board_folder.cmake,
app/toolchain.cmake: every build runs it, and scripts/env.sh and
scripts/setup.sh apply what app/toolchain.cmake prints); kittools keeps a
copy of each (kittools/workspace.py: board_folder, environment), which these
tests hold to what CMake answers, run in its script mode. Also: a board's
priority and stack table is an override only where it differs from the
deployment's (app/Top/Tables.fpp)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from kittools import workspace

KIT_ROOT = Path(__file__).resolve().parents[2]
BOARD_RULE = KIT_ROOT / "app" / "board_folder.cmake"
TOOLCHAIN_RULE = KIT_ROOT / "app" / "toolchain.cmake"
#: What the toolchain rule sets when nothing is chosen
TOOLCHAIN_KEYS = ("ZEPHYR_TOOLCHAIN_VARIANT", "GNUARMEMB_TOOLCHAIN_PATH")


def _cmake() -> str:
    """The kit venv's CMake (beside this Python), else PATH's."""
    beside = Path(sys.executable).parent / "cmake"
    found = str(beside) if beside.is_file() else shutil.which("cmake")
    if found is None:
        pytest.skip("no cmake to run the CMake side of the rule")
    return found


# --- The board-folder rule ----------------------------------------------

def _cmake_board_folders(targets: list[str], boards: Path) -> dict[str, str | None]:
    result = subprocess.run([_cmake(), f"-DKIT_BOARD_TARGETS={';'.join(targets)}", f"-DKIT_BOARDS_DIR={boards}",
                             "-P", str(BOARD_RULE)], capture_output=True, text=True, check=True)
    answers = {}
    for line in result.stdout.splitlines():
        target, _, folder = line.partition(" ")
        answers[target] = folder or None
    return answers


def _python_board_folders(targets: list[str], boards: Path) -> dict[str, str | None]:
    folders = {target: workspace.board_folder(target, boards) for target in targets}
    return {target: folder.name if folder else None for target, folder in folders.items()}


#: Board targets of every shape: a board alone, with a qualifier (ported as
#: such or by its board's name), with two, and boards with no port
TARGETS = ["qemu_cortex_m3", "qemu_cortex_m3/ti_lm3s6965", "mps2/an385", "mps2/an521", "mps2/an521/cpu0",
           "nucleo_f401re", "nrf52840dk/nrf52840", "nrf5340dk/nrf5340/cpuapp", "stm32f4_disco", "unported/board"]


def test_cmake_and_kittools_find_the_same_board_folder_in_the_kit():
    boards = KIT_ROOT / "boards"
    targets = TARGETS + [workspace.board_dir_name(name) for name in workspace.ported_boards(boards)]
    cmake = _cmake_board_folders(targets, boards)
    assert cmake["mps2/an385"] == "mps2_an385" and cmake["qemu_cortex_m3/ti_lm3s6965"] == "qemu_cortex_m3"
    assert cmake == _python_board_folders(targets, boards)


def test_cmake_and_kittools_find_the_same_board_folder_where_both_names_are_ported(tmp_path):
    # A folder for one qualifier and one for the whole board: the full name wins
    for name in ("mps2", "mps2_an385", "nrf5340dk_nrf5340_cpuapp", "qemu_cortex_m3", "stm32f4_disco"):
        (tmp_path / name).mkdir()
    (tmp_path / "nrf52840dk").write_text("a file is no port\n")
    cmake = _cmake_board_folders(TARGETS, tmp_path)
    assert cmake["mps2/an385"] == "mps2_an385" and cmake["mps2/an521"] == "mps2"
    assert cmake["nrf52840dk/nrf52840"] is None and cmake["unported/board"] is None
    assert cmake == _python_board_folders(TARGETS, tmp_path)


# --- The toolchain choice -------------------------------------------------

def _fake_gcc(folder: Path) -> Path:
    """An arm-none-eabi-gcc in folder/bin (a script: nothing runs it)."""
    gcc = folder / "bin" / "arm-none-eabi-gcc"
    gcc.parent.mkdir(parents=True, exist_ok=True)
    gcc.write_text("#!/bin/sh\nexit 0\n")
    gcc.chmod(0o755)
    return gcc


def _environment(path: str, **chosen: str) -> dict[str, str]:
    env = {key: value for key, value in os.environ.items()
           if key not in ("ZEPHYR_TOOLCHAIN_VARIANT", "ZEPHYR_SDK_INSTALL_DIR", "GNUARMEMB_TOOLCHAIN_PATH")}
    env["PATH"] = path
    env.update(chosen)
    return env


def _cmake_choice(cmake: str, env: dict[str, str]) -> dict[str, str] | None:
    """What app/toolchain.cmake prints, as a dict; None when it finds no toolchain."""
    result = subprocess.run([cmake, "-P", str(TOOLCHAIN_RULE)], capture_output=True, text=True, env=env)
    if result.returncode != 0:
        assert "no ARM toolchain" in result.stderr
        return None
    return dict(line.split("=", 1) for line in result.stdout.splitlines() if line)


def _python_choice(env: dict[str, str], monkeypatch: pytest.MonkeyPatch) -> dict[str, str] | None:
    """What kittools' environment() adds of the toolchain's settings; None when it refuses."""
    monkeypatch.setattr(os, "environ", dict(env))
    try:
        made = workspace.environment()
    except workspace.KitError as error:
        assert "no ARM toolchain" in str(error)
        return None
    return {key: made[key] for key in TOOLCHAIN_KEYS if key in made and key not in env}


def _cases(tmp_path: Path) -> dict[str, dict[str, str]]:
    toolchain = tmp_path / "arm-gnu"
    gcc = _fake_gcc(toolchain)
    # A link to the compiler, as /usr/local/bin links can be: the root is the toolchain's
    links = tmp_path / "links"
    links.mkdir()
    (links / gcc.name).symlink_to(gcc)
    empty = tmp_path / "empty"
    empty.mkdir()
    return {
        "nothing chosen": _environment(f"{toolchain / 'bin'}{os.pathsep}{empty}"),
        "nothing chosen, a link on PATH": _environment(str(links)),
        "a Zephyr SDK": _environment(str(toolchain / "bin"), ZEPHYR_SDK_INSTALL_DIR=str(tmp_path / "sdk")),
        "a variant": _environment(str(toolchain / "bin"), ZEPHYR_TOOLCHAIN_VARIANT="zephyr"),
        "gnuarmemb by hand": _environment(str(empty), ZEPHYR_TOOLCHAIN_VARIANT="gnuarmemb",
                                          GNUARMEMB_TOOLCHAIN_PATH=str(tmp_path / "mine")),
        "no toolchain": _environment(str(empty)),
    }


def test_cmake_and_kittools_choose_the_same_toolchain(tmp_path, monkeypatch):
    cmake_command = _cmake()  # found before PATH becomes each case's
    toolchain = str((tmp_path / "arm-gnu").resolve())
    expected = {
        "nothing chosen": {"ZEPHYR_TOOLCHAIN_VARIANT": "gnuarmemb", "GNUARMEMB_TOOLCHAIN_PATH": toolchain},
        "nothing chosen, a link on PATH": {"ZEPHYR_TOOLCHAIN_VARIANT": "gnuarmemb",
                                           "GNUARMEMB_TOOLCHAIN_PATH": toolchain},
        "a Zephyr SDK": {},
        "a variant": {},
        "gnuarmemb by hand": {},
        "no toolchain": None,
    }
    for case, env in _cases(tmp_path).items():
        cmake = _cmake_choice(cmake_command, env)
        assert cmake == expected[case], f"app/toolchain.cmake, {case}"
        assert _python_choice(env, monkeypatch) == cmake, f"kittools/workspace.py disagrees with CMake: {case}"


def test_env_sh_exports_what_cmake_chose(tmp_path):
    if not (KIT_ROOT / ".venv" / "bin" / "cmake").is_file() or not (KIT_ROOT / ".venv" / "bin" / "west").is_file():
        pytest.skip("scripts/env.sh needs the provisioned venv (scripts/setup.sh)")
    toolchain = tmp_path / "arm-gnu"
    _fake_gcc(toolchain)
    env = _environment(f"{toolchain / 'bin'}{os.pathsep}/usr/bin{os.pathsep}/bin")
    show = '. scripts/env.sh && echo "$ZEPHYR_TOOLCHAIN_VARIANT $GNUARMEMB_TOOLCHAIN_PATH"'
    shown = subprocess.run(["bash", "-c", show], cwd=KIT_ROOT, env=env, capture_output=True, text=True,
                           check=True).stdout.split()
    assert shown == ["gnuarmemb", str(toolchain.resolve())]
    sdk = _environment(env["PATH"], ZEPHYR_SDK_INSTALL_DIR=str(tmp_path / "sdk"))
    shown = subprocess.run(["bash", "-c", '. scripts/env.sh && echo "[${ZEPHYR_TOOLCHAIN_VARIANT:-}]"'],
                           cwd=KIT_ROOT, env=sdk, capture_output=True, text=True, check=True).stdout.split()
    assert shown == ["[]"]  # Zephyr finds the SDK itself


# --- The priority and stack table ------------------------------------------

def test_a_boards_table_is_an_override_that_differs_from_the_deployments():
    # boards/<board>/Tables.fpp replaces app/Top/Tables.fpp for that board
    # (app/Top/CMakeLists.txt): a copy of it would be a second place for the
    # same fact, to drift apart unnoticed
    deployment = (KIT_ROOT / "app" / "Top" / "Tables.fpp").read_text()
    assert "module Priorities" in deployment and "module Stacks" in deployment

    def constants(text: str) -> list[str]:
        return [line.strip() for line in text.splitlines() if line.strip().startswith("constant ")]

    for table in (KIT_ROOT / "boards").glob("*/Tables.fpp"):
        assert constants(table.read_text()) != constants(deployment), (
            f"{table.relative_to(KIT_ROOT)} repeats app/Top/Tables.fpp: delete it (the deployment's table serves "
            "every board without an override)")
