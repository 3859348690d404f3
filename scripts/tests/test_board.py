# SPDX-License-Identifier: Apache-2.0
"""kit new-board: a fake Zephyr board tree, a fake kit and fake baselines in tmp_path."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from kittools import boards, cli, metrics, model, workspace
from kittools.suite import platforms
from kittools.workspace import KitError

SUITE = """# the suite
common:
  platform_allow:
    - qemu_cortex_m3
    # a comment between items
    - "mps2/an521"   # quoted, with a comment
  integration_platforms:
    - qemu_cortex_m3
  tags: kit
tests:
  kit.one:
    platform_allow:
      - qemu_cortex_m3   # only here

  kit.two:
    platform_allow: qemu_cortex_m3 mps2/an521
    integration_platforms: [qemu_cortex_m3]  # flow style
    harness: console
"""

REFERENCE_FILES = {
    "kit.conf": "# reference kit.conf\nCONFIG_QEMU_ICOUNT=y\nCONFIG_QEMU_ICOUNT_SHIFT=4\n",
    "Kconfig.defconfig": "if KIT_MODEL_RTOS\nconfig MAIN_STACK_SIZE\n\tdefault 1536\nendif\n",
    "Tables.fpp": "module Kit {\n  module Priorities {\n    constant rg1kHz = 12\n  }\n"
                  "  module Stacks {\n    constant rg1kHz = 2048\n  }\n}\n",
    "app.overlay": "/ {\n  chosen {\n    zephyr,console = &uart0;\n  };\n};\n",
}

BOARDS_SUITE = """# Real boards, built and not run
common:
  platform_allow:
    - nucleo_other
  build_only: true
tests:
  board.baremetal: {}
