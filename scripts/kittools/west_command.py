# SPDX-License-Identifier: Apache-2.0
"""`west kit ...`: the kit's CLI as a west extension command."""

from __future__ import annotations

import argparse

from west.commands import WestCommand

# west loads this file by path, from the venv it runs in; scripts/setup.sh
# installs the kit's package there (editable), so it imports as any other
from kittools import cli


class KitCommand(WestCommand):
    def __init__(self) -> None:
        super().__init__("kit", "F´ baremetal-vs-RTOS kit", cli.__doc__ or "", accepts_unknown_args=True)

    def do_add_parser(self, parser_adder):  # type: ignore[no-untyped-def]
        parser = parser_adder.add_parser(self.name, help=self.help, description=self.description,
                                         formatter_class=argparse.RawDescriptionHelpFormatter, add_help=False)
        return parser

    def do_run(self, args, unknown):  # type: ignore[no-untyped-def]
        code = cli.main(unknown)
        if code != 0:
            self.die(f"kit {' '.join(unknown)} failed (exit {code})")
