# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ The downlink's tally: counts the event and telemetry packets the F´
    @ services emit, and events by ID, and passes every packet on to the
    @ ground link unchanged. Scenarios check their events with it in the
    @ firmware, whether or not a ground station listens.
    passive component Downlink {

        @ Packets in: index 0 events (EventManager), index 1 telemetry (TlmChan)
        sync input port comIn: [2] Fw.Com

        @ The same packets out, same index, to the ground link's queue
        output port comOut: [2] Fw.Com
    }
}
