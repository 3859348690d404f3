# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ 100 Hz monitor: checks the control error against a limit with a
    @ persistence count, so one noisy sample does not raise an alarm.
    passive component Monitor {

        @ Rate group input (100 Hz)
        sync input port schedIn: Svc.Sched

        @ Reads the controller's status
        output port statusGet: ControlStatusGet

        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        event ErrorLimitExceeded(error: I32, limit: I32) severity warning high id 0 format "Control error {} exceeds +-{}"

        event ErrorRecovered(error: I32) severity activity high id 1 format "Control error back within limits ({})"

        @ Largest absolute control error seen
        telemetry MaxError: I32 id 0

        @ Checks run
        telemetry Checks: U32 id 1
    }
}
