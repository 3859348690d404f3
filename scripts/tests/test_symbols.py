# SPDX-License-Identifier: Apache-2.0
import copy
import json

from kittools import cli, model
from kittools.report import writer
from kittools.sizes import by_layer, symbols
from kittools.suite import budget

from test_report import _results


def _report(*leaves: tuple[str, str, int]) -> dict:
    """A Zephyr rom/ram report tree: (top-level group, identifier, size) leaves."""
    groups: dict[str, list[dict]] = {}
    for group, identifier, size in leaves:
        groups.setdefault(group, []).append({"identifier": identifier, "name": identifier.rsplit("/", 1)[-1],
                                             "size": size})
    return {"symbols": {"children": [{"name": g, "identifier": g, "children": c} for g, c in groups.items()]},
            "total_size": sum(s for _, _, s in leaves)}


def test_leaves_key_by_name_and_tell_same_named_statics_apart():
    found = symbols.leaves(_report(
        ("WORKSPACE", "app/src/Report.cpp/_ZN3Kit6Report5printEv", 300),
        ("WORKSPACE", "app/src/A.cpp/helper", 20), ("WORKSPACE", "app/src/B.cpp/helper", 24),
        ("ZEPHYR_BASE", "kernel/sched.c/z_swap", 0)))
    assert [(leaf.key, leaf.size) for leaf in found] == [
        ("_ZN3Kit6Report5printEv", 300), ("helper@A.cpp", 20), ("helper@B.cpp", 24)]
    assert found[0].layer == by_layer.INSTRUMENTS  # the record


def test_a_constructor_alias_swap_is_no_change():
    before = symbols.table(symbols.leaves(_report(("WORKSPACE", "app/T.cpp/_ZN3Kit6TimingC1EPKc", 160),
                                                  ("WORKSPACE", "app/T.cpp/_ZN3Kit6TimingD1Ev", 40))))
    now = symbols.table(symbols.leaves(_report(("WORKSPACE", "app/T.cpp/_ZN3Kit6TimingC2EPKc", 160),
                                               ("WORKSPACE", "app/T.cpp/_ZN3Kit6TimingD2Ev", 40))))
    assert not symbols.diff(before, now, "rom").changed


def test_diff_sorts_changes_like_bloat_o_meter():
    before = {"kept": 100, "grows": 50, "shrinks": 80, "goes": 30}
    now = {"kept": 100, "grows": 90, "shrinks": 60, "comes": 12}
    result = symbols.diff(before, now, "rom")
    assert [d.key for d in result.added] == ["comes"]
    assert [d.key for d in result.removed] == ["goes"]
    assert [(d.key, d.delta) for d in result.grown] == [("grows", 40)]
    assert [(d.key, d.delta) for d in result.shrunk] == [("shrinks", -20)]
    assert (result.up, result.down) == (52, -50)
    assert result.summary() == ("ROM: add/remove: 1/1 grow/shrink: 1/1 up/down: 52/-50 (+2); total 260 -> 262")
    assert [d.key for d in result.rows()] == ["grows", "goes", "shrinks", "comes"]
    text = symbols.render(result, limit=2)
    assert text[0] == result.summary() and text[-1] == "... and 2 more" and len(text) == 5


def test_a_floor_sums_small_symbols_per_layer():
    found = symbols.leaves(_report(("WORKSPACE", "app/src/Big.cpp/big", 400),
                                   ("WORKSPACE", "app/src/S.cpp/small1", 10),
                                   ("WORKSPACE", "app/src/S.cpp/small2", 30),
                                   ("ZEPHYR_BASE", "kernel/sched.c/z_tiny", 8)))
    table = symbols.table(found, floor=128)
    assert table == {"big": 400, f"(symbols under 128 B: {by_layer.INSTRUMENTS})": 40,
                     f"(symbols under 128 B: {by_layer.ZEPHYR})": 8}
    assert sum(table.values()) == sum(leaf.size for leaf in found)


def _with_symbols(data: model.Results, rom: dict[str, int]) -> model.Results:
    for variant in data.variants.values():
        variant.symbols = {"rom": dict(rom), "ram": {"buffer": 512}}
    return data


def test_a_failed_size_budget_says_which_symbols_grew(tmp_path):
    baseline = _with_symbols(_results(), {"Svc::ComQueue::run": 400, "(symbols under 128 B: F´ framework)": 900})
    worse = copy.deepcopy(baseline)
    worse.variants["rtos"].metrics[model.ROM] *= 1.05
    worse.variants["rtos"].symbols["rom"]["Svc::ComQueue::run"] = 5400
    verdict = budget.check(worse, baseline)
    assert verdict.over_size == {"rtos"}
    assert [(name, d.summary()) for name, d in verdict.sizes] == [
        ("rtos", "ROM: add/remove: 0/0 grow/shrink: 1/0 up/down: 5000/0 (+5000); total 1300 -> 6300")]
    writer.write(worse, tmp_path, baseline=baseline)
    text = (tmp_path / "report.md").read_text()
    assert "rtos: ROM symbols against the baseline" in text and "Svc::ComQueue::run" in text


def test_symbols_survive_the_results_file_and_a_baseline(tmp_path):
    data = _with_symbols(_results(), {"a": 300})
    back = model.Results.from_json(json.loads(json.dumps(data.to_json(with_records=False))))
    assert back.variants["rtos"].symbols == {"rom": {"a": 300}, "ram": {"buffer": 512}}


def test_sizediff_between_results_files(tmp_path, capsys):
    before = _with_symbols(_results(), {"a": 300, "b": 200})
    now = _with_symbols(_results(), {"a": 350, "c": 130})
    paths = []
    for name, data in (("before.json", before), ("now.json", now)):
        paths.append(tmp_path / name)
        paths[-1].write_text(json.dumps(data.to_json()))
    assert cli.main(["sizediff", str(paths[0]), str(paths[1]), "--model", "rtos", "--kind", "rom"]) == 0
    out = capsys.readouterr().out
    assert "ROM: add/remove: 1/1 grow/shrink: 1/0 up/down: 180/-200 (-20)" in out
    assert cli.main(["sizediff", str(paths[0]), str(paths[1])]) == 2  # two variants: which?
    assert "name one with --model" in capsys.readouterr().err
    # --variant, its name before every command took --model, still works
    assert cli.main(["sizediff", str(paths[0]), str(paths[1]), "--variant", "rtos", "--kind", "rom"]) == 0
