# SPDX-License-Identifier: Apache-2.0
"""The ground link's tooling without QEMU: the fuzzer's frames against
fprime-gds's own framing, its generator's promises, and the fprime-gds
adapter against a local Unix socket."""

from __future__ import annotations

import json
import random
import socket
import threading
from collections import Counter
from pathlib import Path

import pytest
from fprime_gds.common.communication.framing import FpFramerDeframer

from kittools.build import runner
from kittools.link import client, fuzz, ground
from kittools.link.gds_adapter import UnixSocketAdapter
from kittools.workspace import KitError

# A dispatcher that is not the reference deployment's: the fuzzer names it from the dictionary
DISPATCHER = "Thermal.cmdDisp"
DEPLOYMENT = fuzz.Deployment(noop=0x500, dispatcher=DISPATCHER, with_argument=0x1600,
                             opcodes=frozenset({0x500, 0x1600}), accumulator_size=320)


def test_fuzzer_frames_are_what_fprime_gds_deframes():
    FpFramerDeframer.set_constants()
    payload = client.command(0x500)
    packets, rest, _ = FpFramerDeframer().deframe_all(client.frame(payload), no_copy=False)
    assert packets == [payload] and rest == b""


def test_invalid_frames_are_invalid_and_seeded():
    def batch(seed: int) -> list[bytes]:
        rng = random.Random(seed)
        return [fuzz.invalid_frame(kind, rng, DEPLOYMENT) for kind in fuzz.INVALID_KINDS for _ in range(50)]

    assert batch(7) == batch(7)
    assert batch(7) != batch(8)
    # The batch size's bound against the UART's ring (fuzz.PER_BATCH) holds
    assert max(len(frame) for frame in batch(7)) <= fuzz.INVALID_FRAME_MAX
    FpFramerDeframer.set_constants()
    rng = random.Random(1)
    for kind in ("garbage", "bad_checksum", "truncated", "oversized", "length_wraps"):
        for _ in range(200):
            data = fuzz.invalid_frame(kind, rng, DEPLOYMENT)
            packets, _, _ = FpFramerDeframer().deframe_all(data + fuzz.PADDING, no_copy=False)
            assert packets == [], f"{kind} frame {data.hex()} deframed"
            if kind == "garbage":
                assert not set(data) & client.START_WORD_BYTES
            if kind in ("oversized", "length_wraps"):
                (length,) = client.HEADER.unpack_from(data)[1:]
                assert length + 12 > DEPLOYMENT.accumulator_size


def test_a_truncated_frame_lacks_body_bytes_so_no_next_frame_completes_it():
    FpFramerDeframer.set_constants()
    rng = random.Random(3)
    noop = client.frame(client.command(DEPLOYMENT.noop))
    for _ in range(500):
        data = fuzz.invalid_frame("truncated", rng, DEPLOYMENT)
        (_, length) = client.HEADER.unpack_from(data)
        assert len(data) < client.HEADER.size + length, data.hex()
        packets, _, _ = FpFramerDeframer().deframe_all(data + noop + fuzz.PADDING, no_copy=False)
        assert len(packets) <= 1, data.hex()


def test_bad_payloads_are_well_framed():
    FpFramerDeframer.set_constants()
    rng = random.Random(2)
    for kind in fuzz.FRAMED_KINDS:
        data = fuzz.invalid_frame(kind, rng, DEPLOYMENT)
        packets, _, _ = FpFramerDeframer().deframe_all(data, no_copy=False)
        assert len(packets) == 1, kind


def test_outcome_names_every_shortfall():
    outcome = fuzz.Outcome(seed=1, dispatcher=DISPATCHER, noops_sent=2, noops_answered=1,
                           halt="ASSERT: FrameAccumulator.cpp:123")
    outcome.sent["oversized"] = 1
    outcome.telemetry = {"Kit.linkHealth.FramesDetected": 2, "Kit.linkHealth.Oversized": 1,
                         "Kit.linkHealth.UnknownPackets": 0, "Thermal.cmdDisp.CommandErrors": 0,
                         "Kit.linkHealth.CommandsDropped": 0, "Kit.linkHealth.UartRingDrops": 0,
                         "Kit.linkHealth.UartBytesReceived": 0}
    failures = outcome.failures()
    assert any("NO_OPs answered: 1, expected 2" in f for f in failures)
    assert any("asserted or halted" in f and "FrameAccumulator.cpp:123" in f for f in failures)
    assert len(failures) == 2
    assert outcome.to_json()["seed"] == 1


