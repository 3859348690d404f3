# SPDX-License-Identifier: Apache-2.0
# The command dispatcher: F´'s CommandDispatcher, an active component with
# its own queue and task, called at 10 Hz to write its telemetry
# (CommandsDispatched, CommandErrors). PassiveCmdDispatcher.fpp beside it is
# the other form (CONFIG_KIT_CMD_DISPATCHER_PASSIVE); app/Top/topology.fpp
# imports whichever the build chose.
module Kit {

  instance cmdDisp: Svc.CommandDispatcher base id 0x0500 \
    queue size Queues.cmdDisp \
    stack size Stacks.cmdDisp \
    priority Priorities.cmdDisp

  @ The dispatcher and the one connection only this form has
  topology Dispatcher {

    instance cmdDisp
    instance rg10Hz

    connections RateGroups {
      rg10Hz.RateGroupMemberOut[4] -> cmdDisp.run
    }

  }

}
