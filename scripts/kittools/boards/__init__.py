# SPDX-License-Identifier: Apache-2.0
"""Boards: scaffolding a new board's folder, its devicetree, the suites' YAML."""