"""

# The deployment as measured on the reference board (bytes): about 108 KiB of
# flash and 48 KiB of RAM at most, as on qemu_cortex_m3
FOOTPRINT = {"baremetal": (105046, 33216), "rtos": (110736, 48904)}


def _platform(zephyr: Path, folder: str, stem: str, text: str) -> Path:
    path = zephyr / "boards" / folder / f"{stem}.yaml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def _zephyr(tmp_path: Path, version: bool = True) -> Path:
    zephyr = tmp_path / "zephyr"
    _platform(zephyr, "qemu/cortex_m3", "qemu_cortex_m3",
              "identifier: qemu_cortex_m3\narch: arm\nram: 64\nflash: 256\nsimulation: qemu\n")
    _platform(zephyr, "qemu/cortex_m0", "qemu_cortex_m0",
              "identifier: qemu_cortex_m0\narch: arm\nram: 16\nflash: 256\n"
              "simulation: qemu\n")
    _platform(zephyr, "qemu/x86", "qemu_x86", "identifier: qemu_x86\narch: x86\nram: 1024\nflash: 1024\n")
    (zephyr / "boards" / "qemu" / "x86" / "board.yml").write_text("board:\n  name: qemu_x86\n")
    mps2 = _platform(zephyr, "arm/mps2", "mps2_an385",
                     "identifier: mps2/an385\narch: arm\nsimulation:\n  - name: qemu\n").parent
    (mps2 / "mps2_an385.dts").write_text(
        '#include <arm/armv7-m.dtsi>\n#include "mps2_mem.dtsi"\n/ {\n chosen {\n  zephyr,sram = &sram0;\n'
        "  zephyr,flash = &flash0;\n };\n};\n")
    (mps2 / "mps2_mem.dtsi").write_text(
        '/ {\n sram0: memory@20000000 {\n  compatible = "mmio-sram";\n  reg = <0x20000000 0x400000>;\n };\n'
        " flash0: flash@0 {\n  partitions {\n   slot0: partition@0 {\n    reg = <0x0 0x8000>;\n   };\n  };\n"
        "  reg = <0 0x200000>;\n };\n};\n")
    _platform(zephyr, "arm/mps2", "mps2_an521_cpu0", "identifier: mps2/an521/cpu0\narch: arm\nram: 4096\n"
              "simulation: qemu\n"
              "flash: 4096\n")
    _platform(zephyr, "arm/mps2", "mps2_an521_cpu1", "identifier: mps2/an521/cpu1\narch: arm\nram: 4096\n"
              "simulation: qemu\n"
              "flash: 4096\n")
    _platform(zephyr, "nxp/frdm_k64f", "frdm_k64f", "identifier: frdm_k64f/mk64f12\narch: arm\nram: 192\n"
              "flash: 1024\n")
    nucleo = _platform(zephyr, "st/nucleo", "nucleo_small", "identifier: nucleo_small\narch: arm\n").parent
    (nucleo / "nucleo_small.dts").write_text(
        "/ {\n chosen {\n  zephyr,sram = &sram0;\n  zephyr,flash = &flash0;\n };\n"
        " sram0: memory@20000000 {\n  reg = <0x20000000 DT_SIZE_K(20)>;\n };\n};\n"
        "&flash0 {\n reg = <0x08000000 DT_SIZE_K(64)>;\n};\n")
    _platform(zephyr, "vendor/mystery", "mystery", "identifier: mystery\narch: arm\n")
    if version:
        (zephyr / "VERSION").write_text("VERSION_MAJOR = 4\nVERSION_MINOR = 0\nPATCHLEVEL = 0\nVERSION_TWEAK = 0\n")
    return zephyr


def _results(footprint: dict[str, tuple[int, int]]) -> dict:
    """A minimal results file (docs/results.md) holding just a footprint."""
    return {"schema_version": metrics.SCHEMA_VERSION, "conditions": {},
            "variants": {v: {"metrics": {model.ROM.key: rom, model.RAM.key: ram}, "records": []}
                         for v, (rom, ram) in footprint.items()}}


def _kit(tmp_path: Path, footprint: dict[str, tuple[int, int]] = FOOTPRINT) -> Path:
    root = tmp_path / "kit"
    reference = root / "boards" / "qemu_cortex_m3"
    reference.mkdir(parents=True)
    for name, text in REFERENCE_FILES.items():
        (reference / name).write_text(text)
    (root / "tests" / "baselines").mkdir(parents=True)
    (root / "tests" / "baselines" / "qemu_cortex_m3.json").write_text(json.dumps(_results(footprint)))
    (root / "tests" / "deployment").mkdir()
    (root / "tests" / "deployment" / "testcase.yaml").write_text(SUITE)
    (root / "tests" / "host").mkdir()  # a test folder without a twister file
    (root / "app").mkdir()
    (root / "app" / "sample.yaml").write_text("sample:\n  name: kit\ncommon:\n  platform_allow:\n"
                                              "    - qemu_cortex_m3\n")
    # The real boards' list, as the kit has one: platforms.is_real_board reads it
    (root / "tests" / "boards").mkdir()
    (root / "tests" / "boards" / "testcase.yaml").write_text(BOARDS_SUITE)
    (root / "tests" / "floor" / "paths").mkdir(parents=True)
    (root / "tests" / "floor" / "paths" / "testcase.yaml").write_text(
        "common:\n  platform_allow:\n    - qemu_cortex_m3\ntests:\n  floor.paths: {}\n")
    return root


def _quiet(_message: str) -> None:
    pass


# --- Zephyr knows the board ------------------------------------------------

def test_unknown_board_is_refused_with_close_matches(tmp_path):
    with pytest.raises(KitError) as error:
        boards.find_board("qemu_cortex_m4", _zephyr(tmp_path))
    message = str(error.value)
    assert message.startswith("Zephyr 4.0.0 has no board 'qemu_cortex_m4'. Close matches: ")
    assert "qemu_cortex_m3" in message and "qemu_cortex_m0" in message and "west boards" in message


def test_without_a_version_file_the_message_names_the_pinned_zephyr(tmp_path):
    with pytest.raises(KitError, match="^the pinned Zephyr has no board 'zzz'"):
        boards.find_board("zzz", _zephyr(tmp_path, version=False))


def test_a_board_name_stands_for_its_only_target_and_not_for_several(tmp_path):
    zephyr = _zephyr(tmp_path)
    assert boards.find_board("frdm_k64f", zephyr).identifier == "frdm_k64f/mk64f12"
    assert boards.find_board("mps2/an385", zephyr).identifier == "mps2/an385"
    # mps2/an521 is two targets (cpu0, cpu1): neither is guessed
    with pytest.raises(KitError, match="'mps2/an521' is several boards .*: mps2/an521/cpu0, mps2/an521/cpu1"):
        boards.find_board("mps2/an521", zephyr)
    with pytest.raises(KitError, match="'mps2' is several boards"):
        boards.find_board("mps2", zephyr)


def test_a_missing_zephyr_says_to_run_setup(tmp_path):
    with pytest.raises(KitError, match="scripts/setup.sh"):
        boards.find_board("qemu_cortex_m3", tmp_path / "nothing")


def test_a_board_of_another_architecture_is_refused(tmp_path):
    root = _kit(tmp_path)
    with pytest.raises(KitError, match="qemu_x86 is a 'x86' board .* the kit is ARM only: .*arm-none-eabi"):
        boards.new_board("qemu_x86", root=root, zephyr=_zephyr(tmp_path), say=_quiet)
    assert not (root / "boards" / "qemu_x86").exists()


# --- memory -----------------------------------------------------------------

def test_memory_comes_from_the_platform_file(tmp_path):
    m3 = boards.find_board("qemu_cortex_m3", _zephyr(tmp_path))
    assert (m3.ram_kib, m3.flash_kib, m3.arch) == (64, 256, "arm")


def test_memory_comes_from_the_devicetree_and_its_includes(tmp_path):
    an385 = boards.find_board("mps2/an385", _zephyr(tmp_path))
    # sram0 in the included .dtsi; flash0's own reg, not its partition's
    assert (an385.ram_kib, an385.flash_kib) == (4096, 2048)


def test_devicetree_sizes_in_dt_size_k_and_label_overrides(tmp_path):
    nucleo = boards.find_board("nucleo_small", _zephyr(tmp_path))
    assert (nucleo.ram_kib, nucleo.flash_kib) == (20, 64)


def test_unknown_memory_says_how_to_find_out(tmp_path):
    mystery = boards.find_board("mystery", _zephyr(tmp_path))
    assert (mystery.ram_kib, mystery.flash_kib) == (None, None)
    with pytest.raises(KitError, match="fit cannot be checked.*'Memory region' lines"):
        boards.new_board("mystery", root=_kit(tmp_path), zephyr=_zephyr(tmp_path), say=_quiet)


def test_a_board_too_small_is_refused_with_the_numbers(tmp_path):
    root = _kit(tmp_path)
    with pytest.raises(KitError) as error:
        boards.new_board("qemu_cortex_m0", root=root, zephyr=_zephyr(tmp_path), say=_quiet)
    message = str(error.value)
    assert "qemu_cortex_m0 cannot hold the deployment as measured in tests/baselines/qemu_cortex_m3.json" in message
    # The smallest model's need, named: if it does not fit, none does
    assert "RAM: the smallest model, baremetal, needs 32.4 KiB, the board has 16 KiB" in message
    assert "model, rtos" not in message  # only the smallest model's need (the levers may name rtos's knobs)
    assert "flash:" not in message  # 256 KiB of flash is enough
    assert "'Memory budget'" in message and "MALLOC_ARENA_SIZE" in message
    assert not (root / "boards" / "qemu_cortex_m0").exists()


def test_flash_that_is_short_is_named_with_its_levers(tmp_path):
    root = _kit(tmp_path, {"baremetal": (300_000, 1000), "rtos": (280_000, 1000)})
    m0 = boards.find_board("qemu_cortex_m0", _zephyr(tmp_path))
    with pytest.raises(KitError) as error:
        boards.check_fit(m0, root / "tests" / "baselines" / "qemu_cortex_m3.json")
    message = str(error.value)
    assert "flash: the smallest model, rtos, needs 273.4 KiB, the board has 256 KiB" in message
    assert "baremetal" not in message
    assert "app/config/" in message and "MALLOC_ARENA_SIZE" not in message


def test_the_fit_is_the_smallest_models_and_a_larger_one_short_is_said(tmp_path):
    # As on the kit's baselines: the passive policy is the smallest variant,
    # rtos the largest; a board holding the first and not the second is
    # taken (the old check, of every model, refused it)
    footprint = {"baremetal": (150_143, 45_900), "baremetal_budgeted": (151_123, 46_140),
                 "baremetal_passive": (143_767, 44_452), "rtos": (155_604, 63_172)}
    root = _kit(tmp_path, footprint)
    zephyr = _zephyr(tmp_path)
    _platform(zephyr, "qemu/mid", "qemu_mid", "identifier: qemu_mid\narch: arm\nram: 48\nflash: 256\n"
              "simulation: qemu\n")
    lines = boards.check_fit(boards.find_board("qemu_mid", zephyr),
                              root / "tests" / "baselines" / "qemu_cortex_m3.json")
    assert lines[0] == ("baremetal_passive (the smallest): flash 140.4 of 256 KiB (115.6 KiB spare), "
                        "RAM 43.4 of 48 KiB (4.6 KiB spare)")
    assert "rtos does not fit: 13.7 KiB of RAM short; its build fails until the deployment shrinks" \
        in "\n".join(lines)
    said: list[str] = []
    boards.new_board("qemu_mid", root=root, zephyr=zephyr, say=said.append)
    assert "the board checked against its smallest model, baremetal_passive" in "\n".join(said)


# --- the scaffold -----------------------------------------------------------

def test_the_scaffold_copies_the_reference_with_todo_headers(tmp_path):
    root = _kit(tmp_path)
    said: list[str] = []
    folder = boards.new_board("mps2/an385", root=root, zephyr=_zephyr(tmp_path), say=said.append)
    assert folder == root / "boards" / "mps2_an385"
    assert sorted(p.name for p in folder.iterdir()) == sorted(REFERENCE_FILES)
    for name, original in REFERENCE_FILES.items():
        text = (folder / name).read_text()
        assert text.endswith(original)  # the reference's content, unchanged, under the header
        header = text[:-len(original)]
        assert "copied from boards/qemu_cortex_m3/ for mps2/an385" in header
        if name.endswith(".overlay"):
            assert header.startswith("/*\n * TODO(port): ") and header.endswith(" */\n")
        else:
            assert all(line.startswith("# TODO(port): ") for line in header.splitlines())
    assert "CONFIG_QEMU_ICOUNT_SHIFT" in (folder / "kit.conf").read_text().split("CONFIG_QEMU_ICOUNT=y")[0]
    assert "console" in (folder / "kit.conf").read_text() and "1 kHz" in (folder / "kit.conf").read_text()
    assert "KIT STACK" in (folder / "Kconfig.defconfig").read_text()
    assert "rtos/ThreadStacks.cpp" in (folder / "Tables.fpp").read_text()
    output = "\n".join(said)
    assert "created: boards/mps2_an385/kit.conf" in output
    assert "memory: rtos: flash 108.1 of 2048 KiB" in output and "RAM 47.8 of 4096 KiB" in output
    assert "ROM can differ a few %" in output
    assert "twister: added mps2/an385 to the platform lists of tests/deployment/testcase.yaml" in output
    assert "twister: added mps2/an385 to the platform lists of app/sample.yaml" in output
    assert "scripts/kit compare --board mps2/an385" in output and "scripts/kit test --board mps2/an385" in output
    assert "docs/porting.md" in output


def test_the_scaffold_refuses_to_overwrite_a_port_unless_forced(tmp_path):
    root = _kit(tmp_path)
    zephyr = _zephyr(tmp_path)
    folder = boards.new_board("mps2/an385", root=root, zephyr=zephyr, say=_quiet)
    (folder / "kit.conf").write_text("CONFIG_QEMU_ICOUNT_SHIFT=5\n")
    with pytest.raises(KitError, match="boards/mps2_an385 exists already.*--force"):
        boards.new_board("mps2/an385", root=root, zephyr=zephyr, say=_quiet)
    assert (folder / "kit.conf").read_text() == "CONFIG_QEMU_ICOUNT_SHIFT=5\n"
    boards.new_board("mps2/an385", root=root, zephyr=zephyr, force=True, say=_quiet)
    assert "CONFIG_QEMU_ICOUNT_SHIFT=4" in (folder / "kit.conf").read_text()
    suite = (root / "tests" / "deployment" / "testcase.yaml").read_text()
    # its three platform_allow lists (the deployment suite adds no integration
    # platform: boards/suites.py exclude_from_scenarios); the second run added nothing
    assert suite.count("mps2/an385") == 3


def test_scaffolding_from_an_unresolved_port_does_not_stack_headers(tmp_path):
    root = _kit(tmp_path)
    zephyr = _zephyr(tmp_path)
    boards.new_board("mps2/an385", root=root, zephyr=zephyr, say=_quiet)
    (root / "tests" / "baselines" / "mps2_an385.json").write_text(json.dumps(_results(FOOTPRINT)))
    _platform(zephyr, "big", "big_board", "identifier: big_board\narch: arm\nram: 512\nflash: 2048\nsimulation: qemu\n")
    folder = boards.new_board("big_board", "mps2/an385", root=root, zephyr=zephyr, say=_quiet)
    for name in ("kit.conf", "app.overlay"):
        text = (folder / name).read_text()
        assert text.count("TODO(port): copied from") == 1 and "copied from boards/mps2_an385/ for big_board" in text


def test_a_port_covering_the_board_or_a_missing_reference_is_refused(tmp_path):
    root = _kit(tmp_path)
    zephyr = _zephyr(tmp_path)
    (root / "boards" / "mps2").mkdir()  # covers every mps2 target
    with pytest.raises(KitError, match="boards/mps2 already covers mps2/an385"):
        boards.new_board("mps2/an385", root=root, zephyr=zephyr, say=_quiet)
    with pytest.raises(KitError, match="reference board 'nrf52840dk' has no kit port. Ported boards: mps2, "
                                       "qemu_cortex_m3"):
        boards.new_board("qemu_cortex_m3", "nrf52840dk", root=root, zephyr=zephyr, force=True, say=_quiet)
    with pytest.raises(KitError, match="the reference itself"):
        boards.new_board("qemu_cortex_m3", root=root, zephyr=zephyr, force=True, say=_quiet)


def test_the_cli_scaffolds_with_from(tmp_path, monkeypatch, capsys):
    root = _kit(tmp_path)
    monkeypatch.setattr(workspace, "KIT_ROOT", root)
    monkeypatch.setattr(workspace, "DEPS", tmp_path)  # tmp_path/zephyr
    _zephyr(tmp_path)
    assert cli.main(["new-board", "mps2/an385", "--from", "qemu_cortex_m3"]) == 0
    assert "[kit] created: boards/mps2_an385/Tables.fpp" in capsys.readouterr().out
    assert cli.main(["new-board", "mps2/an385"]) == 2
    assert "exists already" in capsys.readouterr().err


# --- twister lists ----------------------------------------------------------

def test_twister_lists_gain_the_board_once_and_keep_their_comments():
    once = boards.add_to_twister_lists(SUITE, "mps2/an385")
    assert once == SUITE.replace(
        '    - "mps2/an521"   # quoted, with a comment\n',
        '    - "mps2/an521"   # quoted, with a comment\n    - mps2/an385\n').replace(
        "  integration_platforms:\n    - qemu_cortex_m3\n",
        "  integration_platforms:\n    - qemu_cortex_m3\n    - mps2/an385\n").replace(
        "      - qemu_cortex_m3   # only here\n",
        "      - qemu_cortex_m3   # only here\n      - mps2/an385\n").replace(
        "platform_allow: qemu_cortex_m3 mps2/an521\n",
        "platform_allow: qemu_cortex_m3 mps2/an521 mps2/an385\n").replace(
        "[qemu_cortex_m3]  # flow style", "[qemu_cortex_m3, mps2/an385]  # flow style")
    assert boards.add_to_twister_lists(once, "mps2/an385") == once


def test_twister_lists_that_name_the_board_already_are_skipped():
    # quoted and commented items count; the other lists still gain it
    assert boards.add_to_twister_lists(SUITE, "mps2/an521") == SUITE.replace(
        "  integration_platforms:\n    - qemu_cortex_m3\n",
        "  integration_platforms:\n    - qemu_cortex_m3\n    - mps2/an521\n").replace(
        "      - qemu_cortex_m3   # only here\n",
        "      - qemu_cortex_m3   # only here\n      - mps2/an521\n").replace(
        "[qemu_cortex_m3]  # flow style", "[qemu_cortex_m3, mps2/an521]  # flow style")


def test_a_list_at_the_end_of_the_file_gains_a_line():
    assert boards.add_to_twister_lists("common:\n  platform_allow:\n  - a", "b") == \
        "common:\n  platform_allow:\n  - a\n  - b\n"


def test_the_twister_files_are_every_suites_and_the_samples(tmp_path):
    root = _kit(tmp_path)
    (root / "tests" / "other").mkdir()
    (root / "tests" / "other" / "testcase.yaml").write_text("tests:\n  x:\n    platform_allow:\n      - a\n")
    names = [str(p.relative_to(root)) for p in boards.twister_files(root)]
    assert names == ["tests/boards/testcase.yaml", "tests/deployment/testcase.yaml", "tests/other/testcase.yaml",
                     "tests/floor/paths/testcase.yaml", "app/sample.yaml"]
    # The one rule: a QEMU board every suite but the real boards' list, a real board that list alone
    qemu = [str(p.relative_to(root)) for p in boards.suite_files(root, emulated=True)]
    assert qemu == names[1:]
    assert boards.suite_files(root, emulated=False) == [root / "tests" / "boards" / "testcase.yaml"]


def test_a_qemu_board_joins_the_qemu_suites_and_not_the_real_boards_list(tmp_path, monkeypatch):
    root = _kit(tmp_path)
    said: list[str] = []
    boards.new_board("mps2/an385", root=root, zephyr=_zephyr(tmp_path), say=said.append)
    for suite in ("tests/deployment/testcase.yaml", "tests/floor/paths/testcase.yaml", "app/sample.yaml"):
        assert "- mps2/an385" in (root / suite).read_text(), suite
    assert (root / "tests" / "boards" / "testcase.yaml").read_text() == BOARDS_SUITE
    assert not any("tests/boards" in line for line in said)
    # ... so that the next step it prints, kit compare on it, is not refused as a real board's
    (root / "boards" / "nucleo_other").mkdir()  # the listed real board's port
    monkeypatch.setattr(workspace, "BOARDS", root / "boards")
    monkeypatch.setattr(platforms, "BUILD_ONLY_SUITE", root / "tests" / "boards" / "testcase.yaml")
    assert not platforms.is_real_board("mps2/an385") and platforms.is_real_board("nucleo_other")
    platforms.check_runs_here("mps2/an385")


# --- the kit's own lookup of a board folder ---------------------------------

def test_board_folders_are_found_by_full_target_then_board_name(tmp_path):
    for name in ("mps2", "mps2_an385", "qemu_cortex_m3"):
        (tmp_path / name).mkdir()
    assert workspace.board_dir_name("mps2/an385") == "mps2_an385"
    assert workspace.check_board("qemu_cortex_m3", tmp_path) == "qemu_cortex_m3"
    assert workspace.check_board("qemu_cortex_m3/ti_lm3s6965", tmp_path) == "qemu_cortex_m3"
    assert workspace.check_board("mps2/an385", tmp_path) == "mps2_an385"  # its own folder wins
    assert workspace.check_board("mps2/an521/cpu0", tmp_path) == "mps2"  # the board's folder covers it
    with pytest.raises(KitError) as error:
        workspace.check_board("nucleo_f429zi/stm32f429xx", tmp_path)
    message = str(error.value)
    assert "'nucleo_f429zi/stm32f429xx' has no kit port" in message
    assert "Ported boards: mps2, mps2_an385, qemu_cortex_m3" in message and "docs/porting.md" in message


@pytest.mark.skipif(not (workspace.DEPS / "zephyr" / "boards").is_dir(), reason="workspace not provisioned")
def test_the_pinned_zephyr_knows_both_ported_boards():
    m3 = boards.find_board("qemu_cortex_m3")
    assert (m3.identifier, m3.arch, m3.ram_kib, m3.flash_kib) == ("qemu_cortex_m3", "arm", 64, 256)
    an385 = boards.find_board("mps2/an385")
    assert (an385.arch, an385.ram_kib, an385.flash_kib) == ("arm", 4096, 4096)  # from its devicetree


# --- A real board: its HAL, its UARTs, built and not run ----------------------

WEST_YML = """manifest:
  projects:
    - name: zephyr
      import:
        path-prefix: deps
        name-allowlist:
          - cmsis   # every Cortex-M
    - name: fprime
