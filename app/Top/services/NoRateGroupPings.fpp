# SPDX-License-Identifier: Apache-2.0
# The rate groups without health pings: passive rate groups have no queue
# or task to answer one, and the baremetal model's cooperative groups lose
# a cycle to each (CONFIG_KIT_HEALTH_PINGS_RATE_GROUPS in app/Kconfig).
# RateGroupPings.fpp beside it is the build with them.
module Kit {

  @ Health's ping entries after the rate groups' (none)
  constant pingEntriesToRateGroups = pingEntriesToDispatcher

  @ The rate groups, without ping connections (entries 3-5 absent)
  topology RateGroupHealth {

    instance rg1kHz
    instance rg100Hz
    instance rg10Hz

  }

}