def test_the_read_out_command_is_one_more_bad_command_and_one_more_frame():
    """The unknown opcode sent after the fuzzing to write the dispatcher's
    counts again is expected in them: without it counted, a deployment
    that refused it would fail, and one that took it would pass."""
    outcome = fuzz.Outcome(seed=1, dispatcher=DISPATCHER, noops_sent=1, noops_answered=1, read_out_commands=1)
    outcome.events["Thermal.cmdDisp.OpCodeError"] = 1
    outcome.telemetry = {"Kit.linkHealth.FramesDetected": 2, "Kit.linkHealth.Oversized": 0,
                         "Kit.linkHealth.UnknownPackets": 0, "Thermal.cmdDisp.CommandErrors": 1,
                         "Kit.linkHealth.CommandsDropped": 0, "Kit.linkHealth.UartRingDrops": 0,
                         "Kit.linkHealth.UartBytesReceived": 0}
    assert outcome.failures() == []
    outcome.telemetry["Thermal.cmdDisp.CommandErrors"] = 0
    assert outcome.failures() == ["Thermal.cmdDisp.CommandErrors: 0, expected 1"]
    assert fuzz.unknown_opcode(random.Random(5), DEPLOYMENT) not in DEPLOYMENT.opcodes


class _OverflowingLink:
    """A downlink whose first `overflowing` read-outs each see one more
    ComQueue overflow; settle() finds its heartbeat at once."""

    def __init__(self, overflowing: int) -> None:
        self.events: Counter[str] = Counter()
        self.overflowing = overflowing

    def played(self) -> bool:
        if self.overflowing > 0:
            self.overflowing -= 1
            self.events[fuzz.DOWNLINK_OVERFLOW_EVENT] += 1
        return True


@pytest.mark.parametrize("overflowing, played", [(0, 1), (1, 2), (2, 3), (5, fuzz.READ_OUTS_MAX)])
def test_a_read_out_the_downlink_overflowed_during_is_played_again_a_bounded_number_of_times(
        monkeypatch, overflowing, played):
    monkeypatch.setattr(fuzz, "settle", lambda link, seed: None)
    link = _OverflowingLink(overflowing)
    plays = []

    def play() -> bool:
        plays.append(1)
        return link.played()

    ended = fuzz.read_out(link, play, seed=1)  # type: ignore[arg-type]
    assert ended.played == played == len(plays)
    assert ended.overflowed == (overflowing >= fuzz.READ_OUTS_MAX)


def test_a_read_out_whose_no_op_went_unanswered_is_not_played_again(monkeypatch):
    monkeypatch.setattr(fuzz, "settle", lambda link, seed: pytest.fail("settled after a missed answer"))
    link = _OverflowingLink(5)
    assert fuzz.read_out(link, lambda: False, seed=1) == fuzz.ReadOut(1, overflowed=False)  # type: ignore[arg-type]