"""


def _real_board(tmp_path: Path) -> tuple[Path, Path]:
    zephyr = _zephyr(tmp_path)
    folder = _platform(zephyr, "st/nucleo_f401re", "nucleo_f401re",
                       "identifier: nucleo_f401re\narch: arm\nram: 96\nflash: 512\n").parent
    (folder / "board.yml").write_text("board:\n  name: nucleo_f401re\n  vendor: st\n  socs:\n"
                                      "    - name: stm32f401xe\n")
    (folder / "nucleo_f401re.dts").write_text(
        "/ {\n chosen {\n  zephyr,console = &usart2;\n };\n};\n"
        '&usart1 {\n current-speed = <115200>;\n status = "okay";\n};\n'
        '&usart2 {\n status = "okay";\n};\n&usart6 {\n status = "disabled";\n};\n')
    soc = zephyr / "soc" / "st" / "stm32"
    soc.mkdir(parents=True)
    (soc / "soc.yml").write_text("family:\n  - name: stm32\n    series:\n      - name: stm32f4x\n"
                                 "        socs:\n          - name: stm32f401xe\n")
    (zephyr / "west.yml").write_text("manifest:\n  projects:\n    - name: cmsis\n      revision: abc\n"
                                     "      path: modules/hal/cmsis\n    - name: hal_stm32\n"
                                     "      revision: 019d8255333f96bdd47d26b44049bd3e7af8ef55\n"
                                     "      path: modules/hal/stm32\n    - name: hal_nordic\n      revision: x\n")
    root = _kit(tmp_path)
    (root / "west.yml").write_text(WEST_YML)
    return root, zephyr


def test_a_real_board_gets_its_hal_its_link_uart_and_joins_the_builds_only(tmp_path):
    root, zephyr = _real_board(tmp_path)
    said: list[str] = []
    folder = boards.new_board("nucleo_f401re", root=root, zephyr=zephyr, say=said.append)
    assert (folder / "hal").read_text().splitlines()[-1] == "hal_stm32 deps/modules/hal/stm32"
    west = (root / "west.yml").read_text()
    assert "          - cmsis   # every Cortex-M\n          - hal_stm32\n    - name: fprime" in west
    assert "CONFIG_QEMU_ICOUNT" not in (folder / "kit.conf").read_text()
    assert "kit,link-uart = &usart1;" in (folder / "app.overlay").read_text()  # not the console, not disabled
    assert "nucleo_f401re" in (root / "tests" / "boards" / "testcase.yaml").read_text()
    assert "nucleo_f401re" not in (root / "tests" / "deployment" / "testcase.yaml").read_text()
    assert "nucleo_f401re" not in (root / "app" / "sample.yaml").read_text()
    assert any("scripts/setup.sh" in line for line in said)
    # Once allow-listed, the manifest is left as it is
    assert boards.allow_module(west, "hal_stm32") == west


def test_a_real_boards_hal_is_named_from_the_socs_folder(tmp_path):
    _, zephyr = _real_board(tmp_path)
    found, hals = boards.hal_module(boards.find_board("nucleo_f401re", zephyr), zephyr)
    assert found == boards.HalModule("hal_stm32", "deps/modules/hal/stm32",
                                      "019d8255333f96bdd47d26b44049bd3e7af8ef55")
    assert hals == ["hal_nordic", "hal_stm32"]
    assert boards.find_board("nucleo_f401re", zephyr).emulated is False
    assert boards.find_board("mps2/an385", zephyr).emulated is True


# --- A real board that enables its console alone: a UART of its SoC, on the HAL's pins

SOC_DTSI = """#include <arm/armv7-m.dtsi>
/ {
 soc {
  usart2: serial@40004400 {
   compatible = "st,stm32-usart", "st,stm32-uart";
   status = "disabled";
  };
  uart4: serial@40004c00 {
   compatible = "st,stm32-uart";
   status = "disabled";
  };
  usart1: serial@40013800 {
   compatible = "st,stm32-usart", "st,stm32-uart";
   status = "disabled";
  };
  spi3: spi@40003c00 {
   compatible = "st,stm32-spi";
   status = "disabled";
  };
 };
};
"""

PINCTRL_DTSI = """#include <zephyr/dt-bindings/pinctrl/stm32-pinctrl.h>
/ {
 soc {
  pinctrl: pin-controller@40020000 {
   /omit-if-no-ref/ usart1_rx_pa10: usart1_rx_pa10 {
    pinmux = <STM32_PINMUX('A', 10, AF7)>;
   };
   /omit-if-no-ref/ usart1_rx_pb7: usart1_rx_pb7 {
    pinmux = <STM32_PINMUX('B', 7, AF7)>;
   };
   /omit-if-no-ref/ uart4_rx_pc11: uart4_rx_pc11 {
    pinmux = <STM32_PINMUX('C', 11, AF8)>;
   };
   /omit-if-no-ref/ usart1_tx_pa9: usart1_tx_pa9 {
    pinmux = <STM32_PINMUX('A', 9, AF7)>;
   };
   /omit-if-no-ref/ usart1_tx_pb6: usart1_tx_pb6 {
    pinmux = <STM32_PINMUX('B', 6, AF7)>;
   };
   /omit-if-no-ref/ uart4_tx_pc10: uart4_tx_pc10 {
    pinmux = <STM32_PINMUX('C', 10, AF8)>;
   };
  };
 };
};
"""

# As nucleo_l152re's: the console alone among the UARTs; a button on PA9
# (so usart1's TX goes to PB6), a connector map naming every header pin
# (not a use)
CONSOLE_ONLY_DTS = """/dts-v1/;
#include <st/l1/stm32l152Xe.dtsi>
#include <st/l1/stm32l152retx-pinctrl.dtsi>
#include "arduino_r3_connector.dtsi"
/ {
 chosen {
  zephyr,console = &usart2;
 };
 gpio_keys {
  user_button: button {
   gpios = <&gpioa 9 GPIO_ACTIVE_LOW>;
  };
 };
};
&usart2 {
 pinctrl-0 = <&usart2_tx_pa2 &usart2_rx_pa3>;
 current-speed = <115200>;
 status = "okay";
};
&spi3 {
 pinctrl-0 = <&spi3_sck_pc10 &spi3_miso_pc11>;
 status = "okay";
};
"""


def _console_only_board(tmp_path: Path, pinctrl: bool = True) -> tuple[Path, Path]:
    root, zephyr = _real_board(tmp_path)
    folder = _platform(zephyr, "st/nucleo_l1x", "nucleo_l1x",
                       "identifier: nucleo_l1x\narch: arm\nram: 80\nflash: 512\n").parent
    (folder / "board.yml").write_text("board:\n  name: nucleo_l1x\n  vendor: st\n  socs:\n    - name: stm32l152xe\n")
    (folder / "nucleo_l1x.dts").write_text(CONSOLE_ONLY_DTS)
    (folder / "arduino_r3_connector.dtsi").write_text(
        "/ {\n arduino_header: connector {\n  gpio-map = <0 0 &gpioa 9 0>, <1 0 &gpioa 10 0>;\n };\n};\n")
    (zephyr / "soc" / "st" / "stm32" / "soc.yml").write_text(
        "family:\n  - name: stm32\n    series:\n      - name: stm32f4x\n        socs:\n          - name: stm32f401xe\n"
        "      - name: stm32l1x\n        socs:\n          - name: stm32l152xe\n")
    soc = zephyr / "dts" / "arm" / "st" / "l1"
    soc.mkdir(parents=True)
    (soc / "stm32l152Xe.dtsi").write_text('#include <st/l1/stm32l1.dtsi>\n')
    (soc / "stm32l1.dtsi").write_text(SOC_DTSI)
    if pinctrl:  # the HAL's, where the workspace lands it
        hal = root / "deps" / "modules" / "hal" / "stm32" / "dts" / "st" / "l1"
        hal.mkdir(parents=True)
        (hal / "stm32l152retx-pinctrl.dtsi").write_text(PINCTRL_DTSI)
    return root, zephyr


def test_a_spare_uart_is_a_disabled_one_of_the_soc_on_free_pins_of_the_hals_pinctrl_file(tmp_path):
    root, zephyr = _console_only_board(tmp_path)
    found = boards.find_board("nucleo_l1x", zephyr)
    assert boards.link_uarts(found.platform_file) == []  # the console alone
    spare, reason = boards.spare_uart(found, zephyr, root / "deps" / "modules" / "hal" / "stm32")
    # usart1 before uart4 (whose pins the board's SPI takes anyway); its TX
    # not on PA9 (the button's), the connector's map being no use of PA10
    assert spare == boards.SpareUart("usart1", "usart1_tx_pb6", "usart1_rx_pa10", "st/l1/stm32l152retx-pinctrl.dtsi")
    assert reason == "" and (spare.pin(spare.tx), spare.pin(spare.rx)) == ("PB6", "PA10")


def test_a_console_only_real_board_gets_a_uart_of_its_soc_written_into_its_overlay(tmp_path):
    root, zephyr = _console_only_board(tmp_path)
    said: list[str] = []
    folder = boards.new_board("nucleo_l1x", root=root, zephyr=zephyr, say=said.append)
    overlay = (folder / "app.overlay").read_text()
    assert "uart1;" not in overlay.replace("usart1;", "")  # not the QEMU reference's &uart1
    assert "kit,link-uart = &usart1;" in overlay
    assert ("&usart1 {\n\tpinctrl-0 = <&usart1_tx_pb6 &usart1_rx_pa10>;\n\tpinctrl-names = \"default\";\n"
            "\tcurrent-speed = <115200>;\n\tstatus = \"okay\";\n};\n") in overlay
    assert "TX PB6, RX PA10" in overlay and "st/l1/stm32l152retx-pinctrl.dtsi" in overlay
    output = "\n".join(said)
    assert "ground link on usart1, enabled there on TX PB6 and RX PA10" in output
    assert "enable one" not in output and "TODO(port): no UART" not in output
    assert "- nucleo_l1x" in (root / "tests" / "boards" / "testcase.yaml").read_text()
    for suite in ("tests/deployment/testcase.yaml", "tests/floor/paths/testcase.yaml", "app/sample.yaml"):
        assert "nucleo_l1x" not in (root / suite).read_text(), suite


def test_without_the_hals_pinctrl_file_the_overlay_chooses_no_link_and_says_why(tmp_path):
    root, zephyr = _console_only_board(tmp_path, pinctrl=False)
    said: list[str] = []
    folder = boards.new_board("nucleo_l1x", root=root, zephyr=zephyr, say=said.append)
    overlay = (folder / "app.overlay").read_text()
    # No UART named that the devicetree lacks: the build stops at the kit's own #error
    assert overlay.endswith(" */\n") and "/ {" not in overlay and "&uart1" not in overlay  # comments alone
    assert "st/l1/stm32l152retx-pinctrl.dtsi, not found" in overlay
    todo = [line for line in said if line.startswith("TODO(port): no UART for the ground link")]
    assert len(todo) == 1 and "scripts/setup.sh" in todo[0] and "boards/nucleo_l1x/app.overlay" in todo[0]


def test_no_free_pins_is_said_with_the_pins_in_use(tmp_path):
    root, zephyr = _console_only_board(tmp_path)
    dts = zephyr / "boards" / "st" / "nucleo_l1x" / "nucleo_l1x.dts"
    dts.write_text(dts.read_text().replace("<&gpioa 9 GPIO_ACTIVE_LOW>", "<&gpioa 9 0>, <&gpioa 10 0>, <&gpiob 7 0>"))
    spare, reason = boards.spare_uart(boards.find_board("nucleo_l1x", zephyr), zephyr,
                                     root / "deps" / "modules" / "hal" / "stm32")
    assert spare is None
    assert reason.startswith("st/l1/stm32l152retx-pinctrl.dtsi names no TX and RX pins free on this board for "
                             "usart1, uart4") and "pa10" in reason


# --- a small board --------------------------------------------------------

SMALL_SUITE = SUITE + """  profile.small.baremetal_passive:
    platform_allow:
      - qemu_cortex_m3
      - qemu_cortex_m3_small
    extra_args: SNIPPET=fprime-small
