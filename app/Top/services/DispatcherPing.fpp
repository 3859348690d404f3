# SPDX-License-Identifier: Apache-2.0
# Health's ping of the active dispatcher (CONFIG_KIT_SERVICE_CDH, and
# F´'s CommandDispatcher: the passive one has no task to answer a ping).
# NoDispatcherPing.fpp beside it is the build without.
module Kit {

  @ Health's ping entries after the dispatcher's
  constant pingEntriesToDispatcher = 3

  @ The dispatcher's ping: entry 2 (app/Top/services/CdhServices.fpp)
  topology DispatcherHealth {

    instance $health
    instance cmdDisp
    instance cmdDispPing

    connections Health {
      $health.PingSend[2] -> cmdDispPing.pingIn
      cmdDispPing.pingOut -> cmdDisp.pingIn
      cmdDisp.pingOut -> cmdDispPing.returnIn
      cmdDispPing.returnOut -> $health.PingReturn[2]
    }

  }

}