def test_bad_commands_count_from_the_dispatchers_events_in_either_form():
    healthy = {"Kit.linkHealth.FramesDetected": 3, "Kit.linkHealth.Oversized": 0,
               "Kit.linkHealth.UnknownPackets": 0, "Kit.linkHealth.CommandsDropped": 0,
               "Kit.linkHealth.UartRingDrops": 0, "Kit.linkHealth.UartBytesReceived": 0}
    # The passive dispatcher has no CommandErrors channel: its events alone count
    passive = fuzz.Outcome(seed=1, dispatcher=DISPATCHER, noops_sent=1, noops_answered=1, dispatcher_telemetry=False)
    passive.sent.update({"bad_opcode": 1, "bad_arguments": 1})
    passive.telemetry = dict(healthy)
    passive.events.update({"Thermal.cmdDisp.InvalidCommand": 1, "Thermal.cmdDisp.OpCodeError": 1})
    assert passive.failures() == []
    passive.events["Thermal.cmdDisp.OpCodeError"] = 0
    assert [f for f in passive.failures() if "refusal events" in f and ": 1, expected 2" in f]
    # F´'s CommandDispatcher must count them in telemetry as well
    active = fuzz.Outcome(seed=1, dispatcher=DISPATCHER, noops_sent=1, noops_answered=1)
    active.sent.update(passive.sent)
    active.telemetry = dict(healthy)
    active.events.update({"Thermal.cmdDisp.InvalidCommand": 1, "Thermal.cmdDisp.OpCodeError": 1})
    assert active.failures() == ["Thermal.cmdDisp.CommandErrors: None, expected 2"]
    # ... unless every read-out overflowed the downlink: then its events alone count
    active.read_out_overflowed = True
    assert active.failures() == []
    active.events["Thermal.cmdDisp.OpCodeError"] = 0
    assert [f for f in active.failures() if "refusal events" in f]


def test_adapter_reconnects_and_never_raises(tmp_path: Path):
    path = tmp_path / "link.sock"
    adapter = UnixSocketAdapter(str(path))
    adapter.open()  # nothing listens yet: no error
    assert adapter.read(timeout=0.05) == b""
    assert adapter.write(b"x") is False
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(str(path))
    server.listen(1)
    received: list[bytes] = []

    def serve() -> None:
        connection, _ = server.accept()
        received.append(connection.recv(16))
        connection.sendall(b"down")
        connection.close()

    thread = threading.Thread(target=serve)
    thread.start()
    adapter._next_attempt = 0.0  # retry now rather than after RETRY_SECONDS
    assert adapter.write(b"up") is True
    assert adapter.read(timeout=2.0) == b"down"
    thread.join()
    assert received == [b"up"]
    assert adapter.read(timeout=0.2) == b""  # the peer closed: dropped, no exception
    adapter.close()
    server.close()


def test_adapter_refuses_a_path_that_is_not_a_socket(tmp_path: Path):
    (tmp_path / "file").write_text("")
    with pytest.raises(ValueError):
        UnixSocketAdapter.check_arguments(str(tmp_path / "file"))
    with pytest.raises(ValueError):
        UnixSocketAdapter.check_arguments(None)


def test_a_build_without_a_link_is_refused(tmp_path: Path):
    with pytest.raises(KitError, match="not a configured build"):
        ground.link_of(tmp_path)
    (tmp_path / "CMakeCache.txt").write_text("CMAKE_BUILD_TYPE:STRING=\n")
    with pytest.raises(KitError, match="no ground link"):
        ground.link_of(tmp_path)
    (tmp_path / "CMakeCache.txt").write_text("KIT_LINK_SOCKET:STRING=/tmp/x.sock\n")
    with pytest.raises(KitError, match="no F´ dictionary"):
        ground.link_of(tmp_path)


def test_kit_gds_refuses_an_unknown_board_or_model(capsys):
    from kittools import cli

    assert cli.main(["gds", "--board", "nucleo_f429zi"]) == 2
    assert "no kit port" in capsys.readouterr().err
    with pytest.raises(SystemExit):  # argparse: the variants are app/variants.yaml's
        cli.main(["gds", "--model", "superloop"])


def test_a_build_of_another_scenario_is_not_a_ground_station(tmp_path: Path):
    (tmp_path / "CMakeCache.txt").write_text(
        "KIT_LINK_SOCKET:STRING=/tmp/x.sock\nKIT_BOARD_TARGET:STRING=qemu_cortex_m3\n")
    dictionary = tmp_path / "build-artifacts" / "zephyr" / "dict" / "KitTopologyDictionary.json"
    dictionary.parent.mkdir(parents=True)
    dictionary.write_text("{}")
    (tmp_path / "zephyr").mkdir()
    (tmp_path / "zephyr" / ".config").write_text('CONFIG_KIT_SCENARIO="nominal"\n')
    with pytest.raises(KitError, match="does not play the ground scenario"):
        ground.GroundStation(tmp_path, tmp_path / "logs")


