# SPDX-License-Identifier: Apache-2.0
# The command dispatcher: F´'s CommandDispatcher, a task with its queue,
# called at 10 Hz for its telemetry. PassiveCmdDispatcher.fpp beside it is
# the form CONFIG_KIT_CMD_DISPATCHER_PASSIVE (baremetal_passive) chooses.
module Thermal {

  instance cmdDisp: Svc.CommandDispatcher base id 0x4500 \
    queue size Kit.Queues.cmdDisp \
    stack size Kit.Stacks.cmdDisp \
    priority Kit.Priorities.cmdDisp

  @ The dispatcher and the connection only this form has
  topology Dispatcher {

    instance cmdDisp
    instance rg10Hz

    connections RateGroups {
      rg10Hz.RateGroupMemberOut[4] -> cmdDisp.run
    }

  }

}
