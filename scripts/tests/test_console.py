# SPDX-License-Identifier: Apache-2.0
import pytest

from kittools import console

from sample_console import console_log


def test_parses_every_kit_line_and_ignores_the_rest():
    run = console.parse(console_log())
    assert [r.kind for r in run.records] == ["BANNER", "RG", "TASK", "HIST", "HASH", "CMD", "STACK", "CPU", "CPU",
                                             "END"]
    assert run.one("TASK").fields["context"] == "slice"
    assert run.variant == "baremetal"
    assert run.passed
    assert run.one("RG").int("latency_max") == 1200
    assert run.one("CMD").int("opcode") == 0x500


def test_failed_end_line_is_not_a_pass():
    assert not console.parse(console_log(result="FAIL")).passed


def test_run_without_end_line_is_incomplete():
    text = "\n".join(console_log().splitlines()[:-1])
    with pytest.raises(console.ConsoleError, match="did not finish"):
        console.parse(text)


def test_empty_console_did_not_start():
    with pytest.raises(console.ConsoleError, match="did not start"):
        console.parse("qemu-system-arm: warning: nic has no peer\n")


def test_missing_and_malformed_fields_name_the_field():
    record = console.parse_line("KIT RG name=rg1kHz cycles=abc")
    assert record is not None
    with pytest.raises(console.ConsoleError, match="cycles"):
        record.int("cycles")
    with pytest.raises(console.ConsoleError, match="slips"):
        record.int("slips")


def test_non_kit_lines_are_not_records():
    assert console.parse_line("KITTEN END") is None
    assert console.parse_line("[Os::Console] KIT END") is None
