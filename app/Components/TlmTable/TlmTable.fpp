# SPDX-License-Identifier: Apache-2.0
module Kit {
    @ The telemetry store in one table: the ports and behaviour of F´'s
    @ Svc.TlmChan (the latest value of each channel; at each Run, every
    @ channel written since the last one goes down in Fw.TlmPacket packets)
    @ with half its RAM. TlmChan keeps two hash tables (a double buffer, so
    @ that a writer never waits for the read); fprime-baremetal's
    @ TlmLinearChan keeps one, but reads it unlocked, which a preempting
    @ writer can tear. This one keeps one table and reads each entry through
    @ a sequence lock (a copy kept only when no write moved the entry's
    @ number meanwhile), so the read never blocks a writer and never keeps
    @ a torn value, in any execution model. See docs/sdd.md.
    active component TlmTable {
        @ A channel's new value (guarded: under the component's lock)
        guarded input port TlmRecv: Fw.Tlm

        @ A channel's last value, by reference (guarded)
        guarded input port TlmGet: Fw.TlmGet

        @ Starts a packet send cycle
        async input port Run: Svc.Sched

        @ Telemetry packets to the ground link
        output port PktSend: Fw.Com

        @ Svc.Health's ping
        async input port pingIn: Svc.Ping

        @ Its answer
        output port pingOut: Svc.Ping
    }
}
