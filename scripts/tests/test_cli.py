"""The CLI's bad-input paths: one clear error each, exit 2, nothing written."""

import os
import stat
import time

import pytest

from kittools import cli, runner, workspace
from kittools.workspace import KitError


def test_unknown_board_is_one_clear_error(capsys):
    assert cli.main(["test", "--board", "nucleo_f429zi", "--skip-host", "--skip-python"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith("kit: error: board 'nucleo_f429zi' has no kit port") and "docs/porting.md" in err[0]


def test_unprovisioned_workspace_is_one_clear_error(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(workspace, "DEPS", tmp_path / "deps")
    assert cli.main(["compare", "--board", "qemu_cortex_m3", "--output", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "scripts/setup.sh" in err[0]
    assert not (tmp_path / "out").exists()


def test_corrupted_results_file_is_one_clear_error(tmp_path, capsys):
    corrupted = tmp_path / "comparison.json"
    corrupted.write_text('{"schema_version": 1, "conditions": {}, "variants": {"rtos": ')
    assert cli.main(["report", str(corrupted), "--output", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "is not valid JSON" in err[0]
    assert not (tmp_path / "out" / "report.md").exists()


def test_a_second_board_folder_is_found_by_its_full_target():
    assert workspace.check_board("mps2/an385") == "mps2_an385"
    with pytest.raises(KitError, match="mps2/an521"):
        workspace.check_board("mps2/an521")


def _fake_qemu(tmp_path, monkeypatch, body: str):
    """A build folder whose QEMU command is a script printing `body`."""
    script = tmp_path / "bin" / "qemu-system-fake"
    script.parent.mkdir()
    script.write_text("#!/bin/sh\n" + body)
    script.chmod(script.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setenv("PATH", f"{script.parent}{os.pathsep}{os.environ['PATH']}")
    (tmp_path / "build.ninja").write_text(
        "build run: CUSTOM\n  COMMAND = cd /b && qemu-system-fake -kernel /b/zephyr/zephyr.elf && cd /b\n")
    return tmp_path


def test_the_run_ends_at_its_end_line_even_when_it_arrives_in_one_chunk(tmp_path, monkeypatch):
    # Everything at once, then silence: a reader that buffers lines behind
    # select() would wait for the time-out here
    build = _fake_qemu(tmp_path, monkeypatch,
                       "printf 'KIT BANNER variant=rtos\\nKIT END variant=rtos result=PASS\\n'\nsleep 30\n")
    began = time.monotonic()
    text = runner.run(build, tmp_path / "console.log", timeout_s=20)
    assert text.splitlines()[-1] == "KIT END variant=rtos result=PASS"
    assert time.monotonic() - began < 10


def test_a_fatal_halt_ends_the_run_at_once(tmp_path, monkeypatch):
    build = _fake_qemu(tmp_path, monkeypatch,
                       "printf 'KIT BANNER variant=rtos\\nKIT HALT reason=stack_overflow code=2 context=cmdDisp "
                       "expected=no\\nPROJECT EXECUTION FAILED\\n'\nsleep 30\n")
    text = runner.run(build, tmp_path / "console.log", timeout_s=20)
    assert "KIT HALT reason=stack_overflow" in text


def test_a_run_that_never_ends_is_reported_with_its_log(tmp_path, monkeypatch):
    build = _fake_qemu(tmp_path, monkeypatch, "printf 'KIT BANNER variant=rtos\\n'\nsleep 30\n")
    with pytest.raises(KitError, match="did not reach its end line within 2 s"):
        runner.run(build, tmp_path / "console.log", timeout_s=2)
