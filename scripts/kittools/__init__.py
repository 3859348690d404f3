# SPDX-License-Identifier: Apache-2.0
"""Tooling of the F´ baremetal-vs-RTOS kit: build, run, test and compare."""
