# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ The ground link's health: what the uplink rejected, by reason, as
    @ telemetry. F´'s FrameAccumulator drops bytes that start no frame and
    @ frames whose checksum fails without a trace, and F´'s FprimeRouter
    @ drops packets of a type it does not know; the kit's frame detector
    @ (CountingFrameDetector, in this folder) counts the first two, and the
    @ router hands the third here. Ground commands pass it on their way to
    @ the dispatcher: it keeps no more than the configured number in flight
    @ (sent, not yet answered), so a ground that sends faster than the
    @ dispatcher runs loses commands, counted, instead of overrunning the
    @ dispatcher's queue, which asserts when full.
    passive component LinkHealth {

        @ Telemetry out (10 Hz rate group)
        sync input port schedIn: Svc.Sched

        @ Packets of a type the router does not route (its unknownDataOut)
        sync input port unknownIn: Svc.ComDataWithContext

        @ Their buffers, back to the router (its fileBufferReturnIn)
        output port unknownReturnOut: Fw.BufferSend

        @ Ground commands from the router
        sync input port commandIn: Fw.Com

        @ ... to the dispatcher, while fewer than the limit are in flight
        output port commandOut: Fw.Com

        @ The dispatcher's answer to a ground command
        sync input port commandStatusIn: Fw.CmdResponse

        @ ... back to the router
        output port commandStatusOut: Fw.CmdResponse

        time get port timeCaller

        event port logOut

        text event port logTextOut

        @ A ground command arrived with the limit in flight: dropped
        event CommandDropped(inFlight: U32, eventRoom: U32, total: U32) severity warning high id 0 format "Ground command dropped: {} in flight to the dispatcher, room for {} messages at the event service ({} dropped in all)" throttle 5

        telemetry port tlmOut

        @ Frames the detector found whole, with a good checksum
        telemetry FramesDetected: U32 id 0

        @ Frames with a start word and a length that fits, whose checksum
        @ failed: corrupted, or truncated and run into the next frame
        telemetry BadChecksums: U32 id 1

        @ Bytes discarded because no frame starts at them (garbage, and the
        @ rest of every rejected frame)
        telemetry BytesDiscarded: U32 id 2

        @ Frames whose length field exceeds the accumulator (F´ also emits
        @ FrameAccumulator's FrameDetectionSizeError)
        telemetry Oversized: U32 id 3

        @ Well-framed packets of a type the router does not route
        telemetry UnknownPackets: U32 id 4

        @ Ground commands dropped because the dispatcher had the limit in flight
        telemetry CommandsDropped: U32 id 5

        @ Bytes the link UART's receive interrupt read (under QEMU: every byte
        @ the ground wrote; QEMU holds back what the UART cannot take)
        telemetry UartBytesReceived: U32 id 6

        @ Of those, bytes the UART driver's receive ring had no room for:
        @ lost before any frame detection (the ring drains 64 bytes per
        @ 100 Hz poll)
        telemetry UartRingDrops: U32 id 7

        @ Receive errors the UART reported, by kind (Zephyr's uart_err_check;
        @ zero where the board's driver does not report them: the LINK
        @ console line says which). Written on change: rare by nature.
        telemetry UartOverruns: U32 id 8 update on change

        telemetry UartParityErrors: U32 id 9 update on change

        telemetry UartFramingErrors: U32 id 10 update on change

        telemetry UartBreaks: U32 id 11 update on change
    }
}
