"""Tooling of the F´ baremetal-vs-RTOS kit: build, run, test and compare."""
