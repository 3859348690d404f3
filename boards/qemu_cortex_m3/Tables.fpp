# The priority and stack table of the kit's deployment on qemu_cortex_m3,
# used by app/Top/instances.fpp.
module Kit {

  # Written once in F´'s convention: a higher number is more urgent. The
  # baremetal TaskRunner runs tasks in this order within a pass; the RTOS
  # variant maps it onto Zephyr's preemptive priorities (lower is more urgent)
  # in rtos/Os/PriorityMap.hpp. The tick (the main loop) is above all of them
  # in both. Rate groups by rate, then the services, then the background load.
  module Priorities {
    constant rg1kHz = 12
    constant rg100Hz = 11
    constant rg10Hz = 10
    constant cmdDisp = 6
    constant events = 5
    constant tlmSend = 4
    constant load = 2
  }

  # Thread stacks (RTOS variant; the baremetal TaskRunner shares the main
  # stack and ignores them). From the thread analyzer's high-water marks
  # ("KIT STACK" lines of the nominal and fault runs). Zephyr's thread pool
  # has one slot size for all, so every task gets the largest need plus
  # headroom for paths a run does not take: 1792 B, the
  # CONFIG_DYNAMIC_THREAD_STACK_SIZE of rtos.conf beside this file.
  module Stacks {
    constant rg1kHz = 1792
    constant rg100Hz = 1792
    constant rg10Hz = 1792
    constant cmdDisp = 1792
    constant events = 1792
    constant tlmSend = 1792
    constant load = 1792
  }

}
