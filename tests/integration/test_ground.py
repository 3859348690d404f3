# SPDX-License-Identifier: Apache-2.0
"""The deployment from the ground: F´'s integration-test API through
fprime-gds, against a build of the ground scenario (kit test boots each one,
with fprime-gds on its link: kittools/link/ground.py).

QEMU counts instructions (icount); the station runs it in real time (idle
time in host time: GroundStation says why), but host and deployment clocks
still drift, so rates are checked on the F´ time tags the deployment puts
on its telemetry, never on the host's clock.
"""

from __future__ import annotations

import struct
import time
import zlib
from pathlib import Path
from typing import Any

import pytest

from kittools.link.dictionary import Dictionary

TIMEOUT_S = 10  # whole seconds: the API arms signal.alarm with it
# Controller::SETPOINT_LIMIT (app/Components/Controller/Controller.hpp)
SETPOINT_LIMIT = 20000
# Health's 10 Hz cycles a check watches: a ping unanswered for 3 of them is
# health's warning (PING_WARN_CYCLES, app/Top/KitTopologyDefs.hpp)
HEALTH_WATCH_S = 2.0


def _absent(service: str) -> None:
    """Skips a test of an F´ service the build does not have, and says why."""
    pytest.skip(f"this build has no F´ {service}: its deployment, or its board's profile for this model, "
                "leaves it out")


def _names(api: Any) -> Dictionary:
    return Dictionary.read(Path(api.dictionaries.dictionary_path))


def _service(api: Any, command: str, service: str) -> str:
    """The deployment's instance of an F´ service, found by a command of its
    own (kittools.link.dictionary), whatever its topology names it: the
    reference's Kit.version, F´'s CdhCore.version in a deployment that takes
    F´'s CdhCore. Skips the test on a build whose deployment or board
    profile leaves the service out (CONFIG_KIT_SERVICE_CDH: the firmware's
    record says KIT HEALTH services=absent)."""
    owner = _names(api).owner_of(command)
    if owner is None:
        _absent(service)
    return str(owner)


def _dispatcher(api: Any, name: str) -> str:
    """A command, event or channel of the deployment's command dispatcher,
    by its own name: the dispatcher is found in the dictionary (the owner of
    CMD_NO_OP, kittools.link.dictionary), whatever its topology names it."""
    return _names(api).of_dispatcher(name)


def _reference_component(api: Any, command: str) -> None:
    """Skips a test of the reference deployment's own components (its
    controller) on another deployment (kit ... --deployment): its dictionary
    has no such command, and the test says so instead of failing."""
    if command not in api.dictionaries.command_name:
        pytest.skip(f"this deployment has no {command.rsplit('.', 1)[0]}: the reference deployment's own "
                    "component (app/), which the test needs")


def test_noop_completes_with_its_events(fprime_test_api: Any) -> None:
    fprime_test_api.send_and_assert_command(_dispatcher(fprime_test_api, "CMD_NO_OP"), max_delay=TIMEOUT_S)
    fprime_test_api.assert_event(_dispatcher(fprime_test_api, "NoOpReceived"), timeout=TIMEOUT_S)


