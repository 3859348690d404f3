# SPDX-License-Identifier: Apache-2.0

module Kit {

  @ The kit's one deployment, built unchanged as the baremetal and the RTOS variant
  topology Kit {

    instance rg1kHz
    instance rg100Hz
    instance rg10Hz
    instance events
    instance tlmSend
    instance rateGroupDriver
    instance controller
    instance monitor
    instance housekeeping
    instance osTime
    instance fatalAdapter
    instance fatalHandler

    # The kit's instruments: timing, the scripted uplink, the downlink's
    # tally, the background load, faults (app/Subtopologies/Instruments/)
    import Instruments

    # The ground link: F´'s ComFprime chain on the board's link UART
    # (app/Subtopologies/GroundLink/)
    import GroundLink

    # The command dispatcher in the build's form, with the connection only
    # that form has (app/Top/dispatcher/)
    import Dispatcher

    # F´'s health and version services (CdhCore's), where the board's
    # profile has them (app/Top/services/), and health's pings of the
    # dispatcher and the rate groups, where the build has those too
    import CdhServices
    import DispatcherHealth
    import RateGroupHealth

    # F´'s parameter database on the RAM file system, with the components
    # whose parameters it keeps, and its ping (app/Top/services/)
    import ParamServices
    import ParamHealth

    # F´'s file downlink from the RAM file system, with its ping
    # (app/Top/services/)
    import FileServices

    # F´'s file uplink to the RAM file system, with its ping
    # (app/Top/services/)
    import FileUplinkServices

    # F´'s command sequencer, its sequences on the RAM file system, with its
    # ping (app/Top/services/)
    import SequencerServices

    command connections instance cmdDisp
    event connections instance events
    telemetry connections instance tlmSend
    time connections instance osTime

    # The tick, divided into three rate groups. Every rate group starts and
    # ends with the timing probe, so what it measures is exactly the group.
    connections RateGroups {
      timing.CycleOut -> rateGroupDriver.CycleIn

      rateGroupDriver.CycleOut[0] -> rg1kHz.CycleIn
      rg1kHz.RateGroupMemberOut[0] -> timing.cycleStart[0]
      rg1kHz.RateGroupMemberOut[1] -> controller.schedIn
      rg1kHz.RateGroupMemberOut[2] -> faults.schedIn[0]
      rg1kHz.RateGroupMemberOut[3] -> timing.cycleEnd[0]

      rateGroupDriver.CycleOut[1] -> rg100Hz.CycleIn
      rg100Hz.RateGroupMemberOut[0] -> timing.cycleStart[1]
      rg100Hz.RateGroupMemberOut[1] -> monitor.schedIn
      rg100Hz.RateGroupMemberOut[2] -> load.sliceIn
      rg100Hz.RateGroupMemberOut[3] -> faults.schedIn[1]
      rg100Hz.RateGroupMemberOut[4] -> linkUart.schedIn
      rg100Hz.RateGroupMemberOut[5] -> timing.cycleEnd[1]

      rateGroupDriver.CycleOut[2] -> rg10Hz.CycleIn
      rg10Hz.RateGroupMemberOut[0] -> timing.cycleStart[2]
      rg10Hz.RateGroupMemberOut[1] -> housekeeping.schedIn
      rg10Hz.RateGroupMemberOut[2] -> uplink.schedIn
      rg10Hz.RateGroupMemberOut[3] -> tlmSend.Run
      # [4]: the dispatcher's 10 Hz call, where it has one (app/Top/dispatcher/)
      rg10Hz.RateGroupMemberOut[5] -> load.burstIn
      rg10Hz.RateGroupMemberOut[6] -> faults.schedIn[2]
      rg10Hz.RateGroupMemberOut[7] -> comQueue.run
      rg10Hz.RateGroupMemberOut[8] -> linkHealth.schedIn
      # [9]: health's 10 Hz run, where the build has it (app/Top/services/)
      # [10]: the file downlink's 10 Hz run, where the build has it (app/Top/services/)
      # [11]: the sequencer's 10 Hz clock, where the build has it (app/Top/services/)
      rg10Hz.RateGroupMemberOut[12] -> timing.cycleEnd[2]
    }

    connections Control {
      monitor.statusGet -> controller.statusGet
    }

    connections Uplink {
      uplink.cmdOut -> cmdDisp.seqCmdBuff[0]
      cmdDisp.seqCmdStatus[0] -> uplink.cmdResponseIn
    }

    # Events and telemetry pass the kit's tally (Downlink) on their way to
    # the ground link: events before telemetry
    connections LinkFeeds {
      events.PktSend -> downlink.comIn[0]
      tlmSend.PktSend -> downlink.comIn[1]
    }

    # Ground commands, past the link's health component (which keeps no
    # more in flight than the dispatcher's queue can hold), go to the
    # dispatcher like the scripted uplink's
    connections LinkCommands {
      linkHealth.commandOut -> cmdDisp.seqCmdBuff[1]
      cmdDisp.seqCmdStatus[1] -> linkHealth.commandStatusIn
    }

    connections Faults {
      events.FatalAnnounce -> fatalHandler.FatalReceive
    }

  }

}
