# SPDX-License-Identifier: Apache-2.0
"""The build folder (kittools.build.folder): each reader on a fake build
folder, and what each says when the file it reads is missing."""

from __future__ import annotations

import json
import stat
from pathlib import Path

import pytest

from kittools.build import conditions
from kittools.build.folder import BuildFolder
from kittools.sizes import memory
from kittools.workspace import KitError

CONFIG = """# Automatically generated file; DO NOT EDIT.
CONFIG_BOARD="qemu_cortex_m3"
CONFIG_KIT_TICK_HZ=1000
# CONFIG_MULTITHREADING is not set
CONFIG_FPRIME=y
CONFIG_FPRIME_ASSERT_FILE_ID=y
CONFIG_FPRIME_OBJECT_NAMES=n
CONFIG_KIT_SCENARIO="nominal"
"""

CACHE = """# This is the CMakeCache file.
KIT_LINK_SOCKET:STRING=/tmp/kit.sock
QEMU_PIPE:INTERNAL=/tmp/qemu-fifo
EMPTY_ONE:STRING=
"""

CONSTANTS = """namespace FppConstant_FW_COM_BUFFER_MAX_SIZE {
  enum { FW_COM_BUFFER_MAX_SIZE = 128 };
}
enum { FW_ASSERT_COUNT_MAX = 10 };
"""


def _build(root: Path) -> Path:
    """A build folder as west build leaves it, with only what the kit reads."""
    (root / "zephyr").mkdir(parents=True)
    (root / "zephyr" / "zephyr.elf").write_bytes(b"\x7fELF")
    (root / "zephyr" / ".config").write_text(CONFIG)
    (root / "CMakeCache.txt").write_text(CACHE)
    (root / "compile_commands.json").write_text(json.dumps([
        {"command": "gcc -c zephyr/main.c"},
        {"command": "g++ -DFW_OBJECT_NAMES=0 -DFW_ENABLE_TEXT_LOGGING=0 -c app/Main.cpp"},
        {"command": "g++ -DFW_OBJECT_NAMES=1 -c app/Other.cpp"},  # the first with settings counts
    ]))
    header = root / "F-Prime" / "default" / "config" / "FppConstantsAc.hpp"
    header.parent.mkdir(parents=True)
    header.write_text(CONSTANTS)
    for part in ("zephyr", "other"):
        dictionary = root / "build-artifacts" / part / "dict" / "KitTopologyDictionary.json"
        dictionary.parent.mkdir(parents=True)
        dictionary.write_text("{}")
    (root / "handler.log").write_text("KIT END result=PASS\n")
    return root


def test_the_paths_are_the_builds(tmp_path: Path) -> None:
    folder = BuildFolder(tmp_path)
    assert folder.elf == tmp_path / "zephyr" / "zephyr.elf"
    assert folder.config == tmp_path / "zephyr" / ".config"
    assert folder.cmake_cache == tmp_path / "CMakeCache.txt"
    assert folder.compile_commands == tmp_path / "compile_commands.json"
    assert folder.fpp_constants == tmp_path / "F-Prime" / "default" / "config" / "FppConstantsAc.hpp"
    assert folder.console_log == tmp_path / "handler.log"


def test_kconfig_values_without_quotes_or_comments(tmp_path: Path) -> None:
    folder = BuildFolder(_build(tmp_path))
    values = folder.kconfig()
    assert values["CONFIG_BOARD"] == "qemu_cortex_m3"
    assert values["CONFIG_KIT_TICK_HZ"] == "1000"
    assert "CONFIG_MULTITHREADING" not in values  # "is not set" is a comment
    assert list(values) == ["CONFIG_BOARD", "CONFIG_KIT_TICK_HZ", "CONFIG_FPRIME", "CONFIG_FPRIME_ASSERT_FILE_ID",
                            "CONFIG_FPRIME_OBJECT_NAMES", "CONFIG_KIT_SCENARIO"]  # the file's order
    # the switches under modules/fprime's menu, not the menu's own CONFIG_FPRIME
    assert folder.fprime_switches() == {"CONFIG_FPRIME_ASSERT_FILE_ID": "y", "CONFIG_FPRIME_OBJECT_NAMES": "n"}


