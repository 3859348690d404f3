module Kit {

  # ----------------------------------------------------------------------
  # The priority table, written once in F´'s convention: a higher number is
  # more urgent. The baremetal TaskRunner runs tasks in this order within a
  # pass; the RTOS variant maps it onto Zephyr's preemptive priorities (where
  # lower is more urgent) in rtos/Os/PriorityTask.cpp. The tick (the main
  # loop) is above all of them in both.
  # ----------------------------------------------------------------------
  module Priorities {
    constant rg1kHz = 12
    constant rg100Hz = 11
    constant rg10Hz = 10
    constant cmdDisp = 6
    constant events = 5
    constant tlmSend = 4
  }

  # Thread stacks (RTOS variant; the baremetal TaskRunner shares the main
  # stack and ignores them). From the thread analyzer's high-water marks
  # ("KIT STACK" lines of a nominal run): cmdDisp 1320 B, rg10Hz 976,
  # events 640, rg100Hz/rg1kHz 528, tlmSend 368. Zephyr's thread pool has one
  # slot size for all, so every task gets the largest need plus ~35% for
  # paths a nominal run does not take (asserts, fault events): 1792 B, the
  # CONFIG_DYNAMIC_THREAD_STACK_SIZE of rtos/variant.conf.
  module Stacks {
    constant rg1kHz = 1792
    constant rg100Hz = 1792
    constant rg10Hz = 1792
    constant cmdDisp = 1792
    constant events = 1792
    constant tlmSend = 1792
  }

  # Queue depths: a rate group holds one pending cycle (a second is a slip);
  # the services absorb a burst of a few messages.
  module Queues {
    constant rateGroup = 2
    constant cmdDisp = 4
    constant events = 8
    constant tlmSend = 2
  }

  # ----------------------------------------------------------------------
  # Active components. F´'s generated startTasks() starts them in name order,
  # whatever the order here; fprime-baremetal's TaskRunner (915de8e) dropped a
  # task in that case until the kit's patch (baremetal/patches/).
  # ----------------------------------------------------------------------

  instance rg1kHz: Svc.ActiveRateGroup base id 0x0100 \
    queue size Queues.rateGroup \
    stack size Stacks.rg1kHz \
    priority Priorities.rg1kHz

  instance rg100Hz: Svc.ActiveRateGroup base id 0x0200 \
    queue size Queues.rateGroup \
    stack size Stacks.rg100Hz \
    priority Priorities.rg100Hz

  instance rg10Hz: Svc.ActiveRateGroup base id 0x0300 \
    queue size Queues.rateGroup \
    stack size Stacks.rg10Hz \
    priority Priorities.rg10Hz

  instance cmdDisp: Svc.CommandDispatcher base id 0x0500 \
    queue size Queues.cmdDisp \
    stack size Stacks.cmdDisp \
    priority Priorities.cmdDisp

  instance events: Svc.EventManager base id 0x0600 \
    queue size Queues.events \
    stack size Stacks.events \
    priority Priorities.events

  instance tlmSend: Svc.TlmChan base id 0x0700 \
    queue size Queues.tlmSend \
    stack size Stacks.tlmSend \
    priority Priorities.tlmSend

  # ----------------------------------------------------------------------
  # Passive components
  # ----------------------------------------------------------------------

  instance rateGroupDriver: Svc.RateGroupDriver base id 0x0400

  instance timing: Kit.Timing base id 0x1000

  instance controller: Kit.Controller base id 0x1100

  instance monitor: Kit.Monitor base id 0x1200

  instance housekeeping: Kit.Housekeeping base id 0x1300

  instance uplink: Kit.Uplink base id 0x1400

  instance downlink: Kit.Downlink base id 0x1500

  instance osTime: Svc.OsTime base id 0x0800

  instance fatalAdapter: Svc.AssertFatalAdapter base id 0x0900

  instance fatalHandler: Kit.FatalHandler base id 0x0A00

}
