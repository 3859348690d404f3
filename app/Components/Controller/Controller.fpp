# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ Latest state of the control loop, in sensor counts
    struct ControlStatus {
        setpoint: I32
        measurement: I32
        actuator: I32
    }

    @ The controller's gains, each a right shift (gain 1/2^shift): the
    @ parameters' defaults, and the largest shift it takes (in the
    @ dictionary: the ground's tests of the parameters read them)
    module ControllerGains {
        dictionary constant kpShift = 1
        dictionary constant kiShift = 6
        dictionary constant maxShift = 15
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

        @ The gains are F´ parameters: set and saved from the ground
        @ (CONTROLLER_KP_SHIFT_PRM_SET, ..._PRM_SAVE, then PrmDb's
        @ PRM_SAVE_FILE), loaded from the parameter database at start-up
        param get port prmGetOut
        param set port prmSetOut

        @ Set the value the loop tracks, in sensor counts
        sync command SET_SETPOINT(
            setpoint: I32 @< Target, within +-SETPOINT_LIMIT counts
        ) opcode 0

        event SetpointChanged(setpoint: I32) severity activity high id 0 format "Setpoint set to {}"

        event SetpointRejected(setpoint: I32, limit: I32) severity warning low id 1 format "Setpoint {} is outside +-{}"

        @ Proportional gain, as a right shift of the error (1/2^KP_SHIFT)
        param KP_SHIFT: U8 default ControllerGains.kpShift id 0

        @ Integral gain, as a right shift of the integral (1/2^KI_SHIFT)
        param KI_SHIFT: U8 default ControllerGains.kiShift id 1

        @ The gains in effect: at start-up, once the parameters are loaded,
        @ and when the ground changes one
        event GainsApplied(kpShift: U8, kiShift: U8) severity activity high id 2 format "Gains 1/2^{} (P) and 1/2^{} (I) in effect"

        event GainRejected(shift: U8, limit: U8) severity warning low id 3 format "Gain shift {} is above {}: the gains are unchanged"

        telemetry Setpoint: I32 id 0
        telemetry Measurement: I32 id 1
        telemetry Output: I32 id 2
    }
}