def test_kconfig_of_a_folder_never_configured(tmp_path: Path) -> None:
    folder = BuildFolder(tmp_path)
    with pytest.raises(FileNotFoundError):
        folder.kconfig()
    assert folder.kconfig(missing_ok=True) == {}


def test_cache_values_set_unset_and_no_cache(tmp_path: Path) -> None:
    folder = BuildFolder(tmp_path)
    assert not folder.configured()
    with pytest.raises(KitError, match=r"is not a configured build \(no CMakeCache.txt\)"):
        folder.cache_value("KIT_LINK_SOCKET")
    _build(tmp_path)
    assert folder.configured()
    assert folder.cache_value("KIT_LINK_SOCKET") == "/tmp/kit.sock"
    assert folder.cache_value("QEMU_PIPE") == "/tmp/qemu-fifo"
    assert folder.cache_value("EMPTY_ONE") is None
    assert folder.cache_value("NOT_THERE") is None


def test_the_dictionary_and_none(tmp_path: Path) -> None:
    with pytest.raises(KitError, match="has no F´ dictionary: build it first"):
        BuildFolder(tmp_path).dictionary()
    folder = BuildFolder(_build(tmp_path))
    assert folder.dictionary() == tmp_path / "build-artifacts" / "other" / "dict" / "KitTopologyDictionary.json"


def test_the_elf_and_none(tmp_path: Path) -> None:
    with pytest.raises(KitError, match="zephyr.elf is missing: build first"):
        BuildFolder(tmp_path).built_elf()
    assert BuildFolder(_build(tmp_path)).built_elf() == tmp_path / "zephyr" / "zephyr.elf"


def test_fprime_settings_from_the_compile_commands_and_constants(tmp_path: Path) -> None:
    assert BuildFolder(tmp_path).fprime_settings() == {}  # neither file: nothing, not an error
    folder = BuildFolder(_build(tmp_path))
    assert folder.fprime_settings() == {"FW_OBJECT_NAMES": "0", "FW_ENABLE_TEXT_LOGGING": "0",
                                        "FW_COM_BUFFER_MAX_SIZE": "128", "FW_ASSERT_COUNT_MAX": "10"}


def test_builds_found_under_a_twister_folder(tmp_path: Path) -> None:
    one = _build(tmp_path / "qemu_cortex_m3" / "tests" / "deployment" / "kit.rtos")
    (tmp_path / "qemu_cortex_m3" / "tests" / "deployment" / "kit.unbuilt" / "zephyr").mkdir(parents=True)
    assert [f.path for f in BuildFolder.built_under(tmp_path / "qemu_cortex_m3", "kit.rtos")] == [one]
    assert [f.path for f in BuildFolder.built_under(tmp_path)] == [one]


def test_conditions_read_from_the_folder(tmp_path: Path) -> None:
    _build(tmp_path)
    read = conditions.read(tmp_path)
    assert read["toolchain"] == "unknown"  # the cache names no compiler
    assert read["kconfig"] == {"CONFIG_BOARD": "qemu_cortex_m3", "CONFIG_KIT_TICK_HZ": "1000"}
    assert read["fprime"] == BuildFolder(tmp_path).fprime_settings()
    compiler = tmp_path / "g++"
    compiler.write_text("#!/bin/sh\necho 'arm-zephyr-eabi-g++ (Zephyr SDK) 12.2.0'\n")
    compiler.chmod(compiler.stat().st_mode | stat.S_IXUSR)
    (tmp_path / "CMakeCache.txt").write_text(CACHE + f"CMAKE_CXX_COMPILER:FILEPATH={compiler}\n")
    assert conditions.read(tmp_path)["toolchain"] == "arm-zephyr-eabi-g++ (Zephyr SDK) 12.2.0"


def test_conditions_and_memory_of_an_unbuilt_folder(tmp_path: Path) -> None:
    assert conditions.toolchain(BuildFolder(tmp_path)) == "unknown"
    with pytest.raises(FileNotFoundError):
        conditions.read(tmp_path)
    with pytest.raises(FileNotFoundError, match="zephyr.elf is missing: is .* a finished Zephyr build"):
        memory.measure(tmp_path)
    (tmp_path / "zephyr").mkdir()
    (tmp_path / "zephyr" / "zephyr.elf").write_bytes(b"")
    with pytest.raises(FileNotFoundError, match=r"\.config is missing: is .* a finished Zephyr build"):
        memory.measure(tmp_path)
