# SPDX-License-Identifier: Apache-2.0
import subprocess
from pathlib import Path

import pytest

from kittools import workspace
from kittools.workspace import KitError


def test_ported_board_is_accepted_with_or_without_qualifiers():
    assert workspace.check_board("qemu_cortex_m3") == "qemu_cortex_m3"
    assert workspace.check_board("qemu_cortex_m3/ti_lm3s6965") == "qemu_cortex_m3"


def test_a_qualified_target_has_a_folder_of_its_own_before_its_board_name(tmp_path):
    (tmp_path / "mps2").mkdir()
    assert workspace.board_dir_name("mps2/an385") == "mps2_an385"
    assert workspace.check_board("mps2/an385", tmp_path) == "mps2"
    (tmp_path / "mps2_an385").mkdir()
    assert workspace.check_board("mps2/an385", tmp_path) == "mps2_an385"
    assert workspace.check_board("mps2/an521", tmp_path) == "mps2"


def test_unknown_board_names_the_ported_ones_and_the_guide():
    with pytest.raises(KitError) as error:
        workspace.check_board("nucleo_f429zi")
    message = str(error.value)
    assert "nucleo_f429zi" in message and "qemu_cortex_m3" in message and "docs/porting.md" in message


def test_unknown_variant_lists_the_variants():
    from kittools import variants

    with pytest.raises(KitError, match="baremetal, baremetal_budgeted, baremetal_passive, rtos"):
        variants.get("freertos")


def test_unprovisioned_workspace_says_to_run_setup(tmp_path, monkeypatch):
    monkeypatch.setattr(workspace, "DEPS", tmp_path / "deps")
    with pytest.raises(KitError, match="scripts/setup.sh"):
        workspace.check_provisioned()


def test_environment_defaults_to_gnuarmemb_unless_a_toolchain_is_chosen(monkeypatch):
    monkeypatch.delenv("ZEPHYR_TOOLCHAIN_VARIANT", raising=False)
    monkeypatch.delenv("ZEPHYR_SDK_INSTALL_DIR", raising=False)
    env = workspace.environment()
    assert env["ZEPHYR_TOOLCHAIN_VARIANT"] == "gnuarmemb"
    monkeypatch.setenv("ZEPHYR_TOOLCHAIN_VARIANT", "zephyr")
    assert workspace.environment()["ZEPHYR_TOOLCHAIN_VARIANT"] == "zephyr"


def test_missing_toolchain_is_explained(monkeypatch):
    monkeypatch.delenv("ZEPHYR_TOOLCHAIN_VARIANT", raising=False)
    monkeypatch.delenv("ZEPHYR_SDK_INSTALL_DIR", raising=False)
    monkeypatch.setenv("PATH", "/nonexistent")
    monkeypatch.setattr(workspace.shutil, "which", lambda *a, **k: None)
    with pytest.raises(KitError, match="gcc-arm-none-eabi"):
        workspace.environment()


def test_a_second_run_in_the_same_tree_is_refused(tmp_path, monkeypatch):
    import subprocess
    import sys

    monkeypatch.setattr(workspace, "KIT_ROOT", tmp_path)
    # Another process holds the lock, as a `kit test` already running would
    holder = subprocess.Popen([sys.executable, "-c", (
        "import fcntl, os, sys, time\n"
        f"f = open({str(tmp_path / 'build' / '.kit-test.lock')!r}, 'a+')\n"
        "fcntl.flock(f, fcntl.LOCK_EX); f.write('pid %d' % os.getpid()); f.flush()\n"
        "print('held', flush=True); time.sleep(30)\n")], stdout=subprocess.PIPE, text=True,
        preexec_fn=lambda: (tmp_path / "build").mkdir(exist_ok=True))
    try:
        assert holder.stdout is not None and holder.stdout.readline().strip() == "held"
        refused = rf"another `kit test` is running in this tree \(pid {holder.pid}\)"
        with pytest.raises(workspace.KitError, match=refused):
            with workspace.one_at_a_time("test"):
                pass
    finally:
        holder.kill()
        holder.wait()
    with workspace.one_at_a_time("test"):  # free again once the holder is gone
        pass


def test_check_committed_names_the_changed_files(tmp_path: Path) -> None:
    def git(*args: str) -> None:
        subprocess.run(["git", "-C", str(tmp_path), *args], check=True, capture_output=True)

    git("init", "-q")
    (tmp_path / "kept.txt").write_text("one\n")
    git("add", "kept.txt")
    git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "one")
    (tmp_path / "untracked.txt").write_text("not the kit's\n")
    workspace.check_committed("why", tmp_path)  # untracked files are not the image's
    (tmp_path / "kept.txt").write_text("two\n")
    with pytest.raises(KitError, match=r"uncommitted changes \(kept.txt\): why"):
        workspace.check_committed("why", tmp_path)


def test_the_west_workspace_is_the_clone_or_one_that_imports_the_kit(tmp_path):
    kit = tmp_path / "topdir" / "kit"
    kit.mkdir(parents=True)
    assert workspace.west_topdir(kit) is None
    (tmp_path / "topdir" / ".west").mkdir()
    (tmp_path / "topdir" / ".west" / "config").write_text("[manifest]\npath = team\n")
    assert workspace.west_topdir(kit) == tmp_path / "topdir"  # a manifest that imports the kit
    (kit / ".west").mkdir()
    (kit / ".west" / "config").write_text("[manifest]\npath = .\n")
    assert workspace.west_topdir(kit) == kit  # the clone's own, which scripts/setup.sh makes
