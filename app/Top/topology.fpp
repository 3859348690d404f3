# SPDX-License-Identifier: Apache-2.0

module Kit {

  @ The kit's one deployment, built unchanged as the baremetal and the RTOS variant
  topology Kit {

    instance rg1kHz
    instance rg100Hz
    instance rg10Hz
    instance cmdDisp
    instance events
    instance tlmSend
    instance load
    instance rateGroupDriver
    instance timing
    instance controller
    instance monitor
    instance housekeeping
    instance uplink
    instance downlink
    instance faults
    instance osTime
    instance fatalAdapter
    instance fatalHandler

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
      rg100Hz.RateGroupMemberOut[4] -> timing.cycleEnd[1]

      rateGroupDriver.CycleOut[2] -> rg10Hz.CycleIn
      rg10Hz.RateGroupMemberOut[0] -> timing.cycleStart[2]
      rg10Hz.RateGroupMemberOut[1] -> housekeeping.schedIn
      rg10Hz.RateGroupMemberOut[2] -> uplink.schedIn
      rg10Hz.RateGroupMemberOut[3] -> tlmSend.Run
      rg10Hz.RateGroupMemberOut[4] -> cmdDisp.run
      rg10Hz.RateGroupMemberOut[5] -> load.burstIn
      rg10Hz.RateGroupMemberOut[6] -> faults.schedIn[2]
      rg10Hz.RateGroupMemberOut[7] -> timing.cycleEnd[2]
    }

    # The background load's burst goes through its own queue
    connections Load {
      load.ioOut -> load.ioIn
    }

    connections Control {
      monitor.statusGet -> controller.statusGet
    }

    connections Uplink {
      uplink.cmdOut -> cmdDisp.seqCmdBuff[0]
      cmdDisp.seqCmdStatus[0] -> uplink.cmdResponseIn
    }

    connections Downlink {
      events.PktSend -> downlink.comIn[0]
      tlmSend.PktSend -> downlink.comIn[1]
    }

    connections Faults {
      events.FatalAnnounce -> fatalHandler.FatalReceive
    }

  }

}
