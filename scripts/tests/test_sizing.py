# SPDX-License-Identifier: Apache-2.0
from kittools.report import writer
from kittools.sizes import ports, sizing

from test_report import _results


def _advice(current: int, needed: int, must_fit: bool = True) -> sizing.Advice:
    return sizing.Advice("telemetry buckets (TlmChan)", "TLMCHAN_HASH_BUCKETS", current, needed, 152,
                         f"{needed} channels in the dictionary", must_fit)


def test_a_table_smaller_than_the_dictionary_is_a_fault_not_a_saving():
    small = _advice(32, 36)
    assert (small.verdict, small.spare_bytes) == ("TOO SMALL", -608)
    assert sizing.too_small([small]) == [
        "telemetry buckets (TlmChan): 32 < 36 needed (36 channels in the dictionary); raise TLMCHAN_HASH_BUCKETS"]
    assert sizing.too_small([_advice(36, 36), _advice(40, 36), _advice(2, 5, must_fit=False)]) == []
    assert (_advice(36, 36).verdict, _advice(40, 36).verdict, _advice(2, 5, False).verdict) == (
        "exact", "spare", "below the measure")


def test_advice_survives_the_results_file():
    for advice in (_advice(32, 36), _advice(8, 13, must_fit=False)):
        assert sizing.Advice.from_json(advice.to_json()) == advice


def test_queues_are_advised_from_the_run_high_water_marks():
    [queue] = sizing.queue_advice([{"name": "cmdDisp", "depth": "8", "slot_bytes": "148", "high_water": "2"}])
    assert (queue.current, queue.needed, queue.spare_bytes, queue.must_fit) == (8, 2, 888, False)


def test_a_queue_that_dropped_needed_more():
    [queue] = sizing.queue_advice([{"name": "comQueue", "depth": "8", "slot_bytes": "148", "high_water": "8",
                                    "dropped": "3"}])
    assert (queue.needed, queue.verdict) == (9, "below the measure")
    assert "dropped 3 messages" in queue.basis


def test_the_report_shows_sizing_and_ports(tmp_path):
    data = _results()
    cost = ports.PortCost([ports.InstancePorts("cmdDisp", "CommandDispatcherImpl", 1544, 14, 16, 280, 192)])
    for variant in data.variants.values():
        variant.sizing = sizing.Sizing([_advice(36, 36)], cost).to_json()
    writer.write(data, tmp_path)
    text = (tmp_path / "report.md").read_text()
    assert "Sizing advice" in text and "TLMCHAN_HASH_BUCKETS" in text
    assert "Ports:" in text and "30.6%" in text  # (280 + 192) / 1544


def _alias(name: str, bits: int) -> dict:
    integer = {"name": f"U{bits}", "kind": "integer", "size": bits, "signed": False}
    return {"kind": "alias", "qualifiedName": name, "type": integer, "underlyingType": integer}


def test_the_largest_packet_is_measured_as_f_prime_serializes_it():
    u32 = {"name": "U32", "kind": "integer", "size": 32, "signed": False}
    dictionary = {
        "typeDefinitions": [_alias("FwPacketDescriptorType", 16), _alias("FwOpcodeType", 32),
                            _alias("FwEventIdType", 32), _alias("FwChanIdType", 32), _alias("FwSizeStoreType", 16),
                            _alias("FwTimeBaseStoreType", 16), _alias("FwTimeContextStoreType", 8),
                            {"kind": "enum", "qualifiedName": "Kit.Mode",
                             "representationType": {"name": "U8", "kind": "integer", "size": 8, "signed": False}},
                            {"kind": "array", "qualifiedName": "Kit.Four", "size": 4, "elementType": u32}],
        "commands": [{"name": "Kit.c.SAY", "formalParams": [{"type": {"kind": "string", "size": 40}},
                                                              {"type": {"kind": "qualifiedIdentifier",
                                                                        "name": "Kit.Mode"}}]}],
        "events": [{"name": "Kit.e.ASSERT", "formalParams": [{"type": {"kind": "string", "size": 64}},
                                                              {"type": u32}]}],
        "telemetryChannels": [{"name": "Kit.t.Four", "type": {"kind": "qualifiedIdentifier", "name": "Kit.Four"}}],
    }
    # command 2+4+(2+40)+1 = 49; event 2+4+11+(2+64)+4 = 87; channel 2+4+11+16 = 33
    assert sizing.largest_packet(dictionary) == (87, "event Kit.e.ASSERT")
    # F´ truncates an event's strings to FW_LOG_STRING_MAX_SIZE, a command's
    # to FW_CMD_STRING_MAX_SIZE: event 2+4+11+(2+12)+4 = 35, command 2+4+(2+30)+1 = 39
    config = {"CONFIG_FPRIME_LOG_STRING_MAX_SIZE": "12", "CONFIG_FPRIME_CMD_STRING_MAX_SIZE": "30"}
    assert sizing.largest_packet(dictionary, config) == (39, "command Kit.c.SAY")


def test_sizing_refuses_a_log_without_queues(tmp_path, capsys):
    from kittools import cli

    log = tmp_path / "console.log"
    log.write_text("KIT BANNER variant=rtos\n*** Booting Zephyr ***\n")  # a run cut before its records
    assert cli.main(["sizing", str(tmp_path), "--log", str(log)]) == 2
    assert "has no KIT QUEUE lines" in capsys.readouterr().err
    assert cli.main(["sizing", str(tmp_path), "--log", str(tmp_path / "missing.log")]) == 2
    assert "no console log" in capsys.readouterr().err


def test_version_channels_no_path_writes_are_counted_out(tmp_path):
    # Svc.Version's dictionary: framework, project, ten library slots, ten
    # custom ones; a build with two libraries writes four of them
    names = ["version.FrameworkVersion", "version.ProjectVersion"]
    names += [f"version.LibraryVersion{i:02}" for i in range(1, 11)]
    names += [f"version.CustomVersion{i:02}" for i in range(1, 11)]
    channels = [{"name": f"Kit.{n}"} for n in names] + [{"name": "Kit.health.PingLateWarnings"}]
    assert sizing.silent_version_channels(channels, 2) == 18
    assert sizing.silent_version_channels(channels, 10) == 10
    # a channel of that name in a component that is not Svc.Version counts
    assert sizing.silent_version_channels([{"name": "Kit.mine.CustomVersion01"}], 2) == 0
    # F´'s generated count, read from the build; every slot when it is missing
    assert sizing.version_libraries(tmp_path) == 10
    (tmp_path / "versions").mkdir()
    (tmp_path / "versions" / "version.cpp").write_text(
        "    const FwIndexType Version::LIBRARY_VERSIONS_COUNT = 2; \n")
    assert sizing.version_libraries(tmp_path) == 2
