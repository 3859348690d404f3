# SPDX-License-Identifier: Apache-2.0
from kittools import ports, report, sizing

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


def test_the_report_shows_sizing_and_ports(tmp_path):
    data = _results()
    cost = ports.PortCost([ports.InstancePorts("cmdDisp", "CommandDispatcherImpl", 1544, 14, 16, 280, 192)])
    for variant in data.variants.values():
        variant.sizing = sizing.Sizing([_advice(36, 36)], cost).to_json()
    report.write(data, tmp_path)
    text = (tmp_path / "report.md").read_text()
    assert "Sizing advice" in text and "TLMCHAN_HASH_BUCKETS" in text
    assert "Ports:" in text and "30.6%" in text  # (280 + 192) / 1544
