# SPDX-License-Identifier: Apache-2.0
"""The link's line rate and byte accounting without QEMU: what the serial
sweep and the flood offer per point, and how they account for every byte."""

from __future__ import annotations

import json
from pathlib import Path
from unittest import mock

import pytest

from kittools.link import client, flood, serial_points
from kittools.link.client import START_WORD_BYTES, bytes_per_second, line_rate
from kittools.link.health import LinkCounts
from kittools.link.serial_points import Offer, PointTraffic, SegmentClock, traffic_time
from kittools.workspace import KitError

NOOP = bytes(18)
# The reference deployment's: a 1 kHz tick, its 10 Hz group's hyperperiod
REFERENCE_CLOCK = SegmentClock(1000, 100)
POINT_S = REFERENCE_CLOCK.point_s()


def test_the_line_rate_comes_from_the_link_line():
    assert line_rate("KIT LINK ready uart=uart@4000d000 baud=115200 uart_errors=unsupported dictionary=ab") == 115200
    assert bytes_per_second(115200) == 11520
    with pytest.raises(KitError, match="no line rate"):
        line_rate("KIT LINK ready uart=uart@4000d000 dictionary=ab")


def test_noise_frames_nothing():
    import random

    data = client.noise(random.Random(1), 10_000)
    assert len(data) == 10_000 and not set(data) & START_WORD_BYTES


def play(offer: Offer, steps: list[float]) -> tuple[PointTraffic, bytes]:
    traffic = PointTraffic("noise", 0, 50)
    sent = b""
    for elapsed in steps:
        sent += offer.due(elapsed, traffic)
    return traffic, sent


def test_a_point_offers_the_same_traffic_whatever_the_host_timing():
    """Two hosts see the deployment's clock at different moments: the same
    bytes go up, only in other chunks (a slow host takes longer)."""
    coarse = [i * 0.1 for i in range(3000)]
    fine = [i * 0.003 for i in range(1000)]
    a_traffic, a_bytes = play(Offer(NOOP, POINT_S, 40, 5000, seed=7), coarse)
    b_traffic, b_bytes = play(Offer(NOOP, POINT_S, 40, 5000, seed=7), fine)
    assert a_traffic.commands_sent == b_traffic.commands_sent == int(40 * POINT_S)
    assert len(a_bytes) == len(b_bytes) == a_traffic.commands_sent * len(NOOP) + int(5000 * POINT_S)


def test_a_segment_is_whole_hyperperiods_of_the_deployment():
    """Timing refuses any other length: the sweep asks for the whole number
    of hyperperiods nearest its second, the flood for those nearest its 10 s."""
    assert REFERENCE_CLOCK.segment_ticks() == 1000 and POINT_S == pytest.approx(1.2)
    template = SegmentClock(1000, 80)  # fprime-util's template: 50, 25 and 12.5 Hz groups
    assert template.segment_ticks() == 1040 and template.ticks(flood.FLOOD_S) == 10_000
    thermal = SegmentClock(1000, 1000)  # tests/team/Thermal: its 1 Hz group; the point covers the wait for it
    assert thermal.segment_ticks() == 1000 and thermal.point_s() == pytest.approx(2.1)
    slow = SegmentClock(500, 1500)  # longer than a second: one hyperperiod
    assert slow.segment_ticks() == 1500 and slow.seconds(slow.segment_ticks()) == 3.0
    assert SegmentClock(1000, 300).segment_ticks() == 900  # 3.33 hyperperiods: the nearest is 3


def test_a_banner_gives_the_segment_clock_and_an_old_build_one_clear_error():
    lines = ["*** Booting Zephyr OS ***",
             "KIT BANNER variant=rtos board=mps2/an385 tick_hz=1000 run_ticks=2000 hyperperiod_ticks=80"]
    assert SegmentClock.of_console(lines) == SegmentClock(1000, 80)
    with pytest.raises(KitError, match="older kit; rebuild it"):
        SegmentClock.of_console(["KIT BANNER variant=rtos tick_hz=1000 run_ticks=2000"])
    with pytest.raises(KitError, match="no line"):
        SegmentClock.of_console([])


def test_a_late_host_does_not_make_up_its_lag_in_a_burst():
    schedule = serial_points.Schedule(200, 240)
    assert schedule.due(0.05) == 2  # 10 owed, CATCH_UP_S of it (2) goes: the schedule slips
    assert schedule.due(0.05) == 0
    assert schedule.due(0.055) == 1  # then on at its rate from there
    assert schedule.due(0.065) == 2
    # A slow rate still moves: one at a time however late
    slow = serial_points.Schedule(10, 12)
    assert slow.due(5.0) == 1 and slow.due(5.05) == 0 and slow.due(5.1) == 1


