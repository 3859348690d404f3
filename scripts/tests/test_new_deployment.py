# SPDX-License-Identifier: Apache-2.0
"""kit new-deployment on the deployment fprime-tools' own template makes
(the one `fprime-util new --deployment` renders), in a scratch F´ project:
what it changes, that a second run changes nothing, and its errors. The
build and run of the result are CI's (kittools.suite's new-deployment step)."""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import pytest

from kittools import workspace
from kittools.deployments import adapt, fpp
from kittools.workspace import KitError

pytestmark = pytest.mark.skipif(not (workspace.DEPS / "fprime" / "Svc" / "Subtopologies").is_dir(),
                                reason="workspace not provisioned (F´'s subtopologies)")


def make_template(project: Path, driver: str = "TcpClient") -> Path:
    """fprime-tools' deployment template, rendered as fprime-util renders it."""
    cookiecutter = pytest.importorskip("cookiecutter.main").cookiecutter
    import fprime  # the venv's fprime-tools

    template = Path(fprime.__file__).parent / "cookiecutter_templates" / "cookiecutter-fprime-deployment"
    project.mkdir(parents=True, exist_ok=True)
    (project / "settings.ini").write_text("[fprime]\nproject_root: .\n")
    cookiecutter(str(template), no_input=True, output_dir=str(project),
                 extra_context={"deployment_name": "MyDeployment", "com_driver_type": driver})
    return project / "MyDeployment"


def snapshot(folder: Path) -> dict[str, bytes]:
    return {path.relative_to(folder).as_posix(): path.read_bytes() for path in folder.rglob("*") if path.is_file()}


@pytest.mark.parametrize("driver", ["TcpClient", "TcpServer", "UART"])
def test_adapts_the_template_once(tmp_path: Path, driver: str) -> None:
    folder = make_template(tmp_path / "proj", driver)
    record = adapt.new_deployment(folder, Fraction(10))
    assert record.changes and not record.kept
    topology = (folder / "Top" / "topology.fpp").read_text()
    instances = (folder / "Top" / "instances.fpp").read_text()
    # The host's timer, driver and clock are gone; F´'s comm chain is the kit's
    assert "ComCcsds." not in topology.replace("in place of ComCcsds.Subtopology", "")
    assert "import Kit.GroundLink" in topology and "import Kit.Instruments" in topology
    assert "Svc.LinuxTimer" not in "".join(i.type for i in fpp.instances(instances))
    assert not any(i.type.startswith("Drv.") for i in fpp.instances(instances))
    assert "instance chronoTime: Svc.OsTime" in instances
    assert "Kit.timing.CycleOut -> rateGroupDriver.CycleIn" in topology
    # Each rate group starts and ends with the kit's probe, its own members between
    for index, group in enumerate(("rateGroup1", "rateGroup2", "rateGroup3")):
        members = [line.split("->")[1].strip() for line in topology.splitlines()
                   if line.strip().startswith(f"{group}.RateGroupMemberOut[")]
        assert members[0] == f"Kit.timing.cycleStart[{index}]" and members[-1] == f"Kit.timing.cycleEnd[{index}]"
    assert "CdhCore.$health.Run" in topology and "cmdSeq.schedIn" in topology
    # The seam's files, and the rates scaled from the template's 1 : 1/2 : 1/4
    for seam_file in ("config/CMakeLists.txt", "Components/CMakeLists.txt", "Top/Tables.fpp", "Top/KitTopology.hpp",
                      "Top/KitTopology.cpp", "Top/ActiveStacks.hpp", "Top/rategroups/PassiveRateGroups.fpp",
                      "deployment.conf"):
        assert (folder / seam_file).is_file(), seam_file
    table = (folder / "Top" / "KitTopology.cpp").read_text()
    assert '{"rateGroup1", CONFIG_KIT_TICK_HZ * 1 / 10, 0}' in table
    assert '{"rateGroup3", CONFIG_KIT_TICK_HZ * 2 / 5, 2}' in table
    # The template's ChronoTime is OsTime, which counts from the epoch set at
    # setup (without it every event and channel carries time zero)
    assert "MyDeployment::chronoTime.set_epoch(Fw::Time(0, 0), now);" in table
    # FileHandling's parameter file is one MicroFs has, set between its
    # configuration phase and the parameters' load
    configured = table.index("FileHandling::prmDb.configure(RamFs::parameterFile);")
    assert "configComponents(state);\n    configureTopology(state);\n    MyDeployment::loadParameters();" in table
    assert table.index("void configureTopology") < configured < table.index("void setupTopology")
    assert any("FileHandling.prmDb" in change for change in record.changes), record.changes
    assert "Kit.FatalHandler" in (folder / "config" / "CdhCoreFatalHandlerConfig.fpp").read_text()
    # F´'s FileHandling and the sequencer get the kit's RAM file system (without it every file call fails)
    conf = (folder / "deployment.conf").read_text()
    assert "CONFIG_KIT_RAMFS=y" in conf and "FileHandling.fileUplink" in conf
    # Run twice, it changes nothing
    before = snapshot(folder)
    again = adapt.new_deployment(folder)
    assert again.changes == [] and snapshot(folder) == before


