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
  # above the services that feed it, then the background load. Where a
  # board shares one thread among a band of levels (qemu_cortex_m3: 2 to 6,
  # rtos/Os/SharedThread.hpp), the order within the band holds message by
  # message: the thread takes the most urgent member's message first. The downlink
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
  # stack and ignores them), each its own size (rtos/ThreadStacks.cpp).
  # Where a board shares one thread among a band of levels
  # (CONFIG_KIT_RTOS_SHARED_LEVEL_LOW/HIGH, rtos/Os/SharedThread.hpp), that
  # thread's stack is the largest of its members' here: one member runs at
  # a time, to the end of its message, so the rule below holds for it. The
  # rule: the thread's high-water mark over every run of the suite on both
  # boards ("KIT STACK" lines: the nominal, load and faults scenarios; the
  # serial-load sweep through the ground link, whose uplink at its line
  # rate takes the 100 Hz group to 1444 B and the 10 Hz group to 1460 B,
  # where the scenarios reach 532 B and 1012 B; the integration suite, whose
  # parameter files, file transfers and sequences reach no other run's
  # paths: the parameter database 1188 B, the file uplink 840 B, the
  # sequencer 1536 B, where the sweep's sequences took it to 1304 B,
  # kit test's "stacks after the suite"; the dispatcher 1472 B), plus
  # 472 B for an F´ assert raised at that depth, rounded up to 64 B.
  # The rtos model reports an assert on a thread of its own
  # (rtos/AssertReport.cpp): the asserting thread only hands it over, 436 B
  # at most below the assert (F´'s Fw::SwAssert keeps a 164 B message
  # buffer in its frame; then the hand-off and its context switch): an
  # assert in a command handler 736 B deep took the dispatcher to 1172 B
  # (qemu_cortex_m3, the assert scenario). The report itself (its message,
  # its FATAL event, the fatal handler) is 1100 B deep, which no thread's
  # 472 B could hold: on the asserting thread it took 1028 B beyond the
  # assert (the dispatcher 1764 B at the halt), so an assert raised within
  # 556 B of a thread's high-water mark overflowed it (mps2/an385's MPU guard once caught one on the dispatcher's
  # 1792 B stack, which qemu_cortex_m3's sentinel word had missed). With
  # 1280 B, the parameter database's PRM_LOAD_FILE (a file object and a
  # working buffer on the stack) hung the deployment on both boards with
  # no fault reported: 1188 B deep, it had stepped over the 32 B guard and
  # the sentinel word.
  module Stacks {
    constant rg1kHz = 1344
    constant rg100Hz = 1920
    constant rg10Hz = 1984
    constant cmdDisp = 1984
    constant events = 1216
    constant tlmSend = 1152
    constant comQueue = 1536
    constant load = 1024
    constant prmDb = 1664
    constant fileDownlink = 1664
    constant fileUplink = 1344
    constant cmdSeq = 2048
  }

}
