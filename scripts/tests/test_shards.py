# SPDX-License-Identifier: Apache-2.0
"""A split run's shards, joined (kit report --merge), make the results a
single run makes, whichever shard held a board's builds and its floor."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from kittools import console
from kittools.sizes.memory import Footprint
from kittools.suite import results, shards
from kittools.workspace import KitError

from sample_console import console_log

BOARD = "qemu_cortex_m3"


def _played(variant: str, rom: int, board: str = BOARD) -> results.Played:
    run = console.parse(console_log(variant))
    link = [console.Record("SERIAL", {"axis": "uplink", "level": "50", "delivered": "100"})]
    return results.Played(board, variant, Footprint(rom, 20_000, 262_144, 65_536), run.records, link,
                          {"app": rom // 2}, {"app": 9_000}, {"CONFIG_KIT_MODEL": variant},
                          {"rom": {"main": 100}}, {"tables": []})


def _floors() -> results.Floors:
    return results.Floors(
        {"wfi": console.Record("FLOOR", {"path": "wfi", "p50": "120", "p99": "130", "max": "140",
                                         "min": "110", "cycles_hz": "12000000"}),
         "msgq": console.Record("FLOOR", {"path": "msgq", "p50": "300", "p99": "320", "max": "340",
                                          "min": "290", "cycles_hz": "12000000"})},
        [console.Record("ZEPHYR", {"metric": "switch", "cycles": "200"})])


def _write_split(tmp_path: Path, parts: list[list[results.Played]], floor_in: int) -> list[Path]:
    dirs = []
    for k, played in enumerate(parts, start=1):
        folder = tmp_path / f"shard{k}"
        shards.start(folder, f"{k}/{len(parts)}")
        floors = _floors() if k == floor_in else results.Floors()
        shards.write(shards.BoardShard(BOARD, played, floors), folder)
        dirs.append(folder)
    return dirs


def test_joined_shards_equal_the_single_run(tmp_path: Path) -> None:
    everything = [_played("rtos", 150_000), _played("baremetal", 140_000), _played("baremetal_passive", 139_000)]
    single = results.assemble(everything, _floors(), BOARD).to_json()
    # The floor in the shard without the rtos build, and in the one with it
    for floor_in in (1, 2):
        dirs = _write_split(tmp_path / str(floor_in), [everything[:1], everything[1:]], floor_in)
        joined = shards.merge(dirs)[BOARD].results().to_json()
        assert json.dumps(joined, sort_keys=True) == json.dumps(single, sort_keys=True)
    # the floor reached each variant's metrics (the rtos one through the other shard)
    assert any(r["kind"] == "FLOOR" and r["path"] == "msgq" for r in single["variants"]["rtos"]["records"])


def test_a_merge_needs_every_share_once(tmp_path: Path) -> None:
    dirs = _write_split(tmp_path, [[_played("rtos", 1)], [_played("baremetal", 2)], []], floor_in=1)
    with pytest.raises(KitError, match="3/3 missing"):
        shards.merge(dirs[:2])
    with pytest.raises(KitError, match="both share 1"):
        shards.merge([dirs[0], dirs[0]])
    plain = tmp_path / "plain"
    plain.mkdir()
    with pytest.raises(KitError, match="not the output folder of a kit test --subset"):
        shards.merge([plain])


def test_a_new_run_leaves_no_earlier_shard_behind(tmp_path: Path) -> None:
    (folder,) = _write_split(tmp_path, [[_played("rtos", 1)]], floor_in=1)
    shards.start(folder, None)  # a full run into the same folder
    assert not list(folder.glob(f"*/{shards.SHARD_FILE}")) and not (folder / shards.SUBSET_FILE).exists()


def test_the_merge_ends_with_every_board_side_by_side(tmp_path: Path) -> None:
    # As a single run ends: <output>/boards/, once two boards have results
    import argparse

    from kittools.commands import report

    dirs = []
    for k, board in enumerate(("nucleo_f401re", "nucleo_g071rb"), start=1):
        folder = tmp_path / f"shard{k}"
        shards.start(folder, f"{k}/2")
        built = results.assemble([_played("baremetal", 140_000 + k, board)], results.Floors(), board)
        shards.write(shards.BoardShard(board, built_only=built), folder)
        dirs.append(str(folder))
    out = tmp_path / "merged"
    args = argparse.Namespace(merge=dirs, results=None, baseline=None, output=str(out))
    assert report.run(args) == 0
    assert (out / "nucleo_f401re" / "results.json").is_file() and (out / "nucleo_g071rb" / "results.json").is_file()
    side_by_side = (out / "boards" / "report.md").read_text()
    header = side_by_side.split("## Boards side by side\n\n", 1)[1].splitlines()[0]
    assert header.count("baremetal") == 2  # a column per board's build
