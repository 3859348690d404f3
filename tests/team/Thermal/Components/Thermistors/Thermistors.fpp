# SPDX-License-Identifier: Apache-2.0
module Thermal {

  @ 50 Hz thermistor sampling: each zone's reading, filtered, from a model of
  @ the zone's thermal mass (its heater warms it, the environment cools it),
  @ which stands in for an ADC on a board without one
  passive component Thermistors {

    @ Rate group input (50 Hz)
    sync input port schedIn: Svc.Sched

    @ The filtered temperature of a zone
    sync input port temperatureGet: TemperatureGet

    @ A zone's heater, as the controller switched it
    sync input port heaterIn: HeaterSet

    import Fw.Channel
    time get port timeCaller

    @ Zone 0's filtered temperature
    telemetry Zone0: I32 id 0 format "{} mC"

    @ Zone 1's filtered temperature
    telemetry Zone1: I32 id 1 format "{} mC"

    @ Samples taken
    telemetry Samples: U32 id 2
  }
}
