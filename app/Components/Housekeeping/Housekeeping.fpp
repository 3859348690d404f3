# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ 10 Hz housekeeping: scrubs a configuration table in RAM a slice per
    @ cycle (CRC-32 against the value taken at start-up) and reports uptime.
    passive component Housekeeping {

        @ Rate group input (10 Hz)
        sync input port schedIn: Svc.Sched

        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        event ScrubMismatch(expected: U32, actual: U32) severity warning high id 0 format "Config table CRC 0x{x}, expected 0x{x}"

        @ Complete passes over the configuration table
        telemetry ScrubPasses: U32 id 0

        @ Housekeeping cycles run
        telemetry Cycles: U32 id 1
    }
}
