# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Command uplink. Feeds raw command frames (F´ command packets: packet
    @ descriptor, opcode, arguments) into the command dispatcher's sequence
    @ port, as a radio or serial decoder would, and records every response.
    @ The frames come from a script given at configuration, so a run is
    @ deterministic and needs no ground system.
    passive component Uplink {

        @ Rate group input (10 Hz): frames whose cycle has come are sent
        sync input port schedIn: Svc.Sched

        @ Command packets to the dispatcher
        output port cmdOut: Fw.Com

        @ Dispatcher's answer to each frame (cmdSeq = frame index)
        sync input port cmdResponseIn: Fw.CmdResponse

        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        event FrameSent(index: U32, $size: U32) severity activity low id 0 format "Uplink frame {} sent ({} bytes)"

        event FrameAnswered(index: U32, $opcode: U32, response: Fw.CmdResponse) severity activity high id 1 format "Uplink frame {} opcode 0x{x}: {}"

        @ Frames sent
        telemetry FramesSent: U32 id 0

        @ Frames answered with an error
        telemetry FramesRejected: U32 id 1
    }
}
