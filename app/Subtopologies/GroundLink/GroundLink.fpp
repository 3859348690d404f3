# SPDX-License-Identifier: Apache-2.0
# The ground link as an F´ subtopology, the same in every deployment: F´'s
# ComFprime chain (Svc/Subtopologies/ComFprime) with the kit's sizes (F´'s
# are a Linux host's), on fprime-zephyr's UART driver for the board's link
# UART (chosen kit,link-uart in boards/<board>/app.overlay), with the kit's
# LinkHealth counting what the uplink rejects. GroundLink.cpp beside it
# configures it. A deployment's topology imports it and connects:
#   events.PktSend -> downlink.comIn[0], tlmSend.PktSend -> downlink.comIn[1]
#   linkHealth.commandOut -> <dispatcher>.seqCmdBuff[i], and the status back
#     (<dispatcher>.seqCmdStatus[i] -> linkHealth.commandStatusIn)
#   linkUart.schedIn (it polls the UART), comQueue.run and
#     linkHealth.schedIn in its rate groups
# The comQueue's queue, stack and priority are the deployment's table's
# (Kit.Queues.comQueue, Kit.Stacks.comQueue, Kit.Priorities.comQueue).
module Kit {

  @ The ground link's sizes (F´'s ComFprime chain with the kit's numbers:
  @ F´'s defaults are sized for a Linux host)
  module Link {
    @ One pool for every link buffer: a frame of the largest packet
    @ (FW_COM_BUFFER_MAX_SIZE plus the F´ frame's 8 B header and 4 B CRC)
    @ and the UART's receive chunks
    constant bufferSize = 160
    @ The pool's buffers where the build has the file uplink: a frame of
    @ fprime-gds's largest file packet (its uplinker's 256 B of data, the
    @ data packet's 11 B header and the 2 B packet descriptor, in F´'s
    @ 12 B frame: 281 B), rounded to the allocator's 8 B
    constant fileFrameSize = 288
    constant bufferCount = 6
    @ Uplink bytes the frame accumulator holds while a frame arrives
    @ (in the dictionary: the ground tools need it)
    dictionary constant accumulatorSize = 320
    @ The BufferManager's ID, written into the buffers it hands out
    constant bufferManagerId = 1
    @ Ground commands the dispatcher may hold at once (LinkHealth drops
    @ more, counted): a fuzzing batch's worth, four and its NO_OP
    constant commandsInFlight = 5
    # The link's line rate is the link UART's devicetree current-speed
    # (boards/<board>/app.overlay): one place, read by the firmware
    # (GroundLink.cpp) and printed on its LINK line for the ground tools
  }

  @ The downlink's queue: events before telemetry, one packet on the wire at a time
  instance comQueue: Svc.ComQueue base id 0x2000 \
    queue size Queues.comQueue \
    stack size Stacks.comQueue \
    priority Priorities.comQueue


  instance framer: Svc.FprimeFramer base id 0x2100

  instance comStub: Svc.ComStub base id 0x2200

  instance frameAccumulator: Svc.FrameAccumulator base id 0x2300

  instance deframer: Svc.FprimeDeframer base id 0x2400

  instance router: Svc.FprimeRouter base id 0x2500

  instance linkBuffers: Svc.BufferManager base id 0x2600

  instance linkUart: Zephyr.ZephyrUartDriver base id 0x2700

  @ What the uplink rejected, by reason (F´'s chain drops some silently)
  instance linkHealth: Kit.LinkHealth base id 0x2800

  @ The ground link: bytes to and from the link UART, frames, commands
  topology GroundLink {

    instance downlink
    instance comQueue
    instance framer
    instance comStub
    instance frameAccumulator
    instance deframer
    instance router
    instance linkBuffers
    instance linkUart
    instance linkHealth

    # Events and telemetry leave the kit's tally (Downlink) for the link:
    # events before telemetry, framed, written to the link UART
    connections Downlink {
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
    # checked and unwrapped; commands pass the link's health component on
    # their way to the deployment's dispatcher
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

      router.commandOut -> linkHealth.commandIn
      linkHealth.commandStatusOut -> router.cmdResponseIn

      # Packets of a type the router does not route are counted, not lost
      router.unknownDataOut -> linkHealth.unknownIn
      linkHealth.unknownReturnOut -> router.fileBufferReturnIn
    }

  }

}
