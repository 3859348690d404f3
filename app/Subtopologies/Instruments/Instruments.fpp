# SPDX-License-Identifier: Apache-2.0
# The kit's instruments as an F´ subtopology: what the kit adds to the
# deployment it measures, the same in every deployment and every model.
# A deployment's topology imports it (`import Kit.Instruments`) and wires
# each rate group's first and last member to timing.cycleStart[i] and
# timing.cycleEnd[i] and the rate group driver to timing.CycleOut; the
# instruments' own connections are here. Their names (Kit.timing,
# Kit.load, ...) are the dictionary's, so the ground tools and the report
# read any deployment alike.
module Kit {

  @ The RAM file system (fprime-baremetal's MicroFs, app/src/RamFs.cpp),
  @ the kit's in every deployment, so its files' names are in every
  @ dictionary (the ground tools' file checks use them; app/kit.cmake
  @ compiles them). It names a file by its bin and slot: bin 0 holds
  @ CONFIG_KIT_RAMFS_FILES files of CONFIG_KIT_RAMFS_FILE_SIZE bytes, bin 1
  @ (where the build has it) the bulk file of CONFIG_KIT_RAMFS_BULK_FILE_SIZE
  @ bytes
  module RamFs {
    @ The parameter database's file (in the dictionary: the ground names
    @ it in PRM_LOAD_FILE)
    dictionary constant parameterFile = "/bin0/file0"
    @ A file a ground test may write and load (PRM_LOAD_FILE), and where
    @ the ground uplinks a sequence for the sequencer (CS_RUN)
    dictionary constant scratchFile = "/bin0/file1"
    @ The file the file downlink's test fills (Load.FILL_FILE) and sends,
    @ and the file uplink's test writes
    dictionary constant bulkFile = "/bin1/file0"
  }

  @ The tick's source and the rate groups' probe: every group's start and
  @ end, its latency and jitter, its overruns (app/Components/Timing)
  instance timing: Kit.Timing base id 0x1000

  @ The scripted uplink: a scenario's commands, framed like the ground's,
  @ to the dispatcher (app/Components/Uplink)
  instance uplink: Kit.Uplink base id 0x1400

  @ The downlink's tally: every event and telemetry packet counted on its
  @ way to the link (app/Components/Downlink)
  instance downlink: Kit.Downlink base id 0x1500

  @ The background load: a slice each 100 Hz cycle and a burst each 10 Hz
  @ one, set by command (app/Components/Load)
  instance load: Kit.Load base id 0x1600 \
    queue size Queues.load \
    stack size Stacks.load \
    priority Priorities.load

  @ Faults injected by command: an overrun, a hang, an assert
  @ (app/Components/Faults)
  instance faults: Kit.Faults base id 0x1700

  @ The kit's instruments
  topology Instruments {

    instance timing
    instance uplink
    instance downlink
    instance load
    instance faults

    # The background load's burst goes through its own queue
    connections Load {
      load.ioOut -> load.ioIn
    }

  }

}