def test_halt_lines_start_at_the_first_sign_of_a_halt():
    running = ["*** Booting Zephyr OS ***", "KIT LINK ready uart=uart@40005000"]
    assert runner.halt_lines(running) == ""
    halted = [*running, "Assert: \"ComQueue.cpp:42\"", "KIT HALT reason=kernel_panic code=4",
              "PROJECT EXECUTION FAILED"]
    assert runner.halt_lines(halted).splitlines() == halted[2:]
    assert runner.halt_lines([*running, "ZEPHYR FATAL ERROR 2: Stack overflow"]).endswith("Stack overflow")


def test_the_dictionary_id_is_the_one_the_build_compiles_in(tmp_path: Path):
    """app/dictionary_header.cmake (compiled into the LINK line) and the
    ground tools (which compare against it) must name a dictionary alike;
    the header is rewritten only when it changes."""
    import shutil
    import subprocess

    dictionary = tmp_path / "KitTopologyDictionary.json"
    dictionary.write_text('{"metadata": {"projectVersion": "abc"}}\n')
    header = tmp_path / "KitDictionary.hpp"
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.skip("cmake is not on PATH")

    def generate() -> None:
        subprocess.run([cmake, f"-DDICTIONARY={dictionary}", f"-DOUTPUT={header}", "-P",
                        str(ground.KIT_ROOT / "app" / "dictionary_header.cmake")], check=True)

    generate()
    assert f'#define KIT_DICTIONARY_ID "{ground.dictionary_id(dictionary)}"' in header.read_text()
    written = header.stat().st_mtime_ns
    generate()
    assert header.stat().st_mtime_ns == written
    dictionary.write_text('{"metadata": {"projectVersion": "def"}}\n')
    generate()
    assert ground.dictionary_id(dictionary) in header.read_text()


def test_a_dictionary_that_is_not_there_is_refused(tmp_path: Path):
    (tmp_path / "CMakeCache.txt").write_text("KIT_LINK_SOCKET:STRING=/tmp/x.sock\n")
    with pytest.raises(KitError, match="no dictionary at"):
        ground.link_of(tmp_path, tmp_path / "missing.json")


def test_a_taken_gds_port_is_refused_before_anything_starts():
    holder = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    holder.bind(("127.0.0.1", 0))
    holder.listen()
    try:
        with pytest.raises(KitError, match="port .* is taken"):
            ground._check_port_free(holder.getsockname()[1])
    finally:
        holder.close()


def test_a_link_socket_is_free_unless_something_listens(tmp_path: Path):
    path = tmp_path / "link.sock"
    assert ground.socket_free(path)
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(str(path))
    server.listen()
    assert not ground.socket_free(path)
    server.close()
    assert ground.socket_free(path)  # stale file: QEMU rebinds it


def test_the_dictionary_header_counts_its_commands_and_channels(tmp_path: Path):
    """The compile-time checks of the fixed tables (app/src/DictionaryChecks.cpp)
    take these counts: one per opcode and per channel, zero where the
    dictionary lists none."""
    import shutil
    import subprocess

    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.skip("cmake is not on PATH")
    dictionary = tmp_path / "TopologyDictionary.json"
    header = tmp_path / "KitDictionary.hpp"

    def counts(content: dict[str, object]) -> str:
        dictionary.write_text(json.dumps(content))
        subprocess.run([cmake, f"-DDICTIONARY={dictionary}", f"-DOUTPUT={header}", "-P",
                        str(ground.KIT_ROOT / "app" / "dictionary_header.cmake")], check=True)
        return header.read_text()

    text = counts({"commands": [{"opcode": 1}, {"opcode": 2}, {"opcode": 3}], "telemetryChannels": [{"id": 7}]})
    assert "#define KIT_DICTIONARY_COMMANDS 3\n" in text
    assert "#define KIT_DICTIONARY_CHANNELS 1\n" in text
    text = counts({"metadata": {}})
    assert "#define KIT_DICTIONARY_COMMANDS 0\n" in text and "#define KIT_DICTIONARY_CHANNELS 0\n" in text
