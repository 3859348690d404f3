# SPDX-License-Identifier: Apache-2.0
# The thermal deployment's priority, stack and queue table. It is in module
# Kit because the kit's instances (load, comQueue: app/Subtopologies/) take
# their entries from it; the model's build-time checks hold it to their
# rules (<model>/ModelChecks.cpp).
module Kit {

  @ F´'s convention: a higher number is more urgent. The rate groups by
  @ rate, the dispatcher, the downlink above the services that feed it,
  @ then the background load
  module Priorities {
    @ Above the tick (rtos), like every model's fastest group
    constant rg50Hz = 13
    constant rg10Hz = 11
    constant rg1Hz = 10
    constant cmdDisp = 6
    constant comQueue = 5
    constant tlmSend = 4
    constant events = 3
    constant load = 1
  }

  @ Thread stacks (rtos; baremetal runs every task on the main stack): each
  @ thread's own (rtos/ThreadStacks.cpp)
  module Stacks {
    constant rg50Hz = 2048
    constant rg10Hz = 2048
    constant rg1Hz = 2048
    constant cmdDisp = 2048
    constant events = 2048
    constant tlmSend = 2048
    constant comQueue = 2048
    constant load = 2048
  }

  @ Queue depths
  module Queues {
    @ One pending cycle; a second is a slip
    constant rateGroup = 2
    @ The scripted uplink's and the ground's commands, and the 10 Hz call
    constant cmdDisp = 8
    constant events = 12
    constant tlmSend = 2
    constant load = 10
    constant comQueue = 12
  }

}
