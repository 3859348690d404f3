# SPDX-License-Identifier: Apache-2.0
# The active rate groups' health pings (CONFIG_KIT_HEALTH_PINGS_RATE_GROUPS,
# app/Kconfig says where it is on and why); NoRateGroupPings.fpp beside it is
# the build without them. app/Top/topology.fpp imports whichever the build
# chose.
module Kit {

  @ Health's ping entries after the rate groups'
  constant pingEntriesToRateGroups = pingEntriesToDispatcher + 3

  @ The rate groups' health pings: entries 3-5 (app/Top/topology.fpp)
  topology RateGroupHealth {

    instance rg1kHz
    instance rg100Hz
    instance rg10Hz
    instance $health
    instance rg1kHzPing
    instance rg100HzPing
    instance rg10HzPing

    connections Health {
      $health.PingSend[3] -> rg1kHzPing.pingIn
      rg1kHzPing.pingOut -> rg1kHz.PingIn
      rg1kHz.PingOut -> rg1kHzPing.returnIn
      rg1kHzPing.returnOut -> $health.PingReturn[3]

      $health.PingSend[4] -> rg100HzPing.pingIn
      rg100HzPing.pingOut -> rg100Hz.PingIn
      rg100Hz.PingOut -> rg100HzPing.returnIn
      rg100HzPing.returnOut -> $health.PingReturn[4]

      $health.PingSend[5] -> rg10HzPing.pingIn
      rg10HzPing.pingOut -> rg10Hz.PingIn
      rg10Hz.PingOut -> rg10HzPing.returnIn
      rg10HzPing.returnOut -> $health.PingReturn[5]
    }

  }

}
