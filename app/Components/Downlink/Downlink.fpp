# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Downlink end point: receives the event and telemetry packets the F´
    @ services emit, counts them, and counts events by ID. It
    @ stands where a radio or serial framer would go.
    passive component Downlink {

        @ Packets in: index 0 events (EventManager), index 1 telemetry (TlmChan)
        sync input port comIn: [2] Fw.Com
    }
}
