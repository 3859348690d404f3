# SPDX-License-Identifier: Apache-2.0
"""The seam between the kit and the deployment it measures (app/deployment.cmake,
kittools.deployment): the reference deployment passes, a folder that is not
one gets one clear error naming what it lacks, and a deployment's builds
are told apart from the reference's."""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

from kittools import deployment
from kittools.build import conditions
from kittools.build.folder import BuildFolder
from kittools.workspace import KIT_ROOT, KitError


@pytest.fixture
def inside_kit() -> Iterator[Path]:
    """A scratch folder inside the kit's F´ project (build/ is never committed)."""
    folder = KIT_ROOT / "build" / "test-deployment-seam"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    yield folder
    shutil.rmtree(folder, ignore_errors=True)


SEAM_TOPOLOGY = "module Kit {\n  topology Mine {\n    import Instruments\n    import GroundLink\n  }\n}\n"


def _seam(folder: Path, topology: str = SEAM_TOPOLOGY) -> Path:
    for part in ("config", "Components", "Top"):
        (folder / part).mkdir(parents=True, exist_ok=True)
        (folder / part / "CMakeLists.txt").write_text("")
    (folder / "Top" / "topology.fpp").write_text(topology)
    (folder / "Top" / "KitTopology.hpp").write_text("constexpr FwIndexType RATE_GROUP_COUNT = 1;\n")
    (folder / "Top" / "KitTopology.cpp").write_text("const RateGroupSpec RATE_GROUPS[RATE_GROUP_COUNT] = {};\n")
    return folder


def test_the_reference_deployment_is_the_default_and_adds_nothing_to_a_build():
    reference = deployment.resolve(None)
    assert reference.is_reference and reference.name == "app"
    assert reference.cmake_args() == [] and reference.output_suffix() == ""


def test_a_deployment_with_the_seam_passes_and_is_named_by_its_folder(inside_kit: Path):
    mine = deployment.resolve(_seam(inside_kit / "mine"))
    assert mine.name == "build/test-deployment-seam/mine"
    assert mine.cmake_args() == [f"-DKIT_DEPLOYMENT_DIR={inside_kit / 'mine'}"]
    assert mine.output_suffix() == "-mine"


def test_a_topology_may_import_the_instruments_by_their_qualified_name(inside_kit: Path):
    topology = ("module Mine {\n  topology Mine {\n    import Kit.Instruments  # the kit's\n"
                "    import Kit.GroundLink\n  }\n}\n")
    assert deployment.resolve(_seam(inside_kit / "mine", topology)).name.endswith("mine")


@pytest.mark.parametrize(("make", "says"), [
    (lambda root: root / "missing", "does not exist"),
    (lambda root: root, "has no config/CMakeLists.txt"),
    (lambda root: _seam(root / "x").joinpath("Top", "CMakeLists.txt").unlink() or root / "x",
     "has no Top/CMakeLists.txt"),
    (lambda root: _seam(root / "y", "module Y {\n  topology Y {\n    import Kit.GroundLink\n  }\n}\n"),
     "does not import the kit's Instruments subtopology"),
    (lambda root: _seam(root / "z", "module Z {\n  topology Z {\n    import Kit.Instruments\n  }\n}\n"),
     "does not import the kit's GroundLink subtopology"),
    (lambda root: _seam(root / "r").joinpath("Top", "KitTopology.cpp").unlink() or root / "r",
     "cannot find the rate groups"),
    (lambda root: _seam(root / "c").joinpath("Top", "KitTopology.hpp").unlink() or root / "c",
     "cannot find the rate groups"),
])
def test_a_folder_that_is_not_a_deployment_gets_one_clear_error(inside_kit: Path, make, says):
    with pytest.raises(KitError) as error:
        deployment.resolve(make(inside_kit))
    message = str(error.value)
    assert says in message and "docs/your-deployment.md" in message
    assert ".cmake:" not in message and "\n" not in message  # CMake's noise left out