"""


def _kit_with_small_part(tmp_path: Path) -> Path:
    """The fake kit with a small part: its folder, its baseline (the
    fprime-small build it plays) and its scenario in the suite."""
    root = _kit(tmp_path, {"baremetal": (112_000, 45_000), "baremetal_budgeted": (113_000, 45_500),
                           "baremetal_passive": (110_000, 44_000), "rtos": (120_000, 60_000)})
    part = root / "boards" / "qemu_cortex_m3_small"
    part.mkdir()
    (part / "Kconfig.defconfig").write_text("config ISR_STACK_SIZE\n\tdefault 512\n")
    (part / "kit.conf").write_text("CONFIG_QEMU_ICOUNT=y\n")
    (part / "app.overlay").write_text('#include "../qemu_cortex_m3/app.overlay"\n')
    (part / "board").mkdir()  # its Zephyr board definition: not a port's file
    (root / "tests" / "baselines" / "qemu_cortex_m3_small.json").write_text(
        json.dumps(_results({"small.baremetal_passive": (105_700, 36_600)})))
    (root / "tests" / "deployment" / "testcase.yaml").write_text(SMALL_SUITE)
    return root


def test_a_board_the_kit_profile_does_not_fit_takes_the_small_parts_build_that_fits(tmp_path):
    root = _kit_with_small_part(tmp_path)
    zephyr = _zephyr(tmp_path)
    _platform(zephyr, "qemu/g0", "qemu_g0", "identifier: qemu_g0\narch: arm\nram: 36\nflash: 128\n"
              "simulation: qemu\n")
    said: list[str] = []
    folder = boards.new_board("qemu_g0", root=root, zephyr=zephyr, say=said.append)
    text = "\n".join(said)
    assert "the kit profile does not fit" in text
    assert ("the smallest build that passes the suite and fits: baremetal_passive with fprime-small, as measured "
            "on qemu_cortex_m3_small") in text
    # The port starts from the small part's folder (its stacks and heap), not its Zephyr board
    assert (folder / "Kconfig.defconfig").read_text().endswith("config ISR_STACK_SIZE\n\tdefault 512\n")
    assert not (folder / "board").exists()
    # ... and joins the fprime-small scenario, not the whole suite
    suite = (root / "tests" / "deployment" / "testcase.yaml").read_text()
    assert suite.count("qemu_g0") == 1
    assert suite.index("qemu_g0") > suite.index("profile.small.baremetal_passive")
    assert "kit compare" not in text  # a small part has nothing to compare


def test_a_baseline_without_every_model_is_said_so_not_called_a_misfit(tmp_path):
    root = _kit(tmp_path, {"baremetal_passive": (110_000, 44_000), "rtos": (120_000, 60_000)})
    with pytest.raises(KitError, match="has no baremetal variant to measure the deployment from") as error:
        boards.new_board("qemu_cortex_m0", root=root, zephyr=_zephyr(tmp_path), say=_quiet)
    assert "does not fit" not in str(error.value) and "small part" not in str(error.value)


def test_a_board_too_small_for_the_small_part_too_is_refused(tmp_path):
    root = _kit_with_small_part(tmp_path)
    with pytest.raises(KitError, match="Nor does the smallest build of a small part"):
        boards.new_board("qemu_cortex_m0", root=root, zephyr=_zephyr(tmp_path), say=_quiet)


def test_a_small_real_board_joins_the_small_builds_of_the_real_boards():
    text = BOARDS_SUITE + "  board.small.baremetal_passive:\n    extra_args: SNIPPET=fprime-small\n"
    after = boards.add_to_scenario_lists(text, "board.small.", "nucleo_g071rb")
    assert after == text.replace("  board.small.baremetal_passive:\n",
                                 "  board.small.baremetal_passive:\n    platform_allow:\n      - nucleo_g071rb\n")
    assert boards.add_to_scenario_lists(after, "board.small.", "nucleo_g071rb") == after  # once


def test_a_board_of_the_kit_profile_is_kept_out_of_the_small_parts_builds(tmp_path):
    # Twister joins the common list to a scenario's: a board of the kit
    # profile joins every list but the fprime-small builds', which exclude it
    root = _kit(tmp_path)
    (root / "tests" / "deployment" / "testcase.yaml").write_text(SMALL_SUITE)
    boards.new_board("mps2/an521/cpu0", root=root, zephyr=_zephyr(tmp_path), say=_quiet)
    suite = (root / "tests" / "deployment" / "testcase.yaml").read_text()
    assert suite.endswith("  profile.small.baremetal_passive:\n    platform_exclude:\n      - mps2/an521/cpu0\n"
                          "    platform_allow:\n      - qemu_cortex_m3\n      - qemu_cortex_m3_small\n"
                          "    extra_args: SNIPPET=fprime-small\n")
    head = suite[:suite.index("  profile.small.")]
    # every other platform_allow list, as before; no integration list (twister:
    # an excluded integration platform is an error)
    assert head == boards.add_to_twister_lists(SUITE, "mps2/an521/cpu0", ("platform_allow",))


def test_exclusion_from_the_small_builds_is_made_once_and_kept_in_an_existing_list():
    text = BOARDS_SUITE + ("  board.small.baremetal_passive:\n    platform_allow:\n      - nucleo_g071rb\n"
                           "    platform_exclude:\n      - nucleo_other\n")
    after = boards.exclude_from_scenarios(text, "board.small.", "nucleo_new")
    common = "    - nucleo_other\n  build_only"
    assert after == text.replace(common, "    - nucleo_other\n    - nucleo_new\n  build_only").replace(
        "      - nucleo_other\n", "      - nucleo_other\n      - nucleo_new\n")
    assert boards.exclude_from_scenarios(after, "board.small.", "nucleo_new") == after
