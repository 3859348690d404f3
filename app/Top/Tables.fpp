# SPDX-License-Identifier: Apache-2.0
# The priority and stack table of the kit's deployment (app/Top/instances.fpp),
# on every board: the priorities are the deployment's design, not a board's,
# and the stacks were measured on qemu_cortex_m3 and mps2/an385 (the suite's
# runs) and are used unchanged on nucleo_f401re (the same code on the same
# architecture; re-measure from a run on the board, "KIT STACK" lines).
# A board whose measurements differ replaces this file with its own
# boards/<board>/Tables.fpp (the whole table: FPP has no per-constant
# override); app/Top/CMakeLists.txt picks it, and the model's build-time
# checks (<model>/ModelChecks.cpp) hold it to the same rules.
module Kit {

  # Written once in F´'s convention: a higher number is more urgent. The
  # baremetal TaskRunner runs tasks in this order within a pass; the RTOS
  # variant maps it onto Zephyr's preemptive priorities (lower is more urgent)
  # in rtos/Os/PriorityMap.hpp. The tick (the main loop) is above every task
  # but the fastest rate group (rtos; baremetal runs the tick first anyway).
  # Rate groups by rate, then the dispatcher, then the downlink
  # above the services that feed it, then the background load. The downlink
  # (ComQueue) must be above them: it answers its own sends through its own
  # queue (comStatusIn), which asserts when full, and a feeder that runs
  # between its taking a message and that answer can fill the slot it freed
  # (mps2/an385 rtos did, under uplink fuzzing and the load sweep; checked in
  # rtos/ModelChecks.cpp). Telemetry is above events: F´'s TlmChan asserts
  # when its 10 Hz calls fill its queue, where the event logger drops (a
  # flood of events starved it on mps2/an385 rtos at 300 commands/s).
  module Priorities {
    @ Above the tick (rtos: the main thread at F´ level 12, Zephyr's
    @ CONFIG_MAIN_THREAD_PRIORITY 2), so its cycle runs the moment the tick
    @ hands it over; everything below is below the tick
    constant rg1kHz = 13
    constant rg100Hz = 11
    constant rg10Hz = 10
    constant cmdDisp = 6
    @ The file uplink holds a link buffer for each packet it has not
    @ written: at the services' level (2) on mps2/an385 rtos, the events
    @ and telemetry it caused kept it from running, and the router ran out
    @ of buffers for the next packets (141 AllocationError events in a
    @ file-packet fuzzing run); beside the dispatcher, the link's other
    @ consumer, it gives them back within the pass
    constant fileUplink = 6
    constant comQueue = 5
    constant tlmSend = 4
    constant events = 3
    constant prmDb = 2
    constant fileDownlink = 2
    constant cmdSeq = 2
    constant load = 1
  }

  # Thread stacks (RTOS variant; the baremetal TaskRunner shares the main
  # stack and ignores them). Zephyr's thread pool has one slot size for all:
  # CONFIG_DYNAMIC_THREAD_STACK_SIZE, set in each board's Kconfig.defconfig. A nominal
  # run's high-water marks ("KIT STACK" lines) top out at 1324 B (cmdDisp),
  # but an F´ assert in a command handler needs more than 1792 B of the
  # dispatcher's stack: mps2/an385's MPU guard caught that overflow, which
  # qemu_cortex_m3's stack sentinel (one word at the bottom) had missed.
  module Stacks {
    constant rg1kHz = 2048
    constant rg100Hz = 2048
    constant rg10Hz = 2048
    constant cmdDisp = 2048
    constant events = 2048
    constant tlmSend = 2048
    constant comQueue = 2048
    constant load = 2048
    constant prmDb = 2048
    constant fileDownlink = 2048
    constant fileUplink = 2048
    constant cmdSeq = 2048
  }

}