def test_a_deployment_in_a_teams_own_fprime_project_passes(tmp_path: Path):
    """A folder outside the kit's repository builds from its own F´ project
    (the nearest settings.ini above it: app/deployment.cmake)."""
    (tmp_path / "settings.ini").write_text("[fprime]\nproject_root: .\n")
    mine = deployment.resolve(_seam(tmp_path / "MyDeployment"))
    assert not mine.is_reference and mine.location == tmp_path
    assert mine.name == f"{tmp_path.name}/MyDeployment"  # named from its project, wherever that is
    assert mine.output_suffix() == "-MyDeployment"


def test_an_fprime_projects_root_is_not_a_deployment(tmp_path: Path):
    (tmp_path / "settings.ini").write_text("[fprime]\nproject_root: .\n")
    with pytest.raises(KitError, match="is an F´ project's root"):
        deployment.resolve(_seam(tmp_path))


def test_a_builds_conditions_name_its_deployment(tmp_path: Path):
    build = tmp_path / "build"
    build.mkdir()
    (build / "CMakeCache.txt").write_text(f"KIT_DEPLOYMENT_DIR:PATH={KIT_ROOT / 'tests' / 'mine'}\n")
    assert conditions.deployment(BuildFolder(build)) == "tests/mine"
    (build / "CMakeCache.txt").write_text("CMAKE_BUILD_TYPE:STRING=\n")
    assert conditions.deployment(BuildFolder(build)) == "unknown"
    project = tmp_path / "team"
    (build / "CMakeCache.txt").write_text(f"KIT_DEPLOYMENT_DIR:PATH={project / 'Thermal'}\n"
                                          f"KIT_DEPLOYMENT_LOCATION:INTERNAL={project}\n")
    assert conditions.deployment(BuildFolder(build)) == "team/Thermal"


@pytest.mark.parametrize("command", ["compare", "gds", "serial-sweep", "footprint"])
def test_the_measuring_commands_take_a_deployment(command: str):
    from kittools import cli

    args = cli.parser().parse_args([command, "--deployment", "tests/mine"])
    assert args.deployment == "tests/mine"
    assert cli.parser().parse_args([command]).deployment is None  # the reference


def test_a_deployments_ground_build_has_a_folder_of_its_own(inside_kit: Path):
    from kittools.link import ground

    mine = deployment.resolve(_seam(inside_kit / "mine"))
    reference = ground.ground_build_dir("qemu_cortex_m3", "rtos")
    assert reference == ground.ground_build_dir("qemu_cortex_m3", "rtos", deployment.resolve(None))
    assert ground.ground_build_dir("qemu_cortex_m3", "rtos", mine) == reference.with_name(reference.name + "-mine")


def test_the_second_deployment_passes_the_seam_and_shares_nothing_with_the_reference():
    """tests/team/Thermal: its own components, its own rates (50, 10 and 1 Hz,
    declared once in its RATE_GROUPS), none of the reference deployment's
    components, and the kit's subtopologies imported."""
    thermal = deployment.resolve(KIT_ROOT / "tests" / "team" / "Thermal")
    assert thermal.name == "tests/team/Thermal" and not thermal.is_reference
    sources = "\n".join(path.read_text() for path in thermal.path.rglob("*") if path.is_file())
    for reference_own in ("Controller", "Monitor", "Housekeeping", "ParamDefaults", "rg1kHz", "rg100Hz"):
        assert reference_own not in sources, reference_own
    table = (thermal.path / "Top" / "KitTopology.cpp").read_text()
    for rate in ("CONFIG_KIT_TICK_HZ / 50", "CONFIG_KIT_TICK_HZ / 10", "CONFIG_KIT_TICK_HZ / 1,"):
        assert rate in table


