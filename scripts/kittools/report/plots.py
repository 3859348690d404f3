# SPDX-License-Identifier: Apache-2.0
"""The report's plots (PNG, matplotlib): the only module that imports a
plotting library."""

from __future__ import annotations

import io
from collections.abc import Callable
from typing import Any

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402

from kittools import (
    model,  # noqa: E402
    sweep,
)
from kittools.model import Results  # noqa: E402
from kittools.report.document import Image, Table  # noqa: E402


def _png(draw: Callable[[Any], None], size: tuple[float, float]) -> bytes:
    figure = plt.figure(figsize=size, dpi=100)
    try:
        draw(figure)
        figure.tight_layout()
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png")
        return buffer.getvalue()
    finally:
        plt.close(figure)


def modules_chart(table: Table, names: list[str]) -> Image:
    layers = [row[0] for row in table.rows if row[0] != "total"]

    def draw(figure: Any) -> None:
        for index, (kind, offset) in enumerate((("ROM", 1), ("RAM", 1 + len(names)))):
            axes = figure.add_subplot(1, 2, index + 1)
            height = 0.8 / len(names)
            for n, variant in enumerate(names):
                values = [row[offset + n] / 1024 for row in table.rows if row[0] != "total"]
                axes.barh([i + n * height for i in range(len(layers))], values, height=height, label=variant)
            axes.set_yticks([i + height * (len(names) - 1) / 2 for i in range(len(layers))])
            axes.set_yticklabels(layers if index == 0 else [""] * len(layers), fontsize=8)
            axes.invert_yaxis()
            axes.set_xlabel(f"{kind} (KiB)")
            axes.legend(fontsize=8)

    return Image("ROM and RAM by module", _png(draw, (11, 4)))


HIST_LABELS = {"latency": "dispatch latency", "exec": "execution time", "jitter": "period error"}


def histogram_chart(data: Results, rate_group: str) -> Image | None:
    cycles_hz = data.condition("cycles_hz")
    if cycles_hz <= 0:
        return None
    series: dict[str, dict[str, list[tuple[float, int]]]] = {}
    for v in data.names():
        for r in data.variants[v].of_kind("HIST"):
            if r.get("rg") == rate_group and r.get("buckets"):
                points = [tuple(int(x) for x in pair.split(":")) for pair in str(r["buckets"]).split(",")]
                series.setdefault(r["metric"], {})[v] = [(lo * 1e6 / cycles_hz, count) for lo, count in points]
    if not series:
        return None

    def draw(figure: Any) -> None:
        for index, metric in enumerate(model.RG_QUANTITIES):
            axes = figure.add_subplot(1, 3, index + 1)
            for variant, points in sorted(series.get(metric, {}).items()):
                (line,) = axes.step([p[0] for p in points], [p[1] for p in points], where="post", label=variant)
                axes.plot([p[0] for p in points], [p[1] for p in points], "o", markersize=3, color=line.get_color())
            axes.set_title(f"{rate_group} {HIST_LABELS[metric]}", fontsize=9)
            axes.set_xlabel("µs (bucket lower bound)", fontsize=8)
            axes.set_ylabel("cycles", fontsize=8)
            axes.set_yscale("log")
            if series.get(metric):
                axes.legend(fontsize=8)

    return Image(f"{rate_group}: distributions", _png(draw, (12, 3.2)))


def sweep_chart(found: dict[str, sweep.Sweep], cycles_hz: float, axis: str) -> Image:
    names = sorted(found)
    rate_groups = found[names[0]].rate_groups()
    unit = found[names[0]].unit(axis)

    def draw(figure: Any) -> None:
        for index, rg in enumerate(rate_groups):
            axes = figure.add_subplot(1, len(rate_groups), index + 1)
            for v in names:
                points = found[v].series(axis, rg)
                x = [p.level for p in points]
                (line,) = axes.plot(x, [p.latency_p99 * 1e6 / cycles_hz for p in points], "-o", markersize=3,
                                    label=f"{v} p99")
                axes.plot(x, [p.latency_max * 1e6 / cycles_hz for p in points], "--", color=line.get_color(),
                          label=f"{v} max")
                missed = [p for p in points if p.missed]
                if missed:
                    axes.plot([p.level for p in missed], [p.latency_max * 1e6 / cycles_hz for p in missed], "x",
                              color="red", markersize=7, label=f"{v} missed deadline")
                broke = found[v].breaking_point(axis, rg)
                if broke is not None:
                    axes.axvline(broke, linestyle=":", color=line.get_color())
            axes.set_title(f"{rg}: dispatch latency vs load ({axis})", fontsize=9)
            axes.set_xlabel(f"load ({'µs' if unit == 'us' else unit})", fontsize=8)
            axes.set_ylabel("latency (µs)", fontsize=8)
            axes.legend(fontsize=7)

    return Image(f"Latency versus load, axis '{axis}'", _png(draw, (4.2 * len(rate_groups), 3.4)))


def boards_chart(datas: list[Results]) -> Image:
    columns = [(d, v) for d in datas for v in d.names()]

    def draw(figure: Any) -> None:
        for index, (what, metric) in enumerate((("ROM", model.ROM), ("static RAM", model.RAM))):
            axes = figure.add_subplot(1, 2, index + 1)
            values = [(d.variants[v].metric(metric) or 0) / 1024 for d, v in columns]
            axes.barh(range(len(columns)), values)
            axes.set_yticks(range(len(columns)))
            axes.set_yticklabels([f"{d.board} {v}" if index == 0 else "" for d, v in columns], fontsize=8)
            axes.invert_yaxis()
            axes.set_xlabel(f"{what} (KiB)")

    return Image("ROM and RAM per board and variant", _png(draw, (11, 0.5 * len(columns) + 1.5)))
