# SPDX-License-Identifier: Apache-2.0
"""The ground tools find the deployment's command dispatcher in its dictionary."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from kittools.link import fuzz
from kittools.link.dictionary import Dictionary
from kittools.workspace import KitError


def _dictionary(tmp_path: Path, commands: dict[str, int], channels: tuple[str, ...] = ()) -> Path:
    path = tmp_path / "TopologyDictionary.json"
    path.write_text(json.dumps({
        "commands": [{"name": name, "opcode": opcode} for name, opcode in commands.items()],
        "constants": [{"qualifiedName": fuzz.ACCUMULATOR_CONSTANT, "value": 320}],
        "telemetryChannels": [{"name": name} for name in channels],
        "events": [{"name": "Thermal.cmdDisp.NoOpReceived"}],
    }))
    return path


def test_the_dispatcher_is_the_owner_of_cmd_no_op_whatever_its_name(tmp_path: Path):
    path = _dictionary(tmp_path, {"Thermal.cmdDisp.CMD_NO_OP": 0x10, "Kit.load.SET_SLICE": 0x20,
                                  "Thermal.heater.SET_TARGET": 0x30},
                       channels=("Thermal.cmdDisp.CommandErrors",))
    names = Dictionary.read(path)
    assert names.dispatcher == "Thermal.cmdDisp"
    assert (names.noop_command, names.noop_event, names.noop_opcode) == (
        "Thermal.cmdDisp.CMD_NO_OP", "Thermal.cmdDisp.NoOpReceived", 0x10)
    deployment = fuzz.Deployment.from_dictionary(path)
    assert (deployment.noop, deployment.dispatcher, deployment.with_argument) == (0x10, "Thermal.cmdDisp", 0x20)
    assert deployment.dispatcher_telemetry
    assert fuzz.count_channels(names)[-2:] == ("Thermal.cmdDisp.CommandErrors", "Thermal.cmdDisp.CommandsDispatched")


@pytest.mark.parametrize("commands, found", [
    ({"Kit.load.SET_SLICE": 1}, "found none"),
    ({"A.cmdDisp.CMD_NO_OP": 1, "B.cmdDisp.CMD_NO_OP": 2}, "found 2: A.cmdDisp, B.cmdDisp"),
])
def test_no_dispatcher_or_several_is_one_clear_error(tmp_path: Path, commands: dict[str, int], found: str):
    names = Dictionary.read(_dictionary(tmp_path, commands))  # read: the tools that need no NO_OP use it
    with pytest.raises(KitError, match=f"CMD_NO_OP.*{found}"):
        _ = names.noop_command


def test_a_file_that_is_not_a_dictionary_is_one_clear_error(tmp_path: Path):
    path = tmp_path / "dictionary.json"
    path.write_text("{not json")
    with pytest.raises(KitError, match="not an F´ JSON dictionary"):
        Dictionary.read(path)


def test_a_command_the_dictionary_lacks_names_it(tmp_path: Path):
    names = Dictionary.read(_dictionary(tmp_path, {"Thermal.cmdDisp.CMD_NO_OP": 1}))
    with pytest.raises(KitError, match="has no command Kit.load.SET_SLICE"):
        names.opcode("Kit.load.SET_SLICE")


@pytest.mark.parametrize("uplinks, found", [
    (("Kit.fileUplink",), "Kit.fileUplink"),  # the reference deployment
    (("FileHandling.fileUplink",), "FileHandling.fileUplink"),  # F´'s FileHandling subtopology (fprime-util's template)
    ((), None),  # a deployment or a board profile without one
])
def test_the_file_uplink_is_the_instance_with_its_channels_whatever_its_name(
        tmp_path: Path, uplinks: tuple[str, ...], found: str | None):
    channels = tuple(f"{uplink}.{name}" for uplink in uplinks for name in ("FilesReceived", "PacketsReceived",
                                                                           "Warnings"))
    # An instance with only some of its channels is not one (FileDownlink has FilesSent, Warnings)
    channels += ("FileHandling.fileDownlink.FilesSent", "FileHandling.fileDownlink.Warnings")
    names = Dictionary.read(_dictionary(tmp_path, {"Thermal.cmdDisp.CMD_NO_OP": 1}, channels))
    assert names.file_uplink == found


def test_two_file_uplinks_are_one_clear_error(tmp_path: Path):
    channels = tuple(f"{uplink}.{name}" for uplink in ("A.fileUplink", "B.fileUplink")
                     for name in ("FilesReceived", "PacketsReceived", "Warnings"))
    names = Dictionary.read(_dictionary(tmp_path, {"Thermal.cmdDisp.CMD_NO_OP": 1}, channels))
    with pytest.raises(KitError, match="found 2: A.fileUplink, B.fileUplink"):
        _ = names.file_uplink
