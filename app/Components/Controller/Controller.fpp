# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Latest state of the control loop, in sensor counts
    struct ControlStatus {
        setpoint: I32
        measurement: I32
        actuator: I32
    }

    @ Reads the controller's latest status
    port ControlStatusGet -> ControlStatus

    @ 1 kHz controller: low-pass filters a simulated, noisy sensor on a
    @ simulated first-order plant and closes a PI loop on it. Fixed-point,
    @ because the Cortex-M3 has no FPU.
    passive component Controller {

        @ Rate group input (1 kHz)
        sync input port schedIn: Svc.Sched

        @ Status for the monitor
        sync input port statusGet: ControlStatusGet

        import Fw.Command
        import Fw.Event
        import Fw.Channel
        time get port timeCaller

        @ Set the value the loop tracks, in sensor counts
        sync command SET_SETPOINT(
            setpoint: I32 @< Target, within +-SETPOINT_LIMIT counts
        ) opcode 0

        event SetpointChanged(setpoint: I32) severity activity high id 0 format "Setpoint set to {}"

        event SetpointRejected(setpoint: I32, limit: I32) severity warning low id 1 format "Setpoint {} is outside +-{}"

        telemetry Setpoint: I32 id 0
        telemetry Measurement: I32 id 1
        telemetry Output: I32 id 2
    }
}
