# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ The load a measured segment of the ground scenario runs under: the axis
    @ its SWEEP lines name
    enum SegmentAxis {
        UPLINK = 0 @< commands from the ground, in commands per second
        DOWNLINK = 1 @< extra downlink packets (Load.SET_DOWNLINK), in packets per second
        NOISE = 2 @< random bytes up the link, in percent of its line rate
        FILE_DOWNLINK = 3 @< file data Svc.FileDownlink sends down (SendPartial from the ground), in bytes per second
        SEQUENCE = 4 @< commands a sequence runs (Svc.CmdSequencer, CS_RUN from the ground), in commands per second
    }

    @ Why a segment was not measured
    enum SegmentRefusal {
        NOT_SERVED = 0 @< the running scenario plays its own sequence (only the ground scenario measures on request)
        BUSY = 1 @< a segment is already requested or running
        BAD_LENGTH = 2 @< not a whole number of hyperperiods, or longer than SEGMENT_MAX_TICKS
    }

    @ Tick source of the rate groups and their timing probe. The variant's main
    @ loop hands it each board tick; it calls the rate group driver, and the
    @ first and last member of every rate group report cycle start and end, so
    @ the same code measures both variants.
    passive component Timing {

        @ Drives Svc.RateGroupDriver, once per tick
        output port CycleOut: Svc.Cycle

        @ First member of each rate group (port index = rate group index)
        sync input port cycleStart: [RateGroupDriverRateGroupPorts] Svc.Sched

        @ Last member of each rate group (port index = rate group index)
        sync input port cycleEnd: [RateGroupDriverRateGroupPorts] Svc.Sched

        import Fw.Command
        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        @ A rate-group cycle ended after the tick that released its next cycle
        event RateGroupSlip(
            rateGroup: U8 @< Rate group index
            $cycle: U32 @< Cycle number in that rate group
            ticksLate: U32 @< Ticks past the deadline
        ) severity warning high id 0 format "Rate group {} cycle {} ended {} tick(s) past its deadline" throttle 5

        @ Measure a segment under the load the ground has set (the serial-load
        @ sweep, driven by scripts/kit): at the next hyperperiod the records
        @ restart, `ticks` ticks run, and a SWEEP line per rate group goes to
        @ the console. The command completes when the request is taken; the
        @ records follow on the console.
        sync command MEASURE_SEGMENT(
            axis: SegmentAxis
            point: U32 @< Index of the point along the axis
            level: U32 @< The axis' setting, in its unit
            ticks: U32 @< Whole hyperperiods, at most SEGMENT_MAX_TICKS
        ) opcode 0

        event SegmentRequested(axis: SegmentAxis, point: U32, level: U32, ticks: U32) severity activity high id 1 format "Segment requested: {} point {} at {} for {} ticks"

        event SegmentRefused(reason: SegmentRefusal, ticks: U32) severity warning low id 2 format "Segment refused ({}): {} ticks"

        @ Cycles completed by the fastest rate group
        telemetry FastCycles: U32 id 0

        @ Deadline misses over all rate groups
        telemetry Slips: U32 id 1

        @ Longest tick-to-start latency of the fastest rate group, in cycles of the board counter
        telemetry FastMaxLatency: U32 id 2
    }
}