def _group_of(topology: str, member: str) -> str:
    return next(line.split(".RateGroupMemberOut")[0].strip() for line in topology.splitlines()
                if ".RateGroupMemberOut[" in line and line.split("->")[1].strip() == member)


@pytest.mark.parametrize("fastest_hz, uplink", [(50, "rateGroup2"), (10, "rateGroup1")])
def test_the_scripted_uplink_shares_the_bursts_group_where_that_group_is_fast_enough(
        tmp_path: Path, fastest_hz: int, uplink: str) -> None:
    """The faults scenario commands the burst on and off two uplink cycles
    apart: on the burst's group (25 Hz here) that spans two bursts; a group
    slower than 10 Hz (5 Hz here) would not run a scenario's script within
    its run, and the uplink stays on the fastest."""
    folder = make_template(tmp_path / "proj")
    adapt.new_deployment(folder, Fraction(fastest_hz))
    topology = (folder / "Top" / "topology.fpp").read_text()
    assert _group_of(topology, "Kit.load.burstIn") == "rateGroup2"
    assert _group_of(topology, "Kit.uplink.schedIn") == uplink
    assert _group_of(topology, "Kit.load.sliceIn") == "rateGroup1"
    # F´'s dispatcher writes its telemetry only in its run port, which the template leaves unscheduled
    assert _group_of(topology, "CdhCore.cmdDisp.run") == uplink


def test_rates_the_driver_cannot_count_are_refused(tmp_path: Path) -> None:
    folder = make_template(tmp_path / "proj")
    before = snapshot(folder)
    with pytest.raises(KitError, match=r"8,000,000,000.*--fastest-hz") as refused:
        adapt.new_deployment(folder)
    assert snapshot(folder) == before  # nothing written
    # The rate it suggests is one the kit's load sweep runs at whole
    suggested = re.search(r"--fastest-hz (\d+) or more", str(refused.value))
    assert suggested, refused.value
    record = adapt.new_deployment(folder, Fraction(int(suggested.group(1))))
    assert not [line for line in record.todo if "load sweep" in line], record.todo


def test_a_folder_that_is_no_deployment_is_refused(tmp_path: Path) -> None:
    (tmp_path / "proj" / "Empty").mkdir(parents=True)
    (tmp_path / "proj" / "settings.ini").write_text("[fprime]\n")
    with pytest.raises(KitError, match="no Top/topology.fpp"):
        adapt.new_deployment(tmp_path / "proj" / "Empty")


def test_a_deployment_outside_any_project_is_refused(tmp_path: Path) -> None:
    folder = make_template(tmp_path / "proj")
    (tmp_path / "proj" / "settings.ini").unlink()
    with pytest.raises(KitError, match="in no F´ project"):
        adapt.new_deployment(folder)