def test_an_offer_is_complete_only_when_all_its_traffic_went():
    offer = Offer(NOOP, POINT_S, 10, 1000)
    traffic = PointTraffic("noise", 0, 50)
    offer.due(0.5, traffic)
    assert not offer.complete()
    for step in range(1, 2000):
        offer.due(0.5 + step * 0.01, traffic)
    assert offer.complete() and traffic.commands_sent == int(10 * POINT_S)


class FakeLink:
    """A link whose deployment clock the test sets."""

    def __init__(self) -> None:
        self.clock = 0.0
        self.writes: list[bytes] = []

    def estimated_now(self) -> float:
        return self.clock

    def unsent(self) -> int:
        return 0

    def send(self, data: bytes) -> None:
        self.writes.append(data)


def test_a_line_carries_no_more_than_its_rate_and_a_burst_at_once():
    link = FakeLink()
    line = client.Line(link, 115200)  # type: ignore[arg-type]
    assert line.burst == int(11520 * client.LINE_BURST_S)
    line.put(bytes(20000))
    assert line.feed() == line.burst  # a full credit at the start
    link.clock = 0.1  # a host that came back late: still one burst
    assert line.feed() == line.burst
    for step in range(1, 1001):  # then the line rate, over a second of LINE_STEP_S steps
        link.clock = 0.1 + step * client.LINE_STEP_S
        line.feed()
    assert sum(map(len, link.writes)) == pytest.approx(2 * line.burst + 11520, abs=line.burst)
    assert max(map(len, link.writes)) == line.burst
    link.clock = 0.5  # a clock that stepped back (a late time tag) gives no credit
    assert line.feed() == 0
def test_the_quiet_before_a_request_is_skipped_not_made_up():
    quiet_from = serial_points.SETTLE_S - serial_points.REQUEST_QUIET_S
    assert traffic_time(quiet_from / 2) == quiet_from / 2
    assert traffic_time(quiet_from + serial_points.REQUEST_QUIET_S / 2) == pytest.approx(quiet_from)
    assert traffic_time(serial_points.SETTLE_S + 1) == pytest.approx(quiet_from + 1)


def test_at_full_noise_the_noops_and_the_noise_fill_the_line():
    per_s = serial_points.noise_per_second(115200, NOOP, 100) + serial_points.NOISE_NOOP_RATE * len(NOOP)
    assert per_s == pytest.approx(11520)
    assert serial_points.noise_per_second(115200, NOOP, 0) == 0
    assert serial_points.full_line_commands(115200, NOOP) == 640


def test_link_counts_are_deltas_and_positions_count_each_decision():
    before = LinkCounts(frames_detected=2, uart_received=100, ring_drops=0, bytes_discarded=10)
    after = LinkCounts(frames_detected=5, uart_received=400, ring_drops=50, bytes_discarded=196, bad_checksums=1)
    got = after.since(before)
    assert got.uart_received == 300 and got.ring_drops == 50
    # Three whole frames of 18 bytes, and one position per other decision
    assert got.positions(18) == 3 * 18 + 186 + 1


def test_link_counts_read_the_error_kinds_together():
    class Link:
        telemetry = {"Kit.linkHealth.UartBytesReceived": 7, "Kit.linkHealth.UartOverruns": 2,
                     "Kit.linkHealth.UartFramingErrors": 1}

    counts = LinkCounts.of(Link())  # type: ignore[arg-type]
    assert counts.uart_received == 7 and counts.uart_errors == 3 and counts.frames_detected == 0


def test_a_flood_accounts_for_every_byte_or_says_which_are_missing():
    counts = LinkCounts(frames_detected=21, uart_received=1000, ring_drops=100, bytes_discarded=1000 - 100 - 394)
    outcome = flood.Outcome(baud=115200, bytes_sent=1000, noops_sent=20, noops_answered=20, counts=counts,
                            request_bytes=34, noop_bytes=18, sweep_lines=["a", "b", "c"])
    assert outcome.frame_bytes() == 394
    assert outcome.unaccounted() == 0 and outcome.failures() == []
    assert "unaccounted=0" in outcome.record()
    short = flood.Outcome(baud=115200, bytes_sent=1200, noops_sent=20, noops_answered=19,
                          counts=LinkCounts(frames_detected=20, uart_received=1000, ring_drops=100,
                                            bytes_discarded=600),
                          request_bytes=34, noop_bytes=18, halt="ASSERT x")
    failures = short.failures()
    assert any("19 of 20" in f for f in failures)
    assert any("1000 bytes of the 1200" in f for f in failures)
    assert any("not decided on" in f for f in failures)  # more decided than kept
    assert any("asserted or halted" in f for f in failures)
    assert any("no SWEEP lines" in f for f in failures)
    # Its segment's lines are not a point of the noise axis
    assert all(not line.startswith("KIT SWEEP") for line in outcome.to_json()["lines"])


