# SPDX-License-Identifier: Apache-2.0
"""One module per `kit` command, each with its `run(args)`; kittools.cli
builds the parser and dispatches."""
