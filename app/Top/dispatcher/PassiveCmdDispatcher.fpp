# SPDX-License-Identifier: Apache-2.0
# The command dispatcher: fprime-baremetal's PassiveCmdDispatcher
# (CONFIG_KIT_CMD_DISPATCHER_PASSIVE), the form F´'s baremetal guide
# recommends. A command is dispatched in its sender's call (the uplink's,
# in the 100 Hz group), with no queue, no task and no stack of its own; its
# tables come from F´'s allocator at setup (app/Top/KitTopology.cpp). It has
# no telemetry and no 10 Hz call: its events (InvalidCommand,
# MalformedCommand, OpCodeError) are the record of what it refused. The
# same commands, events and ports otherwise as CmdDispatcher.fpp beside it.
module Kit {

  instance cmdDisp: Baremetal.PassiveCmdDispatcher base id 0x0500

  @ The dispatcher: no connection of its own
  topology Dispatcher {

    instance cmdDisp

  }

}