def test_ci_makes_the_second_deployments_whole_run_from_a_repository_that_imports_the_kit(monkeypatch,
                                                                                          tmp_path: Path):
    """kit test's last step: tests/team/Thermal's run on the reference board,
    from a copy of its F´ project (tests/team) in a workspace that imports
    the kit, then `west kit sizing` there; its serial-load sweep in the full
    run only."""
    import argparse
    import contextlib

    from kittools.commands import test as kit_test
    from kittools.suite import deployment_run, imported
    from kittools.suite.counts import Tally

    team = tmp_path / "team"
    shutil.copytree(KIT_ROOT / "tests" / "team", team)
    calls = []

    @contextlib.contextmanager
    def workspace(project: Path, log_dir: Path):
        calls.append(("workspace", project))
        yield team

    def run(chosen, board, out_dir, serial_plays):
        calls.append(("run", chosen.path, board, out_dir, serial_plays))
        elf = out_dir / "twister" / "qemu_cortex_m3" / "app" / "kit.rtos" / "zephyr" / "zephyr.elf"
        elf.parent.mkdir(parents=True, exist_ok=True)
        elf.touch()
        return Tally(41, 0)

    monkeypatch.setattr(imported, "importing_workspace", workspace)
    monkeypatch.setattr(deployment_run, "run_deployment", run)
    monkeypatch.setattr(imported, "west_kit", lambda where, args, log, expect: calls.append(("west", where, args))
                        or Tally(1, 0))
    for full, serial_plays in ((False, 0), (True, 1)):
        calls.clear()
        run_ = object.__new__(kit_test.FullRun)
        run_.log_dir = tmp_path / "logs"
        run_.args = argparse.Namespace(full=full)
        assert run_.second_deployment() == Tally(42, 0)
        out_dir = tmp_path / "logs" / "deployment-Thermal"
        assert calls[0] == ("workspace", KIT_ROOT / "tests" / "team")
        assert calls[1] == ("run", team / "Thermal", "qemu_cortex_m3", out_dir, serial_plays)
        assert calls[2] == ("west", team, ["sizing", str(out_dir / "twister" / "qemu_cortex_m3" / "app" / "kit.rtos")])


def test_the_importing_manifest_puts_the_kits_upstreams_in_its_deps():
    """west.yml of a repository that imports the kit: the kit at kit/ and its
    upstreams, with the same prefix, in kit/deps/ (where the kit reads them)."""
    import yaml

    from kittools.suite import imported

    text = imported.manifest("https://example.org/kit.git", "0123abcd")
    data = yaml.safe_load(text)["manifest"]
    (kit,) = data["projects"]
    assert data["self"]["path"] == "team"
    assert kit["path"] == "." and kit["import"] == {"path-prefix": "kit"} and kit["revision"] == "0123abcd"


class _Stop(Exception):
    pass


def test_a_deployments_run_plays_its_scenarios_in_every_model_then_its_ground_link(monkeypatch, tmp_path: Path):
    from kittools import variants
    from kittools.suite import deployment_run, ground_checks, twister
    from kittools.suite.counts import Tally

    calls = []
    monkeypatch.setattr(twister, "run_twister", lambda *a, **k: calls.append((a, k)) or Tally(4, 0))

    def link(out_dir: Path, twister_out: Path, serial_plays: int) -> Tally:
        calls.append(((out_dir, twister_out, serial_plays), {}))
        raise _Stop

    monkeypatch.setattr(ground_checks, "run_deployment_link", link)
    chosen = deployment.resolve(KIT_ROOT / "tests" / "team" / "Thermal")
    with pytest.raises(_Stop):
        deployment_run.run_deployment(chosen, "qemu_cortex_m3", tmp_path, floors_from=tmp_path / "none",
                                      serial_plays=1)
    (boards, out_dir, twister_out), options = calls[0]
    assert boards == ["qemu_cortex_m3"] and out_dir == tmp_path and twister_out == tmp_path / "twister"
    assert options["models"] == tuple(variants.names()) and options["scenarios"] == ("nominal", "load", "faults")
    # No suite run to take the board's kernel floor from: the deployment's run measures it
    assert options["with_floor"] is True
    assert options["cmake_args"] == (f"-DKIT_DEPLOYMENT_DIR={KIT_ROOT / 'tests' / 'team' / 'Thermal'}",)
    assert calls[1][0] == (tmp_path, tmp_path / "twister", 1)


