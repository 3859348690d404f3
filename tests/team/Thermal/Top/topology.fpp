# SPDX-License-Identifier: Apache-2.0
module Thermal {

  @ A thermal control deployment: two heated zones, sampled at 50 Hz,
  @ controlled at 10 Hz, reported at 1 Hz
  topology Thermal {

    instance rg50Hz
    instance rg10Hz
    instance rg1Hz
    instance rateGroupDriver
    instance events
    instance tlmSend
    instance osTime
    instance fatalAdapter
    instance fatalHandler
    instance thermistors
    instance heaterControl

    # The kit's instruments and ground link (app/Subtopologies/)
    import Kit.Instruments
    import Kit.GroundLink

    # The command dispatcher in the model's form (dispatcher/)
    import Dispatcher

    command connections instance cmdDisp
    event connections instance events
    telemetry connections instance tlmSend
    time connections instance osTime

    # The kit's tick drives the rate groups; every group starts and ends
    # with the kit's timing probe
    connections RateGroups {
      Kit.timing.CycleOut -> rateGroupDriver.CycleIn

      rateGroupDriver.CycleOut[0] -> rg50Hz.CycleIn
      rg50Hz.RateGroupMemberOut[0] -> Kit.timing.cycleStart[0]
      rg50Hz.RateGroupMemberOut[1] -> thermistors.schedIn
      rg50Hz.RateGroupMemberOut[2] -> Kit.load.sliceIn
      rg50Hz.RateGroupMemberOut[3] -> Kit.faults.schedIn[0]
      rg50Hz.RateGroupMemberOut[4] -> Kit.linkUart.schedIn
      rg50Hz.RateGroupMemberOut[5] -> Kit.timing.cycleEnd[0]

      rateGroupDriver.CycleOut[1] -> rg10Hz.CycleIn
      rg10Hz.RateGroupMemberOut[0] -> Kit.timing.cycleStart[1]
      rg10Hz.RateGroupMemberOut[1] -> heaterControl.controlIn
      rg10Hz.RateGroupMemberOut[2] -> Kit.uplink.schedIn
      rg10Hz.RateGroupMemberOut[3] -> tlmSend.Run
      # [4]: the dispatcher's 10 Hz call, where it has one (dispatcher/)
      rg10Hz.RateGroupMemberOut[5] -> Kit.load.burstIn
      rg10Hz.RateGroupMemberOut[6] -> Kit.faults.schedIn[1]
      rg10Hz.RateGroupMemberOut[7] -> Kit.comQueue.run
      rg10Hz.RateGroupMemberOut[8] -> Kit.linkHealth.schedIn
      rg10Hz.RateGroupMemberOut[9] -> Kit.timing.cycleEnd[1]

      rateGroupDriver.CycleOut[2] -> rg1Hz.CycleIn
      rg1Hz.RateGroupMemberOut[0] -> Kit.timing.cycleStart[2]
      rg1Hz.RateGroupMemberOut[1] -> heaterControl.reportIn
      rg1Hz.RateGroupMemberOut[2] -> Kit.faults.schedIn[2]
      rg1Hz.RateGroupMemberOut[3] -> Kit.timing.cycleEnd[2]
    }

    connections Heaters {
      heaterControl.temperatureGet -> thermistors.temperatureGet
      heaterControl.heaterOut -> thermistors.heaterIn
    }

    # The kit's scripted uplink and the ground link's commands
    connections Commands {
      Kit.uplink.cmdOut -> cmdDisp.seqCmdBuff[0]
      cmdDisp.seqCmdStatus[0] -> Kit.uplink.cmdResponseIn
      Kit.linkHealth.commandOut -> cmdDisp.seqCmdBuff[1]
      cmdDisp.seqCmdStatus[1] -> Kit.linkHealth.commandStatusIn
    }

    # Events, then telemetry, through the kit's tally to the ground link
    connections LinkFeeds {
      events.PktSend -> Kit.downlink.comIn[0]
      tlmSend.PktSend -> Kit.downlink.comIn[1]
    }

    connections Faults {
      events.FatalAnnounce -> fatalHandler.FatalReceive
    }

  }

}
