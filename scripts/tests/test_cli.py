# SPDX-License-Identifier: Apache-2.0
"""The CLI's bad-input paths: one clear error each, exit 2, nothing written."""

import stat
import subprocess
import sys
import time

import pytest

from kittools import cli, workspace
from kittools.build import runner
from kittools.commands import test as test_command
from kittools.link import serial_points
from kittools.suite import plan, platforms
from kittools.workspace import KitError


def test_unknown_board_is_one_clear_error(capsys):
    assert cli.main(["test", "--board", "nucleo_f429zi", "--skip-host", "--skip-python"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith("kit: error: board 'nucleo_f429zi' has no kit port") and "docs/porting.md" in err[0]


@pytest.mark.parametrize("command", [["compare", "--board", "nucleo_f401re"],
                                     ["gds", "--board", "nucleo_f401re", "--model", "baremetal"]])
def test_a_real_board_is_refused_where_the_deployment_must_run(command, tmp_path, capsys):
    assert cli.main([*command, *(["--output", str(tmp_path / "out")] if command[0] == "compare" else [])]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "nucleo_f401re is a real board" in err[0] and "qemu_cortex_m3" in err[0]
    assert not (tmp_path / "out").exists()


def test_a_real_board_is_known_however_its_target_is_spelled():
    assert platforms.is_real_board("nucleo_f401re") and platforms.is_real_board("nucleo_f401re/stm32f401xe")
    assert not platforms.is_real_board("qemu_cortex_m3") and not platforms.is_real_board("mps2/an385")


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


def _fake_qemu(tmp_path, monkeypatch, body: str, pipe: bool = False):
    """A build folder whose `run` target is a script printing `body`: on
    stdio, or (pipe) into the QEMU pipe a twister build names in its cache."""
    script = tmp_path / "bin" / "qemu-system-fake"
    script.parent.mkdir()
    fifo = tmp_path / "qemu-fifo"
    redirect = f"exec > {fifo}.out\n" if pipe else ""
    script.write_text("#!/bin/sh\n" + redirect + body)
    script.chmod(script.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setattr(runner, "run_command", lambda build_dir: [str(script)])
    (tmp_path / "CMakeCache.txt").write_text(f"QEMU_PIPE:STRING={fifo}\n" if pipe else "BOARD:STRING=x\n")
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


def test_a_twister_build_is_read_from_its_qemu_pipe(tmp_path, monkeypatch):
    build = _fake_qemu(tmp_path, monkeypatch,
                       "printf 'KIT BANNER variant=rtos\\nKIT END variant=rtos result=PASS\\n'\nsleep 30\n", pipe=True)
    text = runner.run(build, tmp_path / "console.log", timeout_s=20)
    assert text.splitlines() == ["KIT BANNER variant=rtos", "KIT END variant=rtos result=PASS"]


def test_an_unconfigured_build_is_refused(tmp_path):
    with pytest.raises(KitError, match="no CMakeCache.txt"):
        runner.run(tmp_path, tmp_path / "console.log", timeout_s=2)


def test_a_run_that_never_ends_is_reported_with_its_log(tmp_path, monkeypatch):
    build = _fake_qemu(tmp_path, monkeypatch, "printf 'KIT BANNER variant=rtos\\n'\nsleep 30\n")
    with pytest.raises(KitError, match="did not reach its end line within 2 s"):
        runner.run(build, tmp_path / "console.log", timeout_s=2)


REPORT_WITHOUT_WORKSPACE = """
import sys
from importlib.abc import MetaPathFinder

class NoWorkspace(MetaPathFinder):
    # Nothing of west, twister or Zephyr may be imported by kit report
    def find_spec(self, name, path, target=None):
        if name.split(".")[0] in ("west", "twisterlib", "zephyr", "devicetree", "scl"):
            raise ImportError(f"kit report imported {name}")
        return None

sys.meta_path.insert(0, NoWorkspace())
from kittools import cli, workspace
from kittools.commands import compare, test

def unprovisioned(*_args, **_kwargs):
    raise workspace.KitError("the workspace is not provisioned (forced by the test)")

workspace.check_provisioned = compare.check_provisioned = test.check_provisioned = unprovisioned
workspace.environment = unprovisioned
sys.exit(cli.main(sys.argv[1:]))
"""


@pytest.mark.parametrize("board", ["qemu_cortex_m3", "mps2_an385"])
def test_kit_report_needs_no_workspace(tmp_path, board):
    baseline = str(workspace.KIT_ROOT / "tests" / "baselines" / f"{board}.json")
    run = subprocess.run([sys.executable, "-c", REPORT_WITHOUT_WORKSPACE, "report", baseline, "--baseline", baseline,
                          "--output", str(tmp_path)], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert "budget check against" in run.stdout and ": PASS" in run.stdout
    assert "Budget check: PASS" in (tmp_path / "report.md").read_text()
    assert {p.name for p in tmp_path.iterdir()} >= {"report.md", "report.html", "report.json", "report.csv"}


def _plan(monkeypatch, argv: list[str]) -> plan.Plan:
    """The plan `kit test argv` would run (nothing runs)."""
    seen: list[plan.Plan] = []

    def run(steps: plan.Plan) -> int:
        seen.append(steps)
        return 0

    monkeypatch.setattr(plan.Plan, "run", run)
    monkeypatch.setattr(test_command, "check_provisioned", lambda: None)
    assert cli.main(["test", *argv]) == 0
    return seen[0]


def _lanes(monkeypatch, argv: list[str]) -> tuple[list[str], list[str]]:
    """The step names `kit test argv` would run in its QEMU and host lanes (nothing runs)."""
    steps = _plan(monkeypatch, argv)
    return [step.name for step in steps.qemu], [step.name for step in steps.host]


def test_the_porting_and_new_deployment_steps_end_the_host_lane_of_a_full_run(monkeypatch, tmp_path):
    """--full's: beside the suite's twister, done before the ground link
    starts; CI's run (no --full) leaves both out."""
    out = ["--output", str(tmp_path)]
    qemu, host = _lanes(monkeypatch, [*out, "--full"])
    assert host[-2].startswith("porting: a new QEMU board and a console-only real board scaffolded into a scratch")
    assert host[-1].startswith("new deployment: fprime-util new --deployment, kit new-deployment")
    assert not any(name.startswith(("porting:", "new deployment:")) for name in qemu)
    qemu, host = _lanes(monkeypatch, out)
    assert not any(name.startswith(("porting:", "new deployment:")) for name in qemu + host)
    assert any(name.startswith("host unit tests") for name in host)
    for argv in (["--skip-porting"], ["--skip-twister"], ["--board", "qemu_cortex_m3"]):
        qemu, host = _lanes(monkeypatch, [*out, "--full", *argv])
        assert not any(name.startswith("porting:") for name in qemu + host), argv
    for argv in (["--skip-twister"], ["--board", "qemu_cortex_m3"]):
        qemu, host = _lanes(monkeypatch, [*out, "--full", *argv])
        assert not any(name.startswith("new deployment:") for name in qemu + host), argv


def test_a_deployments_own_run_is_its_whole_run_on_each_board_and_nothing_else(monkeypatch, tmp_path):
    """kit test --deployment: that deployment's scenarios, ground link and
    report, per board; not the reference's suite, host tests or porting."""
    out = ["--output", str(tmp_path)]
    thermal = str(workspace.KIT_ROOT / "tests" / "team" / "Thermal")
    qemu, host = _lanes(monkeypatch, [*out, "--deployment", thermal])
    assert host == [] and len(qemu) == 1
    assert qemu[0].startswith("tests/team/Thermal through the seam, every model on qemu_cortex_m3: nominal, load, "
                              "faults")
    qemu, _ = _lanes(monkeypatch, [*out, "--deployment", thermal, "--board", "qemu_cortex_m3",
                                   "--board", "mps2/an385"])
    assert [name.split(": ")[0].rsplit(" ", 1)[-1] for name in qemu] == ["qemu_cortex_m3", "mps2/an385"]


def test_a_full_run_has_the_second_deployments_whole_run_after_the_ground_link_beside_the_reports(
        monkeypatch, tmp_path):
    """It starts once the ground link's checks have ended (both have host
    time-outs) and runs beside the budgets and reports."""
    plan = _plan(monkeypatch, ["--output", str(tmp_path)])
    names = [step.name for step in plan.qemu]
    second = next(i for i, name in enumerate(names) if name.startswith("second deployment: "))
    assert names[second].startswith("second deployment: tests/team/Thermal through the seam, from a repository "
                                    "whose west.yml imports the kit, every model on qemu_cortex_m3: nominal, load, "
                                    "faults, ground link, report, west kit")
    assert names[second - 1].startswith("ground link: ")
    assert plan.qemu[second].beside and not any(step.beside for step in plan.qemu[:second] + plan.qemu[second + 1:])
    assert names[second + 1].startswith("budget: ")


@pytest.mark.parametrize("arguments, message", [
    (["test", "--subset", "3/2"], "--subset 3/2: expected K/N with 1 <= K <= N"),
    (["test", "--subset", "half"], "--subset half: expected K/N"),
    (["test", "--subset", "1/2", "--update-baseline"], "--update-baseline needs the whole run on one machine"),
    (["test", "--quick", "--board", "mps2/an385"], "--quick is the reference board's short run"),
    (["test", "--deployment", "tests/team/Thermal", "--quick"], "--deployment is a deployment's own run"),
    (["test", "--deployment", "tests/team/Thermal", "--update-baseline"], "--deployment is a deployment's own run"),
    (["report", "--merge", "a", "--baseline", "b"], "--merge takes the shards' output folders only"),
    (["report"], "kit report needs results files, or --merge DIR"),
])
def test_the_tiers_bad_input_is_one_clear_error(arguments, message, capsys):
    assert cli.main(arguments) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0]


def test_ci_plays_each_serial_level_once_and_the_full_and_baseline_runs_play_it_for_a_spread():
    """The serial sweep runs in real time: its plays are CI's time."""
    parser = cli.parser()
    assert test_command.serial_plays(parser.parse_args(["test"])) == 1
    for tier in (["--full"], ["--update-baseline"]):
        assert test_command.serial_plays(parser.parse_args(["test", *tier])) == serial_points.REPEATS > 1, tier
