# SPDX-License-Identifier: Apache-2.0

module Kit {

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

        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        @ A rate-group cycle ended after the tick that released its next cycle
        event RateGroupSlip(
            rateGroup: U8 @< Rate group index
            $cycle: U32 @< Cycle number in that rate group
            ticksLate: U32 @< Ticks past the deadline
        ) severity warning high id 0 format "Rate group {} cycle {} ended {} tick(s) past its deadline" throttle 5

        @ Cycles completed by the fastest rate group
        telemetry FastCycles: U32 id 0

        @ Deadline misses over all rate groups
        telemetry Slips: U32 id 1

        @ Longest tick-to-start latency of the fastest rate group, in cycles of the board counter
        telemetry FastMaxLatency: U32 id 2
    }
}
