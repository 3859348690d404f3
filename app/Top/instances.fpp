# SPDX-License-Identifier: Apache-2.0

module Kit {

  # The priority and stack table (Kit.Priorities, Kit.Stacks) is in
  # Tables.fpp beside this file; a board whose measurements differ
  # replaces it with its own boards/<board>/Tables.fpp.

  # Queue depths: a rate group holds one pending cycle (a second is a slip);
  # the services absorb a burst of a few messages.
  module Queues {
    constant rateGroup = 2
    @ The dispatcher's queue holds commands from both uplinks (each in
    @ flight takes one slot: the command, then its answer), and its 10 Hz
    @ telemetry call. It asserts when full: the ground's share is capped
    @ (Link.commandsInFlight, checked in app/Top/TopologyChecks.cpp), which
    @ leaves room for the call and the scripted uplink
    constant cmdDisp = 8
    @ Events arrive in bursts where a command is dispatched in its
    @ sender's call (the passive dispatcher: the faults scenario's five
    @ bad commands in one 10 Hz call filled 8 and dropped 2); the threaded
    @ and cooperative dispatchers peaked at 8 there too (mps2/an385,
    @ budgeted). EventManager drops what a full queue cannot take
    constant events = 12
    constant tlmSend = 2
    # 8 slices (~80 ms at 100 Hz) or a burst of 8 with room for the next slice;
    # a longer burst overflows it, which is how an overrun of the load is
    # provoked (dropped and counted, never blocking the rate group)
    constant load = 10
    @ Downlink: one message per event or telemetry packet, and the link's
    @ status handshake. The telemetry service sends its packets in one
    @ slice (39 channels, six to a 128-byte packet: up to 7), so the queue
    @ holds that burst and the events behind it. 8 dropped a NO_OP's event
    @ under uplink fuzzing on baremetal_passive (whose rate groups write
    @ three channels every cycle); the fuzzing peaked at 9 on both boards
    @ with 16 (KIT QUEUE's dropped= counts what a full queue lost)
    constant comQueue = 12
    @ Health is queued: its Run (10 Hz) first takes the answers that came
    @ back since the last one, at most one per ping entry, and a command
    constant $health = HealthPingPorts + 2
    @ The parameter database: a component's save (its parameter's
    @ _PRM_SAVE command), the database's own commands and health's ping
    constant prmDb = 4
    @ The file downlink: its 10 Hz Run, each packet's buffer coming back,
    @ a command and health's ping
    constant fileDownlink = 5
    @ The file uplink: each packet the router hands it holds one of the
    @ link's buffers until it is written, so the queue takes every buffer
    @ of the pool and health's ping, and never fills (F´ asserts on a
    @ full queue; checked in app/Top/TopologyChecks.cpp)
    constant fileUplink = Link.bufferCount + 1
    @ The sequencer: its 10 Hz clock, a command's answer, a CS_ command
    @ and health's ping, with one spare
    constant cmdSeq = 5
  }

  @ The command sequencer's settings
  module Sequences {
    @ A command of a sequence not answered in this long fails the sequence
    constant commandTimeoutS = 5
  }

  @ The file downlink's clock: it runs in the 10 Hz group
  module FileDownlinkTimings {
    @ Run's period
    constant cycleMs = 100
    @ A packet's buffer not back in this long: the downlink is given up
    constant timeoutMs = 1000
    @ Pause after a file before the next one starts
    constant cooldownMs = 100
    @ Files SendFile may queue behind the one being sent (each entry holds
    @ two file names: 160 B of the heap)
    constant fileQueueDepth = 1
  }


  # ----------------------------------------------------------------------
  # Active components. F´'s generated startTasks() starts them in name order,
  # whatever the order here; fprime-baremetal's TaskRunner (915de8e) dropped a
  # task in that case until the kit's patch (baremetal/patches/).
  # ----------------------------------------------------------------------

  # The rate groups, rg1kHz, rg100Hz and rg10Hz: app/Top/rategroups/
  # (active, or passive with CONFIG_KIT_RATE_GROUPS_PASSIVE)

  # cmdDisp, the command dispatcher: app/Top/dispatcher/ (active, or passive
  # with CONFIG_KIT_CMD_DISPATCHER_PASSIVE)

  instance events: Svc.EventManager base id 0x0600 \
    queue size Queues.events \
    stack size Stacks.events \
    priority Priorities.events

  # tlmSend, the telemetry store: app/Top/telemetry/ (CONFIG_KIT_TELEMETRY_LINEAR)

  # load, the background load: the kit's instruments (app/Subtopologies/Instruments/)

  # ----------------------------------------------------------------------
  # Queued components
  # ----------------------------------------------------------------------

  @ F´'s health checker (CdhCore's): every active component with ping ports
  @ pinged each 10 Hz cycle, a WARNING_HI when one has not answered in
  @ WARN cycles, FATAL in FATAL cycles (app/Top/KitTopologyDefs.hpp)
  instance $health: Svc.Health base id 0x2900 \
    queue size Queues.$health \
  {
    # FPP builds health's ping table from its connections (WARN and FATAL
    # per entry: app/Top/KitTopologyDefs.hpp); CdhCore's setup
    phase Fpp.ToCpp.Phases.configConstants """
    enum {
        HEALTH_WATCHDOG_CODE = 0x123
    };
    """
    phase Fpp.ToCpp.Phases.configComponents """
    Kit::health.setPingEntries(
        ConfigObjects::Kit_health::pingEntries,
        FW_NUM_ARRAY_ELEMENTS(ConfigObjects::Kit_health::pingEntries),
        ConfigConstants::Kit_health::HEALTH_WATCHDOG_CODE
    );
    """
  }

  # ----------------------------------------------------------------------
  # Passive components
  # ----------------------------------------------------------------------

  @ F´'s version reporter (CdhCore's): the framework's, the project's and
  @ the libraries' versions, as events at startup and on command
  instance version: Svc.Version base id 0x2A00 \
  {
    # The versions as events and telemetry at startup (CdhCore's setting)
    phase Fpp.ToCpp.Phases.configComponents """
    Kit::version.config(true);
    """
  }

  # Health's pings, timed: one probe per ping entry (the kit's instrument,
  # app/Components/PingProbe); the entries are in app/Top/services/
  instance eventsPing: Kit.PingProbe base id 0x2B00
  instance tlmSendPing: Kit.PingProbe base id 0x2B10
  instance rg1kHzPing: Kit.PingProbe base id 0x2B20
  instance rg100HzPing: Kit.PingProbe base id 0x2B30
  instance rg10HzPing: Kit.PingProbe base id 0x2B40
  instance cmdDispPing: Kit.PingProbe base id 0x2B50
  instance prmDbPing: Kit.PingProbe base id 0x2B60
  instance fileDownlinkPing: Kit.PingProbe base id 0x2B70
  instance fileUplinkPing: Kit.PingProbe base id 0x2B80
  instance cmdSeqPing: Kit.PingProbe base id 0x2B90

  @ Where there is no parameter database: every parameter keeps its default
  instance paramDefaults: Kit.ParamDefaults base id 0x2D00

  @ F´'s parameter database (FileHandling's prmDb), its file on the kit's
  @ RAM file system (app/src/RamFs.cpp): read at start-up, before the
  @ components load their parameters, and written by PRM_SAVE_FILE
  instance prmDb: Svc.PrmDb base id 0x2C00 \
    queue size Queues.prmDb \
    stack size Stacks.prmDb \
    priority Priorities.prmDb \
  {
    phase Fpp.ToCpp.Phases.configComponents """
    Kit::prmDb.configure(Kit::RamFs::parameterFile);
    """
    phase Fpp.ToCpp.Phases.readParameters """
    Kit::prmDb.readParamFile();
    """
  }

  @ F´'s file downlink (FileHandling's fileDownlink): a file of the RAM
  @ file system to the ground, one packet at a time, the next when the
  @ link returns the last one's buffer; given up after 1 s without it
  instance fileDownlink: Svc.FileDownlink base id 0x2E00 \
    queue size Queues.fileDownlink \
    stack size Stacks.fileDownlink \
    priority Priorities.fileDownlink \
  {
    phase Fpp.ToCpp.Phases.configComponents """
    Kit::fileDownlink.configure(FileDownlinkTimings::timeoutMs, FileDownlinkTimings::cooldownMs,
                                FileDownlinkTimings::cycleMs, FileDownlinkTimings::fileQueueDepth);
    """
  }

  @ F´'s file uplink (FileHandling's fileUplink): the ground's file packets
  @ from the link's router, written to the RAM file system; each packet's
  @ buffer goes back to the router's pool once written
  instance fileUplink: Svc.FileUplink base id 0x2F00 \
    queue size Queues.fileUplink \
    stack size Stacks.fileUplink \
    priority Priorities.fileUplink

  @ F´'s command sequencer (the Ref deployment's cmdSeq): a sequence file of
  @ the RAM file system, its commands to the dispatcher on their own port;
  @ its buffer holds a sequence the size of a RAM file system file
  instance cmdSeq: Svc.CmdSequencer base id 0x3000 \
    queue size Queues.cmdSeq \
    stack size Stacks.cmdSeq \
    priority Priorities.cmdSeq \
  {
    # The F´ allocator's memory ID of its buffer (the link's is 0, the
    # telemetry store's 2, the passive dispatcher's 3: KitTopology.cpp)
    phase Fpp.ToCpp.Phases.configConstants """
    enum {
        SEQUENCE_BUFFER_ID = 4
    };
    """
    phase Fpp.ToCpp.Phases.configComponents """
    Kit::cmdSeq.allocateBuffer(ConfigConstants::Kit_cmdSeq::SEQUENCE_BUFFER_ID, state.allocator,
                               CONFIG_KIT_RAMFS_FILE_SIZE);
    Kit::cmdSeq.setTimeout(Sequences::commandTimeoutS);
    """
    phase Fpp.ToCpp.Phases.tearDownComponents """
    Kit::cmdSeq.deallocateBuffer(state.allocator);
    """
  }

  instance rateGroupDriver: Svc.RateGroupDriver base id 0x0400

  instance controller: Kit.Controller base id 0x1100

  instance monitor: Kit.Monitor base id 0x1200

  instance housekeeping: Kit.Housekeeping base id 0x1300

  instance osTime: Svc.OsTime base id 0x0800

  instance fatalAdapter: Svc.AssertFatalAdapter base id 0x0900

  instance fatalHandler: Kit.FatalHandler base id 0x0A00

  # The ground link (comQueue, framer ... linkUart, linkHealth) is the
  # kit's: app/Subtopologies/GroundLink/

}
