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
