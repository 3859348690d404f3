# SPDX-License-Identifier: Apache-2.0
module Thermal {

  @ The number of heated zones
  constant zones = 2

  @ A zone's temperature, in millidegrees Celsius
  port TemperatureGet(zone: U8) -> I32

  @ A zone's heater switched on or off
  port HeaterSet(zone: U8, heaterOn: bool)

}