def test_a_link_record_an_earlier_run_left_never_joins_this_runs_results(monkeypatch, tmp_path: Path):
    """A deployment's run without the serial sweep, after one with it: the
    old serial.json would put its axes into the new report."""
    from kittools.suite import ground_checks, results
    from kittools.suite.counts import Tally

    logs = results.integration_logs(tmp_path, "qemu_cortex_m3/ti_lm3s6965", "kit.rtos")
    logs.mkdir(parents=True)
    for file_name in results.LINK_RECORD_FILES:
        (logs / file_name).write_text("{}")
    monkeypatch.setattr(ground_checks, "foreign_dictionary_build", lambda *a: Tally(1, 0))
    monkeypatch.setattr(ground_checks, "fuzz_build", lambda *a, **k: Tally(1, 0))
    monkeypatch.setattr(ground_checks, "file_fuzz_build", lambda *a: Tally())
    monkeypatch.setattr(ground_checks, "flood_build", lambda *a: Tally(1, 0))
    tally = ground_checks.deployment_link_checks("qemu_cortex_m3/ti_lm3s6965", tmp_path / "kit.rtos", tmp_path)
    assert tally == Tally(3, 0)
    assert not any((logs / file_name).exists() for file_name in results.LINK_RECORD_FILES)


def test_a_deployment_builds_on_a_board_with_its_boards_table_or_its_own(inside_kit: Path):
    """Top/boards/<board>/Tables.fpp for a board whose stacks or priorities
    differ, else Top/Tables.fpp; a board with neither is one clear error
    that names the boards the deployment has tables for."""
    mine = _seam(inside_kit / "mine")
    with pytest.raises(KitError, match=r"no table for board 'mps2_an385' \(boards it has one for: none\)"):
        deployment.resolve(mine, ["mps2/an385"])
    (mine / "Top" / "boards" / "qemu_cortex_m3").mkdir(parents=True)
    (mine / "Top" / "boards" / "qemu_cortex_m3" / "Tables.fpp").write_text("module Kit {\n}\n")
    assert deployment.resolve(mine, ["qemu_cortex_m3"]).path == mine
    with pytest.raises(KitError) as error:
        deployment.resolve(mine, ["qemu_cortex_m3", "mps2/an385"])
    message = str(error.value)
    assert "boards it has one for: qemu_cortex_m3" in message and "Top/boards/mps2_an385/Tables.fpp" in message
    assert "\n" not in message and ".cmake:" not in message
    (mine / "Top" / "Tables.fpp").write_text("module Kit {\n}\n")
    assert deployment.resolve(mine, ["qemu_cortex_m3", "mps2/an385"]).path == mine


def test_the_reference_and_the_second_deployment_have_a_table_for_every_board():
    from kittools import workspace

    boards = workspace.ported_boards()
    assert deployment.resolve(None, boards).is_reference
    assert deployment.resolve(KIT_ROOT / "tests" / "team" / "Thermal", boards).name == "tests/team/Thermal"


def test_a_build_folder_configured_for_another_deployment_is_configured_from_scratch(tmp_path: Path):
    """Two deployment folders of one name share deployment-<name>/: the
    cached CONF_FILE of the first would name its deployment.conf."""
    from kittools.suite import twister

    def configured(name: str, deployment_dir: Path | None) -> Path:
        build = tmp_path / name
        build.mkdir()
        entry = f"KIT_DEPLOYMENT_DIR:PATH={deployment_dir}\n" if deployment_dir else ""
        (build / "CMakeCache.txt").write_text(entry + "BOARD:STRING=qemu_cortex_m3\n")
        return build / "CMakeCache.txt"

    old, same = configured("a", tmp_path / "x" / "Thermal"), configured("b", tmp_path / "y" / "Thermal")
    floor = configured("floor", None)
    wanted = f"-x=KIT_DEPLOYMENT_DIR={tmp_path / 'y' / 'Thermal'}"
    twister.forget_other_deployments(tmp_path, ["west", "twister", wanted])
    assert not old.exists() and same.exists() and floor.exists()
    twister.forget_other_deployments(tmp_path, ["west", "twister"])  # the reference's run
    assert not same.exists() and floor.exists()
    reference = configured("c", KIT_ROOT / "app")
    twister.forget_other_deployments(tmp_path, ["west", "twister"])
    assert reference.exists()
