# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Background load: the lowest-priority work of the deployment, set at run
    @ time by command. Each slice message (100 Hz) runs one uninterruptible
    @ computation of the commanded length; each burst tick (10 Hz) pushes a
    @ burst of messages through the component's own queue, as a telemetry or
    @ serial burst would. The same component is a cooperative task on
    @ Os/Baremetal and a low-priority thread on Zephyr: where it breaks the
    @ rate groups is what the load sweep measures.
    active component Load {

        @ Slice trigger (100 Hz rate group): one computation of the slice length
        async input port sliceIn: Svc.Sched hook

        @ Burst trigger (10 Hz rate group): queues the commanded burst
        sync input port burstIn: Svc.Sched

        @ The burst, looped back into this component's own queue
        output port ioOut: Svc.Sched

        @ One burst message: one computation of the burst message length
        async input port ioIn: Svc.Sched hook

        import Fw.Command
        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        @ Set the uninterruptible computation per slice message
        sync command SET_SLICE(
            us: U32 @< Microseconds per slice, at most SLICE_MAX_US
        ) opcode 0

        @ Set the burst sent through the queue every 10 Hz cycle
        sync command SET_BURST(
            $count: U32 @< Messages per burst, at most BURST_MAX
            us: U32 @< Microseconds of computation per message, at most SLICE_MAX_US
        ) opcode 1

        @ Set the extra downlink packets sent with every slice message (100 Hz):
        @ the downlink axis of the serial-load sweep. Events, not telemetry
        @ channels: every event is a packet of its own, while a channel
        @ written twice between downlinks is sent once.
        sync command SET_DOWNLINK(
            perSlice: U32 @< Events per slice message, at most DOWNLINK_MAX
        ) opcode 2

        @ Fill a file with the kit's test pattern (a 32-bit xorshift stream
        @ from the seed, its low byte per byte: Load.hpp, Pattern), as much of
        @ it as the file system takes: the file a downlink sends and the
        @ ground checks byte for byte
        sync command FILL_FILE(
            file: string size FileNameStringSize @< The file's path
            bytes: U32 @< The bytes asked for; fewer where the file is smaller
            seed: U32 @< The pattern's seed, not 0
        ) opcode 3

        @ Set the pace of the load: one slice each sliceEvery messages of
        @ sliceIn (the others run no computation), one burst each burstEvery
        @ calls of burstIn. The load sweep paces a load whose work at the top
        @ of its axis would outgrow its rate group's period (app/scenarios/load.cpp)
        sync command SET_PACE(
            sliceEvery: U32 @< sliceIn messages per slice, 1 to PACE_MAX
            burstEvery: U32 @< burstIn calls per burst, 1 to PACE_MAX
        ) opcode 4

        event LoadSet(sliceUs: U32, burst: U32, burstUs: U32) severity activity high id 0 format "Load: {} us per slice, bursts of {} x {} us"

        event LoadRejected(value: U32, limit: U32) severity warning low id 1 format "Load setting {} is above its limit {}"

        @ The queue was full: the load falls behind (an overrun of the lowest priority)
        event MessagesDropped(total: U32) severity warning high id 2 format "Load queue full: {} messages dropped so far" throttle 5

        event DownlinkLoadSet(perSlice: U32) severity activity high id 3 format "Downlink load: {} packets per slice"

        @ One extra downlink packet (SET_DOWNLINK); its number counts them all
        event DownlinkLoadPacket(sequence: U32) severity activity low id 4 format "Downlink load packet {}"

        event FileFilled(file: string size FileNameStringSize, bytes: U32, seed: U32) severity activity high id 5 format "File {} filled: {} bytes of the pattern from seed {}"

        event PaceSet(sliceEvery: U32, burstEvery: U32) severity activity high id 7 format "Load paced: a slice each {} slice messages, a burst each {} burst calls"

        event FileNotFilled(file: string size FileNameStringSize, written: U32, status: I32) severity warning low id 6 format "File {} not filled: {} bytes written, file status {}"

        @ Slice and burst messages processed
        telemetry Processed: U32 id 0

        @ Messages dropped on a full queue
        telemetry Dropped: U32 id 1
    }
}
