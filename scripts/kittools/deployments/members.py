# SPDX-License-Identifier: Apache-2.0
"""Which of a deployment's rate groups takes which of the kit's members
(kit new-deployment, kittools.deployments.adapt): the timing probe around
each group, the load's slice and the link's polls in the fastest, the
load's burst in the next, the scripted uplink with it where that group is
fast enough, and F´'s dispatcher's run where nothing schedules it."""

from __future__ import annotations

from fractions import Fraction

from kittools.deployments import seam

#: The slowest the scripted uplink may run: a scenario's script spans a dozen
#: of its cycles within the run's 2 s (the reference's uplink: 10 Hz)
UPLINK_PERIOD_MAX_S = Fraction(1, 10)


def uplink_group(plan: seam.Plan) -> int:
    """The scripted uplink's group: the burst's (the next after the fastest),
    as in the reference, where that group runs at least every
    UPLINK_PERIOD_MAX_S; else the fastest. The faults scenario commands the
    load's burst on and off two uplink cycles apart, so sharing its group
    gives two bursts whatever the rates; with the uplink on the fastest group
    and the burst on the next, the faults' overrun of the fastest group held
    the uplink back until the one burst between them came before the
    command (rtos on fprime-util's template: no message dropped)."""
    burst = burst_group(plan)
    return burst if plan.deployment.rate_groups[burst].period <= UPLINK_PERIOD_MAX_S else 0


def burst_group(plan: seam.Plan) -> int:
    """The load's burst's group: the next after the fastest."""
    return min(1, len(plan.deployment.rate_groups) - 1)


def kit_members(plan: seam.Plan, group: int) -> tuple[list[str], list[str]]:
    """The kit's members of rate group `group`: the probe first, then the
    deployment's, then the kit's own, and the probe last."""
    # The dispatcher's run first: a second run of new-deployment finds it
    # among the deployment's own members, and must place it where it is
    after = [plan.dispatcher_run] if plan.dispatcher_run and group == uplink_group(plan) else []
    if group == 0:
        after += ["Kit.load.sliceIn", "Kit.linkUart.schedIn", "Kit.comQueue.run", "Kit.linkHealth.schedIn"]
    if group == uplink_group(plan):
        after.append("Kit.uplink.schedIn")
    if group == burst_group(plan):
        after.append("Kit.load.burstIn")
    after += [f"Kit.faults.schedIn[{group}]", f"Kit.timing.cycleEnd[{group}]"]
    return [f"Kit.timing.cycleStart[{group}]"], after