class _FakeClock:
    """A clock that advances only when slept on, so pacing is exact."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.now += seconds


def test_the_gds_adapter_writes_a_file_packet_at_the_line_rate():
    """fprime-gds's 281 B file-packet frame leaves in pieces of 2 ms of the
    line, and the last piece leaves when the line has carried the others."""
    from kittools.link.gds_adapter import HostLine

    clock = _FakeClock()
    line = HostLine(115200, clock=clock, sleep=clock.sleep)
    start = clock.now
    pieces = list(line.pieces(bytes(281)))
    assert b"".join(pieces) == bytes(281)
    assert {len(piece) for piece in pieces[:-1]} == {23}
    assert clock.now - start == pytest.approx((281 - len(pieces[-1])) / 11520)
    # The next write waits for the line to carry the last piece
    list(line.pieces(bytes(1)))
    assert clock.now - start == pytest.approx(281 / 11520)


def test_an_idle_line_banks_no_time():
    from kittools.link.gds_adapter import HostLine

    clock = _FakeClock()
    line = HostLine(115200, clock=clock, sleep=clock.sleep)
    list(line.pieces(bytes(10)))
    clock.now += 60.0
    start = clock.now
    list(line.pieces(bytes(46)))
    assert clock.now - start == pytest.approx(23 / 11520)


def test_a_file_level_asks_for_parts_of_the_bulk_file_at_its_rate():
    # A part every FILE_PERIOD_S while a part that size fits the file ...
    part, per_s = serial_points.file_request(2048, 16384)
    assert part == int(2048 * serial_points.FILE_PERIOD_S) and per_s * part == pytest.approx(2048)
    # ... then the whole file, more often; nothing at level 0
    part, per_s = serial_points.file_request(11520, 2048)
    assert part == 2048 and per_s == pytest.approx(11520 / 2048)
    assert serial_points.file_request(0, 2048) == (0, 0.0)


def test_a_file_point_offers_the_bytes_asked_for_and_delivers_those_received():
    traffic = PointTraffic(serial_points.FILE.name, 0, 2048, file_bytes_asked=1536, file_bytes_received=1024)
    assert (traffic.offered(), traffic.delivered()) == (1536, 1024)
    assert "offered=1536 delivered=1024 lost=512" in traffic.record()


# The least of a dictionary fprime-gds loads: file packets need none of it
EMPTY_DICTIONARY = {"metadata": {"deploymentName": "Kit", "projectVersion": "test", "frameworkVersion": "4.1.0",
                                 "libraryVersions": [], "dictionarySpecVersion": "1.0.0"},
                    "typeDefinitions": [], "constants": [], "commands": [], "parameters": [], "events": [],
                    "telemetryChannels": [], "records": [], "containers": [], "telemetryPacketSets": []}


def test_the_downlink_counts_file_data_bytes_and_ended_files(tmp_path: Path):
    dictionary = tmp_path / "KitTopologyDictionary.json"
    dictionary.write_text(json.dumps(EMPTY_DICTIONARY))
    # No QEMU: the socket is never read, the frames are decoded as they would be
    with mock.patch("socket.socket"):
        link = client.Downlink(tmp_path / "link.sock", dictionary)
    header = client.DESCRIPTOR.pack(client.FW_PACKET_FILE)
    data = header + client.FILE_PACKET_HEADER.pack(client.T_DATA, 1) + client.FILE_DATA_FIELDS.pack(0, 5) + bytes(5)
    end = header + client.FILE_PACKET_HEADER.pack(client.T_END, 2) + bytes(4)
    cut_short = header + bytes([client.T_DATA])
    link._decode(b"".join(client.frame(packet) for packet in (data, data, end, cut_short)))
    assert (link.file_bytes, link.files_ended) == (10, 1)


def test_every_serial_axis_is_judged_as_host_timed():
    from kittools import sweep

    assert {axis.unit for axis in serial_points.AXES} <= set(sweep.HOST_TIMED_UNITS)


def test_the_downlink_axis_offers_what_the_deployments_slices_can():
    """Packets per slice times the slices' rate: the reference's 100 Hz
    slices offer the axis' levels; slower slices the nearest each can, up to
    Load's 16 a slice, and no level twice."""
    assert serial_points.downlink_levels(100) == [(0, 0), (100, 1), (200, 2), (400, 4), (800, 8), (1600, 16)]
    assert serial_points.downlink_levels(50) == [(0, 0), (100, 2), (200, 4), (400, 8), (800, 16)]
    assert serial_points.downlink_levels(40) == [(0, 0), (120, 3), (200, 5), (400, 10), (640, 16)]
    assert serial_points.downlink_levels(1000) == [(0, 0), (1000, 1), (2000, 2)]
