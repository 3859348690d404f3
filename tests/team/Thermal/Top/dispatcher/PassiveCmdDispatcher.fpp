# SPDX-License-Identifier: Apache-2.0
# The command dispatcher: fprime-baremetal's PassiveCmdDispatcher
# (CONFIG_KIT_CMD_DISPATCHER_PASSIVE): a command is dispatched in its
# sender's call; its tables come from F´'s allocator (KitTopology.cpp).
module Thermal {

  instance cmdDisp: Baremetal.PassiveCmdDispatcher base id 0x4500

  @ The dispatcher: no connection of its own
  topology Dispatcher {

    instance cmdDisp

  }

}
