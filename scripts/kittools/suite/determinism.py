# SPDX-License-Identifier: Apache-2.0
"""Determinism: twister's binaries built again must hash the same."""

from __future__ import annotations

import concurrent.futures
from pathlib import Path

from kittools import console
from kittools.build import runner
from kittools.log import say
from kittools.suite import results
from kittools.suite.counts import Tally
from kittools.suite.platforms import TWISTER_OUT
from kittools.workspace import KitError


def recorded_hashes(twister_out: Path) -> dict[tuple[str, Path, str], str]:
    """(platform, build, scenario) -> the sample hash (KIT HASH line) of each
    scenario the suite played, from its console log (results.run_log)."""
    hashes: dict[tuple[str, Path, str], str] = {}
    for platform, build in results.suite_builds(twister_out):
        for log in sorted((build / results.RUNS_DIR).glob("*.log")):
            run = results.played(build, log.stem)
            if run is not None and run.of_kind("HASH") and "fnv" in run.one("HASH").fields:
                hashes[(platform, build, log.stem)] = run.one("HASH").fields["fnv"]
    return hashes


def check_determinism(log_dir: Path, jobs: int = 2, required: bool = True) -> Tally:
    """Play each scenario that printed a sample hash once more on its build
    under QEMU, `jobs` at a time, through the build's own run target (the
    console from its QEMU pipe): under icount the raw timing samples, and so
    their hash, must be identical to the suite's run. Not `required` (a
    shard of a split run): a run that played none checks none."""
    runs = [(platform, build, scenario, expected)
            for (platform, build, scenario), expected in sorted(recorded_hashes(TWISTER_OUT).items())
            # the soak: ten more virtual minutes per board; it checks itself
            if scenario != "soak"]
    if not runs:
        if not required:
            return Tally()
        raise KitError("the suite recorded no sample hash: nothing to compare")

    def rerun(platform: str, build: Path, scenario: str) -> str | None:
        log = log_dir / f"{platform.replace('/', '_')}.{build.name}.{scenario}.rerun.log"
        text = runner.run(build, log, scenario=scenario)
        return console.parse(text).one("HASH").fields.get("fnv")

    def rerun_build(platform: str, build: Path) -> dict[str, str | None]:
        # One build's scenarios one after another: two QEMUs of one build
        # would share its console FIFOs and its link socket
        return {scenario: rerun(platform, build, scenario) for p, b, scenario, _ in runs if (p, b) == (platform, build)}

    builds = sorted({(platform, build) for platform, build, _, _ in runs})
    tally = Tally()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {key: pool.submit(rerun_build, *key) for key in builds}
        for platform, build, scenario, expected in runs:
            again = futures[(platform, build)].result()[scenario]
            same = again == expected
            say(f"  {platform} {build.name} {scenario}: sample hash {expected}, then {again}: "
                f"{'identical' if same else 'DIFFERENT'}")
            tally.add(Tally(passed=1) if same else Tally(failed=1))
    return tally
