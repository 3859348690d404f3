# SPDX-License-Identifier: Apache-2.0
"""One module per `kit` command (cli.py builds the parser and dispatches)."""
