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
    instance comQueue
    instance framer
    instance comStub
    instance frameAccumulator
    instance deframer
    instance router
    instance linkBuffers
    instance linkUart
    instance linkHealth

    # The kit's instruments: timing, the scripted uplink, the downlink's
    # tally, the background load, faults (app/Instruments/)
    import Instruments

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
    # the link: events before telemetry, framed, written to the link UART
    connections Downlink {
      events.PktSend -> downlink.comIn[0]
      tlmSend.PktSend -> downlink.comIn[1]
      downlink.comOut[0] -> comQueue.comPacketQueueIn[0]
      downlink.comOut[1] -> comQueue.comPacketQueueIn[1]

      comQueue.dataOut -> framer.dataIn
      framer.dataReturnOut -> comQueue.dataReturnIn
      framer.comStatusOut -> comQueue.comStatusIn
      framer.bufferAllocate -> linkBuffers.bufferGetCallee
      framer.bufferDeallocate -> linkBuffers.bufferSendIn

      framer.dataOut -> comStub.dataIn
      comStub.dataReturnOut -> framer.dataReturnIn
      comStub.comStatusOut -> framer.comStatusIn
      comStub.drvSendOut -> linkUart.$send
      linkUart.ready -> comStub.drvConnected
    }

    # Bytes from the ground: the UART's chunks are accumulated into frames,
    # checked and unwrapped, and commands go to the dispatcher like the
    # scripted uplink's
    connections GroundUplink {
      linkUart.allocate -> linkBuffers.bufferGetCallee
      linkUart.deallocate -> linkBuffers.bufferSendIn
      linkUart.$recv -> comStub.drvReceiveIn
      comStub.drvReceiveReturnOut -> linkUart.recvReturnIn

      comStub.dataOut -> frameAccumulator.dataIn
      frameAccumulator.dataReturnOut -> comStub.dataReturnIn
      frameAccumulator.bufferAllocate -> linkBuffers.bufferGetCallee
      frameAccumulator.bufferDeallocate -> linkBuffers.bufferSendIn

      frameAccumulator.dataOut -> deframer.dataIn
      deframer.dataReturnOut -> frameAccumulator.dataReturnIn
      deframer.dataOut -> router.dataIn
      router.dataReturnOut -> deframer.dataReturnIn
      router.bufferAllocate -> linkBuffers.bufferGetCallee
      router.bufferDeallocate -> linkBuffers.bufferSendIn

      # Ground commands pass the link's health component, which keeps no
      # more in flight than the dispatcher's queue can hold
      router.commandOut -> linkHealth.commandIn
      linkHealth.commandOut -> cmdDisp.seqCmdBuff[1]
      cmdDisp.seqCmdStatus[1] -> linkHealth.commandStatusIn
      linkHealth.commandStatusOut -> router.cmdResponseIn

      # Packets of a type the router does not route are counted, not lost
      router.unknownDataOut -> linkHealth.unknownIn
      linkHealth.unknownReturnOut -> router.fileBufferReturnIn
    }

    connections Faults {
      events.FatalAnnounce -> fatalHandler.FatalReceive
    }

  }

}
