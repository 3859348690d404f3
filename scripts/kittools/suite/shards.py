# SPDX-License-Identifier: Apache-2.0
"""A full `kit test` split across machines (`kit test --subset K/N`) and
joined again (`kit report --merge DIR...`).

Twister's own `--subset K/N` gives each shard part of the suite's builds: a
board's variants, its kernel-floor builds and its real boards' builds may
land in different shards. So a shard writes no results file: it writes, per
board, what it made of that board (`shard.json`): each QEMU build's part
(kittools.suite.results.Played) and the floor builds' records, or a real board's
builds' results. The merge joins every shard's parts per board and makes the
results exactly as a single run does (kittools.suite.results.assemble): the same
records in the same order, the same metrics.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from kittools import console, model
from kittools.sizes.memory import Footprint
from kittools.suite import results
from kittools.workspace import KitError, check_board

#: A shard's file per board, in <shard output>/<board folder>/
SHARD_FILE = "shard.json"
SHARD_SCHEMA = 1
#: In a shard's output folder: its share, K/N
SUBSET_FILE = "subset.json"


def start(log_dir: Path, subset: str | None) -> None:
    """Before a run into `log_dir`: an earlier run's shard files go (a
    merge must not take another run's part), and a shard says its share."""
    for stale in [*log_dir.glob(f"*/{SHARD_FILE}"), log_dir / SUBSET_FILE]:
        stale.unlink(missing_ok=True)
    if subset:
        log_dir.mkdir(parents=True, exist_ok=True)
        (log_dir / SUBSET_FILE).write_text(json.dumps({"subset": subset}) + "\n")


def check_complete(dirs: list[Path]) -> None:
    """KitError unless `dirs` are the shards of one split: the same N, every
    K from 1 to N once."""
    shares: dict[int, Path] = {}
    splits = set()
    for folder in dirs:
        path = folder / SUBSET_FILE
        try:
            k, n = (int(x) for x in json.loads(path.read_text())["subset"].split("/"))
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise KitError(f"{folder} is not the output folder of a kit test --subset K/N run (no readable "
                           f"{SUBSET_FILE}: {error})") from error
        if k in shares:
            raise KitError(f"{folder} and {shares[k]} are both share {k}: give each share of the split once")
        shares[k] = folder
        splits.add(n)
    if len(splits) != 1:
        raise KitError(f"the folders come from splits into different numbers of shares ({sorted(splits)})")
    n = splits.pop()
    missing = sorted(set(range(1, n + 1)) - set(shares))
    if missing:
        raise KitError(f"share(s) {', '.join(f'{k}/{n}' for k in missing)} missing: the merge needs every share "
                       f"of the split to be equal to a single run")


def _records_json(records: list[console.Record]) -> list[dict[str, str]]:
    return [{"kind": r.kind, **r.fields} for r in records]


def _records(data: list[dict[str, str]]) -> list[console.Record]:
    return [console.Record(r["kind"], {k: v for k, v in r.items() if k != "kind"}) for r in data]


def played_json(part: results.Played) -> dict[str, Any]:
    f = part.footprint
    return {"platform": part.platform, "variant": part.variant,
            "footprint": {"rom": f.rom, "ram": f.ram, "rom_size": f.rom_size, "ram_size": f.ram_size},
            "records": _records_json(part.records), "link_records": _records_json(part.link_records),
            "rom_modules": part.rom_modules, "ram_modules": part.ram_modules, "build": part.build,
            "symbols": part.symbols, "sizing": part.sizing}


def played_of(data: dict[str, Any]) -> results.Played:
    return results.Played(
        data["platform"], data["variant"], Footprint(**data["footprint"]), _records(data["records"]),
        _records(data["link_records"]), dict(data["rom_modules"]), dict(data["ram_modules"]),
        dict(data["build"]), {k: dict(v) for k, v in data["symbols"].items()}, dict(data["sizing"]))


@dataclass
class BoardShard:
    """What one shard made of one board."""

    board: str
    played: list[results.Played] = field(default_factory=list)
    floors: results.Floors = field(default_factory=results.Floors)
    #: a real board's builds (tests/boards): results of the shard's builds
    built_only: model.Results | None = None

    def to_json(self) -> dict[str, Any]:
        return {"schema": SHARD_SCHEMA, "board": self.board,
                "played": [played_json(p) for p in self.played],
                "floors": _records_json(list(self.floors.paths.values())),
                "zephyr": _records_json(self.floors.zephyr),
                "built_only": self.built_only.to_json() if self.built_only is not None else None}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> BoardShard:
        floors = results.Floors({r.fields["path"]: r for r in _records(data["floors"])}, _records(data["zephyr"]))
        built = model.Results.from_json(data["built_only"]) if data.get("built_only") else None
        return cls(data["board"], [played_of(p) for p in data["played"]], floors, built)

    def add(self, other: BoardShard) -> None:
        self.played += other.played
        self.floors.add(other.floors)
        if other.built_only is not None:
            if self.built_only is None:
                self.built_only = model.Results(dict(other.built_only.conditions), {})
            self.built_only.variants.update(other.built_only.variants)

    def results(self) -> model.Results:
        """The board's results, as a single run makes them."""
        if self.built_only is not None:
            return model.Results(self.built_only.conditions,
                                 {name: self.built_only.variants[name] for name in sorted(self.built_only.variants)})
        return results.assemble(self.played, self.floors, self.board)


def write(shard: BoardShard, log_dir: Path) -> Path:
    """<log_dir>/<board folder>/shard.json"""
    path = log_dir / check_board(shard.board) / SHARD_FILE
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(shard.to_json(), indent=1) + "\n")
    return path


def read(path: Path) -> BoardShard:
    try:
        data = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as error:
        raise KitError(f"{path}: not a shard file of kit test --subset: {error}") from error
    if not isinstance(data, dict) or data.get("schema") != SHARD_SCHEMA:
        raise KitError(f"{path}: not a shard file of this kit (schema {SHARD_SCHEMA}; kit test --subset writes it)")
    return BoardShard.from_json(data)


def merge(dirs: list[Path]) -> dict[str, BoardShard]:
    """Board -> its parts joined, from every shard output folder in `dirs`
    (each kit test --subset K/N's --output). KitError when a folder holds
    no shard, or when two shards made the same build (not one split)."""
    check_complete(dirs)
    joined: dict[str, BoardShard] = {}
    seen: dict[tuple[str, str], Path] = {}
    for folder in dirs:
        files = sorted(folder.glob(f"*/{SHARD_FILE}"))
        if not files:
            raise KitError(f"{folder} holds no {SHARD_FILE}: give the --output folder of each "
                           "`kit test --subset K/N` run")
        for path in files:
            shard = read(path)
            names = [p.variant for p in shard.played] + list(shard.built_only.variants if shard.built_only else ())
            for name in names:
                if (shard.board, name) in seen:
                    raise KitError(f"{shard.board} {name} is in two shards ({seen[(shard.board, name)]} and "
                                   f"{path}): merge the shards of one split (the same N, each K once)")
                seen[(shard.board, name)] = path
            if shard.board in joined:
                joined[shard.board].add(shard)
            else:
                joined[shard.board] = shard
    return joined
