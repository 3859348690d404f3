# SPDX-License-Identifier: Apache-2.0
"""kit gds: a board and model booted under QEMU with fprime-gds on its ground link."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from kittools import deployment, variants
from kittools.link import ground
from kittools.link.dictionary import Dictionary
from kittools.log import say
from kittools.suite import platforms
from kittools.workspace import KitError, check_provisioned


def ground_build(args: argparse.Namespace) -> tuple[Path, Path]:
    """The ground scenario's build of --board and --model, built or brought
    up to date; returns it and its logs folder."""
    platforms.check_runs_here(args.board)
    variants.get(args.model)  # argparse checks the name only when it comes from the command line
    check_provisioned()
    chosen = deployment.resolve(args.deployment, [args.board])
    build_dir = ground.ground_build_dir(args.board, args.model, chosen)
    logs = build_dir.with_name(build_dir.name + "-logs")
    say(f"building {args.board} {args.model} of deployment {chosen.name} (ground scenario) ...")
    ground.build_ground(args.board, args.model, logs / "build.log", chosen)
    return build_dir, logs


def run(args: argparse.Namespace) -> int:
    build_dir, logs = ground_build(args)
    with ground.GroundStation(build_dir, logs, gui=True, gui_port=args.port, dictionary=args.dictionary) as station:
        say(f"QEMU runs {build_dir}; its link: {station.link.socket}")
        say(f"fprime-gds: http://127.0.0.1:{args.port} (dictionary {station.link.dictionary})")
        noop = Dictionary.read(station.link.dictionary).noop_command
        say(f"from a shell: fprime-cli command-send {noop} {' '.join(station.client_arguments())}")
        say("Ctrl-C stops both")
        try:
            while station.qemu is not None and station.qemu.running():
                time.sleep(0.5)
        except KeyboardInterrupt:
            say("stopping")
            return 0
        raise KitError(f"QEMU stopped on its own; its console:\n{station.console()[-3000:]}")
