# SPDX-License-Identifier: Apache-2.0
"""The report's first section: the conditions of the runs it reports (board,
versions, clocks, the timing histograms' resolution, the toolchain)."""

from __future__ import annotations

from kittools.model import Results
from kittools.report.document import CAVEAT, Text


def conditions_text(data: Results) -> Text:
    """Where and how the runs were made, from the results' conditions (the
    runs' banner) and each variant's build."""
    c = data.conditions
    built_only = c.get("run")  # a board only built (results.built_only): no times, so no caveat on them
    if built_only:
        lines = [f"Board {c.get('board')}: {built_only}."]
    else:
        lines = [f"Board {c.get('board')}; kit {c.get('kit')}; Zephyr {c.get('zephyr')}; F´ {c.get('fprime')}.",
                 f"Rate-group tick {c.get('tick_hz')} Hz, system clock {c.get('sys_tick_hz')} Hz, cycle counter "
                 f"{c.get('cycles_hz')} Hz, QEMU icount shift {c.get('icount_shift')}, run of "
                 f"{c.get('run_ticks')} ticks."]
        if c.get("timing_buckets"):  # the board's histograms (CONFIG_KIT_TIMING_SUB_BITS), every model's
            buckets = int(c["timing_buckets"])
            lines.append(f"Timing histograms: {buckets} buckets per power of two, so a percentile is within "
                         f"{100 / buckets:g} % above its true value; min and max are exact.")
    deployments = sorted({str(data.variants[name].build["deployment"]) for name in data.names()
                          if data.variants[name].build.get("deployment")})
    if deployments:
        lines.append(f"F´ deployment measured: {', '.join(deployments)} (its folder in the kit; app is the "
                     "reference deployment).")
    for name in data.names():
        build = data.variants[name].build
        if build.get("toolchain"):
            lines.append(f"{name}: {build['toolchain']}.")
    if not built_only:
        lines.append(CAVEAT)
    return Text("Conditions", lines)
