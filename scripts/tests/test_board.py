"""kit new-board: a fake Zephyr board tree and a fake kit in tmp_path."""

import shutil
from pathlib import Path

import pytest

from kittools import board, workspace
from kittools.workspace import KIT_ROOT, KitError

SUITE = """# the suite
common:
  platform_allow:
    - qemu_cortex_m3
  integration_platforms:
    - qemu_cortex_m3
  tags: kit
tests:
  kit.one:
    platform_allow:
      - qemu_cortex_m3   # only here
"""


def _zephyr(tmp_path: Path) -> Path:
    zephyr = tmp_path / "zephyr"
    (zephyr / "boards" / "qemu" / "m3").mkdir(parents=True)
    (zephyr / "boards" / "qemu" / "m3" / "qemu_cortex_m3.yaml").write_text(
        "identifier: qemu_cortex_m3\narch: arm\nram: 64\nflash: 256\n")
    (zephyr / "boards" / "qemu" / "m0").mkdir(parents=True)
    (zephyr / "boards" / "qemu" / "m0" / "qemu_cortex_m0.yaml").write_text(
        "identifier: qemu_cortex_m0\narch: arm\nram: 16\nflash: 256\n")
    (zephyr / "boards" / "qemu" / "x86").mkdir(parents=True)
    (zephyr / "boards" / "qemu" / "x86" / "qemu_x86.yaml").write_text("identifier: qemu_x86\narch: x86\n")
    mps2 = zephyr / "boards" / "arm" / "mps2"
    mps2.mkdir(parents=True)
    (mps2 / "mps2_an385.yaml").write_text("identifier: mps2/an385\narch: arm\n")
    (mps2 / "mps2_an385.dts").write_text('#include "mps2_mem.dtsi"\n/ {\n chosen {\n  zephyr,sram = &sram0;\n'
                                         "  zephyr,flash = &flash0;\n };\n};\n")
    (mps2 / "mps2_mem.dtsi").write_text("/ {\n sram0: memory@20000000 {\n  compatible = \"mmio-sram\";\n"
                                        "  reg = <0x20000000 0x400000>;\n };\n flash0: flash@0 {\n"
                                        "  reg = <0 0x200000>;\n };\n};\n")
    (zephyr / "VERSION").write_text("VERSION_MAJOR = 4\nVERSION_MINOR = 0\nPATCHLEVEL = 0\n")
    return zephyr


def _kit(tmp_path: Path) -> Path:
    root = tmp_path / "kit"
    shutil.copytree(KIT_ROOT / "boards" / "qemu_cortex_m3", root / "boards" / "qemu_cortex_m3")
    (root / "tests" / "baselines").mkdir(parents=True)
    shutil.copy(KIT_ROOT / "tests" / "baselines" / "qemu_cortex_m3.json", root / "tests" / "baselines")
    (root / "tests" / "deployment").mkdir()
    (root / "tests" / "deployment" / "testcase.yaml").write_text(SUITE)
    return root


def test_unknown_board_is_refused_with_close_matches(tmp_path):
    with pytest.raises(KitError, match=r"Zephyr 4\.0\.0 has no board 'qemu_cortex_m4'\. Close matches: "
                                       r"qemu_cortex_m3, qemu_cortex_m0"):
        board.find_board("qemu_cortex_m4", _zephyr(tmp_path))


def test_memory_comes_from_the_platform_file_or_the_devicetree(tmp_path):
    zephyr = _zephyr(tmp_path)
    m3 = board.find_board("qemu_cortex_m3", zephyr)
    assert (m3.ram_kib, m3.flash_kib) == (64, 256)
    an385 = board.find_board("mps2/an385", zephyr)
    assert (an385.ram_kib, an385.flash_kib) == (4096, 2048)
    assert board.find_board("mps2", zephyr).identifier == "mps2/an385"  # the only mps2


def test_a_board_too_small_is_refused_with_the_numbers(tmp_path):
    root = _kit(tmp_path)
    with pytest.raises(KitError) as error:
        board.new_board("qemu_cortex_m0", root=root, zephyr=_zephyr(tmp_path), say=lambda _m: None)
    message = str(error.value)
    assert "qemu_cortex_m0 cannot hold the deployment" in message
    assert "rtos: RAM needs" in message and "the board has 16 KiB" in message and "Memory budget" in message
    assert not (root / "boards" / "qemu_cortex_m0").exists()


def test_a_board_of_another_architecture_is_refused(tmp_path):
    with pytest.raises(KitError, match="'x86' board"):
        board.new_board("qemu_x86", root=_kit(tmp_path), zephyr=_zephyr(tmp_path), say=lambda _m: None)


def test_the_scaffold_copies_the_reference_with_todos_and_joins_the_suite(tmp_path):
    root = _kit(tmp_path)
    zephyr = _zephyr(tmp_path)
    said: list[str] = []
    folder = board.new_board("mps2/an385", root=root, zephyr=zephyr, say=said.append)
    assert folder == root / "boards" / "mps2_an385"
    assert sorted(p.name for p in folder.iterdir()) == ["Tables.fpp", "baremetal.conf", "kit.conf", "rtos.conf"]
    assert (folder / "kit.conf").read_text().startswith("# TODO(port): QEMU icount")
    assert "CONFIG_QEMU_ICOUNT=y" in (folder / "kit.conf").read_text()
    suite = (root / "tests" / "deployment" / "testcase.yaml").read_text()
    assert suite.count("- mps2/an385") == 3 and "# only here" in suite
    assert any("rtos: RAM needs" in line and "spare" in line for line in said)
    with pytest.raises(KitError, match="exists already"):
        board.new_board("mps2/an385", root=root, zephyr=zephyr, say=said.append)


def test_twister_lists_gain_the_board_once():
    once = board.add_to_twister_lists(SUITE, "mps2/an385")
    assert once.count("mps2/an385") == 3
    assert board.add_to_twister_lists(once, "mps2/an385") == once
    assert "      - mps2/an385\n" in once  # the nested list's own indentation


def test_board_folders_are_found_by_full_target_then_board_name():
    assert workspace.check_board("qemu_cortex_m3/ti_lm3s6965") == "qemu_cortex_m3"
    assert workspace.check_board("mps2/an385") == "mps2_an385"
    assert workspace.board_dir_name("mps2/an385") == "mps2_an385"


@pytest.mark.skipif(not (workspace.DEPS / "zephyr" / "boards").is_dir(), reason="workspace not provisioned")
def test_the_pinned_zephyr_knows_both_ported_boards():
    assert board.find_board("qemu_cortex_m3").ram_kib == 64
    assert board.find_board("mps2/an385").ram_kib == 4096
