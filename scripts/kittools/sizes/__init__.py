# SPDX-License-Identifier: Apache-2.0
"""ROM and RAM: of a build, by layer, by symbol, per knob, and the fixed tables' sizing."""