@pytest.mark.parametrize("setpoint", [0, 1500, -SETPOINT_LIMIT, SETPOINT_LIMIT])
def test_setpoint_accepted_and_reported(fprime_test_api: Any, setpoint: int) -> None:
    _reference_component(fprime_test_api, "Kit.controller.SET_SETPOINT")
    # The handler's event may precede the dispatcher's: checked on its own
    fprime_test_api.send_and_assert_command("Kit.controller.SET_SETPOINT", [setpoint], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event("Kit.controller.SetpointChanged", [setpoint], timeout=TIMEOUT_S)
    fprime_test_api.assert_telemetry("Kit.controller.Setpoint", setpoint, timeout=TIMEOUT_S)


@pytest.mark.parametrize("setpoint", [SETPOINT_LIMIT + 1, -SETPOINT_LIMIT - 1, 2**31 - 1])
def test_setpoint_out_of_range_rejected(fprime_test_api: Any, setpoint: int) -> None:
    _reference_component(fprime_test_api, "Kit.controller.SET_SETPOINT")
    fprime_test_api.send_command("Kit.controller.SET_SETPOINT", [setpoint])
    fprime_test_api.assert_event("Kit.controller.SetpointRejected", [setpoint, SETPOINT_LIMIT], timeout=TIMEOUT_S)
    fprime_test_api.assert_event(_dispatcher(fprime_test_api, "OpCodeError"), timeout=TIMEOUT_S)


def test_load_commands_complete(fprime_test_api: Any) -> None:
    fprime_test_api.send_and_assert_command("Kit.load.SET_SLICE", [0], max_delay=TIMEOUT_S)
    fprime_test_api.send_and_assert_command("Kit.load.SET_BURST", [0, 0], max_delay=TIMEOUT_S)


def test_telemetry_every_tenth_of_a_second(fprime_test_api: Any) -> None:
    """The fastest group's cycle count, written each tenth of a second
    whatever its rate (Timing::tlmDecimation): consecutive samples are
    100 ms apart in the deployment's time, and as many cycles apart each
    time (100 for the reference deployment's 1 kHz group, 5 for
    tests/team/Thermal's 50 Hz one)."""
    samples = fprime_test_api.await_telemetry_count(6, "Kit.timing.FastCycles", timeout=TIMEOUT_S)
    times = [sample.get_time().get_float() for sample in samples]
    values = [sample.get_val() for sample in samples]
    gaps = [later - earlier for earlier, later in zip(times, times[1:], strict=False)]
    steps = [later - earlier for earlier, later in zip(values, values[1:], strict=False)]
    assert all(abs(gap - 0.1) < 0.002 for gap in gaps), gaps
    assert steps[0] > 0 and all(step == steps[0] for step in steps), steps


def test_version_reported_on_command(fprime_test_api: Any) -> None:
    version = _service(fprime_test_api, "VERSION", "version service")
    fprime_test_api.send_and_assert_command(f"{version}.VERSION", ["FRAMEWORK"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event(f"{version}.FrameworkVersion", timeout=TIMEOUT_S)
    fprime_test_api.send_and_assert_command(f"{version}.VERSION", ["PROJECT"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event(f"{version}.ProjectVersion", timeout=TIMEOUT_S)


def test_health_checks_without_warning_at_rest(fprime_test_api: Any) -> None:
    """Health's checking, turned on again from the ground, pings every entry
    each 10 Hz cycle; at rest no entry is late (HLTH_PING_WARN) over 20
    cycles, with the link busy with this test's commands and telemetry."""
    health = _service(fprime_test_api, "HLTH_ENABLE", "health service")
    fprime_test_api.send_and_assert_command(f"{health}.HLTH_ENABLE", ["ENABLED"], max_delay=TIMEOUT_S)
    fprime_test_api.assert_event(f"{health}.HLTH_CHECK_ENABLE", ["ENABLED"], timeout=TIMEOUT_S)
    time.sleep(HEALTH_WATCH_S)
    fprime_test_api.assert_event_count(0, f"{health}.HLTH_PING_WARN")


# A warm restart's answer, the restart (RESTART_DELAY_CYCLES of the 10 Hz
# group: Faults.hpp), the boot and the first events through the link
RESTART_S = 10


def _parameter_file(api: Any) -> str:
    """The parameter database's file on the RAM file system (a dictionary
    constant); skips a test of the reference's database on a build whose
    board profile leaves it out (CONFIG_KIT_SERVICE_PARAMS: the record says
    KIT RAMFS mount=absent) and on another deployment's build."""
    if "Kit.prmDb.PRM_SAVE_FILE" not in api.dictionaries.command_name:
        database = _service(api, "PRM_SAVE_FILE", "parameter database")
        pytest.skip(f"this test drives the reference deployment's database and controller (Kit.prmDb, "
                    f"Kit.controller); this deployment's database, {database}, is tested by "
                    "test_parameter_database_saves_and_loads_its_file")
    return str(api.dictionaries.constant_name["Kit.RamFs.parameterFile"])


def test_parameter_database_saves_and_loads_its_file(fprime_test_api: Any) -> None:
    """The deployment's parameter database, whatever its topology names it
    (the reference's Kit.prmDb, F´'s FileHandling.prmDb), writes its file on
    the RAM file system and reads back as many records as it wrote: its file
    is one the file system has (F´'s FileHandling names it PrmDb.dat, which
    MicroFs has not: kit new-deployment configures it again with
    Kit.RamFs.parameterFile)."""
    api = fprime_test_api
    prm_db = _service(api, "PRM_SAVE_FILE", "parameter database")
    parameter_file = str(api.dictionaries.constant_name["Kit.RamFs.parameterFile"])
    api.send_and_assert_command(f"{prm_db}.PRM_SAVE_FILE", max_delay=TIMEOUT_S)
    saved = api.assert_event(f"{prm_db}.PrmFileSaveComplete", timeout=TIMEOUT_S)
    records = int(saved.get_args()[0].val)
    api.send_and_assert_command(f"{prm_db}.PRM_LOAD_FILE", [parameter_file, "RESET"], max_delay=TIMEOUT_S)
    api.assert_event(f"{prm_db}.PrmFileLoadComplete", ["STAGING", records, records, 0], timeout=TIMEOUT_S)
    # What it staged is what it holds: committed, nothing changes
    api.send_and_assert_command(f"{prm_db}.PRM_COMMIT_STAGED", max_delay=TIMEOUT_S)
    api.assert_event(f"{prm_db}.PrmDbCommitComplete", timeout=TIMEOUT_S)


def _gains(api: Any) -> tuple[int, int]:
    """The controller's default gains (shifts), from the dictionary: the
    parameters the database's tests save and load (skipped where the
    deployment has no controller)."""
    _reference_component(api, "Kit.controller.KP_SHIFT_PRM_SET")
    constants = api.dictionaries.constant_name
    return int(constants["Kit.ControllerGains.kpShift"]), int(constants["Kit.ControllerGains.kiShift"])


def _save_kp(api: Any, kp: int) -> None:
    """Sets the controller's proportional gain, saves it in the database,
    and the database in its file."""
    _, ki = _gains(api)
    api.send_and_assert_command("Kit.controller.KP_SHIFT_PRM_SET", [kp], max_delay=TIMEOUT_S)
    api.assert_event("Kit.controller.GainsApplied", [kp, ki], timeout=TIMEOUT_S)
    api.send_and_assert_command("Kit.controller.KP_SHIFT_PRM_SAVE", max_delay=TIMEOUT_S)
    api.send_and_assert_command("Kit.prmDb.PRM_SAVE_FILE", max_delay=TIMEOUT_S)
    api.assert_event("Kit.prmDb.PrmFileSaveComplete", timeout=TIMEOUT_S)


def _restart(api: Any) -> None:
    """A warm restart from the ground; returns once the deployment is back."""
    api.send_and_assert_command("Kit.faults.RESTART", max_delay=TIMEOUT_S)
    api.assert_event("Kit.faults.RestartArmed", timeout=TIMEOUT_S)
    api.assert_event("Kit.controller.GainsApplied", start="NOW", timeout=RESTART_S)


def test_parameter_set_saved_and_reloaded(fprime_test_api: Any) -> None:
    """A gain set from the ground and saved to the file is loaded back from
    it (PRM_LOAD_FILE, then PRM_COMMIT_STAGED) after the ground changed it
    again without saving."""
    api = fprime_test_api
    parameter_file = _parameter_file(api)
    kp_default, ki = _gains(api)
    try:
        _save_kp(api, kp_default + 1)
        api.send_and_assert_command("Kit.controller.KP_SHIFT_PRM_SET", [kp_default + 2], max_delay=TIMEOUT_S)
        api.assert_event("Kit.controller.GainsApplied", [kp_default + 2, ki], timeout=TIMEOUT_S)
        api.send_and_assert_command("Kit.prmDb.PRM_LOAD_FILE", [parameter_file, "RESET"], max_delay=TIMEOUT_S)
        api.assert_event("Kit.prmDb.PrmFileLoadComplete", ["STAGING", 1, 1, 0], timeout=TIMEOUT_S)
        api.send_and_assert_command("Kit.prmDb.PRM_COMMIT_STAGED", max_delay=TIMEOUT_S)
        api.assert_event("Kit.prmDb.PrmDbCommitComplete", timeout=TIMEOUT_S)
        # A committed database reaches a component at its next read: the
        # component's own set is what changes its value in the run
        api.send_and_assert_command("Kit.controller.KP_SHIFT_PRM_SET", [kp_default + 1], max_delay=TIMEOUT_S)
        api.assert_event("Kit.controller.GainsApplied", [kp_default + 1, ki], timeout=TIMEOUT_S)
    finally:
        _save_kp(api, kp_default)


def test_parameter_read_back_after_warm_restart(fprime_test_api: Any) -> None:
    """The saved gain is in effect after a warm restart of the same run: the
    RAM file system kept its file (app/src/RamFs.cpp), the database read it
    at start-up, and the controller loaded it."""
    api = fprime_test_api
    _parameter_file(api)
    kp_default, ki = _gains(api)
    try:
        _save_kp(api, kp_default + 1)
        _restart(api)
        api.assert_event("Kit.prmDb.PrmFileLoadComplete", ["ACTIVE", 1, 1, 0], timeout=RESTART_S)
        api.assert_event("Kit.controller.GainsApplied", [kp_default + 1, ki], timeout=RESTART_S)
        api.send_and_assert_command(_dispatcher(api, "CMD_NO_OP"), max_delay=TIMEOUT_S)
    finally:
        _save_kp(api, kp_default)


# Damage to a saved parameter file (one record: delimiter, record size, id,
# value; F´'s PrmDb) and the read stage where F´'s PrmDb rejects it
PARAMETER_FILE_DAMAGE = [
    (("FLIP", 0), "DELIMITER_VALUE"),  # the record's delimiter byte
    (("FLIP", 1), "RECORD_SIZE_VALUE"),  # the record size's top byte
    (("TRUNCATE", 3), "RECORD_SIZE_SIZE"),  # the record size cut short
    (("TRUNCATE", 8), "PARAMETER_ID_SIZE"),  # the id cut short
]


@pytest.mark.parametrize(("damage", "stage"), PARAMETER_FILE_DAMAGE, ids=[s for _, s in PARAMETER_FILE_DAMAGE])
def test_damaged_parameter_file_rejected(fprime_test_api: Any, damage: tuple[str, int], stage: str) -> None:
    """A damaged parameter file is refused with PrmDb's read error and its
    load abandoned; the gains in effect stay, and the deployment goes on."""
    api = fprime_test_api
    parameter_file = _parameter_file(api)
    kp_default, ki = _gains(api)
    try:
        _save_kp(api, kp_default + 1)
        api.send_and_assert_command("Kit.faults.CORRUPT_FILE", [parameter_file, *damage], max_delay=TIMEOUT_S)
        api.assert_event("Kit.faults.FileCorrupted", timeout=TIMEOUT_S)
        api.send_command("Kit.prmDb.PRM_LOAD_FILE", [parameter_file, "RESET"])
        api.assert_event("Kit.prmDb.PrmFileReadError", [stage, 0, None], timeout=TIMEOUT_S)
        api.assert_event("Kit.prmDb.PrmDbFileLoadFailed", timeout=TIMEOUT_S)
        api.send_and_assert_command(_dispatcher(api, "CMD_NO_OP"), max_delay=TIMEOUT_S)
    finally:
        _save_kp(api, kp_default)


def test_damaged_parameter_file_at_restart_leaves_defaults(fprime_test_api: Any) -> None:
    """A parameter file damaged before a warm restart is refused at start-up
    with PrmDb's read error: the controller starts on its defaults, and
    nothing halts."""
    api = fprime_test_api
    parameter_file = _parameter_file(api)
    kp_default, ki = _gains(api)
    try:
        _save_kp(api, kp_default + 1)
        api.send_and_assert_command("Kit.faults.CORRUPT_FILE", [parameter_file, "FLIP", 0], max_delay=TIMEOUT_S)
        _restart(api)
        api.assert_event("Kit.prmDb.PrmFileReadError", ["DELIMITER_VALUE", 0, None], timeout=RESTART_S)
        api.assert_event("Kit.controller.GainsApplied", [kp_default, ki], timeout=RESTART_S)
        api.send_and_assert_command(_dispatcher(api, "CMD_NO_OP"), max_delay=TIMEOUT_S)
    finally:
        _save_kp(api, kp_default)


# The file downlink: the bulk file filled with the kit's pattern from this
# seed (Load.FILL_FILE), asked for far past any board's bulk file so that the
# whole file is filled, then sent to the ground
FILL_SEED = 0x4B495431
FILL_ASK_BYTES = 1 << 20
# Issue 32's floor for the file a board's RAM file system holds (qemu_cortex_m3: 2 KiB)
BULK_MIN_BYTES = 2048
# 16 KiB at 115200 baud is about 2 s of the link; the rest is margin for a
# loaded host (the station runs QEMU in real time)
DOWNLINK_S = 60
# The ground's file is complete a moment after the deployment's FileSent
WRITTEN_S = 10.0


def pattern(seed: int, count: int) -> bytes:
    """The kit's test pattern (Load::Pattern, app/Components/Load/Load.hpp):
    a 32-bit xorshift (13, 17, 5) stream, its low byte per step."""
    state = seed
    out = bytearray(count)
    for index in range(count):
        state ^= (state << 13) & 0xFFFFFFFF
        state ^= state >> 17
        state ^= (state << 5) & 0xFFFFFFFF
        out[index] = state & 0xFF
    return bytes(out)


def _bulk_file(api: Any, seed: int) -> tuple[str, int]:
    """Fills the RAM file system's bulk file with the kit's pattern from
    `seed` (Load.FILL_FILE, asked for more than any board's bulk file
    holds); returns its name and the bytes it holds. Skips a test on a build
    whose board profile leaves the file downlink out."""
    _service(api, "SendFile", "file downlink")
    bulk = str(api.dictionaries.constant_name["Kit.RamFs.bulkFile"])
    api.send_and_assert_command("Kit.load.FILL_FILE", [bulk, FILL_ASK_BYTES, seed], max_delay=TIMEOUT_S)
    filled = api.assert_event("Kit.load.FileFilled", timeout=TIMEOUT_S)
    size = int(filled.get_args()[1].val)
    assert size >= BULK_MIN_BYTES, f"the bulk file holds {size} B, under {BULK_MIN_BYTES}"
    return bulk, size


def _downlinked(api: Any, source: str, size: int, destination: str) -> bytes:
    """Sends `source` to the ground (Svc.FileDownlink's SendFile); returns
    what fprime-gds's downlinker wrote, once it holds `size` bytes."""
    downlink = _service(api, "SendFile", "file downlink")
    api.send_and_assert_command(f"{downlink}.SendFile", [source, destination], max_delay=DOWNLINK_S)
    api.assert_event(f"{downlink}.FileSent", timeout=TIMEOUT_S)
    received = Path(api.pipeline.down_store) / destination
    deadline = time.monotonic() + WRITTEN_S
    while time.monotonic() < deadline and (not received.is_file() or received.stat().st_size < size):
        time.sleep(0.1)
    assert received.is_file(), f"fprime-gds wrote no {received}"
    return received.read_bytes()


def _first_difference(data: bytes, expected: bytes) -> int | None:
    return next((index for index, (got, want) in enumerate(zip(data, expected, strict=False)) if got != want), None)


def test_file_downlinked_byte_for_byte(fprime_test_api: Any) -> None:
    """The bulk file of the RAM file system, filled with the kit's pattern,
    reaches the ground through Svc.FileDownlink and fprime-gds's downlinker
    with every byte as the pattern says (at least 2 KiB: the bulk file's
    size is the board's, CONFIG_KIT_RAMFS_BULK_FILE_SIZE)."""
    api = fprime_test_api
    bulk, size = _bulk_file(api, FILL_SEED)
    data = _downlinked(api, bulk, size, f"kit-bulk-{size}.bin")
    mismatch = _first_difference(data, pattern(FILL_SEED, size))
    assert len(data) == size and mismatch is None, f"{len(data)} B of {size}, first difference at byte {mismatch}"


# The file uplink's test writes the bulk file with the pattern from another
# seed than the fill's, so that what comes back can only be the uplink's
UPLINK_SEED = 0x55504C4B
# fprime-gds's uplinker waits for each packet's handshake; 16 KiB is 65
# packets (its 256 B chunks) at the link's pace
UPLINK_S = 60


def _file_uplink(api: Any) -> str:
    """The deployment's file uplink (the instance with Svc.FileUplink's
    channels); skips a test of it on a build whose deployment or board
    profile leaves it out (CONFIG_KIT_SERVICE_FILE_UPLINK)."""
    uplink = _names(api).file_uplink
    if uplink is None:
        _absent("file uplink")
    return str(uplink)


def test_file_uplinked_byte_for_byte(fprime_test_api: Any, tmp_path: Path) -> None:
    """A file as large as the bulk file, uplinked through fprime-gds's
    uplinker and Svc.FileUplink over the bulk file's earlier fill, comes
    back through the file downlink with every byte as sent: the round trip
    checks what the uplink wrote, not what the ground believes it sent."""
    api = fprime_test_api
    uplink = _file_uplink(api)
    bulk, size = _bulk_file(api, FILL_SEED)
    sent = pattern(UPLINK_SEED, size)
    api.uplink_file(str(_upload_source(tmp_path, f"kit-up-{size}.bin", sent)), bulk)
    api.assert_event(f"{uplink}.FileReceived", timeout=UPLINK_S)
    api.assert_event_count(0, f"{uplink}.BadChecksum")
    data = _downlinked(api, bulk, size, f"kit-roundtrip-{size}.bin")
    mismatch = _first_difference(data, sent)
    assert len(data) == size and mismatch is None, f"{len(data)} B of {size}, first difference at byte {mismatch}"


# A sequence as an operator writes one (fprime-gds's .seq text, compiled by
# its fprime-seqgen against the build's dictionary): two commands at once,
# the third a second after the second (commands every dispatcher has: the
# passive one has no CMD_NO_OP_STRING)
SEQUENCE_SETPOINT = 1234
SEQUENCE_TIMED_SETPOINT = 4321
SEQUENCE_TEXT = f"""; The kit's ground test sequence
R00:00:00 {{noop}}
R00:00:00 Kit.controller.SET_SETPOINT {SEQUENCE_SETPOINT}
R00:00:01 Kit.controller.SET_SETPOINT {SEQUENCE_TIMED_SETPOINT}
"""
SEQUENCE_GAP_S = 1.0
# The sequencer's clock is the 10 Hz group: a timed record starts within a tick
SEQUENCE_TICK_S = 0.1
# CS_RUN with BLOCK answers when the sequence has run
SEQUENCE_S = 10
# fprime-seqgen's time base for a sequence that runs on any clock (TB_DONT_CARE)
ANY_TIME_BASE = 0xFFFF


def _sequence(api: Any, tmp_path: Path) -> tuple[str, bytes]:
    """The ground test sequence compiled from its text with fprime-gds's
    sequence generator; skips a test of the sequencer on a build whose
    board profile leaves it out (CONFIG_KIT_SERVICE_SEQUENCER)."""
    if "Kit.cmdSeq.CS_RUN" not in api.dictionaries.command_name:
        _absent("command sequencer")
    _reference_component(api, "Kit.controller.SET_SETPOINT")
    from fprime_gds.common.tools.seqgen import generateSequence

    text = tmp_path / "kit.seq"
    text.write_text(SEQUENCE_TEXT.format(noop=_dispatcher(api, "CMD_NO_OP")))
    binary = tmp_path / "kit.bin"
    generateSequence(str(text), str(binary), str(api.dictionaries.dictionary_path), ANY_TIME_BASE)
    return str(api.dictionaries.constant_name["Kit.RamFs.scratchFile"]), binary.read_bytes()


def _upload_source(tmp_path: Path, name: str, data: bytes) -> Path:
    """`data` in a file to upload, under a name no other test's upload has:
    fprime-gds copies a file into its upload store under its base name and
    deletes that copy once the last packet is sent, on the thread that reads
    the link, so a test that uploads the same name next can copy its file
    in before that deletion and lose it (tmp_path's folder is the test's own)."""
    source = tmp_path / f"{tmp_path.name}-{name}"
    source.write_bytes(data)
    return source


def _uplink(api: Any, tmp_path: Path, name: str, data: bytes, destination: str) -> None:
    api.uplink_file(str(_upload_source(tmp_path, name, data)), destination)
    api.assert_event(f"{_file_uplink(api)}.FileReceived", timeout=UPLINK_S)


def test_sequence_uplinked_and_run(fprime_test_api: Any, tmp_path: Path) -> None:
    """A sequence made with fprime-seqgen, uplinked to the RAM file system
    and run (CS_RUN): its commands reach the dispatcher from the sequencer,
    each answered, the timed one a second after the one before it in the
    deployment's time."""
    api = fprime_test_api
    destination, sequence = _sequence(api, tmp_path)
    _uplink(api, tmp_path, "kit.bin", sequence, destination)
    start = api.get_event_test_history().size()
    api.send_and_assert_command("Kit.cmdSeq.CS_RUN", [destination, "BLOCK"], max_delay=SEQUENCE_S)
    api.assert_event("Kit.cmdSeq.CS_SequenceComplete", start=start, timeout=TIMEOUT_S)
    noop = api.assert_event(_dispatcher(api, "NoOpReceived"), start=start, timeout=TIMEOUT_S)
    api.assert_event("Kit.controller.SetpointChanged", [SEQUENCE_SETPOINT], start=start, timeout=TIMEOUT_S)
    timed = api.assert_event("Kit.controller.SetpointChanged", [SEQUENCE_TIMED_SETPOINT], start=start,
                             timeout=TIMEOUT_S)
    gap = timed.get_time().get_float() - noop.get_time().get_float()
    assert SEQUENCE_GAP_S <= gap <= SEQUENCE_GAP_S + 3 * SEQUENCE_TICK_S, f"the timed record ran {gap:.3f} s later"
    api.assert_event_count(0, "Kit.cmdSeq.CS_CommandError", start=start)


def test_sequence_with_a_bad_crc_refused(fprime_test_api: Any, tmp_path: Path) -> None:
    """A sequence whose CRC does not match its records is refused before any
    of them runs (CS_FileCrcFailure, the CS_RUN command fails), and the
    deployment goes on."""
    api = fprime_test_api
    destination, sequence = _sequence(api, tmp_path)
    damaged = bytearray(sequence)
    damaged[-1] ^= 0x01
    _uplink(api, tmp_path, "kit-bad-crc.bin", bytes(damaged), destination)
    start = api.get_event_test_history().size()
    api.send_command("Kit.cmdSeq.CS_RUN", [destination, "BLOCK"])
    api.assert_event("Kit.cmdSeq.CS_FileCrcFailure", start=start, timeout=TIMEOUT_S)
    api.assert_event_count(0, _dispatcher(api, "NoOpReceived"), start=start)
    api.send_and_assert_command(_dispatcher(api, "CMD_NO_OP"), max_delay=TIMEOUT_S)


# F´'s sequence file (Svc/CmdSequencer/formats, fprime-gds's SeqBinaryWriter):
# a header (the size of what follows it, the number of records, the time
# base and its context), the records, then a CRC-32 of all before it
SEQUENCE_HEADER = struct.Struct(">IIHB")
SEQUENCE_CRC_BYTES = 4
# A record descriptor past END_OF_SEQUENCE (2) names no record
BAD_DESCRIPTOR = 7
# Past any sequencer buffer the kit sizes (CONFIG_KIT_RAMFS_FILE_SIZE)
SIZE_PAST_THE_BUFFER = 0x10000


def _resealed(data: bytes) -> bytes:
    """A sequence with its CRC computed again: the damage is in the records,
    past the check that a CRC is right."""
    body = data[:-SEQUENCE_CRC_BYTES]
    return body + struct.pack(">I", zlib.crc32(body))


def _with_header(data: bytes, **fields: int) -> bytes:
    size, records, base, context = SEQUENCE_HEADER.unpack_from(data)
    values = {"size": size, "records": records, "base": base, "context": context} | fields
    header = SEQUENCE_HEADER.pack(values["size"], values["records"], values["base"], values["context"])
    return _resealed(header + data[SEQUENCE_HEADER.size:])


def _bad_descriptor(data: bytes) -> bytes:
    return _resealed(data[:SEQUENCE_HEADER.size] + bytes([BAD_DESCRIPTOR]) + data[SEQUENCE_HEADER.size + 1:])


def _more_records(data: bytes) -> bytes:
    return _with_header(data, records=SEQUENCE_HEADER.unpack_from(data)[1] + 1)


def _fewer_records(data: bytes) -> bytes:
    return _with_header(data, records=SEQUENCE_HEADER.unpack_from(data)[1] - 1)


def _no_records(data: bytes) -> bytes:
    return _with_header(data, records=0)


def _size_past_the_buffer(data: bytes) -> bytes:
    return _with_header(data, size=SIZE_PAST_THE_BUFFER)


# Each damage with the event CmdSequencer refuses it with. A file cut short
# of its header's size is not among them: FileUplink opens its destination
# with OPEN_WRITE, which keeps what a longer earlier file left past the new
# end (MicroFs as F´'s Posix file does), so the sequencer reads on into an
# earlier upload and refuses the CRC instead
BAD_SEQUENCES = {
    "a record descriptor that names no record": (_bad_descriptor, "CS_RecordInvalid"),
    "a header counting more records than the file holds": (_more_records, "CS_RecordInvalid"),
    "a header counting fewer records than the file holds": (_fewer_records, "CS_RecordMismatch"),
    "a header counting no records": (_no_records, "CS_NoRecords"),
    "a header's size past the sequencer's buffer": (_size_past_the_buffer, "CS_FileSizeError"),
}


@pytest.mark.parametrize("damage", list(BAD_SEQUENCES), ids=lambda damage: damage.replace(" ", "-"))
def test_sequence_with_bad_records_refused(fprime_test_api: Any, tmp_path: Path, damage: str) -> None:
    """A sequence with a sound CRC and damaged records or header is refused
    with CmdSequencer's event for that damage, none of its commands runs,
    and the deployment goes on answering."""
    api = fprime_test_api
    destination, sequence = _sequence(api, tmp_path)
    damaged, event = BAD_SEQUENCES[damage]
    _uplink(api, tmp_path, "kit-bad-records.bin", damaged(sequence), destination)
    start = api.get_event_test_history().size()
    api.send_command("Kit.cmdSeq.CS_RUN", [destination, "BLOCK"])
    api.assert_event(f"Kit.cmdSeq.{event}", start=start, timeout=TIMEOUT_S)
    api.assert_event_count(0, _dispatcher(api, "NoOpReceived"), start=start)
    api.assert_event_count(0, "Kit.controller.SetpointChanged", start=start)
    api.send_and_assert_command(_dispatcher(api, "CMD_NO_OP"), max_delay=TIMEOUT_S)
