# SPDX-License-Identifier: Apache-2.0
module Kit {
    @ The health pings' round trip, timed. Sits on each of Svc.Health's ping
    @ connections: a ping passes through on its way to the component (its
    @ send time kept), and the answer on its way back (the round trip
    @ recorded). Svc.Health counts a late answer only in its own cycles
    @ (WARN cycles of its rate group); this gives the time, per component, so
    @ the report can show how far each answer is from the warning. One
    @ instance per ping entry: FPP connects each port of health's matched
    @ PingSend/PingReturn arrays to an instance of its own.
    passive component PingProbe {
        @ From Svc.Health's PingSend[i]
        sync input port pingIn: Svc.Ping
        @ To the pinged component's pingIn
        output port pingOut: Svc.Ping
        @ From the pinged component's pingOut, on its own task
        sync input port returnIn: Svc.Ping
        @ To Svc.Health's PingReturn[i]
        output port returnOut: Svc.Ping
    }
}
