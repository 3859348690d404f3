# SPDX-License-Identifier: Apache-2.0
"""The ground link: its client, the fprime-gds adapter, and what drives the link (fuzz, flood, serial sweep)."""
