# SPDX-License-Identifier: Apache-2.0
module Thermal {

  @ Heater control: at 10 Hz each zone's heater on below its setpoint less
  @ the hysteresis and off above it; at 1 Hz the duty cycle of each heater
  @ over the last second
  passive component HeaterControl {

    @ Control (10 Hz)
    sync input port controlIn: Svc.Sched

    @ Status report (1 Hz)
    sync input port reportIn: Svc.Sched

    @ The zones' temperatures
    output port temperatureGet: TemperatureGet

    @ The zones' heaters
    output port heaterOut: HeaterSet

    import Fw.Command
    import Fw.Event
    import Fw.Channel
    time get port timeCaller

    @ Set a zone's setpoint
    sync command SET_SETPOINT(
      zone: U8 @< The zone, 0 or 1
      setpointMc: I32 @< Millidegrees Celsius, within the heaters' range
    ) opcode 0

    event SetpointChanged(zone: U8, setpointMc: I32) severity activity high id 0 format "Zone {} setpoint {} mC"

    event SetpointRejected(zone: U8, setpointMc: I32) severity warning low id 1 format "Zone {} setpoint {} mC refused"

    event HeaterSwitched(zone: U8, heaterOn: bool) severity activity low id 2 format "Zone {} heater on: {}"

    @ Zone 0's heater duty over the last second, in percent
    telemetry Duty0: U8 id 0

    @ Zone 1's heater duty over the last second, in percent
    telemetry Duty1: U8 id 1

    @ Control cycles run
    telemetry Cycles: U32 id 2
  }
}
